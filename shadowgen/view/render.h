#pragma once

// A picture of the shadowed database from any camera, as data: flat-shaded 2D pieces in
// pixel coordinates. No shadow is computed here; this is the paper's second half
// (Atherton, Weiler and Greenberg 1978, section IV): the lit details found once are
// "surface details on their parent polygons", and a view needs only hidden-surface removal
// of the parents.
//
// Method:
//   1. hidden-surface removal from the camera (hsr::remove_hidden_surfaces) on the parent
//      faces' parts only, never on the lit details (an orthographic camera's parts are
//      first cut in 3D at the plane through its eye; perspective ones are cut at the near
//      plane by hsr);
//   2. every visible fragment of a face seen from its front side is split by the face's
//      light-set regions (shadowgen/shadows/light_regions.h), each projected into the image by
//      hsr::project_polygon (cut at the near plane in 3D): the fragment is clipped by the
//      regions of non-empty sets in turn with the Weiler–Atherton clipper, the inside
//      going to that set, and what is left at the end is in shadow. So the pieces of one
//      fragment never overlap and cover it, whatever rounding did to the regions;
//   3. each piece is shaded flat and mapped to pixels.
// Sun-hours maps (sun_hours_map.h) take the same steps with other regions and colours
// (detail/painter.h).
//
// Shading (linear RGB in [0, 1], clamped per channel, written as 8-bit round(255·v)):
//
//   colour = albedo ⊙ (ambient + (1 − ambient) · (1/N) · Σ_{L in the piece's set}
//                                                   intensity_L · max(0, n·l_L) · f_L)
//
// with N the number of lights in the scene (so a face lit head-on by every light at full
// intensity 1 gets the albedo, and no sum of lights saturates), evaluated at the piece's
// 3D centroid c (its image unprojected onto the face's plane), where n is the face part's
// unit front normal, l_L the unit vector from c toward L (−direction/|direction| for a
// directional light) and f_L the fall-off: 1 for directional lights and point lights
// without a range; for a range (s = falloff_start, e = end, k = exponent) and
// d = |position − c|:
//
//   f_L = 1 for d <= s,   0 for d >= e,   (1 − (d − s)/(e − s))^k  between.
//
// Shadow (the empty set) is albedo · ambient: dark, but visible.
//
// Back sides: a face part seen from its back is drawn in the ambient colour, one piece
// per visible fragment, with an empty light set and `back_side` set: the spec's lit region
// lies on the front side only, so nothing reaches the back (a wall lit from the other
// side does not show its lit pattern through itself).
//
// Layers by light (render_by_light): instead of splitting fragments by light sets, whose
// regions grow faster than the lights (the arrangement of every light's shadow edges),
// every visible fragment is drawn whole in shadow (albedo · ambient) and, over it, one
// layer per light in scene order: the fragment clipped by the image of that light's lit
// polygons, coloured by that light's term of the formula alone,
//
//   albedo ⊙ (1 − ambient) · (1/N) · intensity_L · max(0, n·l_L) · f_L,
//
// at the piece's centroid (the difference of shade() for {L} and for no light, so clamped
// alike). Added up over the base, as an SVG viewer blends the layers (svg_writer.h), they
// give the formula's sum. Time and pieces grow linearly with the lights. The base pieces
// and each layer's pieces do not overlap among themselves; layers overlap the base and
// one another.
//
// Pieces are in pixel coordinates (x right, y down, (0, 0) the top-left corner); their
// loops are oriented so that clipper::area is positive (outer loops have positive signed
// area in these numbers). The picture's pieces never overlap and cover exactly the image
// of the visible faces within the picture's rectangle (up to the clipper's rounding).

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
  // Sun-hours maps: the label of the band the hours lie in ("2–4 h"); empty otherwise.
  std::string band;
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
// from the least hours to the most, a light-set picture's light sets in the order of
// light_set_name's sets (shadow first), each in the colour covering most of the picture
// among its pieces (shading differs from face to face with each face's angle to the lights).
struct LegendEntry {
  Rgb colour;
  std::string label;
};
struct Legend {
  std::string kind;  // "sun-hours" or "light-sets": the SVG's data-legend
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

// Throws std::invalid_argument for a bad camera or size (see CameraView) and when `lit`
// is not shaped [face][light].
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
