#include "bench/cgal_bool_ops.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <cmath>
#include <iterator>
#include <vector>

namespace shadowgen::bench {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using CgalPolygon = CGAL::Polygon_2<Kernel>;
using CgalPolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;

using clipper::Loop2;
using clipper::PolygonSet2;
using clipper::PolygonWithHoles2;

// CGAL wants the outer boundary counter-clockwise and the holes clockwise, whatever
// the caller's orientation.
CgalPolygon to_cgal(const Loop2& loop, CGAL::Orientation wanted) {
  CgalPolygon p;
  for (const auto& v : loop) p.push_back(Kernel::Point_2(v.x, v.y));
  if (p.orientation() != wanted) p.reverse_orientation();
  return p;
}

CgalPolygonWithHoles to_cgal(const PolygonWithHoles2& polygon) {
  CgalPolygonWithHoles p(to_cgal(polygon.outer, CGAL::COUNTERCLOCKWISE));
  for (const auto& hole : polygon.holes) p.add_hole(to_cgal(hole, CGAL::CLOCKWISE));
  return p;
}

Loop2 to_doubles(const CgalPolygon& polygon) {
  Loop2 loop;
  loop.reserve(polygon.size());
  for (const auto& v : polygon.vertices())
    loop.push_back({CGAL::to_double(v.x()), CGAL::to_double(v.y())});
  return loop;
}

using Rational = CGAL::Exact_rational;

Rational exact(const Kernel::FT& x) { return Rational(CGAL::exact(x)); }

Rational exact_area(const std::vector<CgalPolygonWithHoles>& pieces) {
  Kernel::FT sum = 0;
  for (const auto& p : pieces) {
    sum += CGAL::abs(p.outer_boundary().area());
    for (const auto& hole : p.holes()) sum -= CGAL::abs(hole.area());
  }
  return exact(sum);
}

Rational exact_abs_area(const Loop2& loop) {
  Rational twice = 0;
  for (std::size_t i = 0, n = loop.size(); i < n; ++i) {
    const auto& a = loop[i];
    const auto& b = loop[(i + 1) % n];
    twice += Rational(a.x) * Rational(b.y) - Rational(b.x) * Rational(a.y);
  }
  return CGAL::abs(twice) / 2;
}

Rational exact_area(const PolygonSet2& polygons) {
  Rational sum = 0;
  for (const auto& p : polygons) {
    sum += exact_abs_area(p.outer);
    for (const auto& hole : p.holes) sum -= exact_abs_area(hole);
  }
  return sum;
}

}  // namespace

struct CgalBoolOps::Impl {
  CgalPolygonWithHoles subject;
  CgalPolygonWithHoles clip_region;
  std::vector<CgalPolygonWithHoles> inside;
  std::vector<CgalPolygonWithHoles> outside;
};

CgalBoolOps::CgalBoolOps(const PolygonWithHoles2& subject, const PolygonWithHoles2& clip_region)
    : impl_(std::make_unique<Impl>()) {
  impl_->subject = to_cgal(subject);
  impl_->clip_region = to_cgal(clip_region);
}

CgalBoolOps::~CgalBoolOps() = default;

void CgalBoolOps::run() {
  Impl& s = *impl_;
  s.inside.clear();
  s.outside.clear();
  CGAL::intersection(s.subject, s.clip_region, std::back_inserter(s.inside));
  CGAL::difference(s.subject, s.clip_region, std::back_inserter(s.outside));
}

clipper::ClipResult CgalBoolOps::result() const {
  clipper::ClipResult r;
  auto convert = [](const std::vector<CgalPolygonWithHoles>& pieces, PolygonSet2& out) {
    for (const auto& p : pieces) {
      PolygonWithHoles2 q;
      q.outer = to_doubles(p.outer_boundary());
      for (const auto& hole : p.holes()) q.holes.push_back(to_doubles(hole));
      out.push_back(std::move(q));
    }
  };
  convert(impl_->inside, r.inside);
  convert(impl_->outside, r.outside);
  return r;
}

struct ExactAreaReference::Areas {
  Rational inside;
  Rational outside;
};

ExactAreaReference::ExactAreaReference(const PolygonWithHoles2& subject,
                                       const PolygonWithHoles2& clip_region) {
  CgalBoolOps ops(subject, clip_region);
  ops.run();
  areas_ =
      std::make_unique<Areas>(Areas{exact_area(ops.impl_->inside), exact_area(ops.impl_->outside)});
}

ExactAreaReference::~ExactAreaReference() = default;
ExactAreaReference::ExactAreaReference(ExactAreaReference&&) noexcept = default;
ExactAreaReference& ExactAreaReference::operator=(ExactAreaReference&&) noexcept = default;

double ExactAreaReference::relative_area_error(const clipper::ClipResult& result) const {
  const Rational error = CGAL::abs(exact_area(result.inside) - areas_->inside) +
                         CGAL::abs(exact_area(result.outside) - areas_->outside);
  return CGAL::to_double(error / (areas_->inside + areas_->outside));
}

}  // namespace shadowgen::bench
