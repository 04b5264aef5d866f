// Shadow rays cast in packets against the same rays cast one by one (ray_caster.h): only
// the call to Embree differs, so every ray must get the same answer, and an estimator must
// give the same numbers bit for bit either way. The scenes are many random occluders, so
// that the rays cross every kind of place in the hierarchy, lit and shadowed alike.

#include "shadowgen/sampled/ray_caster.h"

#include <embree3/rtcore.h>
#include <gtest/gtest.h>

#include <cstddef>
#include <glm/geometric.hpp>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "shadowgen/sampled/estimate.h"
#include "shadowgen/scene/scene_reader.h"

namespace shadowgen::sampled {
namespace {

// `count` random triangles of side about 0.5 to 2 in the box [0,10]² × [0.5,5].
std::vector<Triangle3> random_triangles(std::mt19937_64& random, int count) {
  std::uniform_real_distribution<double> x(0.0, 10.0), z(0.5, 5.0), d(-1.0, 1.0);
  std::vector<Triangle3> out;
  for (int i = 0; i < count; ++i) {
    const glm::dvec3 a(x(random), x(random), z(random));
    out.push_back({a, a + glm::dvec3(d(random), d(random), d(random)),
                   a + glm::dvec3(d(random), d(random), d(random))});
  }
  return out;
}

Light sun(const glm::dvec3& direction) {
  Light light;
  light.type = LightType::kDirectional;
  light.direction = direction;
  return light;
}

Light lamp(const glm::dvec3& position) {
  Light light;
  light.type = LightType::kPoint;
  light.position = position;
  return light;
}

class Device {
 public:
  Device() : device_(rtcNewDevice(nullptr)) {}
  ~Device() { rtcReleaseDevice(device_); }
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;
  RTCDevice get() const { return device_; }

 private:
  RTCDevice device_;
};

TEST(RayCaster, PacketsAnswerEveryRayAsOneByOne) {
  std::mt19937_64 random(20240611);
  const Device device;
  ASSERT_NE(device.get(), nullptr);
  const std::vector<Triangle3> occluders = random_triangles(random, 600);
  const RayCaster caster(device.get(), occluders);
  RecordProperty("packet_width", caster.packet_width());
  EXPECT_TRUE(caster.packet_width() == 1 || caster.packet_width() == 4 ||
              caster.packet_width() == 8 || caster.packet_width() == 16);

  // Points among the occluders and on the ground below them, a few on the occluders
  // themselves (where the offset decides), each with a normal towards the light.
  std::uniform_real_distribution<double> x(0.0, 10.0), z(0.0, 5.0), u(0.0, 1.0);
  const Light lights[] = {sun({0.3, -0.2, -1.0}), sun({1.0, 0.0, -0.1}), lamp({5.0, 5.0, 4.0}),
                          lamp({2.0, 8.0, 12.0})};
  for (const Light& light : lights) {
    std::vector<glm::dvec3> points, normals;
    for (int i = 0; i < 20000; ++i) {
      glm::dvec3 p;
      if (i % 10 == 0) {
        const Triangle3& t = occluders[static_cast<std::size_t>(i) % occluders.size()];
        const double a = u(random), b = u(random) * (1.0 - a);
        p = t.a + a * (t.b - t.a) + b * (t.c - t.a);
      } else {
        p = {x(random), x(random), i % 3 == 0 ? 0.0 : z(random)};
      }
      const glm::dvec3 to_light =
          light.type == LightType::kDirectional ? -light.direction : light.position - p;
      points.push_back(p);
      normals.push_back(glm::normalize(to_light + glm::dvec3(0.1, -0.2, 0.3) * u(random)));
    }
    // Odd counts too, so that the last packet is padded.
    for (std::size_t n : {points.size(), std::size_t{1}, std::size_t{17}, std::size_t{1237}}) {
      const std::span<const glm::dvec3> p(points.data(), n), nrm(normals.data(), n);
      std::vector<double> one(n, -1.0), packets(n, -1.0), single(n, -1.0);
      caster.lit(light, p, nrm, one, Casting::kOneByOne);
      caster.lit(light, p, nrm, packets, Casting::kPackets);
      for (std::size_t i = 0; i < n; ++i) single[i] = caster.lit(light, p[i], nrm[i]);
      std::size_t differ = 0, lit = 0;
      for (std::size_t i = 0; i < n; ++i) {
        differ += packets[i] != one[i] || single[i] != one[i];
        lit += one[i] == 1.0;
        ASSERT_TRUE(one[i] == 0.0 || one[i] == 1.0);
      }
      EXPECT_EQ(differ, 0u) << "of " << n << " rays";
      if (n == points.size()) {
        // Both answers common: the comparison means something.
        EXPECT_GT(lit, n / 10) << "lit";
        EXPECT_LT(lit, n - n / 10);
      }
    }
  }
}

// A ground under many random triangles, a lamp with a range that leaves some out (a
// caster of its own) and two lights that take everything in (the shared caster).
std::string random_scene(int count) {
  std::mt19937_64 random(7);
  std::ostringstream json;
  json.precision(17);
  json << R"({"format": "shadowgen-scene/1", "polygons": [)"
       << R"({"id": "ground", "outer": [[0,0,0],[10,0,0],[10,10,0],[0,10,0]]})";
  int i = 0;
  for (const Triangle3& t : random_triangles(random, count)) {
    json << ",\n{\"id\": \"t" << i++ << "\", \"outer\": [";
    const glm::dvec3* v[] = {&t.a, &t.b, &t.c};
    for (int k = 0; k < 3; ++k) {
      json << (k ? "," : "") << "[" << v[k]->x << "," << v[k]->y << "," << v[k]->z << "]";
    }
    json << "]}";
  }
  json << R"(], "lights": [
    {"id": "sun", "type": "directional", "direction": [0.3,-0.2,-1]},
    {"id": "lamp", "type": "point", "position": [5,5,6]},
    {"id": "near", "type": "point", "position": [2,2,3], "range": {"falloff_start": 1, "end": 4}}
  ]})";
  return json.str();
}

TEST(RayCaster, EstimatesInPacketsAreBitIdentical) {
  const Scene scene = parse_scene(random_scene(1500), "random.json").scene;
  Estimator packets(scene, {MethodKind::kRays, 64, 0});
  Estimator one(scene, {MethodKind::kRays, 64, 0});
  set_casting(packets, Casting::kPackets);
  set_casting(one, Casting::kOneByOne);
  for (const Light& light : scene.lights) {
    const PartLitAreas a = packets.lit_areas(light), b = one.lit_areas(light);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t f = 0; f < a.size(); ++f) {
      ASSERT_EQ(a[f].size(), b[f].size());
      for (std::size_t k = 0; k < a[f].size(); ++k) {
        EXPECT_EQ(a[f][k], b[f][k]) << light.id << ", face " << scene.faces[f].id;
      }
    }
    // The ground (100 in area) partly shadowed: rays on both sides of the shadows.
    EXPECT_GT(a[0][0], 1.0) << light.id;
    EXPECT_LT(a[0][0], 99.0) << light.id;
  }
}

}  // namespace
}  // namespace shadowgen::sampled
