// Views: the frame, and the consistency of project, ray_through, unproject, nearness_on
// and nearness_of with each other, for orthographic and perspective views, near the
// origin and far from it.

#include "hsr/view.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

namespace shadowgen::hsr {
namespace {

using glm::dvec3;

double uniform(std::mt19937_64& rng, double low, double high) {
  return std::uniform_real_distribution<double>(low, high)(rng);
}

dvec3 random_unit(std::mt19937_64& rng) {
  for (;;) {
    const dvec3 p(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
    const double length = glm::length(p);
    if (length > 0.1 && length <= 1.0) return p / length;
  }
}

// Distance from p to the line of `ray`.
double distance_to_line(const dvec3& p, const Ray3& ray) {
  const dvec3 d = glm::normalize(ray.direction);
  const dvec3 w = p - ray.origin;
  return glm::length(w - glm::dot(w, d) * d);
}

// The plane through p with the given unit normal.
Plane3 plane_through(const dvec3& p, const dvec3& normal) { return {normal, glm::dot(normal, p)}; }

// A random view near `center`, orthographic or perspective, and random points it sees
// (in front of the eye, beyond the near plane).
struct ViewCase {
  View view;
  std::vector<dvec3> points;
};

ViewCase random_case(std::mt19937_64& rng, bool perspective, const dvec3& center) {
  const dvec3 forward = random_unit(rng);
  ViewCase c;
  if (perspective) {
    const dvec3 eye = center - 3.0 * forward;
    c.view = View::perspective(eye, forward, random_unit(rng), uniform(rng, 20, 150), 0.5,
                               uniform(rng, 0.5, 2.0));
  } else {
    c.view = View::orthographic(forward * uniform(rng, 0.1, 10.0), center);
  }
  for (int i = 0; i < 50; ++i) {
    c.points.push_back(center +
                       dvec3(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)));
  }
  return c;
}

TEST(View, FrameIsOrthonormalWithImageAxesAsTheEyeSeesThem) {
  std::mt19937_64 rng(1);
  for (int i = 0; i < 100; ++i) {
    const dvec3 direction = random_unit(rng) * uniform(rng, 0.01, 100.0);
    const dvec3 center(uniform(rng, -5, 5), uniform(rng, -5, 5), uniform(rng, -5, 5));
    for (const View& view : {View::orthographic(direction, center),
                             View::perspective(center, direction, random_unit(rng), 60, 0.1)}) {
      // Columns: the eye-frame coordinates of the world axes.
      const dvec3 x = view.to_eye_frame(view.eye() + dvec3(1, 0, 0));
      const dvec3 y = view.to_eye_frame(view.eye() + dvec3(0, 1, 0));
      const dvec3 z = view.to_eye_frame(view.eye() + dvec3(0, 0, 1));
      const dvec3 row[3] = {{x.x, y.x, z.x}, {x.y, y.y, z.y}, {x.z, y.z, z.z}};
      for (int a = 0; a < 3; ++a) {
        for (int b = 0; b < 3; ++b) {
          EXPECT_NEAR(glm::dot(row[a], row[b]), a == b ? 1.0 : 0.0, 1e-15);
        }
      }
      // Image x to the right and y up as seen looking along forward: right × up =
      // −forward, so a loop counter-clockwise seen from the eye is counter-clockwise in
      // the image.
      EXPECT_NEAR(glm::dot(glm::cross(row[0], row[1]), row[2]), -1.0, 1e-15);
      EXPECT_NEAR(glm::distance(row[2], glm::normalize(direction)), 0.0, 1e-15);
      EXPECT_NEAR(glm::distance(view.forward(), glm::normalize(direction)), 0.0, 1e-15);
    }
  }
}

TEST(View, ImageUpFollowsTheUpHint) {
  const View ortho = View::orthographic({1, 2, -0.5}, {0, 0, 0});
  EXPECT_GT(ortho.to_eye_frame({0, 0, 1}).y, 0.0);  // world z up, unless looking along it
  const View perspective = View::perspective({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 90, 0.1);
  EXPECT_GT(perspective.to_eye_frame({1, 1, 0}).y, 0.0);
  // Looking straight down the up hint: any frame, but still orthonormal and forward.
  const View down = View::perspective({0, 0, 0}, {0, 0, -1}, {0, 0, 1}, 90, 0.1);
  EXPECT_NEAR(down.to_eye_frame({0, 0, -2}).z, 2.0, 1e-15);
}

TEST(View, LoopsCounterClockwiseSeenFromTheEyeStayCounterClockwiseInTheImage) {
  std::mt19937_64 rng(7);
  for (int i = 0; i < 100; ++i) {
    const dvec3 forward = random_unit(rng);
    const dvec3 u = glm::normalize(glm::cross(forward, random_unit(rng)));
    const dvec3 v = glm::cross(u, forward);
    // u, v, -forward right-handed: the loop c + u, c + v, c - u, c - v turns
    // counter-clockwise seen from the side -forward points to, the eye's side.
    ASSERT_GT(glm::dot(glm::cross(u, v), -forward), 0.0);
    const dvec3 c = 3.0 * forward;
    for (const View& view : {View::orthographic(forward, dvec3(0.0)),
                             View::perspective(dvec3(0.0), forward, random_unit(rng), 90, 0.1)}) {
      clipper::Loop2 image;
      for (const dvec3& p : {c + u, c + v, c - u, c - v}) image.push_back(view.project(p));
      EXPECT_GT(clipper::signed_area(image), 0.0);
    }
  }
}

TEST(View, RayThroughTheImageOfAPointPassesThroughIt) {
  std::mt19937_64 rng(2);
  for (const bool perspective : {false, true}) {
    for (int i = 0; i < 50; ++i) {
      const ViewCase c = random_case(rng, perspective, dvec3(uniform(rng, -5, 5), 0, 1));
      for (const dvec3& p : c.points) {
        const Ray3 ray = c.view.ray_through(c.view.project(p));
        EXPECT_LE(distance_to_line(p, ray), 1e-14);
        if (perspective) {
          EXPECT_EQ(ray.origin, c.view.eye());
          EXPECT_GT(glm::dot(p - ray.origin, ray.direction), 0.0);
          EXPECT_NEAR(glm::dot(ray.direction, c.view.forward()), 1.0, 1e-15);
        } else {
          EXPECT_NEAR(glm::dot(ray.origin - c.view.eye(), c.view.forward()), 0.0, 1e-15);
          EXPECT_NEAR(glm::distance(glm::normalize(ray.direction), c.view.forward()), 0.0, 1e-15);
        }
      }
    }
  }
}

TEST(View, UnprojectInvertsProjectOnThePointsPlane) {
  std::mt19937_64 rng(3);
  for (const bool perspective : {false, true}) {
    for (int i = 0; i < 50; ++i) {
      const ViewCase c = random_case(rng, perspective, dvec3(0, uniform(rng, -5, 5), 0));
      for (const dvec3& p : c.points) {
        const Plane3 plane = plane_through(p, random_unit(rng));
        const std::optional<dvec3> back = c.view.unproject(c.view.project(p), plane);
        ASSERT_TRUE(back);
        // The error grows as the plane turns edge-on: 1 / |cos| of the angle between the
        // plane's normal and the ray.
        const dvec3 ray = glm::normalize(c.view.ray_through(c.view.project(p)).direction);
        const double cosine = std::fabs(glm::dot(plane.normal, ray));
        EXPECT_LE(glm::distance(*back, p), 1e-14 / cosine) << "cosine " << cosine;
      }
    }
  }
}

TEST(View, NearnessOnAPlaneAgreesWithNearnessOfItsPoints) {
  std::mt19937_64 rng(4);
  for (const bool perspective : {false, true}) {
    for (int i = 0; i < 50; ++i) {
      const ViewCase c = random_case(rng, perspective, dvec3(0, 0, uniform(rng, -5, 5)));
      const Plane3 plane = plane_through(c.points[0], random_unit(rng));
      const std::optional<Nearness> nearness = c.view.nearness_on(plane);
      ASSERT_TRUE(nearness);
      for (const dvec3& q : c.points) {
        // q moved onto the plane along the view's ray, so it has an image.
        const std::optional<dvec3> p = c.view.unproject(c.view.project(q), plane);
        ASSERT_TRUE(p);
        if (perspective && !(c.view.to_eye_frame(*p).z > 0.0)) continue;
        const double expected = c.view.nearness_of(*p);
        const clipper::Point2 image = c.view.project(*p);
        const double scale = std::fabs(nearness->a * image.x) + std::fabs(nearness->b * image.y) +
                             std::fabs(nearness->c) + std::fabs(expected);
        EXPECT_NEAR(nearness->at(image), expected, 1e-12 * scale);
      }
    }
  }
}

TEST(View, NearnessGrowsTowardTheEye) {
  std::mt19937_64 rng(5);
  for (const bool perspective : {false, true}) {
    for (int i = 0; i < 50; ++i) {
      const ViewCase c = random_case(rng, perspective, dvec3(0));
      for (const dvec3& p : c.points) {
        const Ray3 ray = c.view.ray_through(c.view.project(p));
        const dvec3 nearer = p - 0.01 * ray.direction;
        if (perspective && !(c.view.to_eye_frame(nearer).z > 0.0)) continue;
        EXPECT_GT(c.view.nearness_of(nearer), c.view.nearness_of(p));
      }
    }
  }
  // Orthographic: -z; perspective: 1 / z.
  const View ortho = View::orthographic({0, 0, -1}, {0, 0, 0});
  EXPECT_EQ(ortho.nearness_of({5, 7, 2}), 2.0);
  const View perspective = View::perspective({0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 90, 0.1);
  EXPECT_EQ(perspective.nearness_of({5, 7, 4}), 0.25);
}

TEST(View, EdgeOnPlanesHaveNoNearness) {
  const View ortho = View::orthographic({0, 0, -1}, {3, 4, 5});
  EXPECT_FALSE(ortho.nearness_on({{1, 0, 0}, 7.0}));  // contains the direction
  EXPECT_TRUE(ortho.nearness_on({{0, 0, 1}, 7.0}));
  const View perspective = View::perspective({1, 2, 3}, {0, 0, 1}, {0, 1, 0}, 90, 0.1);
  EXPECT_FALSE(perspective.nearness_on({{0, 1, 0}, 2.0}));  // through the eye
  EXPECT_TRUE(perspective.nearness_on({{0, 1, 0}, 2.5}));
  EXPECT_FALSE(ortho.unproject({0.5, 0.5}, {{1, 0, 0}, 7.0}));
}

TEST(View, WindowIsTheFrustumSeenFromTheEye) {
  EXPECT_FALSE(View::orthographic({0, 0, 1}, {0, 0, 0}).window());
  const double aspect = 1.5;
  const View view = View::perspective({0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 60, 0.1, aspect);
  const std::optional<clipper::PolygonWithHoles2> window = view.window();
  ASSERT_TRUE(window);
  const double h = std::tan(std::numbers::pi / 6.0);
  EXPECT_NEAR(clipper::area(*window), 4.0 * h * h * aspect, 1e-15);
  // A point on the frustum's top side projects onto the window's top edge.
  const double top = view.project({0.0, h * 5.0, 5.0}).y;
  EXPECT_NEAR(top, h, 1e-15);
  for (const clipper::Point2& corner : window->outer) {
    EXPECT_NEAR(std::fabs(corner.x), h * aspect, 1e-15);
    EXPECT_NEAR(std::fabs(corner.y), h, 1e-15);
  }
}

TEST(View, FarFromTheOriginImagesAreRelativeToTheCentre) {
  // Image coordinates are measured from the centre: a scene at 1e8 projects exactly as
  // the same scene at the origin, because p - centre is exact for nearby doubles.
  std::mt19937_64 rng(6);
  const dvec3 far(1e8, -0.75e8, 0.5e8);
  for (int i = 0; i < 20; ++i) {
    const dvec3 direction = random_unit(rng);
    const View near_view = View::orthographic(direction, dvec3(0.0));
    const View far_view = View::orthographic(direction, far);
    const View near_eye = View::perspective(dvec3(0.0), direction, {0, 0, 1}, 90, 0.1);
    const View far_eye = View::perspective(far, direction, {0, 0, 1}, 90, 0.1);
    for (int k = 0; k < 20; ++k) {
      // An offset exactly representable both near 0 and near 1e8 (multiples of 2^-20).
      const dvec3 d =
          glm::round(dvec3(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)) *
                     1048576.0) /
          1048576.0;
      EXPECT_EQ(far_view.project(far + d), near_view.project(d));
      if (glm::dot(d, direction) > 0.1) {
        EXPECT_EQ(far_eye.project(far + d), near_eye.project(d));
      }
    }
  }
}

TEST(View, RejectsDegenerateParameters) {
  EXPECT_THROW(View::orthographic({0, 0, 0}, {0, 0, 0}), std::invalid_argument);
  EXPECT_THROW(View::orthographic({NAN, 0, 1}, {0, 0, 0}), std::invalid_argument);
  EXPECT_THROW(View::perspective({0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 0, 0.1), std::invalid_argument);
  EXPECT_THROW(View::perspective({0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 180, 0.1), std::invalid_argument);
  EXPECT_THROW(View::perspective({0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 90, 0.0), std::invalid_argument);
  EXPECT_THROW(View::perspective({0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 90, 0.1, 0.0),
               std::invalid_argument);
}

}  // namespace
}  // namespace shadowgen::hsr
