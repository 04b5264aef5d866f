#include "face_builder.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <sstream>
#include <type_traits>
#include <unordered_map>
#include <utility>

#include "clipper/clip.h"
#include "clipper/predicates.h"
#include "clipper/triangulate.h"
#include "coordinate_range.h"
#include "face_plane.h"
#include "hsr/area.h"
#include "hsr/collinearity.h"
#include "hsr/plane_chart.h"
#include "loop_validation.h"
#include "numbers.h"
#include "region_less_holes.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen::scene::detail {

namespace {

// The steps of build_face, sharing what it reports to.
class FaceBuilder {
 public:
  FaceBuilder(const FaceSource& source, bool strict, std::vector<std::string>& warnings)
      : source_(source),
        strict_(strict),
        warnings_(warnings),
        mesh_(source.kind == FaceKind::kMeshFace),
        outer_name_(mesh_ ? "the face" : "the outer loop") {}

  Face build(hsr::Polygon3 polygon) {
    Face face{source_.id, {}, source_.file, source_.origin, source_.vertex_rounding};
    check_vertex_counts(polygon);
    if (const std::optional<std::string> problem = coordinate_problem(polygon)) fail(*problem);
    if (degenerate(polygon)) {  // kept as given
      face.parts.push_back(std::move(polygon));
      return face;
    }
    const std::vector<std::string> loop_names = drop_collinear_holes(polygon);
    const glm::dvec3 normal = hsr::plane_of(polygon).normal;
    const bool has_normal = finite(normal) && normal != glm::dvec3(0.0);
    const std::string how_far =
        distance_from_plane(polygon, normal, has_normal, source_.vertex_rounding);
    const bool planar = how_far.empty();
    if (!planar && strict_) fail("not planar (" + how_far + ")");

    // A planar face is checked in its exact chart; a non-planar one in its projection on
    // the best-fit plane, where it will be triangulated (a coordinate chart could fold it).
    std::vector<clipper::Loop2> loops;
    hsr::PlaneChart chart;
    std::optional<PlaneFrame> frame;  // where a non-planar face is checked in its projection
    auto in_chart = [&chart](const hsr::Loop3& l) { return chart.flatten(l); };
    if (planar) {
      chart = has_normal ? hsr::chart_facing(normal) : chart_without_normal(polygon.outer);
      loops = flatten_loops(polygon, in_chart);
    } else {
      frame.emplace(polygon.outer[0], normal);
      loops = flatten_loops(polygon, [&frame](const hsr::Loop3& l) { return frame->project(l); });
    }
    LoopCheck check = checked(loops, loop_names);
    if (check.problem && !planar) {
      // The projection's rounded coordinates can put a hole's vertex that lies on an edge
      // of the outer loop in 3D (a window along a bent wall's side) a hair beyond it. The
      // exact chart keeps every incidence of the 3D points: where the loops are valid in
      // it (it does not fold the face), they are cut and triangulated there.
      chart = hsr::chart_facing(normal);
      std::vector<clipper::Loop2> charted = flatten_loops(polygon, in_chart);
      LoopCheck exact = checked(charted, loop_names);
      if (!exact.problem) {
        loops = std::move(charted);
        check = std::move(exact);
        frame.reset();
      }
    }
    if (check.problem) fail(*check.problem);
    orient_holes(polygon, loops, check);
    if (planar && !check.shares_edges) {
      face.parts.push_back(std::move(polygon));
      return face;
    }
    if (planar) {
      face.parts = planar_region(polygon, has_normal ? normal : chart_normal(chart, check));
    } else {
      auto lift = [&](const clipper::Point2& q) {
        return frame ? frame->lift(q)
                     : hsr::ChartedPlane(normal, polygon.outer[0], hsr::ChartFrom::kWorld)
                           .on_plane(q);
      };
      face.parts = check.shares_edges
                       ? region_triangles(polygon, loops, check.counter_clockwise[0], lift, how_far)
                       : triangles(loops, all_vertices(polygon), how_far);
      if (!face.parts.empty() || !check.shares_edges) {
        warn("not planar (" + how_far + "): split into " + std::to_string(face.parts.size()) +
             " triangles");
      }
    }
    if (face.parts.empty() && check.shares_edges) {
      // Holes that cover the outer loop whole: a face without area, kept as the other
      // degenerate faces are, its one part a loop along the outer loop's first edge.
      warn("zero area (its holes cover it whole): kept, with area 0");
      face.parts.push_back({{polygon.outer[0], polygon.outer[1], polygon.outer[0]}, {}});
    }
    return face;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(source_.file, source_.id, what);
  }
  void warn(const std::string& what) {
    warnings_.push_back(face_message(source_.file, source_.id, what));
  }

  void check_vertex_counts(const hsr::Polygon3& polygon) const {
    if (polygon.outer.size() < 3) {
      fail(outer_name_ + " has " + std::to_string(polygon.outer.size()) +
           " vertices; at least 3 are needed");
    }
    for (std::size_t k = 0; k < polygon.holes.size(); ++k) {
      if (polygon.holes[k].size() < 3) {
        fail("hole " + std::to_string(k) + " has " + std::to_string(polygon.holes[k].size()) +
             " vertices; at least 3 are needed");
      }
      if (hsr::distinct_points_up_to_3(polygon.holes[k]) < 3) {
        fail("hole " + std::to_string(k) + " has fewer than 3 distinct vertices");
      }
    }
  }

  // Whether the face has no area; degenerate faces are kept as given, with a warning.
  bool degenerate(const hsr::Polygon3& polygon) {
    const bool too_few = hsr::distinct_points_up_to_3(polygon.outer) < 3;
    if (too_few && !mesh_) fail(outer_name_ + " has fewer than 3 distinct vertices");
    if (!too_few && !hsr::all_collinear(polygon.outer)) return false;
    if (!polygon.holes.empty()) {
      fail("the outer loop has no area (its vertices are collinear), so no hole can lie in it");
    }
    warn(std::string("zero area (") +
         (too_few ? "fewer than 3 distinct vertices" : "collinear vertices") +
         "): kept, with area 0");
    return true;
  }

  // Drops the holes without area; returns the names of the loops left, outer loop first.
  std::vector<std::string> drop_collinear_holes(hsr::Polygon3& polygon) {
    std::vector<std::string> loop_names{outer_name_};
    std::vector<hsr::Loop3> holes;
    for (std::size_t k = 0; k < polygon.holes.size(); ++k) {
      if (hsr::all_collinear(polygon.holes[k])) {
        warn("hole " + std::to_string(k) + " has no area (collinear vertices): ignored");
        continue;
      }
      holes.push_back(std::move(polygon.holes[k]));
      loop_names.push_back("hole " + std::to_string(k));
    }
    polygon.holes = std::move(holes);
    return loop_names;
  }

  // "" for a planar face; otherwise how far from its best-fit plane it is, in words.
  static std::string distance_from_plane(const hsr::Polygon3& polygon, const glm::dvec3& normal,
                                         bool has_normal, double vertex_rounding) {
    // Three points always lie in a plane. Measured against the rounded Newell normal, the
    // corners of a sliver triangle can seem 1e-7 of its extent off it.
    if (polygon.outer.size() == 3 && polygon.holes.empty()) return "";
    const Planarity flat = has_normal ? planarity(polygon, normal) : Planarity{};
    // Against the face's size: the smaller of its extent (its length) and its width (area
    // over extent). Against the length alone, a ribbon 1e9 long and 8 wide whose end was 4
    // off the plane passed as planar, and its lit area came out larger than its area.
    const double width = flat.extent > 0.0 ? hsr::area(polygon) / flat.extent : 0.0;
    const double size = std::min(flat.extent, width);
    if (!(flat.deviation > kPlanarityTolerance * size)) return "";
    if (flat.deviation <= 2.0 * vertex_rounding) return "";
    return "a vertex lies " + short_number(flat.deviation, 3) + " from the best-fit plane, " +
           short_number(flat.deviation / size, 3) +
           " of the face's size (the smaller of its extent and its width); tolerance " +
           short_number(kPlanarityTolerance, 3);
  }

  template <typename Flatten>
  static std::vector<clipper::Loop2> flatten_loops(const hsr::Polygon3& polygon, Flatten flatten) {
    std::vector<clipper::Loop2> loops{flatten(polygon.outer)};
    for (const hsr::Loop3& hole : polygon.holes) loops.push_back(flatten(hole));
    return loops;
  }

  LoopCheck checked(const std::vector<clipper::Loop2>& loops,
                    const std::vector<std::string>& loop_names) const {
    return clipping("its holes that share edges could not be checked",
                    [&] { return check_loops(loops, loop_names); });
  }

  // Turns holes to run opposite to the outer loop, as the check of the loops found them.
  static void orient_holes(hsr::Polygon3& polygon, std::vector<clipper::Loop2>& loops,
                           const LoopCheck& check) {
    for (std::size_t k = 0; k < polygon.holes.size(); ++k) {
      if (check.counter_clockwise[k + 1] == check.counter_clockwise[0]) {
        std::reverse(polygon.holes[k].begin(), polygon.holes[k].end());
        std::reverse(loops[k + 1].begin(), loops[k + 1].end());
      }
    }
  }

  // The normal of a planar face whose Newell vector came out zero, as its chart has it
  // (chart_without_normal): the unit vector of the dropped axis, signed so that the chart
  // does not mirror the outer loop's front side.
  static glm::dvec3 chart_normal(const hsr::PlaneChart& chart, const LoopCheck& check) {
    glm::dvec3 n(0.0);
    n[chart.dropped_axis] = check.counter_clockwise[0] ? 1.0 : -1.0;
    return n;
  }

  // The region of a planar face whose holes share edges with its outer loop or each other
  // (region_less_holes.h), computed in the chart the loops were checked in (the one
  // chart_facing `normal` chooses; ChartFrom::kWorld, the coordinates as they are), its
  // pieces lifted back onto the input's own 3D vertices: the face's parts, each turning
  // as the outer loop did. A point that is no input vertex is put on the plane through
  // the outer loop's first vertex (hsr::ChartedPlane::on_plane).
  std::vector<hsr::Polygon3> planar_region(const hsr::Polygon3& polygon,
                                           const glm::dvec3& normal) const {
    hsr::ChartedPlane plane(normal, polygon.outer[0], hsr::ChartFrom::kWorld);
    const clipper::PolygonWithHoles2 flat = plane.flatten_known(polygon);
    std::vector<clipper::Loop2> loops{flat.outer};
    loops.insert(loops.end(), flat.holes.begin(), flat.holes.end());
    return plane.lift(region(loops));
  }

  // A non-planar face whose holes share edges: its region in the 2D coordinates where it
  // was checked (`loops`, the outer loop counter-clockwise there or not), each piece split
  // into triangles on the input's 3D vertices, running as the outer loop does (a point
  // that is no input vertex: `lift`, onto the best-fit plane).
  template <typename Lift>
  std::vector<hsr::Polygon3> region_triangles(const hsr::Polygon3& polygon,
                                              const std::vector<clipper::Loop2>& loops,
                                              bool outer_counter_clockwise, Lift lift_new,
                                              const std::string& how_far) const {
    std::unordered_map<clipper::Point2, glm::dvec3, clipper::Point2Hash> known;
    const std::vector<glm::dvec3> vertices = all_vertices(polygon);
    std::size_t k = 0;
    for (const clipper::Loop2& loop : loops) {
      for (const clipper::Point2& q : loop) known.emplace(q, vertices[k++]);
    }
    auto lift = [&](const clipper::Point2& q) {
      const auto it = known.find(q);
      return it != known.end() ? it->second : lift_new(q);
    };
    std::vector<hsr::Polygon3> parts;
    for (const clipper::PolygonWithHoles2& piece : region(loops)) {
      std::vector<clipper::Loop2> piece_loops{piece.outer};
      piece_loops.insert(piece_loops.end(), piece.holes.begin(), piece.holes.end());
      if (!outer_counter_clockwise) {  // the clipper's pieces run counter-clockwise
        for (clipper::Loop2& loop : piece_loops) std::reverse(loop.begin(), loop.end());
      }
      std::vector<glm::dvec3> corners;
      for (const clipper::Loop2& loop : piece_loops) {
        for (const clipper::Point2& q : loop) corners.push_back(lift(q));
      }
      std::vector<hsr::Polygon3> more = triangles(piece_loops, corners, how_far);
      parts.insert(parts.end(), std::make_move_iterator(more.begin()),
                   std::make_move_iterator(more.end()));
    }
    return parts;
  }

  // region_less_holes, its clipper's failure named after the face.
  clipper::PolygonSet2 region(const std::vector<clipper::Loop2>& loops) const {
    return clipping("its region, the outer loop less holes that share edges, could not be computed",
                    [&] { return region_less_holes(loops); });
  }

  // `work`, a clip whose snapping does not settle (docs/clipper.md, Limit; no input is known
  // to cause it) named after the face: not the input's fault, so no InputError.
  template <typename Work>
  std::invoke_result_t<Work&> clipping(const std::string& what, Work work) const {
    try {
      return work();
    } catch (const clipper::SnapRoundingError& e) {
      throw clipper::SnapRoundingError(
          face_message(source_.file, source_.id, what + ": " + e.what()));
    }
  }

  static std::vector<glm::dvec3> all_vertices(const hsr::Polygon3& polygon) {
    std::vector<glm::dvec3> vertices(polygon.outer);
    for (const hsr::Loop3& hole : polygon.holes) {
      vertices.insert(vertices.end(), hole.begin(), hole.end());
    }
    return vertices;
  }

  // Triangles on the 3D vertices (numbered through the loops in order), those without
  // area left out; the loops are valid as check_loops accepts them, sharing no edges.
  std::vector<hsr::Polygon3> triangles(const std::vector<clipper::Loop2>& loops,
                                       const std::vector<glm::dvec3>& vertices,
                                       const std::string& how_far) const {
    const std::optional<std::vector<clipper::Triangle>> triangles = clipper::triangulate(loops);
    if (!triangles) fail("not planar (" + how_far + "), and could not be split into triangles");
    std::vector<hsr::Polygon3> parts;
    for (const clipper::Triangle& t : *triangles) {
      hsr::Loop3 corners{vertices[t[0]], vertices[t[1]], vertices[t[2]]};
      if (hsr::all_collinear(corners)) continue;  // no area in 3D either: adds nothing
      parts.push_back({std::move(corners), {}});
    }
    return parts;
  }

  const FaceSource& source_;
  bool strict_;
  std::vector<std::string>& warnings_;
  bool mesh_;
  std::string outer_name_;
};

}  // namespace

std::string face_message(const std::string& file, const std::string& face_id,
                         const std::string& what) {
  return InputError(file, face_id, what).what();
}

Face build_face(hsr::Polygon3 polygon, const FaceSource& source, bool strict,
                std::vector<std::string>& warnings) {
  return FaceBuilder(source, strict, warnings).build(std::move(polygon));
}

}  // namespace shadowgen::scene::detail
