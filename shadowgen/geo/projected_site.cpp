#include "shadowgen/geo/projected_site.h"

#include <proj.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <string_view>

#include "shadowgen/model/number_text.h"

namespace shadowgen::geo {
namespace {

// PROJ's objects, released when they go out of scope.
struct ContextDeleter {
  void operator()(PJ_CONTEXT* context) const { proj_context_destroy(context); }
};
struct ObjectDeleter {
  void operator()(PJ* object) const { proj_destroy(object); }
};
using Context = std::unique_ptr<PJ_CONTEXT, ContextDeleter>;
using Object = std::unique_ptr<PJ, ObjectDeleter>;

// The step along the meridian either side of the point, in degrees (see the header).
constexpr double kMeridianStepDeg = 1e-4;

std::string point_text(double x, double y) {
  std::string text = "(";
  append_shortest(text, x);
  text += ", ";
  append_shortest(text, y);
  text += ')';
  return text;
}

std::string type_name(PJ_TYPE type) {
  switch (type) {
    case PJ_TYPE_GEOGRAPHIC_2D_CRS:
    case PJ_TYPE_GEOGRAPHIC_3D_CRS:
    case PJ_TYPE_GEOGRAPHIC_CRS:
      return "a geographic CRS";
    case PJ_TYPE_GEOCENTRIC_CRS:
      return "a geocentric CRS";
    case PJ_TYPE_VERTICAL_CRS:
      return "a vertical CRS";
    case PJ_TYPE_ENGINEERING_CRS:
      return "an engineering (local) CRS";
    case PJ_TYPE_COMPOUND_CRS:
      return "a compound CRS without a projected part";
    default:
      return "not a coordinate reference system PROJ can project";
  }
}

class Projection {
 public:
  explicit Projection(const std::string& crs) : crs_text_(crs), context_(proj_context_create()) {
    if (!context_) throw CrsError("PROJ could not start");
    // Everything needed is in proj.db; a lookup on the network would make results depend
    // on the machine.
    proj_context_set_enable_network(context_.get(), 0);
    // PROJ logs its errors to stderr by default; they come back here as CrsError instead.
    proj_log_level(context_.get(), PJ_LOG_NONE);
    Object crs_object(proj_create(context_.get(), crs.c_str()));
    if (!crs_object) throw CrsError("PROJ does not know the CRS " + crs);
    if (proj_get_type(crs_object.get()) == PJ_TYPE_COMPOUND_CRS) {
      Object horizontal(proj_crs_get_sub_crs(context_.get(), crs_object.get(), 0));
      if (horizontal) crs_object = std::move(horizontal);
    }
    if (proj_get_type(crs_object.get()) != PJ_TYPE_PROJECTED_CRS) {
      throw CrsError(crs + " is " + type_name(proj_get_type(crs_object.get())) +
                     ", not a projected one");
    }
    check_axes(crs_object.get());
    Object geographic(proj_crs_get_geodetic_crs(context_.get(), crs_object.get()));
    if (!geographic) throw CrsError(crs + " has no geographic base CRS PROJ knows");
    Object operation(proj_create_crs_to_crs_from_pj(context_.get(), crs_object.get(),
                                                    geographic.get(), nullptr, nullptr));
    if (!operation) throw CrsError("PROJ has no inverse projection for " + crs);
    // (easting, northing) in, (longitude, latitude) in degrees out, whatever the axis order
    // of either CRS's definition.
    to_geographic_.reset(proj_normalize_for_visualization(context_.get(), operation.get()));
    if (!to_geographic_) throw CrsError("PROJ has no inverse projection for " + crs);
    read_area_of_use(crs_object.get());
  }

  // Longitude and latitude (degrees) of grid point (x, y); CrsError where the projection
  // is not defined.
  PJ_COORD geographic(double x, double y) const {
    const PJ_COORD out = proj_trans(to_geographic_.get(), PJ_FWD, proj_coord(x, y, 0.0, 0.0));
    if (!std::isfinite(out.v[0]) || !std::isfinite(out.v[1])) {
      throw CrsError(point_text(x, y) + " is not a point " + crs_text_ + " maps to the Earth");
    }
    return out;
  }

  // Grid point (easting, northing) of longitude and latitude (degrees).
  PJ_COORD grid(double longitude, double latitude) const {
    const PJ_COORD out =
        proj_trans(to_geographic_.get(), PJ_INV, proj_coord(longitude, latitude, 0.0, 0.0));
    if (!std::isfinite(out.v[0]) || !std::isfinite(out.v[1])) {
      throw CrsError("the meridian at longitude " + shortest(longitude) + " cannot be projected");
    }
    return out;
  }

  // Empty, or why (longitude, latitude) of grid point (x, y) lies outside the area of use.
  std::string caution(double x, double y, double longitude, double latitude) const {
    if (!has_area_) return "";
    const bool in_latitude = latitude >= south_ && latitude <= north_;
    // An area across the antimeridian runs from west to east through 180.
    const bool in_longitude = west_ <= east_ ? longitude >= west_ && longitude <= east_
                                             : longitude >= west_ || longitude <= east_;
    if (in_latitude && in_longitude) return "";
    std::string text = point_text(x, y) + " lies outside the area of use of " + crs_text_;
    if (!area_name_.empty()) text += ", " + area_name_;
    return text + " (longitude " + shortest(west_) + " to " + shortest(east_) + ", latitude " +
           shortest(south_) + " to " + shortest(north_) + " degrees)";
  }

 private:
  void check_axes(PJ* crs) const {
    Object cs(proj_crs_get_coordinate_system(context_.get(), crs));
    const int count = cs ? proj_cs_get_axis_count(context_.get(), cs.get()) : 0;
    bool east = false, north = false;
    std::string directions;
    for (int i = 0; i < count; ++i) {
      const char* direction = nullptr;
      if (!proj_cs_get_axis_info(context_.get(), cs.get(), i, nullptr, nullptr, &direction, nullptr,
                                 nullptr, nullptr, nullptr) ||
          direction == nullptr) {
        continue;
      }
      const std::string_view d(direction);
      east = east || d == "east" || d == "East";
      north = north || d == "north" || d == "North";
      directions += (directions.empty() ? "" : " and ") + std::string(d);
    }
    if (count != 2 || !east || !north) {
      throw CrsError(crs_text_ + "'s axes point " + directions +
                     ", not east and north as a scene's x and y do");
    }
  }

  void read_area_of_use(PJ* crs) {
    const char* name = nullptr;
    has_area_ = proj_get_area_of_use(context_.get(), crs, &west_, &south_, &east_, &north_,
                                     &name) != 0 &&
                west_ > -1000.0;  // PROJ gives -1000 for bounds it does not know
    if (name != nullptr) area_name_ = name;
    // Names in proj.db are sentences; the caution goes on after one.
    if (area_name_.ends_with('.')) area_name_.pop_back();
  }

  std::string crs_text_;
  Context context_;
  Object to_geographic_;
  bool has_area_ = false;
  double west_ = 0.0, south_ = 0.0, east_ = 0.0, north_ = 0.0;
  std::string area_name_;
};

}  // namespace

ProjectedSite projected_site(const std::string& crs, double x, double y) {
  const Projection projection(crs);
  const PJ_COORD here = projection.geographic(x, y);
  const double longitude = here.v[0];
  const double latitude = here.v[1];
  if (!(std::abs(latitude) <= 90.0 && std::abs(longitude) <= 180.0)) {
    throw CrsError(point_text(x, y) + " is not a point " + crs + " maps to the Earth");
  }

  // The meridian through the point, a step either side (one side only at a pole's
  // neighbourhood, where the other would cross it), as a chord of the grid.
  const double up = std::min(latitude + kMeridianStepDeg, 90.0);
  const double down = std::max(latitude - kMeridianStepDeg, -90.0);
  const PJ_COORD north = projection.grid(longitude, up);
  const PJ_COORD south = projection.grid(longitude, down);
  const double dx = north.v[0] - south.v[0];
  const double dy = north.v[1] - south.v[1];
  // True north points along (dx, dy) in the grid; the grid's +y lies γ clockwise of it
  // when true north leans west of grid north (dx < 0): γ = atan2(−dx, dy).
  const double convergence = std::atan2(-dx, dy) * 180.0 / std::numbers::pi;

  ProjectedSite out;
  out.site.latitude_deg = latitude;
  out.site.longitude_deg = longitude;
  // A convergence of -0.0 reads as 0 wherever it is written.
  out.site.north_axis_deg = convergence == 0.0 ? 0.0 : convergence;
  out.site.from = crs + " through PROJ at " + point_text(x, y);
  out.caution = projection.caution(x, y, longitude, latitude);
  return out;
}

}  // namespace shadowgen::geo
