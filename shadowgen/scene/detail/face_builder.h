#pragma once

// From loops as a file gives them to a scene Face: the checks and normalisations that the
// scene format (docs/scene-format.md) asks of JSON polygons and mesh faces
// alike.
//
//   - A loop needs at least 3 vertices (an error otherwise).
//   - A face without area (fewer than 3 distinct vertices, or all collinear; decided
//     exactly) is degenerate, not malformed: kept as given, with a warning. In a JSON
//     polygon, though, a loop with fewer than 3 distinct vertices is an error, like one
//     with fewer than 3 vertices: the repeats are a mistake of whoever wrote it, not the
//     collapse of a mesh face. A hole that is collinear is dropped with a warning.
//   - Planarity: every vertex within kPlanarityTolerance × (the face's size: the smaller of
//     its largest extent and its width, area / extent), or within twice the source's
//     vertex rounding (FaceSource::vertex_rounding), of
//     the best-fit plane (Newell's normal through the outer loop's centroid, as
//     hsr::plane_of). A face that is not planar is an error under ReadOptions::strict;
//     otherwise it is split into triangles on its original 3D vertices (triangulate.h),
//     each exactly planar, all keeping the face's id, with a warning. A triangle is planar
//     whatever the rounded normal says.
//   - Loops must be simple, holes inside the outer loop and apart from each other, though
//     they may touch it and each other at points and share segments of their edges
//     (loop_validation.h). A planar face is checked in its plane chart
//     (hsr/plane_chart.h), exactly; a non-planar one in its projection on the best-fit
//     plane (rounded coordinates, exact predicates on them), the same 2D image its
//     triangulation uses, since a coordinate chart can fold a strongly bent face onto
//     itself. The projection's rounding can put a hole's vertex that lies on an edge of
//     the outer loop in 3D a hair beyond it; a non-planar face refused in its projection
//     is checked again in its exact chart (chart_facing its best-fit normal), which keeps
//     every incidence of the 3D points, and where its loops are valid there, it is cut and
//     triangulated there.
//   - Holes are turned to run opposite to the outer loop, which keeps its orientation:
//     it defines the front side.
//   - Holes that share a segment with the outer loop or with each other are resolved at
//     once, so that nothing downstream meets loops along an edge: the face's region (the
//     outer loop less the holes) is computed with the clipper in the chart it was checked
//     in (region_less_holes.h), and each of its pieces, lifted back onto the input's own
//     3D vertices, is a part of the face. A door at the foot of a wall leaves one part,
//     a window across the wall's whole width two, coplanar. Holes that cover the outer
//     loop whole leave a face without area: kept, with a warning, its one part a loop
//     along the outer loop's first edge (as a degenerate face, area 0). A non-planar face
//     with such holes has each piece of its region split into triangles.

#include <string>
#include <vector>

#include "hsr/polygon3.h"
#include "shadowgen/model/scene.h"

namespace shadowgen::scene::detail {

enum class FaceKind { kPolygon, kMeshFace };

struct FaceSource {
  std::string id;
  std::string file;  // for messages and Face::source_file
  FaceKind kind = FaceKind::kPolygon;
  // SourceFace::vertex_rounding, in scene coordinates: a face whose vertices all lie
  // within twice this of its best-fit plane is planar, whatever its size. Each vertex is
  // within this of the plane the face was meant to lie in, and the best-fit plane of
  // vertices so moved is within it too, near the face.
  double vertex_rounding = 0.0;
  FaceOrigin origin = {};
};

// Throws InputError naming source.file and source.id; appends warnings to `warnings`.
Face build_face(hsr::Polygon3 polygon, const FaceSource& source, bool strict,
                std::vector<std::string>& warnings);

// "file: face 'id': what", the form of InputError's messages.
std::string face_message(const std::string& file, const std::string& face_id,
                         const std::string& what);

}  // namespace shadowgen::scene::detail
