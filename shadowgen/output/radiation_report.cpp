#include "shadowgen/output/radiation_report.h"

#include <cmath>
#include <numbers>

#include "detail/csv_fields.h"
#include "detail/instant_time.h"
#include "detail/sun_paths_required.h"
#include "shadowgen/model/number_text.h"
#include "shadowgen/output/irradiation_report.h"
#include "shadowgen/sky/cumulative_sky.h"
#include "shadowgen/sky/perez_sky.h"
#include "shadowgen/sun/civil_time.h"
#include "shadowgen/weather/irradiance.h"

namespace shadowgen {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

int day_of_year(const sun::CivilTime& time) {
  int day = time.day;
  for (int month = 1; month < time.month; ++month) day += sun::days_in_month(time.year, month);
  return day;
}

}  // namespace

std::vector<PathSky> path_skies(const ShadowedScene& shadowed,
                                std::span<const sky::SkyPatch> patches, const Weather& weather,
                                const RadiationOptions& options) {
  output::detail::require_sun_paths(shadowed, "radiation");
  const sky::PerezSky perez(patches);
  std::vector<PathSky> skies;
  std::size_t albedo_missing = 0;
  for (const SunPathHours& path : shadowed.sun_paths) {
    const double hours = path.step_min / 60.0;
    std::vector<sky::WeightedSkyHour> sky_hours;
    PathSky path_sky;
    for (const std::size_t l : path.instants) {
      const Light& light = shadowed.scene().lights.at(l);
      const sun::CivilTime time = output::detail::instant_time(light, path, weather.file);
      using weather::Radiation;
      sky::SkyHour hour;
      hour.sun_altitude_rad = light.sun->elevation_deg * kDegree;
      hour.sun_azimuth_rad = light.sun->azimuth_deg * kDegree;
      hour.direct_normal_w_m2 = weather::radiation_wh_m2(weather, time, Radiation::kDirectNormal);
      hour.diffuse_horizontal_w_m2 =
          weather::radiation_wh_m2(weather, time, Radiation::kDiffuseHorizontal);
      hour.day_of_year = day_of_year(time);
      sky_hours.push_back({hour, hours});
      const double global = weather::radiation_wh_m2(weather, time, Radiation::kGlobalHorizontal);
      std::optional<double> albedo = options.albedo;
      if (!albedo) albedo = weather::weather_hour_needed(weather, time).albedo;
      if (!albedo) ++albedo_missing;
      path_sky.ground_wh_m2 += albedo.value_or(kDefaultAlbedo) * global * hours;
    }
    path_sky.radiance_wh = sky::cumulative_sky(perez, sky_hours);
    skies.push_back(std::move(path_sky));
  }
  if (albedo_missing > 0 && options.on_warning) {
    options.on_warning(weather.file + ": the albedo (field 33) is missing (999) in the hours of " +
                       std::to_string(albedo_missing) +
                       (albedo_missing == 1 ? " instant" : " instants") + "; " +
                       shortest(kDefaultAlbedo) + " is taken there (--albedo sets it)");
  }
  return skies;
}

std::vector<RadiationRow> radiation_rows(const ShadowedScene& shadowed,
                                         const sky::SkyExposure& exposure,
                                         std::span<const PathSky> skies, const Weather& weather) {
  const std::vector<IrradiationRow> direct = irradiation_rows(shadowed, weather);
  std::vector<RadiationRow> rows;
  rows.reserve(direct.size());
  for (const IrradiationRow& d : direct) {
    RadiationRow row;
    row.face = d.face;
    row.path = d.path;
    row.area = d.area;
    row.direct_wh = d.direct_wh;
    row.unshaded_direct_wh = d.unshaded_wh;
    const PathSky& sky = skies[d.path];
    const std::vector<double>& lit = exposure.lit_weight[d.face];
    const std::vector<double>& open = exposure.open_weight[d.face];
    for (std::size_t p = 0; p < sky.radiance_wh.size(); ++p) {
      row.diffuse_wh += lit[p] * sky.radiance_wh[p];
      row.unshaded_diffuse_wh += open[p] * sky.radiance_wh[p];
    }
    row.diffuse_wh *= d.area;
    row.unshaded_diffuse_wh *= d.area;
    row.ground_wh = d.area * exposure.ground_view_factor[d.face] * sky.ground_wh_m2;
    rows.push_back(row);
  }
  return rows;
}

std::vector<RadiationRow> radiation_rows(const ShadowedScene& shadowed,
                                         const sky::SkyExposure& exposure, const Weather& weather,
                                         const RadiationOptions& options) {
  const std::vector<PathSky> skies = path_skies(shadowed, exposure.patches, weather, options);
  return radiation_rows(shadowed, exposure, skies, weather);
}

std::string radiation_csv(const ShadowedScene& shadowed, const sky::SkyExposure& exposure,
                          const Weather& weather, const RadiationOptions& options, CsvIds ids) {
  const std::vector<RadiationRow> rows = radiation_rows(shadowed, exposure, weather, options);
  std::string out =
      "face_id,sun_path,area,direct_wh,diffuse_wh,ground_wh,total_wh,direct_wh_per_area,"
      "diffuse_wh_per_area,ground_wh_per_area,total_wh_per_area,unshaded_total_wh,"
      "unshaded_direct_wh_per_area,unshaded_diffuse_wh_per_area,unshaded_total_wh_per_area,"
      "total_ratio\n";
  for (const RadiationRow& row : rows) {
    output::detail::append_csv_field(out, shadowed.scene().faces[row.face].id, ids);
    out += ',';
    output::detail::append_csv_field(out, shadowed.sun_paths[row.path].id, ids);
    const auto per_area = [&row](double wh) { return row.area > 0.0 ? wh / row.area : 0.0; };
    const double total = row.total_wh(), unshaded = row.unshaded_total_wh();
    for (const double v :
         {row.area, row.direct_wh, row.diffuse_wh, row.ground_wh, total, per_area(row.direct_wh),
          per_area(row.diffuse_wh), per_area(row.ground_wh), per_area(total), unshaded,
          per_area(row.unshaded_direct_wh), per_area(row.unshaded_diffuse_wh), per_area(unshaded),
          unshaded > 0.0 ? total / unshaded : 0.0}) {
      out += ',';
      output::detail::append_csv_number(out, v);
    }
    out += '\n';
  }
  return out;
}

}  // namespace shadowgen
