#pragma once

// How two closed segments meet, decided exactly with clipper::orient2d.

#include "clipper/point.h"

namespace shadowgen::clipper {

enum class Contact {
  kNone,     // disjoint
  kTouch,    // exactly one common point, an endpoint of one of them
  kCross,    // one common point interior to both
  kOverlap,  // collinear, sharing a piece of positive length
};

struct SegmentContact {
  Contact contact = Contact::kNone;
  clipper::Point2 at;  // kTouch: the common point (one of the four given points)
};

// Segments [a, b] and [c, d], each of positive length.
SegmentContact segment_contact(const clipper::Point2& a, const clipper::Point2& b,
                               const clipper::Point2& c, const clipper::Point2& d);

}  // namespace shadowgen::clipper
