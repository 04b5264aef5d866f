#include "bench/clipper1_bool_ops.h"

#include <algorithm>
#include <clipper.hpp>
#include <cmath>
#include <stdexcept>

namespace shadowgen::bench {
namespace {

using clipper::Loop2;
using clipper::PolygonSet2;
using clipper::PolygonWithHoles2;

double largest_magnitude(const PolygonWithHoles2& polygon) {
  double m = 0.0;
  auto visit = [&m](const Loop2& loop) {
    for (const auto& p : loop) m = std::max({m, std::abs(p.x), std::abs(p.y)});
  };
  visit(polygon.outer);
  for (const auto& hole : polygon.holes) visit(hole);
  return m;
}

void append_rounded(const PolygonWithHoles2& polygon, double scale, ClipperLib::Paths& out) {
  auto rounded = [scale](const Loop2& loop) {
    ClipperLib::Path path;
    path.reserve(loop.size());
    for (const auto& p : loop)
      path.emplace_back(std::llround(p.x * scale), std::llround(p.y * scale));
    return path;
  };
  out.push_back(rounded(polygon.outer));
  for (const auto& hole : polygon.holes) out.push_back(rounded(hole));
}

Loop2 to_doubles(const ClipperLib::Path& path, double scale) {
  Loop2 loop;
  loop.reserve(path.size());
  for (const auto& p : path) {
    loop.push_back({static_cast<double>(p.X) / scale, static_cast<double>(p.Y) / scale});
  }
  return loop;
}

// Outer nodes become polygons holding their hole children; islands inside a hole are
// outer nodes again, one level further down.
void collect(const ClipperLib::PolyNode& node, double scale, PolygonSet2& out) {
  for (const ClipperLib::PolyNode* outer : node.Childs) {
    PolygonWithHoles2 polygon;
    polygon.outer = to_doubles(outer->Contour, scale);
    for (const ClipperLib::PolyNode* hole : outer->Childs) {
      polygon.holes.push_back(to_doubles(hole->Contour, scale));
      collect(*hole, scale, out);
    }
    out.push_back(std::move(polygon));
  }
}

}  // namespace

struct Clipper1BoolOps::Impl {
  const PolygonWithHoles2* subject;
  const PolygonWithHoles2* clip_region;
  Output output;
  double scale;

  ClipperLib::Paths subject_paths;
  ClipperLib::Paths clip_paths;
  ClipperLib::Clipper engine;
  ClipperLib::PolyTree inside_tree;
  ClipperLib::PolyTree outside_tree;
  ClipperLib::Paths inside_paths;
  ClipperLib::Paths outside_paths;
};

Clipper1BoolOps::Clipper1BoolOps(const PolygonWithHoles2& subject,
                                 const PolygonWithHoles2& clip_region, Output output)
    : impl_(std::make_unique<Impl>()) {
  impl_->subject = &subject;
  impl_->clip_region = &clip_region;
  impl_->output = output;
  const double extent = std::max(largest_magnitude(subject), largest_magnitude(clip_region));
  if (!(extent > 0.0)) throw std::invalid_argument("Clipper1BoolOps: empty input");
  impl_->scale = 1e9 / extent;
}

Clipper1BoolOps::~Clipper1BoolOps() = default;

void Clipper1BoolOps::run() {
  Impl& s = *impl_;
  s.subject_paths.clear();
  s.clip_paths.clear();
  append_rounded(*s.subject, s.scale, s.subject_paths);
  append_rounded(*s.clip_region, s.scale, s.clip_paths);

  s.engine.Clear();
  s.engine.AddPaths(s.subject_paths, ClipperLib::ptSubject, true);
  s.engine.AddPaths(s.clip_paths, ClipperLib::ptClip, true);
  bool ok = true;
  if (s.output == Output::kPolyTree) {
    ok = s.engine.Execute(ClipperLib::ctIntersection, s.inside_tree, ClipperLib::pftEvenOdd,
                          ClipperLib::pftEvenOdd) &&
         s.engine.Execute(ClipperLib::ctDifference, s.outside_tree, ClipperLib::pftEvenOdd,
                          ClipperLib::pftEvenOdd);
  } else {
    ok = s.engine.Execute(ClipperLib::ctIntersection, s.inside_paths, ClipperLib::pftEvenOdd,
                          ClipperLib::pftEvenOdd) &&
         s.engine.Execute(ClipperLib::ctDifference, s.outside_paths, ClipperLib::pftEvenOdd,
                          ClipperLib::pftEvenOdd);
  }
  if (!ok) throw std::runtime_error("Clipper1BoolOps: Clipper::Execute failed");
}

clipper::ClipResult Clipper1BoolOps::result() const {
  if (impl_->output != Output::kPolyTree) {
    throw std::logic_error("Clipper1BoolOps::result needs Output::kPolyTree");
  }
  const double scale = impl_->scale;
  clipper::ClipResult r;
  collect(impl_->inside_tree, scale, r.inside);
  collect(impl_->outside_tree, scale, r.outside);
  return r;
}

}  // namespace shadowgen::bench
