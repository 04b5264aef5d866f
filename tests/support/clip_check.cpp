#include "tests/support/clip_check.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <sstream>

#include "tests/support/wkt.h"

namespace shadowgen::test {

using clipper::ClipResult;
using clipper::PolygonSet2;

double ClipCheck::forward_error() const {
  return std::max({inside_error, outside_error, conservation_error});
}

double ClipCheck::worst_error() const {
  return std::max({forward_error(), swapped_inside_error, swapped_outside_error,
                   swapped_conservation_error, swap_mismatch});
}

std::string ClipCheck::failure(double forward_bound, double swapped_bound) const {
  if (!exception.empty()) return "clip threw: " + exception;
  if (!invalid.empty()) return "invalid output: " + invalid;
  std::ostringstream out;
  out.precision(3);
  auto exceeds = [&out](const char* what, double error, double bound) {
    if (error <= bound) return false;  // a NaN error fails too
    out << what << " error " << error << " exceeds " << bound;
    return true;
  };
  if (exceeds("inside area", inside_error, forward_bound) ||
      exceeds("outside area", outside_error, forward_bound) ||
      exceeds("inside + outside = subject", conservation_error, forward_bound) ||
      exceeds("swapped inside area", swapped_inside_error, swapped_bound) ||
      exceeds("swapped outside area", swapped_outside_error, swapped_bound) ||
      exceeds("swapped inside + outside = clip", swapped_conservation_error, swapped_bound) ||
      exceeds("swap mismatch of the inside area", swap_mismatch, forward_bound) ||
      (inside_discrepancy >= 0.0 &&
       exceeds("inside symmetric difference", inside_discrepancy, forward_bound)) ||
      (outside_discrepancy >= 0.0 &&
       exceeds("outside symmetric difference", outside_discrepancy, forward_bound))) {
    return out.str();
  }
  return {};
}

namespace {

std::string first_problem(const ClipResult& result, const std::string& run) {
  if (std::string problem = validity_problem(result.inside); !problem.empty()) {
    return run + " inside pieces: " + problem;
  }
  if (std::string problem = validity_problem(result.outside); !problem.empty()) {
    return run + " outside pieces: " + problem;
  }
  return {};
}

// For an invalid set, CGAL's own verdict on each polygon that validity_problem rejects:
// a second opinion on the oracle's checker, printed with the failure.
std::string cgal_opinion(const ClipResult& result) {
  std::string opinion;
  for (const auto* pieces : {&result.inside, &result.outside}) {
    for (std::size_t i = 0; i < pieces->size(); ++i) {
      const PolygonWithHoles2& polygon = (*pieces)[i];
      if (validity_problem(polygon).empty()) continue;
      opinion += std::string(pieces == &result.inside ? "inside" : "outside") + " polygon " +
                 std::to_string(i) + ": CGAL is_valid_polygon_with_holes " +
                 (cgal_accepts(polygon) ? "accepts it" : "rejects it too") + "; ";
    }
  }
  return opinion;
}

}  // namespace

ClipCheck check_clip(const PolygonSet2& subject, const PolygonSet2& clip,
                     const ClipCheckOptions& options) {
  ClipCheck check;
  const ExactOverlay overlay(subject, clip);
  check.exact = overlay.areas();
  try {
    check.forward = clipper::clip(subject, clip);
    if (options.swapped) check.swapped = clipper::clip(clip, subject);
  } catch (const std::exception& error) {
    check.exception = error.what();
    return check;
  }
  const double inside = exact_area_of_pieces(check.forward.inside);
  const double outside = exact_area_of_pieces(check.forward.outside);
  check.inside_error = std::abs(inside - check.exact.inside);
  check.outside_error = std::abs(outside - check.exact.outside);
  check.conservation_error = std::abs(inside + outside - check.exact.subject);
  check.invalid = first_problem(check.forward, "forward");
  if (!check.invalid.empty()) check.cgal_opinion = cgal_opinion(check.forward);
  if (options.swapped) {
    const double swapped_inside = exact_area_of_pieces(check.swapped.inside);
    const double swapped_outside = exact_area_of_pieces(check.swapped.outside);
    check.swapped_inside_error = std::abs(swapped_inside - check.exact.inside);
    check.swapped_outside_error = std::abs(swapped_outside - check.exact.clip_outside);
    check.swapped_conservation_error =
        std::abs(swapped_inside + swapped_outside - check.exact.clip);
    check.swap_mismatch = std::abs(inside - swapped_inside);
    if (check.invalid.empty()) {
      check.invalid = first_problem(check.swapped, "swapped");
      if (!check.invalid.empty()) check.cgal_opinion = cgal_opinion(check.swapped);
    }
  }
  if (options.symmetric_difference && check.invalid.empty()) {
    check.inside_discrepancy = overlay.inside_discrepancy(check.forward.inside);
    check.outside_discrepancy = overlay.outside_discrepancy(check.forward.outside);
  }
  return check;
}

namespace {

struct Extent {
  double largest_norm = 0.0;
  double longest_edge = 0.0;
  double perimeter = 0.0;
};

Extent extent_of(const PolygonSet2& polygons) {
  Extent extent;
  auto add = [&extent](const clipper::Loop2& loop) {
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const clipper::Point2& p = loop[i];
      const clipper::Point2& q = loop[(i + 1) % loop.size()];
      const double length = std::hypot(q.x - p.x, q.y - p.y);
      extent.largest_norm = std::max(extent.largest_norm, std::hypot(p.x, p.y));
      extent.longest_edge = std::max(extent.longest_edge, length);
      extent.perimeter += length;
    }
  };
  for (const clipper::PolygonWithHoles2& p : polygons) {
    add(p.outer);
    for (const clipper::Loop2& hole : p.holes) add(hole);
  }
  return extent;
}

}  // namespace

double area_error_bound(const PolygonSet2& subject, const PolygonSet2& clip) {
  const double u = 0x1p-53;
  const Extent s = extent_of(subject);
  const Extent c = extent_of(clip);
  const double delta = u * (4.0 * std::max(s.longest_edge, c.longest_edge) +
                            std::max(s.largest_norm, c.largest_norm));
  return 2.0 * delta * (s.perimeter + c.perimeter);
}

std::string describe(const ClipCheck& check, const PolygonSet2& subject, const PolygonSet2& clip) {
  std::ostringstream out;
  out.precision(6);
  out << "subject: " << to_wkt(subject) << "\nclip:    " << to_wkt(clip) << '\n';
  out << "exact areas: subject " << check.exact.subject << ", clip " << check.exact.clip
      << ", inside " << check.exact.inside << ", outside " << check.exact.outside << '\n';
  out << "errors: inside " << check.inside_error << ", outside " << check.outside_error
      << ", conservation " << check.conservation_error << "; swapped: inside "
      << check.swapped_inside_error << ", outside " << check.swapped_outside_error
      << ", conservation " << check.swapped_conservation_error << ", mismatch "
      << check.swap_mismatch << '\n';
  if (check.inside_discrepancy >= 0.0) {
    out << "symmetric differences: inside " << check.inside_discrepancy << ", outside "
        << check.outside_discrepancy << '\n';
  }
  out << "pieces: forward " << check.forward.inside.size() << " inside, "
      << check.forward.outside.size() << " outside; swapped " << check.swapped.inside.size()
      << " inside, " << check.swapped.outside.size() << " outside\n";
  if (!check.exception.empty()) out << "exception: " << check.exception << '\n';
  if (!check.invalid.empty()) out << "invalid: " << check.invalid << '\n';
  if (!check.cgal_opinion.empty()) out << "second opinion: " << check.cgal_opinion << '\n';
  return out.str();
}

}  // namespace shadowgen::test
