#include "tests/shadowgen/shadows/shadow_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>

#include "shadowgen/output/report.h"
#include "shadowgen/shadows/generate.h"
#include "tests/shadowgen/shadows/shadow_oracle.h"

namespace shadowgen::test {
namespace {

std::string format(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", v);
  return buffer;
}

std::string format17(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

double boundary_length(const std::vector<hsr::Polygon3>& polygons) {
  double length = 0.0;
  auto add = [&length](const hsr::Loop3& loop) {
    for (std::size_t i = 0; i < loop.size(); ++i) {
      length += glm::distance(loop[i], loop[(i + 1) % loop.size()]);
    }
  };
  for (const hsr::Polygon3& p : polygons) {
    add(p.outer);
    for (const hsr::Loop3& h : p.holes) add(h);
  }
  return length;
}

}  // namespace

OracleCheck check_against_oracle(const Scene& scene, const ShadowedScene& shadowed,
                                 double tolerance, double vertex_error) {
  OracleCheck check;
  const ShadowOracle oracle(scene);
  const std::vector<ReportRow> rows = report_rows(shadowed);
  for (const ReportRow& row : rows) {
    const ExactLit exact = oracle.lit(row.face, row.light);
    if (!(exact.face_area > 0.0)) continue;
    ++check.pairs;
    const LitComparison c =
        oracle.compare(row.face, row.light, polygons_of(shadowed.lit()[row.face][row.light]));
    const double area_error = std::fabs(row.lit_area - exact.lit_area) / exact.face_area;
    const double region_error = c.symmetric_difference / exact.face_area;
    const double overlap = (c.our_pieces_area - c.our_union_area) / exact.face_area;
    const double outside = c.outside_face_area / exact.face_area;
    check.worst_area_error = std::max(check.worst_area_error, area_error);
    if (c.problem.empty()) {
      check.worst_region_error = std::max(check.worst_region_error, region_error);
      check.worst_overlap = std::max(check.worst_overlap, overlap);
      check.worst_outside = std::max(check.worst_outside, outside);
    }
    if (!c.invalid.empty() && ++check.invalid <= 6) {
      check.invalid_report += "  face '" + scene.faces[row.face].id + "', light '" +
                              scene.lights[row.light].id + "': " + c.invalid + "\n";
    }
    const double bound =
        tolerance + vertex_error *
                        boundary_length(polygons_of(shadowed.lit()[row.face][row.light])) /
                        exact.face_area;
    const double worst = std::max({area_error, region_error, overlap, outside});
    check.worst_bound_ratio = std::max(check.worst_bound_ratio, worst / bound);
    const bool bad = !c.problem.empty() || !(area_error <= bound) || !(region_error <= bound) ||
                     !(overlap <= bound) || !(outside <= bound);
    if (!bad) continue;
    if (++check.failures <= 6) {
      check.report +=
          "  face '" + scene.faces[row.face].id + "', light '" + scene.lights[row.light].id +
          "': area " + format17(exact.face_area) + ", exact lit " + format17(exact.lit_area) +
          ", our lit " + format17(row.lit_area) + " (" +
          std::to_string(shadowed.lit()[row.face][row.light].size()) + " polygons); bound " +
          format(bound) + "; relative errors: area " + format(area_error);
      if (c.problem.empty()) {
        check.report += ", symmetric difference " + format(region_error) + ", overlap " +
                        format(overlap) + ", outside the face " + format(outside) + "\n";
      } else {
        check.report += "; our polygons unreadable: " + c.problem + "\n";
      }
    }
  }
  return check;
}

OracleCheck check_against_oracle(const Scene& scene, double tolerance, double vertex_error) {
  return check_against_oracle(scene, generate_shadows(scene).shadowed, tolerance, vertex_error);
}

std::string summary(const OracleCheck& check) {
  return "worst relative errors: area " + format(check.worst_area_error) + ", region " +
         format(check.worst_region_error) + ", overlap " + format(check.worst_overlap) +
         ", outside " + format(check.worst_outside) + " (worst error/bound " +
         format(check.worst_bound_ratio) + ") over " + std::to_string(check.pairs) + " pairs, " +
         std::to_string(check.failures) + " failing, " + std::to_string(check.invalid) +
         " with loops not simple";
}

std::map<std::pair<std::string, std::string>, double> lit_fractions(const ShadowedScene& shadowed) {
  std::map<std::pair<std::string, std::string>, double> out;
  for (const ReportRow& row : report_rows(shadowed)) {
    out[{shadowed.scene().faces[row.face].id, shadowed.scene().lights[row.light].id}] =
        row.lit_fraction;
  }
  return out;
}

}  // namespace shadowgen::test
