#include "detail/ridge_edge_loops.h"

#include <algorithm>
#include <array>
#include <glm/geometric.hpp>
#include <map>
#include <numeric>
#include <utility>

namespace shadowgen::view::detail {
namespace {

// Visible (the papers' footnote): the ray from the light to the face against its normal.
Facing facing_of(const hsr::Plane3& plane, PartRole role, const Light& light) {
  if (role == PartRole::kLeftOut || glm::dot(plane.normal, plane.normal) == 0.0) {
    return Facing::kLeftOut;
  }
  if (receives(role)) return role == PartRole::kFacing ? Facing::kVisible : Facing::kHidden;
  const bool visible = light.type == LightType::kPoint
                           ? plane.signed_distance(light.position) > 0.0
                           : glm::dot(plane.normal, light.direction) < 0.0;
  return visible ? Facing::kVisible : Facing::kHidden;
}

std::size_t find_root(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

std::size_t RidgeEdgeLoops::count(EdgeKind kind) const {
  return static_cast<std::size_t>(
      std::count_if(edges.begin(), edges.end(), [&](const MeshEdge& e) { return e.kind == kind; }));
}

RidgeEdgeLoops ridge_edge_loops(std::span<const hsr::Polygon3> polygons,
                                std::span<const hsr::Plane3> planes,
                                std::span<const PartRole> roles, const Light& light) {
  RidgeEdgeLoops out;
  const std::size_t n = polygons.size();
  out.facing.resize(n);
  out.object_of_part.assign(n, kNoObject);
  out.part_loop_edges.resize(n);

  std::map<std::array<double, 3>, std::size_t> vertex_ids;
  auto vertex = [&](const glm::dvec3& p) {
    const auto [it, added] = vertex_ids.try_emplace({p.x, p.y, p.z}, out.vertices.size());
    if (added) out.vertices.push_back(p);
    return it->second;
  };
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> edge_ids;
  for (std::size_t i = 0; i < n; ++i) {
    out.facing[i] = facing_of(planes[i], roles[i], light);
    if (out.facing[i] == Facing::kLeftOut) continue;
    auto add_loop = [&](const hsr::Loop3& loop) {
      std::vector<std::size_t>& ids = out.part_loop_edges[i].emplace_back();
      for (std::size_t k = 0, m = loop.size(); k < m; ++k) {
        std::size_t a = vertex(loop[k]);
        std::size_t b = vertex(loop[(k + 1) % m]);
        if (a > b) std::swap(a, b);
        const auto [it, added] = edge_ids.try_emplace({a, b}, out.edges.size());
        if (added) out.edges.push_back({a, b, {}, EdgeKind::kOpen});
        std::vector<std::size_t>& parts = out.edges[it->second].parts;
        if (std::find(parts.begin(), parts.end(), i) == parts.end()) parts.push_back(i);
        ids.push_back(it->second);
      }
    };
    add_loop(polygons[i].outer);
    for (const hsr::Loop3& hole : polygons[i].holes) add_loop(hole);
  }

  // Objects: parts joined through shared edges.
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  for (MeshEdge& edge : out.edges) {
    for (std::size_t k = 1; k < edge.parts.size(); ++k) {
      parent[find_root(parent, edge.parts[k])] = find_root(parent, edge.parts[0]);
    }
    if (edge.parts.size() == 1) {
      edge.kind = EdgeKind::kOpen;
    } else if (edge.parts.size() > 2) {
      edge.kind = EdgeKind::kNonManifold;
    } else {
      const bool v0 = out.facing[edge.parts[0]] == Facing::kVisible;
      const bool v1 = out.facing[edge.parts[1]] == Facing::kVisible;
      edge.kind = v0 != v1 ? EdgeKind::kRidge : (v0 ? EdgeKind::kVisible : EdgeKind::kHidden);
    }
  }
  std::vector<std::size_t> object_of_root(n, kNoObject);
  for (std::size_t i = 0; i < n; ++i) {
    if (out.facing[i] == Facing::kLeftOut) continue;
    std::size_t& object = object_of_root[find_root(parent, i)];
    if (object == kNoObject) object = out.objects++;
    out.object_of_part[i] = object;
  }

  // Ridge edges directed as their visible face runs along them, then followed into loops.
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> leaving(out.vertices.size());
  std::size_t ridges = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (out.facing[i] != Facing::kVisible) continue;
    for (std::size_t l = 0; l < out.part_loop_edges[i].size(); ++l) {
      const hsr::Loop3& loop = l == 0 ? polygons[i].outer : polygons[i].holes[l - 1];
      const std::vector<std::size_t>& ids = out.part_loop_edges[i][l];
      for (std::size_t k = 0, m = ids.size(); k < m; ++k) {
        if (out.edges[ids[k]].kind != EdgeKind::kRidge) continue;
        const std::size_t from = vertex_ids.at({loop[k].x, loop[k].y, loop[k].z});
        const glm::dvec3& q = loop[(k + 1) % m];
        leaving[from].push_back({vertex_ids.at({q.x, q.y, q.z}), ids[k]});
        ++ridges;
      }
    }
  }
  std::vector<bool> used(out.edges.size(), false);
  std::vector<std::size_t> cursor(out.vertices.size(), 0);
  auto next_unused = [&](std::size_t v) -> const std::pair<std::size_t, std::size_t>* {
    for (; cursor[v] < leaving[v].size(); ++cursor[v]) {
      if (!used[leaving[v][cursor[v]].second]) return &leaving[v][cursor[v]];
    }
    return nullptr;
  };
  for (std::size_t start = 0; start < out.vertices.size() && ridges > 0; ++start) {
    while (const auto* first = next_unused(start)) {
      RidgeLoop loop;
      loop.object = out.object_of_part[out.edges[first->second].parts[0]];
      std::size_t v = start;
      const auto* step = first;
      while (step != nullptr) {
        loop.vertices.push_back(v);
        used[step->second] = true;
        v = step->first;
        if (v == start) break;
        step = next_unused(v);
      }
      loop.closed = v == start;
      if (!loop.closed) loop.vertices.push_back(v);
      out.loops.push_back(std::move(loop));
    }
  }
  return out;
}

}  // namespace shadowgen::view::detail
