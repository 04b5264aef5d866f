#include "shadowgen/report.h"

#include <array>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string_view>

#include "shadowgen/area.h"
#include "shadowgen/detail/json_text.h"

namespace shadowgen {
namespace {

using detail::append_json_number;
using detail::append_json_string;

double fraction(double part, double whole) { return whole == 0.0 ? 0.0 : part / whole; }

// Neumaier's compensated sum: the error stays near one rounding however many rows there
// are, so totals do not depend on the scene's size.
class Sum {
 public:
  void add(double x) {
    const double t = sum_ + x;
    if (std::fabs(sum_) >= std::fabs(x)) {
      compensation_ += (sum_ - t) + x;
    } else {
      compensation_ += (x - t) + sum_;
    }
    sum_ = t;
  }
  double value() const { return sum_ + compensation_; }

 private:
  double sum_ = 0.0;
  double compensation_ = 0.0;
};

// %.17g, but independent of the C locale's decimal point.
void append_csv_number(std::string& out, double value) {
  std::array<char, 40> buffer{};
  char* const begin = buffer.data();
  const char* end =
      std::to_chars(begin, begin + buffer.size(), value, std::chars_format::general, 17).ptr;
  out.append(begin, static_cast<std::size_t>(end - begin));
}

// RFC 4180: a field holding a comma, a quote, CR or LF is quoted, its quotes doubled.
void append_csv_field(std::string& out, std::string_view field) {
  if (field.find_first_of(",\"\r\n") == std::string_view::npos) {
    out += field;
    return;
  }
  out += '"';
  for (const char c : field) {
    if (c == '"') out += '"';
    out += c;
  }
  out += '"';
}

void append_totals(std::string& out, const Sum& area, const Sum& lit_area) {
  out += "\"area\":";
  append_json_number(out, area.value());
  out += ",\"lit_area\":";
  append_json_number(out, lit_area.value());
  out += ",\"lit_fraction\":";
  append_json_number(out, fraction(lit_area.value(), area.value()));
}

}  // namespace

std::vector<ReportRow> report_rows(const ShadowedScene& shadowed) {
  const Scene& scene = shadowed.scene;
  if (shadowed.lit.size() != scene.faces.size()) {
    throw std::invalid_argument("report: lit details for " + std::to_string(shadowed.lit.size()) +
                                " faces, the scene has " + std::to_string(scene.faces.size()));
  }
  std::vector<ReportRow> rows;
  rows.reserve(scene.faces.size() * scene.lights.size());
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    if (shadowed.lit[f].size() != scene.lights.size()) {
      throw std::invalid_argument("report: face '" + scene.faces[f].id + "': lit details for " +
                                  std::to_string(shadowed.lit[f].size()) +
                                  " lights, the scene has " + std::to_string(scene.lights.size()));
    }
    const double face_area = area(scene.faces[f].parts);
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
      ReportRow row;
      row.face = f;
      row.light = l;
      row.area = face_area;
      row.lit_area = area(shadowed.lit[f][l]);
      row.lit_fraction = fraction(row.lit_area, face_area);
      rows.push_back(row);
    }
  }
  return rows;
}

std::string report_csv(const ShadowedScene& shadowed) {
  const std::vector<ReportRow> rows = report_rows(shadowed);
  std::string out = "face_id,light_id,area,lit_area,lit_fraction\n";
  for (const ReportRow& row : rows) {
    append_csv_field(out, shadowed.scene.faces[row.face].id);
    out += ',';
    append_csv_field(out, shadowed.scene.lights[row.light].id);
    out += ',';
    append_csv_number(out, row.area);
    out += ',';
    append_csv_number(out, row.lit_area);
    out += ',';
    append_csv_number(out, row.lit_fraction);
    out += '\n';
  }
  return out;
}

std::string report_json(const ShadowedScene& shadowed) {
  const std::vector<ReportRow> rows = report_rows(shadowed);
  const Scene& scene = shadowed.scene;
  std::vector<Sum> light_area(scene.lights.size());
  std::vector<Sum> light_lit_area(scene.lights.size());
  Sum total_area;
  Sum total_lit_area;

  std::string out = "{\n  \"format\": \"shadowgen-report/1\",\n  \"rows\": [";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const ReportRow& row = rows[i];
    out += i == 0 ? "\n    " : ",\n    ";
    out += "{\"face_id\":";
    append_json_string(out, scene.faces[row.face].id);
    out += ",\"light_id\":";
    append_json_string(out, scene.lights[row.light].id);
    out += ",\"area\":";
    append_json_number(out, row.area);
    out += ",\"lit_area\":";
    append_json_number(out, row.lit_area);
    out += ",\"lit_fraction\":";
    append_json_number(out, row.lit_fraction);
    out += '}';
    light_area[row.light].add(row.area);
    light_lit_area[row.light].add(row.lit_area);
    total_area.add(row.area);
    total_lit_area.add(row.lit_area);
  }
  out += rows.empty() ? "],\n  \"lights\": [" : "\n  ],\n  \"lights\": [";
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    out += l == 0 ? "\n    " : ",\n    ";
    out += "{\"light_id\":";
    append_json_string(out, scene.lights[l].id);
    out += ',';
    append_totals(out, light_area[l], light_lit_area[l]);
    out += '}';
  }
  out += scene.lights.empty() ? "],\n  \"totals\": {" : "\n  ],\n  \"totals\": {";
  append_totals(out, total_area, total_lit_area);
  out += "}\n}\n";
  return out;
}

}  // namespace shadowgen
