#include "tests/shadowgen/shadows/shadow_scenes.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numeric>
#include <random>
#include <sstream>
#include <utility>

#include "shadowgen/scene/scene_reader.h"

namespace shadowgen::test {
namespace {

// Rounds to a multiple of 1/64: keeps scene coordinates exact far from the origin.
double grid(double v) { return std::round(v * 64.0) / 64.0; }

hsr::Polygon3 map_polygon(const hsr::Polygon3& p, const auto& f) {
  hsr::Polygon3 out;
  for (const glm::dvec3& v : p.outer) out.outer.push_back(f(v));
  for (const hsr::Loop3& h : p.holes) {
    hsr::Loop3 loop;
    for (const glm::dvec3& v : h) loop.push_back(f(v));
    out.holes.push_back(std::move(loop));
  }
  return out;
}

Scene map_scene(const Scene& scene, const auto& point, const auto& vector) {
  Scene out = scene;
  for (Face& face : out.faces) {
    for (hsr::Polygon3& part : face.parts) part = map_polygon(part, point);
  }
  for (Light& light : out.lights) {
    light.position = point(light.position);
    light.direction = vector(light.direction);
  }
  return out;
}

std::vector<BoxSpec> three_boxes() {
  return {{-1.0, -1.0, 1.0, 1.5, 1.25, 0.0, 0.0},
          {1.25, 0.5, 0.75, 0.75, 2.0, 0.0, 0.5},
          {-0.5, 1.75, 1.5, 0.5, 0.75, 0.0, -0.25}};
}

Scene boxes_scene() {
  Scene scene;
  add_face(scene, "ground", ground(-4, -4, 4, 4));
  int n = 0;
  for (const BoxSpec& box : three_boxes()) add_box(scene, "box" + std::to_string(n++), box);
  return scene;
}

}  // namespace

hsr::Polygon3 polygon(std::vector<glm::dvec3> outer, std::vector<hsr::Loop3> holes) {
  return {std::move(outer), std::move(holes)};
}

void add_face(Scene& scene, std::string id, hsr::Polygon3 p) {
  Face face;
  face.id = std::move(id);
  face.parts.push_back(std::move(p));
  face.source_file = "test";
  scene.faces.push_back(std::move(face));
}

Light directional_light(std::string id, glm::dvec3 direction) {
  Light light;
  light.id = std::move(id);
  light.type = LightType::kDirectional;
  light.direction = direction;
  return light;
}

Light point_light(std::string id, glm::dvec3 position) {
  Light light;
  light.id = std::move(id);
  light.type = LightType::kPoint;
  light.position = position;
  return light;
}

hsr::Polygon3 ground(double x0, double y0, double x1, double y1, double z) {
  return polygon({{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}});
}

void add_box(Scene& scene, const std::string& prefix, const BoxSpec& b) {
  const double c = std::cos(b.angle), s = std::sin(b.angle);
  const double hx = 0.5 * b.sx, hy = 0.5 * b.sy;
  const double u[4] = {-hx, hx, hx, -hx}, v[4] = {-hy, -hy, hy, hy};
  glm::dvec3 lo[4], hi[4];
  for (int k = 0; k < 4; ++k) {
    const double x = b.angle == 0.0 ? b.cx + u[k] : b.cx + c * u[k] - s * v[k];
    const double y = b.angle == 0.0 ? b.cy + v[k] : b.cy + s * u[k] + c * v[k];
    lo[k] = {x, y, b.base};
    hi[k] = {x, y, b.base + b.height};
  }
  auto add = [&](const std::string& name, std::vector<glm::dvec3> loop) {
    if (b.inward) std::reverse(loop.begin(), loop.end());
    add_face(scene, prefix + "." + name, polygon(std::move(loop)));
  };
  if (b.with_bottom) add("bottom", {lo[0], lo[3], lo[2], lo[1]});
  if (!b.open_top) add("top", {hi[0], hi[1], hi[2], hi[3]});
  const char* names[4] = {"y0", "x1", "y1", "x0"};
  for (int k = 0; k < 4; ++k) add(names[k], {lo[k], lo[(k + 1) % 4], hi[(k + 1) % 4], hi[k]});
}

hsr::Polygon3 comb_with_holes(double cx, double cy, double size, int teeth, double z0,
                              double slope_x, double slope_y) {
  const double h = 0.5 * size, w = size / (2 * teeth - 1);
  auto at = [&](double u, double v) {
    const double x = grid(cx + u), y = grid(cy + v);
    return glm::dvec3(x, y, z0 + slope_x * x + slope_y * y);
  };
  std::vector<glm::dvec3> outer = {at(-h, -h), at(h, -h)};
  for (int k = teeth - 1; k >= 0; --k) {
    const double left = -h + 2 * k * w, right = left + w;
    outer.push_back(at(right, h));
    outer.push_back(at(left, h));
    if (k > 0) {
      outer.push_back(at(left, -h / 3));
      outer.push_back(at(left - w, -h / 3));
    }
  }
  const double q = size / 8;
  std::vector<hsr::Loop3> holes;
  for (double u0 : {-h / 2, h / 2}) {
    const double v0 = -2 * h / 3;
    // Clockwise seen from above: opposite to the outer loop.
    holes.push_back({at(u0 - q / 2, v0 - q / 2), at(u0 - q / 2, v0 + q / 2),
                     at(u0 + q / 2, v0 + q / 2), at(u0 + q / 2, v0 - q / 2)});
  }
  return polygon(std::move(outer), std::move(holes));
}

NamedScene boxes_on_ground_sun() {
  Scene scene = boxes_scene();
  scene.lights.push_back(directional_light("sun", {-0.375, 0.25, -1.0}));
  return {"boxes_on_ground_sun", scene};
}

NamedScene boxes_on_ground_lamp() {
  Scene scene = boxes_scene();
  scene.lights.push_back(point_light("lamp", {0.25, -0.5, 3.0}));
  return {"boxes_on_ground_lamp", scene};
}

NamedScene holed_polygons_shadowing() {
  Scene scene;
  add_face(scene, "ground", ground(-3, -3, 3, 3));
  add_face(scene, "combA", comb_with_holes(0.0, 0.0, 2.0, 3, 1.0));
  add_face(scene, "combB", comb_with_holes(0.25, 0.25, 1.5, 4, 2.0, 0.25, 0.0));
  add_face(scene, "combC", comb_with_holes(-0.5, 0.75, 1.0, 2, 0.5, 0.0, -0.125));
  scene.lights.push_back(directional_light("sun", {0.125, -0.25, -1.0}));
  scene.lights.push_back(point_light("lamp", {0.5, 0.25, 4.0}));
  return {"holed_polygons_shadowing", scene};
}

NamedScene interpenetrating_polygons() {
  Scene scene;
  add_face(scene, "ground", ground(-3, -3, 3, 3));
  // z = 1 + x/2 and z = 1 - y/2 cross along a line; x = 1/4 crosses both.
  auto za = [](double x) { return 1.0 + 0.5 * x; };
  auto zb = [](double y) { return 1.0 - 0.5 * y; };
  add_face(scene, "tiltA",
           polygon({{-1, -1, za(-1)}, {1, -1, za(1)}, {1, 1, za(1)}, {-1, 1, za(-1)}}));
  add_face(scene, "tiltB",
           polygon({{-0.75, -1.25, zb(-1.25)},
                    {1.25, -1.25, zb(-1.25)},
                    {1.25, 0.75, zb(0.75)},
                    {-0.75, 0.75, zb(0.75)}}));
  // Front side towards -x.
  add_face(
      scene, "wall",
      polygon({{0.25, -0.75, 0.25}, {0.25, -0.75, 1.75}, {0.25, 0.75, 1.75}, {0.25, 0.75, 0.25}}));
  add_face(scene, "spike", polygon({{-1.25, 0.5, 0.5}, {0.5, -0.25, 1.5}, {0.75, 1.0, 0.75}}));
  scene.lights.push_back(directional_light("sun", {0.25, 0.125, -1.0}));
  scene.lights.push_back(point_light("lamp", {-0.5, 0.5, 3.5}));
  return {"interpenetrating_polygons", scene};
}

NamedScene lamp_among_objects() {
  Scene scene;
  add_face(scene, "ground", ground(-4, -4, 4, 4));
  hsr::Polygon3 ceiling = ground(-4, -4, 4, 4, 3.0);
  std::reverse(ceiling.outer.begin(), ceiling.outer.end());  // front side down
  add_face(scene, "ceiling", ceiling);
  add_box(scene, "east", {1.5, 0.0, 0.5, 1.0, 2.0});
  add_box(scene, "west", {-1.5, 0.25, 0.75, 0.5, 1.5, 0.0, 0.3});
  add_box(scene, "north", {0.0, 1.5, 1.0, 0.5, 2.5});
  add_box(scene, "south", {0.25, -1.5, 0.5, 0.5, 0.5});
  add_box(scene, "shelf", {0.0, 0.0, 0.75, 0.75, 0.125, 2.0});  // floats above the lamp
  scene.lights.push_back(point_light("lamp", {0.125, -0.25, 1.0}));
  return {"lamp_among_objects", scene};
}

NamedScene open_box_lit_inside() {
  Scene scene;
  BoxSpec room{0.0, 0.0, 4.0, 4.0, 2.0};
  room.inward = true;
  room.open_top = true;
  add_box(scene, "room", room);
  add_box(scene, "crate", {0.75, 0.5, 0.5, 0.5, 0.75});
  scene.lights.push_back(point_light("lamp", {-0.5, -0.25, 1.5}));
  scene.lights.push_back(directional_light("sun", {0.5, 0.25, -1.0}));
  return {"open_box_lit_inside", scene};
}

NamedScene eight_lights() {
  Scene scene = boxes_scene();
  scene.lights.push_back(directional_light("sun0", {-0.375, 0.25, -1.0}));
  scene.lights.push_back(directional_light("sun1", {0.5, 0.5, -1.0}));
  // No sun exactly edge-on to a box face: the spec leaves such a face unlit, and a rigid
  // motion that rounds it a hair off edge-on may rightly light it.
  scene.lights.push_back(directional_light("sun2", {0.0625, -0.25, -1.0}));
  scene.lights.push_back(directional_light("sun3", {1.0, 0.125, -0.5}));
  scene.lights.push_back(point_light("lamp0", {0.25, -0.5, 3.0}));
  scene.lights.push_back(point_light("lamp1", {-2.0, 2.0, 1.5}));
  scene.lights.push_back(point_light("lamp2", {2.5, 2.5, 0.75}));
  Light ranged = point_light("lamp3", {-3.0, -3.0, 0.5});
  ranged.range = LightRange{1.0, 2.5, 2.0};
  scene.lights.push_back(ranged);
  return {"eight_lights", scene};
}

Scene walls_sharing_edges_as_written() {
  // A rectangle from (x0, z0) to (x1, z1) in the plane y = y, front side towards -y.
  auto rectangle = [](double y, double x0, double z0, double x1, double z1) {
    return hsr::Loop3{{x0, y, z0}, {x1, y, z0}, {x1, y, z1}, {x0, y, z1}};
  };
  Scene scene;
  add_face(scene, "ground", ground(-2, -6, 12, 6));
  add_face(
      scene, "front",
      polygon(rectangle(0, 0, 0, 10, 3), {rectangle(0, 4, 0, 5, 2),      // a door at the foot
                                          rectangle(0, 1, 1, 2.5, 2),    // two windows side by side
                                          rectangle(0, 2.5, 1, 3.5, 2),  //
                                          rectangle(0, 7, 2, 9, 3)}));   // a window at the top
  add_face(scene, "back", polygon(rectangle(1.5, 0, 0, 10, 3), {rectangle(1.5, 0, 1, 10, 2)}));
  add_face(scene, "overhang",
           polygon({{1, -1.5, 2.75}, {9, -1.5, 2.75}, {9, -0.25, 2.75}, {1, -0.25, 2.75}}));
  add_face(scene, "post", polygon({{3.5, -2, 0}, {3.5, -1, 0}, {3.5, -1, 2.5}, {3.5, -2, 2.5}}));
  scene.lights.push_back(directional_light("sun", {0.375, 0.75, -0.625}));
  scene.lights.push_back(point_light("lamp", {5, -4, 2.5}));
  return scene;
}

NamedScene walls_with_openings_sharing_edges() {
  return {"walls_with_openings_sharing_edges", as_read(walls_sharing_edges_as_written())};
}

Scene as_read(const Scene& scene) {
  // Each face's first part written as a scene's polygon (numbers round-trip) and read.
  const auto loop_json = [](const hsr::Loop3& loop) {
    nlohmann::json points = nlohmann::json::array();
    for (const glm::dvec3& p : loop) points.push_back({p.x, p.y, p.z});
    return points;
  };
  nlohmann::json polygons = nlohmann::json::array();
  for (const Face& face : scene.faces) {
    nlohmann::json holes = nlohmann::json::array();
    for (const hsr::Loop3& hole : face.parts.at(0).holes) holes.push_back(loop_json(hole));
    polygons.push_back(
        {{"id", face.id}, {"outer", loop_json(face.parts.at(0).outer)}, {"holes", holes}});
  }
  const nlohmann::json text = {{"format", "shadowgen-scene/1"}, {"polygons", polygons}};
  Scene out = scene;
  out.faces = parse_scene(text.dump(), "scene.json").scene.faces;
  return out;
}

std::vector<NamedScene> oracle_scenes() {
  return {boxes_on_ground_sun(),
          boxes_on_ground_lamp(),
          holed_polygons_shadowing(),
          interpenetrating_polygons(),
          lamp_among_objects(),
          open_box_lit_inside(),
          eight_lights(),
          walls_with_openings_sharing_edges()};
}

Scene shuffled(const Scene& scene, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  Scene out = scene;
  std::shuffle(out.faces.begin(), out.faces.end(), rng);
  std::shuffle(out.lights.begin(), out.lights.end(), rng);
  return out;
}

Scene moved(const Scene& scene, const glm::dmat3& r, const glm::dvec3& offset) {
  return map_scene(
      scene, [&](const glm::dvec3& p) { return r * p + offset; },
      [&](const glm::dvec3& d) { return r * d; });
}

Scene scaled(const Scene& scene, double factor) {
  Scene out = map_scene(
      scene, [&](const glm::dvec3& p) { return p * factor; },
      [](const glm::dvec3& d) { return d; });
  for (Light& light : out.lights) {
    if (light.range) {
      light.range->falloff_start *= factor;
      light.range->end *= factor;
    }
  }
  return out;
}

Scene offset_by(const Scene& scene, const glm::dvec3& offset) {
  return map_scene(
      scene, [&](const glm::dvec3& p) { return p + offset; },
      [](const glm::dvec3& d) { return d; });
}

glm::dmat3 rotation(const glm::dvec3& axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle), t = 1.0 - c;
  const double x = axis.x, y = axis.y, z = axis.z;
  // Column-major (glm): m[column][row].
  glm::dmat3 m;
  m[0] = {t * x * x + c, t * x * y + s * z, t * x * z - s * y};
  m[1] = {t * x * y - s * z, t * y * y + c, t * y * z + s * x};
  m[2] = {t * x * z + s * y, t * y * z - s * x, t * z * z + c};
  return m;
}

std::string scene_json(const Scene& scene) {
  std::ostringstream out;
  out.precision(17);
  auto vec = [&out](const glm::dvec3& v) { out << '[' << v.x << ',' << v.y << ',' << v.z << ']'; };
  auto loop = [&](const hsr::Loop3& l) {
    out << '[';
    for (std::size_t i = 0; i < l.size(); ++i) {
      if (i > 0) out << ',';
      vec(l[i]);
    }
    out << ']';
  };
  out << "{\"format\":\"shadowgen-scene/1\",\"polygons\":[\n";
  bool first = true;
  for (const Face& face : scene.faces) {
    for (std::size_t p = 0; p < face.parts.size(); ++p) {
      const hsr::Polygon3& part = face.parts[p];
      if (!first) out << ",\n";
      first = false;
      out << " {\"id\":\"" << face.id;
      if (face.parts.size() > 1) out << '-' << p;
      out << "\",\"outer\":";
      loop(part.outer);
      if (!part.holes.empty()) {
        out << ",\"holes\":[";
        for (std::size_t h = 0; h < part.holes.size(); ++h) {
          if (h > 0) out << ',';
          loop(part.holes[h]);
        }
        out << ']';
      }
      out << '}';
    }
  }
  out << "],\n\"lights\":[\n";
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    const Light& light = scene.lights[l];
    if (l > 0) out << ",\n";
    out << " {\"id\":\"" << light.id << '"';
    if (light.type == LightType::kDirectional) {
      out << ",\"type\":\"directional\",\"direction\":";
      vec(light.direction);
    } else {
      out << ",\"type\":\"point\",\"position\":";
      vec(light.position);
      if (light.range) {
        out << ",\"range\":{\"falloff_start\":" << light.range->falloff_start
            << ",\"end\":" << light.range->end << ",\"exponent\":" << light.range->exponent << '}';
      }
    }
    out << '}';
  }
  out << "]}\n";
  return out.str();
}

}  // namespace shadowgen::test
