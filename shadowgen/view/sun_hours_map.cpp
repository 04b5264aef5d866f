#include "shadowgen/view/sun_hours_map.h"

#include <span>
#include <stdexcept>
#include <vector>

#include "detail/painter.h"

namespace shadowgen {
namespace {

Rgb rgb(const glm::dvec3& colour) { return {colour.r, colour.g, colour.b}; }

// Faces split by one sun path's sun-hours regions, each piece coloured by its band; the
// region of largest area gets what the others leave.
class SunHoursTiling : public view::detail::FaceTiling {
 public:
  SunHoursTiling(const ShadowedScene& shadowed, const SunPathHours& path, const HourBands& bands)
      : shadowed_(shadowed), path_(path), bands_(bands) {}

  void load(std::size_t face) override {
    regions_ = &path_.regions[face];
    rest_ = view::detail::kNoRegion;
    double largest = 0.0;
    for (std::size_t r = 0; r < regions_->size(); ++r) {
      const double area = lit_area((*regions_)[r].polygons);
      if (rest_ == view::detail::kNoRegion || area > largest) {
        rest_ = r;
        largest = area;
      }
    }
  }
  std::size_t size() const override { return regions_->size(); }
  std::span<const LitPolygon> polygons(std::size_t region) const override {
    return (*regions_)[region].polygons;
  }
  std::size_t rest() const override { return rest_; }

  void style(Piece& piece, std::size_t region, const glm::dvec3& /*centroid*/,
             const glm::dvec3& /*normal*/) const override {
    piece.face_id = shadowed_.scene().faces[piece.face].id;
    const double hours = region == view::detail::kNoRegion ? 0.0 : (*regions_)[region].hours;
    piece.sun_hours = hours;
    const HourBand& band = bands_.bands[bands_.band_of(hours)];
    piece.colour = rgb(band.colour);
    piece.band = band.label;
  }

 private:
  const ShadowedScene& shadowed_;
  const SunPathHours& path_;
  const HourBands& bands_;
  const std::vector<SunHoursRegion>* regions_ = nullptr;
  std::size_t rest_ = view::detail::kNoRegion;
};

}  // namespace

Picture render_sun_hours(const ShadowedScene& shadowed, const SunPathHours& path,
                         const HourBands& bands, const Camera& camera,
                         const RenderOptions& options) {
  require_regions(path, shadowed.scene().file, "a sun-hours map");
  if (path.regions.size() != shadowed.scene().faces.size()) {
    throw std::invalid_argument("the sun path's sun-hours regions are not one list per face");
  }
  SunHoursTiling tiling(shadowed, path, bands);
  Picture picture = view::detail::paint_picture(shadowed.scene(), camera, options, tiling);
  picture.legend.kind = "sun-hours";
  picture.legend.caption = bands.caption();
  for (const HourBand& band : bands.bands) {
    picture.legend.entries.push_back({rgb(band.colour), band.label});
  }
  return picture;
}

}  // namespace shadowgen
