#pragma once

// A camera: where a picture of the shadowed database is taken from, and how its image maps
// to pixels. The hidden-surface view (hsr::View) works in its own image coordinates; the
// camera adds the map from those to pixels, image y pointing down, (0, 0) the top-left
// corner of a width × height picture.
//
// Perspective: from `eye` toward `target`, `up` fixing the roll, `fov_deg` the full
// vertical angle; the picture is the view's window |x| <= tan(fov/2)·width/height,
// |y| <= tan(fov/2), so pixels are square. Polygons crossing the near plane are cut there
// in 3D (hsr::project_polygon); the near distance is 1e-5 of the scene's bounding-box
// diagonal unless set, so a camera inside the scene sees everything but what lies almost
// in its eye.
//
// Orthographic: a parallel projection along target − eye, `up` fixing the roll; `target`
// is at the picture's centre. Its near plane is the plane through the eye perpendicular to
// the direction: what lies behind it is cut away in 3D (shadowgen/render.h), so an
// orthographic camera inside the scene (between a roof and the floor) sees what is in
// front of it. `pixels_per_unit` > 0 sets the
// scale; 0 fits the scene: the largest scale at which every face vertex lies inside the
// picture with 5% to spare on the tighter side.
//
// An `up` along the direction of view (a top-down view with up = +z; "along" as
// shadowgen/model/view_limits.h says) is replaced by +y, or by +z when the view looks
// along y: north is up on a map. The readers and `render --up` refuse such an up where
// it is given; this serves the default.
//
// The map from view image coordinates to pixels is a similarity (rotation, uniform scale,
// a y flip, a translation), so pixel areas are scene areas times pixels_per_unit² in
// orthographic views of faces seen face-on.

#include <glm/vec3.hpp>

#include "clipper/polygon.h"
#include "hsr/view.h"
#include "shadowgen/model/scene.h"

namespace shadowgen {

struct Camera {
  glm::dvec3 eye{0.0};
  glm::dvec3 target{0.0, 0.0, -1.0};
  glm::dvec3 up{0.0, 0.0, 1.0};
  double fov_deg = 45.0;
  bool orthographic = false;
  double pixels_per_unit = 0.0;  // orthographic: 0 fits the scene
  double near = 0.0;             // perspective: 0 chooses from the scene's size
};

// The scene's view `spec` as a camera.
Camera camera_from_view(const ViewSpec& spec, bool orthographic);

class CameraView {
 public:
  // Throws std::invalid_argument for a non-finite camera, eye == target, a field of view
  // or a scale (other than 0) outside their ranges (shadowgen/model/view_limits.h), a
  // non-positive size.
  CameraView(const Camera& camera, const Scene& scene, int width, int height);

  const hsr::View& view() const { return view_; }
  int width() const { return width_; }
  int height() const { return height_; }
  // Orthographic: pixels per scene unit (the fitted one when fitting); 0 for perspective.
  double pixels_per_unit() const { return pixels_per_unit_; }

  clipper::Point2 to_pixels(const clipper::Point2& image) const;
  clipper::Point2 from_pixels(const clipper::Point2& pixel) const;
  // The picture's rectangle in view image coordinates, counter-clockwise.
  clipper::PolygonWithHoles2 window() const;

 private:
  hsr::View view_;
  int width_ = 0;
  int height_ = 0;
  double pixels_per_unit_ = 0.0;
  // pixel = (tx, ty) + scale · R · image, R = [[c, s], [s, −c]]: a rotation by the angle
  // between the view's image axes and the camera's, then the y flip.
  double scale_ = 1.0;
  double cos_ = 1.0;
  double sin_ = 0.0;
  double tx_ = 0.0;
  double ty_ = 0.0;
};

}  // namespace shadowgen
