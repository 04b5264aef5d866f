#pragma once

// A picture of the shadowed database from any camera, as data: flat-shaded 2D pieces in
// pixel coordinates, no shadow computed here (Atherton, Weiler and Greenberg 1978, section
// IV: a view needs only hidden-surface removal of the parent faces). The method, the
// shading formula, back sides and layers by light are docs/rendering.md. Pieces are in
// pixel coordinates (x right, y down), loops of positive clipper::area; a picture's pieces
// never overlap and cover the image of the visible faces within its rectangle.

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "clipper/polygon.h"
#include "hsr/hidden_surface.h"
#include "shadowgen/model/shadowed_scene.h"
#include "shadowgen/view/camera.h"

namespace shadowgen {

struct Rgb {
  double r = 0.0;
  double g = 0.0;
  double b = 0.0;
};

struct RenderOptions {
  int width = 800;
  int height = 600;
  Rgb albedo{0.8, 0.8, 0.8};
  double ambient = 0.2;
  Rgb background{1.0, 1.0, 1.0};
};

struct Piece {
  std::size_t face = 0;  // index into scene.faces
  std::size_t part = 0;  // index into the face's parts
  std::string face_id;
  std::vector<std::size_t> lights;  // ascending indices into scene.lights; empty: shadow
  std::string light_set;            // light_set_name(scene, lights): "sun+lamp", "shadow"
  bool back_side = false;
  clipper::PolygonWithHoles2 shape;  // pixels
  Rgb colour;
  // Sun-hours maps (sun_hours_map.h): the hours of the piece's region; lights and
  // light_set are then empty.
  std::optional<double> sun_hours;
  // Layers by light (render_by_light): 0 the base in shadow, 1 + L the layer of light L.
  std::size_t layer = 0;
  // Sun-hours and radiation maps: the label of the band the hours or the kWh/m² lie in
  // ("2–4 h", "2–2.5 kWh/m²"); empty otherwise.
  std::string band;
  // Radiation maps (radiation_map.h): the face's total irradiation over the path, kWh/m².
  std::optional<double> kwh_per_m2;
};

// The visible outline of one face, or of one object of a model file: the union of the
// face's (or the object's faces') base pieces, drawn thin and dark over the fills so that
// buildings can be told apart from gardens (outlines.h).
struct Outline {
  std::string face_id;         // the face's id, or empty for an object's outline
  std::string object;          // the origin's object (FaceOrigin::object), or empty for a face
  clipper::PolygonSet2 shape;  // pixels
};

// Where the picture's marks go (map_marks.h): true north as seen in the picture, a scale
// bar in orthographic views.
struct NorthArrow {
  double angle_deg = 0.0;  // clockwise from the picture's up to true north, in [0, 360)
};
struct ScaleBar {
  double length = 0.0;  // scene units: 1, 2 or 5 × 10^k
  double pixels = 0.0;  // length × pixels_per_unit
  std::string label;    // "10 m", or "10 units" where the scene gives no unit
};

// A legend beside the picture: caption lines, then one swatch per entry; a sun-hours map's
// from the least hours to the most (a radiation map's from the least kWh/m²), a light-set picture's
// light sets in the order of light_set_name's sets (shadow first), each in the colour covering most
// of the picture among its pieces (shading differs from face to face with each face's angle to the
// lights).
struct LegendEntry {
  Rgb colour;
  std::string label;
};
struct Legend {
  std::string kind;  // "sun-hours", "radiation" or "light-sets": the SVG's data-legend
  std::vector<std::string> caption;
  std::vector<LegendEntry> entries;
};

struct RenderStats {
  hsr::HsrStats hsr;                // the one hidden-surface pass, from the camera
  std::size_t parent_polygons = 0;  // face parts given to it
  std::size_t fragments = 0;        // visible fragments within the picture
  std::size_t region_clips = 0;     // fragment × light-set region clips
  std::size_t pieces = 0;
  std::size_t back_side_pieces = 0;
};

struct Picture {
  int width = 0;
  int height = 0;
  double pixels_per_unit = 0.0;  // orthographic views; 0 for perspective ones
  Rgb background;
  std::vector<Piece> pieces;
  RenderStats stats;
  Legend legend;                      // no entries in layers by light
  bool layered = false;               // layers by light: the base's pieces, then each layer's
  std::vector<Outline> outlines;      // each visible face's, or each visible object's
  std::optional<NorthArrow> north;    // where the database has a site and north shows
  std::optional<ScaleBar> scale_bar;  // orthographic views
};

// Throws std::invalid_argument for a bad camera or size (see CameraView).
Picture render(const ShadowedScene& shadowed, const Camera& camera,
               const RenderOptions& options = {});

// The layers by light (above); throws as render() does.
Picture render_by_light(const ShadowedScene& shadowed, const Camera& camera,
                        const RenderOptions& options = {});

// The shading formula above for one point of a face's front side lit by `lights`.
Rgb shade(const Scene& scene, const std::vector<std::size_t>& lights, const glm::dvec3& point,
          const glm::dvec3& normal, const RenderOptions& options);

// The same formula with each light's term weighted: weights[L] in [0, 1] for every light
// of the scene (a pixel's share of it that is lit, raster_render.h); weights of 0 and 1
// give shade() of the lights weighted 1. Throws std::invalid_argument where there is not
// one weight per light.
Rgb shade_weighted(const Scene& scene, std::span<const double> weights, const glm::dvec3& point,
                   const glm::dvec3& normal, const RenderOptions& options);

}  // namespace shadowgen
