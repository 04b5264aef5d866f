#include "sun_hours_checks.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "coordinate_range.h"
#include "hsr/area.h"
#include "hsr/plane_chart.h"
#include "lit_checks.h"
#include "shadowgen/model/instant_blocks.h"
#include "shadowgen/model/number_text.h"

namespace shadowgen::scene::detail {

// On a face of several parts: each part's lit area at most the part's, and the parts'
// sum the face's lit area, at every instant, up to `tolerance` (the regions').
std::optional<std::string> part_lit_area_problem(const Face& face, const SunPathHours& path,
                                                 std::size_t f, double tolerance) {
  const std::vector<std::vector<double>>& on_parts = path.part_lit_area[f];
  if (on_parts.empty()) return std::nullopt;
  for (std::size_t k = 0; k < path.lit_area[f].size(); ++k) {  // a shard's own instants
    double sum = 0.0;
    for (std::size_t i = 0; i < on_parts.size(); ++i) {
      const double part_area = hsr::area(face.parts[i]);
      if (on_parts[i][k] > part_area + tolerance) {
        return "part " + std::to_string(i) + "'s lit area of " + shortest(on_parts[i][k]) +
               " at instant " + std::to_string(path.shard_first + k) +
               ", more than the part's area of " + shortest(part_area);
      }
      sum += on_parts[i][k];
    }
    if (std::fabs(sum - path.lit_area[f][k]) > tolerance) {
      return "the parts' lit areas at instant " + std::to_string(path.shard_first + k) +
             " sum to " + shortest(sum) + ", not the face's lit area of " +
             shortest(path.lit_area[f][k]);
    }
  }
  return std::nullopt;
}

// A path of lit areas alone: no instant's lit area above the face's, nor a part's above
// the part's, and the parts' summing the face's, up to the rounding along the face's
// boundary (LitChecker::area_tolerance).
std::optional<std::string> lit_areas_problem(const Face& face, const SunPathHours& path,
                                             std::size_t f) {
  const double face_area = hsr::area(face.parts);
  const double tolerance = detail::LitChecker(face).area_tolerance({});
  for (const double a : path.lit_area[f]) {
    if (a > face_area + tolerance) {
      return "a lit area of " + shortest(a) + ", more than the face's area of " +
             shortest(face_area);
    }
  }
  return part_lit_area_problem(face, path, f, tolerance);
}

// sun_hours_problem: the regions of a whole database.
std::optional<std::string> sun_hours_problem(const Face& face, const SunPathHours& path,
                                             std::size_t f) {
  if (!path.regions_kept) return lit_areas_problem(face, path, f);
  std::vector<LitPolygon> all;
  double hour_area = 0.0, area = 0.0;
  for (const SunHoursRegion& region : path.regions[f]) {
    const double a = lit_area(region.polygons);
    area += a;
    hour_area += region.hours * a;
    all.insert(all.end(), region.polygons.begin(), region.polygons.end());
  }
  const detail::LitChecker checker(face);
  if (std::optional<detail::LitProblem> problem = checker.check(all)) {
    return "regions: " + problem->what;
  }
  const double face_area = hsr::area(face.parts);
  const double tolerance = checker.area_tolerance(all);
  const double path_hours = static_cast<double>(path.instants.size()) * path.step_min / 60.0;
  if (std::fabs(area - face_area) > tolerance) {
    return "the regions cover an area of " + shortest(area) + ", not the face's " +
           shortest(face_area);
  }
  if (std::optional<std::string> problem = part_lit_area_problem(face, path, f, tolerance)) {
    return problem;
  }
  double lit_hours = 0.0;
  for (const double a : path.lit_area[f]) {
    if (a > face_area + tolerance) {
      return "a lit area of " + shortest(a) + ", more than the face's area of " +
             shortest(face_area);
    }
    lit_hours += a * path.step_min / 60.0;
  }
  if (std::fabs(hour_area - lit_hours) > path_hours * tolerance) {
    return "the regions' hours times areas sum to " + shortest(hour_area) + ", the lit areas' to " +
           shortest(lit_hours);
  }
  return std::nullopt;
}

// A shard's nodes on one face, each checked as a face's regions are: the pieces of all
// its counts, lifted from their part's chart (the chart FaceSunHours takes: the part's
// plane, its vertices kept exactly) onto the part, lie on it and inside it without
// overlapping; on each part they list, their areas sum to the part's (a part not listed
// is lit at none of the node's instants); no count exceeds the node's instants; and Σ
// count × area is the sum of the lit areas of the node's instants, up to that many times
// the rounding along the pieces' boundaries (LitChecker::area_tolerance).
std::optional<std::string> nodes_problem(const Face& face, const SunPathHours& path,
                                         std::size_t f) {
  const detail::LitChecker checker(face);
  const std::vector<SunHoursNode>& nodes = path.nodes[f];
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const SunHoursNode& node = nodes[i];
    const std::string where = "nodes[" + std::to_string(i) + "]: ";
    const std::size_t blocks = std::size_t{1} << node.level;
    const IndexRun instants{
        std::min(node.first_block * kInstantsPerBlock, path.instants.size()),
        std::min((node.first_block + blocks) * kInstantsPerBlock, path.instants.size())};
    std::vector<LitPolygon> pieces;
    std::vector<std::pair<std::size_t, double>> part_areas;  // (part, Σ its pieces' areas)
    double count_area = 0.0;
    for (const SunHoursPieces::Part& part : node.sums.parts) {
      if (part.part >= face.parts.size()) {
        return where + "part " + std::to_string(part.part) + " of a face of " +
               std::to_string(face.parts.size()) + " parts";
      }
      const std::optional<hsr::OwnChart> own = hsr::own_chart(face.parts[part.part]);
      if (!own) {
        return where + "sums on part " + std::to_string(part.part) + ", which has no area";
      }
      const hsr::ChartedPlane& chart = own->chart;
      double on_part = 0.0;
      for (const SunHoursPieces::Count& count : part.counts) {
        if (count.count > instants.size()) {
          return where + "a count of " + std::to_string(count.count) + " instants in a node of " +
                 std::to_string(instants.size());
        }
        for (const clipper::PolygonWithHoles2& piece : count.pieces) {
          LitPolygon lifted{part.part, chart.lift(piece)};
          if (const std::optional<std::string> problem = detail::vertex_problem(lifted.polygon)) {
            return where + "a piece on part " + std::to_string(part.part) + ": " + *problem;
          }
          const double a = hsr::area(lifted.polygon);
          on_part += a;
          count_area += static_cast<double>(count.count) * a;
          pieces.push_back(std::move(lifted));
        }
      }
      part_areas.emplace_back(part.part, on_part);
    }
    if (std::optional<detail::LitProblem> problem = checker.check(pieces)) {
      return where + "pieces: " + problem->what;
    }
    const double tolerance = checker.area_tolerance(pieces);
    for (const auto& [part, on_part] : part_areas) {
      const double part_area = hsr::area(face.parts[part]);
      if (std::fabs(on_part - part_area) > tolerance) {
        return where + "the pieces on part " + std::to_string(part) + " cover an area of " +
               shortest(on_part) + ", not the part's " + shortest(part_area);
      }
    }
    double lit = 0.0;
    for (std::size_t k = instants.first; k < instants.last; ++k) {
      lit += path.lit_area[f].at(k - path.shard_first);
    }
    if (std::fabs(count_area - lit) > static_cast<double>(instants.size()) * tolerance) {
      return where + "the counts times areas sum to " + shortest(count_area) +
             ", the lit areas of the node's " + std::to_string(instants.size()) + " instants to " +
             shortest(lit);
    }
  }
  return std::nullopt;
}

}  // namespace shadowgen::scene::detail
