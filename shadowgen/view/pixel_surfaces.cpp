#include "shadowgen/view/pixel_surfaces.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <stdexcept>
#include <utility>

#include "detail/embree_scene.h"
#include "hsr/parallel.h"
#include "hsr/polygon3.h"
#include "shadowgen/model/scene_centre.h"
#include "shadowgen/sampled/part_triangles.h"

namespace shadowgen {
namespace {

// Relative depth within which two parts tie (the module comment).
constexpr double kDepthTie = 0x1.0p-40;

struct PartPlane {
  std::size_t face = 0, part = 0;
  glm::dvec3 normal{0.0};  // unit; zero without a plane
  glm::dvec3 origin{0.0};  // a vertex of the part
};

}  // namespace

PixelSurfaces pixel_surfaces(const Scene& scene, const Camera& camera, int width, int height) {
  const CameraView camera_view(camera, scene, width, height);
  const hsr::View& view = camera_view.view();

  std::vector<PartPlane> planes;
  std::vector<sampled::Triangle3> triangles;
  std::vector<std::size_t> owner;  // triangle -> index into planes
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    for (std::size_t p = 0; p < scene.faces[f].parts.size(); ++p) {
      const hsr::Polygon3& polygon = scene.faces[f].parts[p];
      const sampled::PartTriangles part = sampled::part_triangles(polygon);
      if (part.triangles.empty()) continue;
      planes.push_back({f, p, part.normal, polygon.outer.front()});
      for (const sampled::Triangle3& t : part.triangles) {
        triangles.push_back(t);
        owner.push_back(planes.size() - 1);
      }
    }
  }
  const view::detail::EmbreeDevice device;
  const view::detail::TriangleScene hierarchy(device.get(), triangles, scene_centre(scene));

  PixelSurfaces surfaces;
  surfaces.camera = camera;
  surfaces.width = width;
  surfaces.height = height;
  surfaces.perspective = view.is_perspective();
  surfaces.eye = camera.eye;
  surfaces.forward = glm::normalize(view.forward());
  surfaces.pixels.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  const glm::dvec3 forward = surfaces.forward;
  const double tnear = view.is_perspective() ? view.near() : 0.0;

  hsr::for_each_in_parallel(static_cast<std::size_t>(height), [&](std::size_t y) {
    std::vector<view::detail::SegmentHit> hits;
    for (int x = 0; x < width; ++x) {
      const clipper::Point2 image =
          camera_view.from_pixels({static_cast<double>(x) + 0.5, static_cast<double>(y) + 0.5});
      hsr::Ray3 ray = view.ray_through(image);
      if (!view.is_perspective()) {
        // From the plane through the eye, not the one through the view's centre.
        ray.origin += forward * glm::dot(camera.eye - ray.origin, forward);
      }
      PixelSurface& pixel =
          surfaces.pixels[y * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
      pixel.from = ray.origin;
      hits.clear();
      hierarchy.hits(ray.origin, ray.direction, tnear, std::numeric_limits<double>::infinity(),
                     hits);
      double best_t = std::numeric_limits<double>::infinity();
      std::size_t best = planes.size();
      for (const view::detail::SegmentHit& hit : hits) {
        const std::size_t k = owner[hit.triangle];
        const PartPlane& plane = planes[k];
        const double denom = glm::dot(plane.normal, ray.direction);
        // Seen edge-on: the part has no area in the picture; Embree's own depth stands.
        double t = static_cast<double>(hit.t);
        if (denom != 0.0) t = glm::dot(plane.normal, plane.origin - ray.origin) / denom;
        if (!(t >= tnear) || !std::isfinite(t)) t = std::max(tnear, static_cast<double>(hit.t));
        const double tie = kDepthTie * std::max(std::fabs(t), std::fabs(best_t));
        const bool nearer = best == planes.size() || t < best_t - tie;
        const bool tied = !nearer && std::fabs(t - best_t) <= tie && k < best;
        if (nearer || tied) {
          best_t = t;
          best = k;
        }
      }
      if (best == planes.size()) continue;
      const PartPlane& plane = planes[best];
      pixel.face = plane.face;
      pixel.part = plane.part;
      pixel.point = ray.origin + best_t * ray.direction;
      pixel.normal = plane.normal;
      pixel.front = glm::dot(plane.normal, ray.direction) < 0.0;
      pixel.depth = glm::dot(pixel.point - camera.eye, forward);
    }
  });
  return surfaces;
}

}  // namespace shadowgen
