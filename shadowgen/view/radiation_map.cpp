#include "shadowgen/view/radiation_map.h"

#include <span>
#include <stdexcept>

#include "detail/painter.h"

namespace shadowgen {
namespace {

Rgb rgb(const glm::dvec3& colour) { return {colour.r, colour.g, colour.b}; }

// Faces whole, without regions: every fragment is what no region takes, coloured by its
// face's band.
class RadiationTiling : public view::detail::FaceTiling {
 public:
  RadiationTiling(const ShadowedScene& shadowed, std::span<const double> kwh_per_m2,
                  const RadiationBands& bands)
      : shadowed_(shadowed), kwh_per_m2_(kwh_per_m2), bands_(bands) {}

  void load(std::size_t /*face*/) override {}
  std::size_t size() const override { return 0; }
  std::span<const LitPolygon> polygons(std::size_t /*region*/) const override { return {}; }
  std::size_t rest() const override { return view::detail::kNoRegion; }

  void style(Piece& piece, std::size_t /*region*/, const glm::dvec3& /*centroid*/,
             const glm::dvec3& /*normal*/) const override {
    piece.face_id = shadowed_.scene().faces[piece.face].id;
    const double value = piece.back_side ? 0.0 : kwh_per_m2_[piece.face];
    piece.kwh_per_m2 = value;
    const RadiationBand& band = bands_.bands[bands_.band_of(value)];
    piece.colour = rgb(band.colour);
    piece.band = band.label;
  }

 private:
  const ShadowedScene& shadowed_;
  std::span<const double> kwh_per_m2_;
  const RadiationBands& bands_;
};

}  // namespace

Picture render_radiation(const ShadowedScene& shadowed, std::span<const double> kwh_per_m2,
                         const RadiationBands& bands, const Camera& camera,
                         const RenderOptions& options) {
  if (kwh_per_m2.size() != shadowed.scene().faces.size()) {
    throw std::invalid_argument("a radiation map needs one value per face");
  }
  RadiationTiling tiling(shadowed, kwh_per_m2, bands);
  Picture picture = view::detail::paint_picture(shadowed.scene(), camera, options, tiling);
  picture.legend.kind = "radiation";
  picture.legend.caption = bands.caption();
  for (const RadiationBand& band : bands.bands) {
    picture.legend.entries.push_back({rgb(band.colour), band.label});
  }
  return picture;
}

}  // namespace shadowgen
