#include "stencil_plan.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <stdexcept>

namespace shadowgen::view::detail {
namespace {

using glm::dvec3;
using glm::dvec4;

// Slack of the infinite far plane (Everitt and Kilgard): points at infinity land at NDC
// depth 1 − kInfinitySlack, inside the depth range after float rounding.
constexpr double kInfinitySlack = 0x1p-20;

// The point of triangle abc nearest p (Ericson, Real-Time Collision Detection, 5.1.5).
dvec3 closest_on_triangle(const dvec3& p, const dvec3& a, const dvec3& b, const dvec3& c) {
  const dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + (d1 / (d1 - d3)) * ab;
  const dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  }
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

// Whether triangle abc may meet the convex hull of `hull` (points, with `hull_edges` the
// directions of its edges): no separating axis among the triangle's normal, the cross
// products of the hull's edge directions (its face normals among them) and those of the
// triangle's edges with the hull's. Nearly touching counts as meeting.
bool may_meet_hull(const sampled::Triangle3& tri, const std::vector<dvec3>& hull,
                   const std::vector<dvec3>& hull_edges) {
  const std::array<dvec3, 3> t{tri.a, tri.b, tri.c};
  double scale = 0.0;
  for (const dvec3& p : hull) scale = std::max(scale, glm::length(p));
  for (const dvec3& p : t) scale = std::max(scale, glm::length(p));
  auto separates = [&](const dvec3& axis) {
    const double length = glm::length(axis);
    if (!(length > 1e-12)) return false;
    double t0 = INFINITY, t1 = -INFINITY, h0 = INFINITY, h1 = -INFINITY;
    for (const dvec3& p : t) {
      t0 = std::min(t0, glm::dot(p, axis));
      t1 = std::max(t1, glm::dot(p, axis));
    }
    for (const dvec3& p : hull) {
      h0 = std::min(h0, glm::dot(p, axis));
      h1 = std::max(h1, glm::dot(p, axis));
    }
    const double gap = 1e-9 * length * scale;
    return t1 < h0 - gap || h1 < t0 - gap;
  };
  const std::array<dvec3, 3> tri_edges{t[1] - t[0], t[2] - t[1], t[0] - t[2]};
  if (separates(glm::cross(tri_edges[0], tri_edges[1]))) return false;
  for (std::size_t i = 0; i < hull_edges.size(); ++i) {
    for (std::size_t j = i + 1; j < hull_edges.size(); ++j) {
      if (separates(glm::cross(hull_edges[i], hull_edges[j]))) return false;
    }
    for (const dvec3& e : tri_edges) {
      if (separates(glm::cross(e, hull_edges[i]))) return false;
    }
  }
  return true;
}

template <typename Visit>
void for_each_vertex(const hsr::Polygon3& part, Visit&& visit) {
  for (const dvec3& v : part.outer) visit(v);
  for (const hsr::Loop3& hole : part.holes) {
    for (const dvec3& v : hole) visit(v);
  }
}

struct Sphere {
  dvec3 centre{0.0};
  double radius = 0.0;
};

// The bounding box's centre and half diagonal.
Sphere bounding_sphere(const std::vector<StencilPart>& parts) {
  dvec3 lo(INFINITY), hi(-INFINITY);
  for (const StencilPart& part : parts) {
    for_each_vertex(*part.polygon, [&](const dvec3& v) {
      lo = glm::min(lo, v);
      hi = glm::max(hi, v);
    });
  }
  if (!(lo.x <= hi.x)) return {};
  return {0.5 * (lo + hi), 0.5 * glm::length(hi - lo)};
}

struct Frame {
  dvec3 eye, right, up, forward;  // eye: the picture's centre for orthographic views
};

// The hsr view's frame, probed through its public map (to_eye_frame is linear): a probe
// a power of two at least the eye's magnitude, so that eye + probe − eye is exact enough.
Frame view_frame(const hsr::View& view) {
  Frame f;
  f.eye = view.eye();
  const double magnitude = std::max({1.0, std::abs(f.eye.x), std::abs(f.eye.y), std::abs(f.eye.z)});
  const double probe = std::exp2(std::ceil(std::log2(magnitude)));
  const dvec3 cx = view.to_eye_frame(f.eye + dvec3(probe, 0, 0)) / probe;
  const dvec3 cy = view.to_eye_frame(f.eye + dvec3(0, probe, 0)) / probe;
  const dvec3 cz = view.to_eye_frame(f.eye + dvec3(0, 0, probe)) / probe;
  f.right = {cx.x, cy.x, cz.x};
  f.up = {cx.y, cy.y, cz.y};
  f.forward = {cx.z, cy.z, cz.z};
  return f;
}

// Column-major element (row, col).
double& at(std::array<double, 16>& m, int row, int col) { return m[col * 4 + row]; }

}  // namespace

StencilPlan make_stencil_plan(const Scene& scene, const Light& light, const CameraView& view,
                              const StencilOptions& options) {
  StencilPlan plan;
  if (light.type == LightType::kDirectional &&
      !(glm::length(light.direction) > 0.0 && std::isfinite(glm::length(light.direction)))) {
    throw std::invalid_argument("a directional light needs a finite non-zero direction");
  }
  plan.parts = stencil_parts(scene, light);
  SilhouetteMarks silhouettes;
  if (options.volumes == StencilVolumes::kSilhouettes) silhouettes = silhouette_marks(scene, light);
  const SilhouetteMarks* marks =
      options.volumes == StencilVolumes::kSilhouettes ? &silhouettes : nullptr;
  const hsr::View& hv = view.view();
  const Frame frame = view_frame(hv);
  const dvec3 origin = frame.eye;
  const bool perspective = hv.is_perspective();
  const Sphere sphere = bounding_sphere(plan.parts);
  const double w = view.width(), h = view.height();

  StencilGlCamera& cam = plan.camera;
  cam.origin = origin;
  cam.perspective = perspective;

  // The modelview: rows right, up, −forward (GL's eye looks down −z).
  cam.modelview.fill(0.0);
  for (int c = 0; c < 3; ++c) {
    at(cam.modelview, 0, c) = frame.right[c];
    at(cam.modelview, 1, c) = frame.up[c];
    at(cam.modelview, 2, c) = -frame.forward[c];
  }
  at(cam.modelview, 3, 3) = 1.0;

  // CameraView's image-to-pixel map, affine: pixel = t + sx·image.x + sy·image.y.
  const clipper::Point2 t = view.to_pixels({0.0, 0.0});
  const clipper::Point2 px = view.to_pixels({1.0, 0.0}), py = view.to_pixels({0.0, 1.0});
  const double s00 = px.x - t.x, s10 = px.y - t.y, s01 = py.x - t.x, s11 = py.y - t.y;
  // Window (x, height − y): its Jacobian [[s00, s01], [−s10, −s11]] keeps orientation
  // when its determinant is positive.
  cam.front_ccw = -(s00 * s11 - s01 * s10) > 0.0;

  const dvec3 light_dir =
      light.type == LightType::kDirectional ? glm::normalize(light.direction) : dvec3(0.0);

  // ---- Depth range and extrusion.
  // Extrusion of vertex v of a part, for its volume: a homogeneous point relative to origin.
  // Orthographic: finite, past the bounding sphere.
  const double reach = 2.0 * sphere.radius * 1.05 + 1e-9 * (1.0 + glm::length(sphere.centre));
  auto extrude = [&](const dvec3& v, double scale) -> dvec4 {
    if (perspective) {
      return light.type == LightType::kDirectional ? dvec4(light_dir, 0.0)
                                                   : dvec4(v - light.position, 0.0);
    }
    if (light.type == LightType::kDirectional) return dvec4(v - origin + reach * light_dir, 1.0);
    return dvec4(light.position + scale * (v - light.position) - origin, 1.0);
  };
  // A point light's scale for a part: its nearest point to the light lands past the sphere.
  auto point_scale = [&](const StencilPart& part) {
    if (perspective || light.type == LightType::kDirectional) return 1.0;
    double nearest = INFINITY;
    for (const sampled::Triangle3& tri : part.triangles.triangles) {
      nearest = std::min(
          nearest,
          glm::length(closest_on_triangle(light.position, tri.a, tri.b, tri.c) - light.position));
    }
    const double far = glm::length(light.position - sphere.centre) + sphere.radius;
    return std::max(1.0, 1.05 * far / std::max(nearest, 1e-12 * far) + 1.0);
  };

  // Silhouette volumes join their front parts' caps and sides at shared vertices, so they
  // share one point-light scale: the largest any of them needs.
  double shared_scale = 1.0;
  for (const StencilPart& part : plan.parts) {
    if (marks != nullptr && builds_volume(part, marks)) {
      shared_scale = std::max(shared_scale, point_scale(part));
    }
  }

  // ---- The volumes (and the depth pass's triangles).
  auto local = [&](const dvec3& v) { return dvec4(v - origin, 1.0); };
  double extruded_far = -INFINITY;  // orthographic: the deepest extruded vertex
  for (std::size_t p = 0; p < plan.parts.size(); ++p) {
    const StencilPart& part = plan.parts[p];
    std::vector<dvec4>& pass = part.role == PartRole::kFacing ? plan.facing : plan.other;
    for (const sampled::Triangle3& tri : part.triangles.triangles) {
      pass.push_back(local(tri.a));
      pass.push_back(local(tri.b));
      pass.push_back(local(tri.c));
    }
    if (!builds_volume(part, marks)) continue;
    // m: the part's normal toward the light; loops and caps counter-clockwise about it.
    const dvec3 m = part.plane.normal * static_cast<double>(part.light_side);
    const double scale = marks != nullptr ? shared_scale : point_scale(part);
    auto track = [&](const dvec4& v) {
      if (v.w != 0.0) extruded_far = std::max(extruded_far, glm::dot(dvec3(v), frame.forward));
    };
    for_each_side_edge(part, marks ? &(*marks)[p] : nullptr, [&](const dvec3& a, const dvec3& b) {
      // Heidmann: the side is drawn against the edge's direction, (b, a, a', b'), so its
      // normal points out of the volume.
      const dvec4 ea = extrude(a, scale), eb = extrude(b, scale);
      plan.sides.insert(plan.sides.end(), {local(b), local(a), ea, local(b), ea, eb});
      track(ea);
      track(eb);
    });
    const bool far_cap = !(perspective && light.type == LightType::kDirectional);
    for (const sampled::Triangle3& tri : part.triangles.triangles) {
      dvec3 a = tri.a, b = tri.b, c = tri.c;
      if (glm::dot(glm::cross(b - a, c - a), m) < 0.0) std::swap(b, c);
      plan.caps.insert(plan.caps.end(), {local(a), local(b), local(c)});  // near: out = m
      if (far_cap) {
        plan.caps.insert(plan.caps.end(),
                         {extrude(a, scale), extrude(c, scale), extrude(b, scale)});  // out = −m
      }
    }
  }

  // ---- The projection.
  cam.projection.fill(0.0);
  at(cam.projection, 0, 0) = 2.0 * s00 / w;
  at(cam.projection, 0, 1) = 2.0 * s01 / w;
  at(cam.projection, 1, 0) = -2.0 * s10 / h;
  at(cam.projection, 1, 1) = -2.0 * s11 / h;
  if (perspective) {
    // The near plane: no part nearer along the view than the nearest part's distance
    // over the frustum's corner factor.
    double corner = 0.0;
    for (const clipper::Point2& p : {clipper::Point2{0.0, 0.0}, clipper::Point2{w, 0.0},
                                     clipper::Point2{0.0, h}, clipper::Point2{w, h}}) {
      const clipper::Point2 image = view.from_pixels(p);
      corner = std::max(corner, image.x * image.x + image.y * image.y);
    }
    double nearest = INFINITY;
    for (const StencilPart& part : plan.parts) {
      for (const sampled::Triangle3& tri : part.triangles.triangles) {
        nearest = std::min(
            nearest, glm::length(closest_on_triangle(frame.eye, tri.a, tri.b, tri.c) - frame.eye));
      }
    }
    double near = hv.near();
    if (std::isfinite(nearest)) near = std::max(near, 0.99 * nearest / std::sqrt(1.0 + corner));
    cam.near = near;
    cam.far = INFINITY;
    // w_c = −z_e; x_ndc = 2·pixel.x/w − 1, y_ndc = 1 − 2·pixel.y/h.
    at(cam.projection, 0, 2) = -(2.0 * t.x / w - 1.0);
    at(cam.projection, 1, 2) = -(1.0 - 2.0 * t.y / h);
    at(cam.projection, 2, 2) = kInfinitySlack - 1.0;
    at(cam.projection, 2, 3) = near * (kInfinitySlack - 2.0);
    at(cam.projection, 3, 2) = -1.0;
  } else {
    double lo = INFINITY, hi = -INFINITY;
    for (const StencilPart& part : plan.parts) {
      for_each_vertex(*part.polygon, [&](const dvec3& v) {
        const double d = glm::dot(v - origin, frame.forward);
        lo = std::min(lo, d);
        hi = std::max(hi, d);
      });
    }
    if (!(lo <= hi)) lo = hi = 0.0;
    hi = std::max(hi, extruded_far);
    const double span = std::max(hi - lo, 1e-9 * (1.0 + sphere.radius));
    double near = lo - 1e-3 * span;
    if (options.eye) near = glm::dot(*options.eye - origin, frame.forward);
    double far = hi + 1e-3 * span;
    if (!(far > near)) far = near + span;
    cam.near = near;
    cam.far = far;
    // Depth d = −z_e along forward; z_ndc = (2d − (far + near)) / (far − near).
    at(cam.projection, 0, 3) = 2.0 * t.x / w - 1.0;
    at(cam.projection, 1, 3) = 1.0 - 2.0 * t.y / h;
    at(cam.projection, 2, 2) = -2.0 / (far - near);
    at(cam.projection, 2, 3) = -(far + near) / (far - near);
    at(cam.projection, 3, 3) = 1.0;
  }

  // z-pass holds where no volume reaches the near plane within the picture, the window W:
  // a point p of W lies in the volume of part P when the segment from p toward the light
  // meets P, so W misses every volume when no occluding part meets the hull of W and the
  // light (a point light), or of W and W moved toward the light past the scene (a
  // directional one). Relative to the origin, as GL gets them.
  std::vector<dvec3> hull, hull_edges;
  for (const clipper::Point2& p : {clipper::Point2{0.0, 0.0}, clipper::Point2{w, 0.0},
                                   clipper::Point2{w, h}, clipper::Point2{0.0, h}}) {
    const clipper::Point2 image = view.from_pixels(p);
    const dvec3 across = image.x * frame.right + image.y * frame.up;
    hull.push_back(perspective ? cam.near * (frame.forward + across)
                               : across + cam.near * frame.forward);
  }
  for (std::size_t i = 0; i < 4; ++i) hull_edges.push_back(hull[(i + 1) % 4] - hull[i]);
  if (light.type == LightType::kDirectional) {
    double past = 0.0;
    for (const dvec3& p : hull) past = std::max(past, glm::length(p + origin - sphere.centre));
    const dvec3 toward = -(past + 2.0 * sphere.radius + 1.0) * light_dir;
    for (std::size_t i = 0; i < 4; ++i) hull.push_back(hull[i] + toward);
    hull_edges.push_back(toward);
  } else {
    for (std::size_t i = 0; i < 4; ++i) hull_edges.push_back(light.position - origin - hull[i]);
    hull.push_back(light.position - origin);
  }
  plan.zfail = false;
  for (const StencilPart& part : plan.parts) {
    if (!builds_volume(part, marks) || plan.zfail) continue;
    for (const sampled::Triangle3& tri : part.triangles.triangles) {
      const sampled::Triangle3 relative{tri.a - origin, tri.b - origin, tri.c - origin};
      if (may_meet_hull(relative, hull, hull_edges)) {
        plan.zfail = true;
        break;
      }
    }
  }
  if (options.method == StencilMethod::kZPass) plan.zfail = false;
  if (options.method == StencilMethod::kZFail) plan.zfail = true;
  return plan;
}

}  // namespace shadowgen::view::detail
