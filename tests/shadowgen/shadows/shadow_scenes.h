#pragma once

// Scenes for the shadow-generation suites, built in code, and the metamorphic transforms
// of whole scenes (shuffles, rigid motions, scales, offsets).
//
// Unless a builder says otherwise, coordinates are small dyadic rationals (multiples of
// 1/64 within a few units of the origin) and faces are exactly planar, so that the scenes
// stay exact when moved far from the origin: at 1e8 one ulp is 2^-26, and every vertex
// keeps its value. Rotated boxes turn about the vertical axis only, so their side faces
// stay exactly planar (a vertical face's top and bottom vertices share x and y).

#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "hsr/polygon3.h"
#include "shadowgen/model/scene.h"

namespace shadowgen::test {

struct NamedScene {
  std::string name;
  Scene scene;
};
// GoogleTest prints a parameter by its name.
inline void PrintTo(const NamedScene& scene, std::ostream* out) { *out << scene.name; }

hsr::Polygon3 polygon(std::vector<glm::dvec3> outer, std::vector<hsr::Loop3> holes = {});
void add_face(Scene& scene, std::string id, hsr::Polygon3 polygon);
Light directional_light(std::string id, glm::dvec3 direction);
Light point_light(std::string id, glm::dvec3 position);

// The square [x0, x1] × [y0, y1] at height z, front side up (+z).
hsr::Polygon3 ground(double x0, double y0, double x1, double y1, double z = 0.0);

// The six faces of a box standing on z = base: a `sx` × `sy` footprint centred at
// (cx, cy), turned by `angle` radians about the vertical, `height` tall. Faces front
// side out, or in (a closed room) when `inward`; `open_top` leaves the top out. Ids are
// <prefix>.bottom, .top, .x0, .x1, .y0, .y1.
struct BoxSpec {
  double cx = 0.0, cy = 0.0, sx = 1.0, sy = 1.0, height = 1.0, base = 0.0, angle = 0.0;
  bool inward = false;
  bool open_top = false;
  bool with_bottom = true;
};
void add_box(Scene& scene, const std::string& prefix, const BoxSpec& box);

// A concave polygon (a comb with `teeth` teeth) with two square holes, in the plane
// z = z0 + slope_x·x + slope_y·y, centred at (cx, cy), about `size` wide.
hsr::Polygon3 comb_with_holes(double cx, double cy, double size, int teeth, double z0,
                              double slope_x = 0.0, double slope_y = 0.0);

// The scenes of the oracle suite (each with its lights).
NamedScene boxes_on_ground_sun();
NamedScene boxes_on_ground_lamp();
NamedScene holed_polygons_shadowing();
NamedScene interpenetrating_polygons();
NamedScene lamp_among_objects();
NamedScene open_box_lit_inside();
NamedScene eight_lights();
// Two walls with openings whose edges they share (a door at the foot, windows side by
// side, a window at the top, a window across a whole wall), an overhang, a post and the
// ground, under a sun and a lamp. As written, each wall is one polygon with its holes
// (which the oracle takes as they are); as read, each face is what the scene reader makes
// of it (the region less the holes as its parts, as the scene reader builds faces).
Scene walls_sharing_edges_as_written();
NamedScene walls_with_openings_sharing_edges();
std::vector<NamedScene> oracle_scenes();

// The scene with every face's one polygon read as the scene reader reads it.
Scene as_read(const Scene& scene);

// Metamorphic transforms. Each coordinate is rounded once (except shuffles).
Scene shuffled(const Scene& scene, std::uint64_t seed);  // faces and lights permuted
Scene moved(const Scene& scene, const glm::dmat3& rotation, const glm::dvec3& offset);
Scene scaled(const Scene& scene, double factor);
Scene offset_by(const Scene& scene, const glm::dvec3& offset);

// A rotation by `angle` radians about the unit `axis`.
glm::dmat3 rotation(const glm::dvec3& axis, double angle);

// The scene as `shadowgen-scene/1` JSON (polygons only, %.17g numbers): for reproducers.
std::string scene_json(const Scene& scene);

}  // namespace shadowgen::test
