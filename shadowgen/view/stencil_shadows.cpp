#include "shadowgen/view/stencil_shadows.h"

#include <GL/osmesa.h>
// osmesa.h brings GL/gl.h, which brings GL/glext.h (GL_INCR_WRAP, GL 1.4).
#include <GL/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>
#include <stdexcept>
#include <string>

#include "detail/gl_library.h"
#include "detail/ridge_edge_loops.h"
#include "hsr/polygon3.h"
#include "shadowgen/sampled/part_triangles.h"
#include "shadowgen/shadows/light_scope.h"

namespace shadowgen {
namespace {

const detail::GlLibrary& gl() { return detail::gl_library(); }

using glm::dvec3;
using glm::dvec4;
static_assert(sizeof(dvec4) == 4 * sizeof(double), "vertex arrays of dvec4 as GL_DOUBLE × 4");

// Slack of the infinite far plane (Everitt and Kilgard): points at infinity land at NDC
// depth 1 − kInfinitySlack, inside the depth range after float rounding.
constexpr double kInfinitySlack = 0x1p-20;
// The volumes' push away from the eye: slope factor and units of the depth buffer's step.
constexpr float kOffsetFactor = 0.5f;
constexpr float kOffsetUnits = 4.0f;

struct PartInfo {
  const hsr::Polygon3* polygon = nullptr;
  hsr::Plane3 plane;
  sampled::PartTriangles triangles;
  PartRole role = PartRole::kFacing;
  int light_side = 0;  // +1: the light on the front side, −1 on the back, 0 in the plane
};

// ---- Geometry in doubles ---------------------------------------------------------------

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

// ---- The scene under the light ---------------------------------------------------------

std::vector<PartInfo> scene_parts(const Scene& scene, const Light& light) {
  const ScenePartPlanes all(scene);
  const std::vector<PartRole> roles = part_roles(all.polygons, all.planes, light);
  const std::vector<hsr::Plane3>& planes = all.planes;
  std::vector<PartInfo> parts;
  std::size_t k = 0;
  for (const Face& face : scene.faces) {
    for (const hsr::Polygon3& part : face.parts) {
      PartInfo info;
      info.polygon = &part;
      info.plane = planes[k];
      info.role = roles[k];
      info.triangles = sampled::part_triangles(part);
      const dvec3& n = info.plane.normal;
      const double side = light.type == LightType::kDirectional
                              ? -glm::dot(n, light.direction)
                              : info.plane.signed_distance(light.position);
      info.light_side = n == dvec3(0.0) ? 0 : side > 0.0 ? 1 : side < 0.0 ? -1 : 0;
      parts.push_back(std::move(info));
      ++k;
    }
  }
  return parts;
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
Sphere bounding_sphere(const std::vector<PartInfo>& parts) {
  dvec3 lo(INFINITY), hi(-INFINITY);
  for (const PartInfo& part : parts) {
    for_each_vertex(*part.polygon, [&](const dvec3& v) {
      lo = glm::min(lo, v);
      hi = glm::max(hi, v);
    });
  }
  if (!(lo.x <= hi.x)) return {};
  return {0.5 * (lo + hi), 0.5 * glm::length(hi - lo)};
}

bool casts_volume(const PartInfo& part) {
  return occludes(part.role) && part.light_side != 0 && !part.triangles.triangles.empty();
}

// Per part, per loop (outer first, then holes), per edge from vertex i to i + 1: whether it
// is a silhouette edge, shared by exactly two parts of which one has the light on its front
// side (detail::EdgeKind::kRidge). Empty for the parts the light leaves out.
using SilhouetteMarks = std::vector<std::vector<std::vector<bool>>>;

SilhouetteMarks silhouette_marks(const Scene& scene, const Light& light) {
  const ScenePartPlanes all(scene);
  const std::vector<PartRole> roles = part_roles(all.polygons, all.planes, light);
  const detail::RidgeEdgeLoops ridges =
      detail::ridge_edge_loops(all.polygons, all.planes, roles, light);
  SilhouetteMarks marks(all.polygons.size());
  for (std::size_t p = 0; p < marks.size(); ++p) {
    for (const std::vector<std::size_t>& loop : ridges.part_loop_edges[p]) {
      std::vector<bool>& loop_marks = marks[p].emplace_back();
      for (const std::size_t edge : loop) {
        loop_marks.push_back(ridges.edges[edge].kind == detail::EdgeKind::kRidge);
      }
    }
  }
  return marks;
}

// Whether the part builds a volume: every part that casts one, or with silhouette marks
// only the front parts (their caps; the silhouette edges are theirs).
bool builds_volume(const PartInfo& part, const SilhouetteMarks* marks) {
  return casts_volume(part) && (marks == nullptr || part.light_side > 0);
}

// Calls visit(a, b) for each side edge of the part's volume, directed counter-clockwise
// about its normal toward the light: every edge of its loops, or with `marks` (the part's
// own, per loop) the silhouette edges only.
template <typename Visit>
void for_each_side_edge(const PartInfo& part, const std::vector<std::vector<bool>>* marks,
                        Visit&& visit) {
  const dvec3 m = part.plane.normal * static_cast<double>(part.light_side);
  auto loop_edges = [&](const hsr::Loop3& loop, bool outer, std::size_t index) {
    const double turn = glm::dot(hsr::newell_vector(loop), m);
    const bool forward = outer ? turn > 0.0 : turn < 0.0;
    const std::size_t n = loop.size();
    for (std::size_t i = 0; i < n; ++i) {
      if (marks != nullptr && !(*marks)[index][i]) continue;
      dvec3 a = loop[i], b = loop[(i + 1) % n];
      if (!forward) std::swap(a, b);
      if (a == b) continue;
      visit(a, b);
    }
  };
  loop_edges(part.polygon->outer, true, 0);
  for (std::size_t h = 0; h < part.polygon->holes.size(); ++h) {
    loop_edges(part.polygon->holes[h], false, h + 1);
  }
}

// ---- The view as GL matrices -----------------------------------------------------------

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

// Everything the GL passes draw: the camera and the volumes' triangles, as homogeneous
// vertices relative to the camera's origin.
struct Plan {
  StencilGlCamera camera;
  std::vector<PartInfo> parts;
  std::vector<dvec4> facing, other;  // the depth pass: parts facing the light, the rest
  std::vector<dvec4> sides, caps;    // the volumes
  bool zfail = false;
};

Plan make_plan(const Scene& scene, const Light& light, const CameraView& view,
               const StencilOptions& options) {
  Plan plan;
  if (light.type == LightType::kDirectional &&
      !(glm::length(light.direction) > 0.0 && std::isfinite(glm::length(light.direction)))) {
    throw std::invalid_argument("a directional light needs a finite non-zero direction");
  }
  plan.parts = scene_parts(scene, light);
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
  auto point_scale = [&](const PartInfo& part) {
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
  for (const PartInfo& part : plan.parts) {
    if (marks != nullptr && builds_volume(part, marks)) {
      shared_scale = std::max(shared_scale, point_scale(part));
    }
  }

  // ---- The volumes (and the depth pass's triangles).
  auto local = [&](const dvec3& v) { return dvec4(v - origin, 1.0); };
  double extruded_far = -INFINITY;  // orthographic: the deepest extruded vertex
  for (std::size_t p = 0; p < plan.parts.size(); ++p) {
    const PartInfo& part = plan.parts[p];
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
    for (const PartInfo& part : plan.parts) {
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
    for (const PartInfo& part : plan.parts) {
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
  for (const PartInfo& part : plan.parts) {
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

// ---- OSMesa ----------------------------------------------------------------------------

class OffscreenContext {
 public:
  OffscreenContext(int width, int height) : buffer_(static_cast<std::size_t>(width) * height * 4) {
    context_ = gl().OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
    if (context_ == nullptr) throw std::runtime_error("OSMesa could not create a GL context");
    if (!gl().OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width, height)) {
      gl().OSMesaDestroyContext(context_);
      throw std::runtime_error("OSMesa could not make its GL context current");
    }
  }
  ~OffscreenContext() {
    gl().OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    gl().OSMesaDestroyContext(context_);
  }
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

 private:
  OSMesaContext context_ = nullptr;
  std::vector<unsigned char> buffer_;
};

void require_capabilities() {
  GLint depth = 0, stencil = 0;
  gl().GetIntegerv(GL_DEPTH_BITS, &depth);
  gl().GetIntegerv(GL_STENCIL_BITS, &stencil);
  const char* version = reinterpret_cast<const char*>(gl().GetString(GL_VERSION));
  int major = 0, minor = 0;
  if (version == nullptr || std::sscanf(version, "%d.%d", &major, &minor) != 2) major = 0;
  if (depth < 24 || stencil < 8 || major * 10 + minor < 14) {
    throw std::runtime_error(
        "OSMesa's context lacks 24 depth bits, 8 stencil bits or GL 1.4 (got " +
        std::to_string(depth) + ", " + std::to_string(stencil) + ", " +
        (version ? version : "no version") + ")");
  }
}

void draw(const std::vector<dvec4>& vertices) {
  if (vertices.empty()) return;
  gl().VertexPointer(4, GL_DOUBLE, 0, vertices.data());
  gl().DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices.size()));
}

}  // namespace

StencilGlCamera stencil_gl_camera(const Scene& scene, const Light& light, const CameraView& view,
                                  const StencilOptions& options) {
  return make_plan(scene, light, view, options).camera;
}

std::vector<StencilEdge> stencil_silhouette_edges(const Scene& scene, const Light& light) {
  const std::vector<PartInfo> parts = scene_parts(scene, light);
  const SilhouetteMarks marks = silhouette_marks(scene, light);
  std::vector<StencilEdge> edges;
  for (std::size_t p = 0; p < parts.size(); ++p) {
    if (!builds_volume(parts[p], &marks)) continue;
    for_each_side_edge(parts[p], &marks[p], [&](const dvec3& a, const dvec3& b) {
      edges.push_back({a, b});
    });
  }
  return edges;
}

StencilResult stencil_lit_mask(const Scene& scene, const Light& light, const CameraView& view,
                               const StencilOptions& options) {
  const Plan plan = make_plan(scene, light, view, options);
  const int w = view.width(), h = view.height();
  StencilResult result;
  result.width = w;
  result.height = h;
  result.zfail_used = plan.zfail;
  result.lit.assign(static_cast<std::size_t>(w) * h, 0);

  OffscreenContext context(w, h);
  require_capabilities();
  gl().Viewport(0, 0, w, h);
  gl().MatrixMode(GL_PROJECTION);
  gl().LoadMatrixd(plan.camera.projection.data());
  gl().MatrixMode(GL_MODELVIEW);
  gl().LoadMatrixd(plan.camera.modelview.data());
  gl().Disable(GL_LIGHTING);
  gl().Disable(GL_DITHER);
  gl().Disable(GL_CULL_FACE);
  gl().FrontFace(plan.camera.front_ccw ? GL_CCW : GL_CW);
  gl().EnableClientState(GL_VERTEX_ARRAY);

  // 1. The depth pass; red marks the parts facing the light.
  gl().ClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  gl().ClearDepth(1.0);
  gl().ClearStencil(0);
  gl().Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  gl().Enable(GL_DEPTH_TEST);
  gl().DepthFunc(GL_LESS);
  gl().DepthMask(GL_TRUE);
  gl().Color4ub(255, 0, 0, 255);
  draw(plan.facing);
  gl().Color4ub(0, 0, 0, 255);
  draw(plan.other);

  // 2. The volumes into the stencil buffer: no depth or colour writes.
  gl().ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  gl().DepthMask(GL_FALSE);
  gl().Enable(GL_STENCIL_TEST);
  gl().StencilFunc(GL_ALWAYS, 0, 0xff);
  gl().StencilMask(0xff);
  gl().Enable(GL_POLYGON_OFFSET_FILL);
  gl().PolygonOffset(kOffsetFactor, kOffsetUnits);
  gl().Enable(GL_CULL_FACE);
  if (plan.zfail) {
    gl().CullFace(GL_FRONT);
    gl().StencilOp(GL_KEEP, GL_INCR_WRAP, GL_KEEP);  // back faces behind the surface: +1
    draw(plan.sides);
    draw(plan.caps);
    gl().CullFace(GL_BACK);
    gl().StencilOp(GL_KEEP, GL_DECR_WRAP, GL_KEEP);  // front faces behind the surface: −1
    draw(plan.sides);
    draw(plan.caps);
  } else {
    gl().CullFace(GL_BACK);
    gl().StencilOp(GL_KEEP, GL_KEEP, GL_INCR_WRAP);  // front faces before the surface: +1
    draw(plan.sides);
    gl().CullFace(GL_FRONT);
    gl().StencilOp(GL_KEEP, GL_KEEP, GL_DECR_WRAP);  // back faces before the surface: −1
    draw(plan.sides);
  }
  gl().Finish();
  if (gl().GetError() != GL_NO_ERROR) throw std::runtime_error("OpenGL reported an error");

  // 3. Read back (GL's row 0 is the bottom).
  const std::size_t n = static_cast<std::size_t>(w) * h;
  std::vector<GLubyte> stencil(n), colour(4 * n);
  std::vector<GLfloat> depth(n);
  gl().PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl().ReadPixels(0, 0, w, h, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil.data());
  gl().ReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, colour.data());
  gl().ReadPixels(0, 0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::size_t gl = static_cast<std::size_t>(h - 1 - y) * w + x;
      const bool lit = stencil[gl] == 0 && depth[gl] < 1.0f && colour[4 * gl] == 255;
      result.lit[static_cast<std::size_t>(y) * w + x] = lit ? 1 : 0;
    }
  }
  return result;
}

}  // namespace shadowgen
