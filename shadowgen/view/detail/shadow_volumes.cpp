#include "detail/shadow_volumes.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <utility>

#include "detail/embree_scene.h"
#include "shadowgen/sampled/part_triangles.h"

namespace shadowgen::view::detail {
namespace {

// The most a point light's edge piece subtends: its quad's far edge then lies at least
// cos(45°) of the extrusion distance from the light.
constexpr double kMaxPieceCos = 0.70710678118654752;  // cos 45°, half of 90°
constexpr int kMaxPieceDepth = 40;

struct VolumeFace {
  std::size_t part = 0;     // the part whose volume it bounds
  glm::dvec3 outward{0.0};  // out of the volume
  bool cap = false;
};

}  // namespace

struct ShadowVolumes::Impl {
  Light light;
  bool directional = true;
  glm::dvec3 travel{0.0};  // directional: the unit direction light travels
  double far = 0.0;        // how far the quads reach from their edge (directional) or the light
  std::vector<sampled::Triangle3> triangles;
  std::vector<VolumeFace> faces;  // per triangle
  EmbreeDevice device;
  std::unique_ptr<TriangleScene> scene;
  double offset = 0.0;

  // The far end of the quad through `p`.
  glm::dvec3 extruded(const glm::dvec3& p) const {
    if (directional) return p + far * travel;
    const glm::dvec3 away = p - light.position;
    return light.position + away * (far / glm::length(away));
  }

  void add(const sampled::Triangle3& t, std::size_t part, const glm::dvec3& outward, bool cap) {
    triangles.push_back(t);
    faces.push_back({part, outward, cap});
  }

  // The quad of edge piece p → q, `inward` pointing from the edge into the part.
  void add_quad(const glm::dvec3& p, const glm::dvec3& q, const glm::dvec3& inward,
                std::size_t part) {
    const glm::dvec3 p2 = extruded(p), q2 = extruded(q);
    glm::dvec3 outward = glm::cross(q - p, p2 - p);
    const double length = glm::length(outward);
    if (!(length > 0.0)) return;
    outward /= length;
    if (glm::dot(outward, inward) > 0.0) outward = -outward;
    add({p, q, q2}, part, outward, false);
    add({p, q2, p2}, part, outward, false);
  }

  // Edge p → q cut, for a point light, into pieces subtending at most 90° from it.
  void add_edge(const glm::dvec3& p, const glm::dvec3& q, const glm::dvec3& inward,
                std::size_t part, int depth) {
    if (!directional && depth < kMaxPieceDepth) {
      const glm::dvec3 a = glm::normalize(p - light.position);
      const glm::dvec3 b = glm::normalize(q - light.position);
      if (glm::dot(a, b) < 0.0) {  // more than 90°
        const glm::dvec3 m = 0.5 * (p + q);
        add_edge(p, m, inward, part, depth + 1);
        add_edge(m, q, inward, part, depth + 1);
        return;
      }
    }
    add_quad(p, q, inward, part);
  }

  void add_volume(const hsr::Polygon3& polygon, const hsr::Plane3& plane, std::size_t part) {
    const glm::dvec3& n = plane.normal;
    if (!(glm::length(n) > 0.0)) return;
    // Toward the light from the part's plane; none when the light is in it.
    const glm::dvec3 toward =
        directional ? -travel : glm::normalize(light.position - polygon.outer.front());
    const double facing = glm::dot(n, toward);
    if (!(std::fabs(facing) > 1e-12)) return;
    const glm::dvec3 cap_out = facing > 0.0 ? n : -n;
    for (const sampled::Triangle3& t : sampled::part_triangles(polygon).triangles) {
      add(t, part, cap_out, true);
    }
    auto loop_quads = [&](const hsr::Loop3& loop, bool hole) {
      // The loop's own interior lies left of each edge seen from its Newell vector's side;
      // the part's interior is across a hole's edges.
      const glm::dvec3 loop_normal = hsr::newell_vector(loop);
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const glm::dvec3& p = loop[i];
        const glm::dvec3& q = loop[(i + 1) % loop.size()];
        if (p == q) continue;
        glm::dvec3 inward = glm::cross(loop_normal, q - p);
        if (hole) inward = -inward;
        add_edge(p, q, inward, part, 0);
      }
    };
    loop_quads(polygon.outer, false);
    for (const hsr::Loop3& hole : polygon.holes) loop_quads(hole, true);
  }
};

ShadowVolumes::ShadowVolumes(const Light& light, std::span<const hsr::Polygon3> parts,
                             std::span<const hsr::Plane3> planes, std::span<const PartRole> roles,
                             const Reach& reach)
    : impl_(std::make_unique<Impl>()) {
  Impl& impl = *impl_;
  impl.light = light;
  impl.directional = light.type == LightType::kDirectional;
  const glm::dvec3 centre = 0.5 * (reach.lo + reach.hi);
  const double diagonal = glm::length(reach.hi - reach.lo);
  if (impl.directional) {
    impl.travel = glm::normalize(light.direction);
    impl.far = 2.0 * diagonal + 1.0;
  } else {
    // The farthest corner of the reach from the light, doubled, past cos 45°.
    double radius = 0.0;
    for (int c = 0; c < 8; ++c) {
      const glm::dvec3 corner((c & 1) ? reach.hi.x : reach.lo.x, (c & 2) ? reach.hi.y : reach.lo.y,
                              (c & 4) ? reach.hi.z : reach.lo.z);
      radius = std::max(radius, glm::length(corner - light.position));
    }
    impl.far = 2.0 * radius / kMaxPieceCos + 1.0;
  }
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (occludes(roles[i])) impl.add_volume(parts[i], planes[i], i);
  }
  impl.scene = std::make_unique<TriangleScene>(impl.device.get(), impl.triangles, centre);
  impl.offset = kVolumeOffsetUlps * 0x1.0p-23 * std::max(impl.scene->magnitude(), diagonal);
}

ShadowVolumes::~ShadowVolumes() = default;

double ShadowVolumes::offset() const { return impl_->offset; }
std::size_t ShadowVolumes::triangles() const { return impl_->triangles.size(); }

std::vector<std::size_t> ShadowVolumes::holding(const glm::dvec3& from) const {
  const Impl& impl = *impl_;
  std::vector<SegmentHit> hits;
  if (impl.directional) {
    impl.scene->hits(from, -impl.travel, 0.0, std::numeric_limits<double>::infinity(), hits);
  } else {
    // Up to the light, which no volume holds.
    impl.scene->hits(from, impl.light.position - from, 0.0, 1.0, hits);
  }
  std::vector<std::size_t> parts;
  for (const SegmentHit& hit : hits) {
    const VolumeFace& face = impl.faces[hit.triangle];
    if (face.cap) parts.push_back(face.part);
  }
  // A segment through an edge between two of a cap's triangles meets both: one volume.
  std::sort(parts.begin(), parts.end());
  parts.erase(std::unique(parts.begin(), parts.end()), parts.end());
  return parts;
}

int ShadowVolumes::count(const glm::dvec3& from, std::span<const std::size_t> from_holding,
                         const glm::dvec3& point, const glm::dvec3& normal,
                         std::size_t part) const {
  const Impl& impl = *impl_;
  int count = static_cast<int>(from_holding.size());
  if (std::binary_search(from_holding.begin(), from_holding.end(), part)) --count;

  const glm::dvec3 direction = point - from;
  const double length = glm::length(direction);
  if (!(length > 0.0)) return count;
  // Stop where the ray is offset() off the part toward its start.
  const double height = glm::dot(normal, from - point);
  const double tfar = 1.0 - (height > 0.0 ? std::min(0.5, impl.offset / height) : 0.5);
  thread_local std::vector<SegmentHit> hits;
  hits.clear();
  impl.scene->hits(from, direction, 0.0, tfar, hits);

  struct Crossing {
    std::size_t part;
    float t;
    int sign;
  };
  thread_local std::vector<Crossing> crossings;
  crossings.clear();
  for (const SegmentHit& hit : hits) {
    const VolumeFace& face = impl.faces[hit.triangle];
    if (face.part == part) continue;
    const double along = glm::dot(face.outward, direction);
    if (along == 0.0) continue;  // the ray in the face's plane: it does not cross it
    crossings.push_back({face.part, hit.t, along < 0.0 ? 1 : -1});
  }
  std::sort(crossings.begin(), crossings.end(), [](const Crossing& a, const Crossing& b) {
    return a.part != b.part ? a.part < b.part : a.t < b.t;
  });
  // Crossings of one volume within offset() along the ray count once, as their sum's sign.
  const double same = impl.offset / length;
  for (std::size_t i = 0; i < crossings.size();) {
    int sum = crossings[i].sign;
    std::size_t j = i + 1;
    while (j < crossings.size() && crossings[j].part == crossings[i].part &&
           static_cast<double>(crossings[j].t) - static_cast<double>(crossings[j - 1].t) <= same) {
      sum += crossings[j].sign;
      ++j;
    }
    count += (sum > 0) - (sum < 0);
    i = j;
  }
  return count;
}

}  // namespace shadowgen::view::detail
