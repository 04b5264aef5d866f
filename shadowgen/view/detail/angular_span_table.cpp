#include "detail/angular_span_table.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowgen::view::detail {
namespace {

// One loop of a hidden part in local coordinates, each vertex with what the edge leaving it
// crosses when a row meets it.
struct LocalLoop {
  std::vector<glm::dvec3> points;
  std::vector<Crossing> edges;
};

Crossing crossing_of(EdgeKind kind) {
  switch (kind) {
    case EdgeKind::kRidge:
      return Crossing::kRidge;
    case EdgeKind::kHidden:
      return Crossing::kHidden;
    default:
      return Crossing::kOpen;
  }
}

// Sutherland and Hodgman against W >= 0: the part of the loop in this hemisphere; the
// pieces along W = 0 are tagged kHemisphere.
LocalLoop clipped(const LocalLoop& loop) {
  LocalLoop out;
  const std::size_t n = loop.points.size();
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec3& p = loop.points[i];
    const glm::dvec3& q = loop.points[(i + 1) % n];
    const bool p_in = p.z >= 0.0, q_in = q.z >= 0.0;
    auto cut = [&] { return p + (q - p) * (p.z / (p.z - q.z)); };
    if (p_in) {
      out.points.push_back(p);
      out.edges.push_back(loop.edges[i]);
      if (!q_in) {
        out.points.push_back(cut());
        out.edges.push_back(Crossing::kHemisphere);
      }
    } else if (q_in) {
      out.points.push_back(cut());
      out.edges.push_back(loop.edges[i]);
    }
  }
  return out;
}

struct RowCrossing {
  double phi;
  glm::dvec3 point;
  Crossing what;
};

}  // namespace

AngularSpanTable::AngularSpanTable(const AngularFrame& frame, int hemisphere,
                                   const RidgeEdgeLoops& loops,
                                   std::span<const hsr::Polygon3> polygons, int resolution)
    : frame_(&frame),
      lo_(std::numeric_limits<double>::infinity()),
      hi_(-std::numeric_limits<double>::infinity()) {
  struct HiddenPart {
    std::size_t object;
    std::vector<LocalLoop> loops;
    double lo, hi;
  };
  std::vector<HiddenPart> hidden;
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    if (loops.facing[i] != Facing::kHidden) continue;
    HiddenPart part{loops.object_of_part[i],
                    {},
                    std::numeric_limits<double>::infinity(),
                    -std::numeric_limits<double>::infinity()};
    for (std::size_t l = 0; l < loops.part_loop_edges[i].size(); ++l) {
      const hsr::Loop3& loop3 = l == 0 ? polygons[i].outer : polygons[i].holes[l - 1];
      LocalLoop loop;
      for (std::size_t k = 0; k < loop3.size(); ++k) {
        loop.points.push_back(frame.local(loop3[k], hemisphere));
        loop.edges.push_back(crossing_of(loops.edges[loops.part_loop_edges[i][l][k]].kind));
      }
      if (frame.point()) loop = clipped(loop);
      if (loop.points.size() < 2) continue;
      for (const glm::dvec3& q : loop.points) {
        part.lo = std::min(part.lo, frame.row(q));
        part.hi = std::max(part.hi, frame.row(q));
      }
      part.loops.push_back(std::move(loop));
    }
    if (part.loops.empty()) continue;
    lo_ = std::min(lo_, part.lo);
    hi_ = std::max(hi_, part.hi);
    hidden.push_back(std::move(part));
  }
  if (empty()) return;
  const int n = hi_ > lo_ ? std::max(resolution, 1) : 1;
  step_ = (hi_ - lo_) / n;
  rows_.resize(static_cast<std::size_t>(n));
  reach_.resize(static_cast<std::size_t>(n));

  // Scan conversion: each hidden part's loops cut by the planes of the rows it spans.
  std::vector<RowCrossing> crossings;
  for (const HiddenPart& part : hidden) {
    const int first = row_of(part.lo), last = row_of(part.hi);
    for (int k = first; k <= last; ++k) {
      const double theta = lo_ + (k + 0.5) * step_;
      crossings.clear();
      for (const LocalLoop& loop : part.loops) {
        for (std::size_t i = 0, m = loop.points.size(); i < m; ++i) {
          const glm::dvec3& p = loop.points[i];
          const glm::dvec3& q = loop.points[(i + 1) % m];
          const double sp = frame.side(p, theta), sq = frame.side(q, theta);
          if ((sp > 0.0) == (sq > 0.0)) continue;
          const glm::dvec3 x = p + (q - p) * (sp / (sp - sq));
          crossings.push_back({frame.span(x), x, loop.edges[i]});
        }
      }
      std::sort(crossings.begin(), crossings.end(),
                [](const RowCrossing& u, const RowCrossing& v) { return u.phi < v.phi; });
      for (std::size_t c = 0; c + 1 < crossings.size(); c += 2) {
        const RowCrossing& u = crossings[c];
        const RowCrossing& v = crossings[c + 1];
        rows_[static_cast<std::size_t>(k)].push_back(
            {u.phi, v.phi, u.point, v.point, part.object, u.what, v.what});
      }
    }
  }
  for (std::size_t k = 0; k < rows_.size(); ++k) {
    std::vector<SpanPair>& row = rows_[k];
    std::sort(row.begin(), row.end(),
              [](const SpanPair& u, const SpanPair& v) { return u.phi0 < v.phi0; });
    double reach = -std::numeric_limits<double>::infinity();
    for (const SpanPair& pair : row) reach_[k].push_back(reach = std::max(reach, pair.phi1));
  }
}

int AngularSpanTable::row_of(double theta) const {
  if (empty() || !(theta >= lo_ && theta <= hi_)) return -1;
  if (!(step_ > 0.0)) return 0;
  const int k = static_cast<int>(std::floor((theta - lo_) / step_));
  return std::clamp(k, 0, rows() - 1);
}

std::size_t AngularSpanTable::pairs() const {
  std::size_t total = 0;
  for (const std::vector<SpanPair>& row : rows_) total += row.size();
  return total;
}

bool AngularSpanTable::in_shadow(const glm::dvec3& q) const {
  const int k = row_of(frame_->row(q));
  if (k < 0) return false;
  const std::vector<SpanPair>& row = rows_[static_cast<std::size_t>(k)];
  const std::vector<double>& reach = reach_[static_cast<std::size_t>(k)];
  const double phi = frame_->span(q);
  const double r = frame_->depth(q);
  const double margin = 1e-9 * std::max(std::abs(r), 1.0);
  // The last pair with φa <= φ, then back while an earlier pair may still reach φ.
  auto it = std::upper_bound(row.begin(), row.end(), phi,
                             [](double value, const SpanPair& pair) { return value < pair.phi0; });
  for (auto i = static_cast<std::size_t>(it - row.begin()); i-- > 0;) {
    if (reach[i] < phi) break;
    const SpanPair& pair = row[i];
    if (pair.phi1 < phi) continue;
    if (frame_->depth_at(pair.a, pair.b, phi) < r - margin) return true;
  }
  return false;
}

}  // namespace shadowgen::view::detail
