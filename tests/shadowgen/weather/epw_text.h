#pragma once

// Synthetic EnergyPlus weather files for tests: the 8 header lines as the EnergyPlus
// weather converter writes them (the LOCATION of London Gatwick's IWEC file), and hourly
// rows of 35 fields whose three radiation fields (global horizontal 14, direct normal 15,
// diffuse horizontal 16) hold different values, so that a test sees which one was read.

#include <string>
#include <vector>

namespace shadowgen::test {

inline const std::string kEpwLocation =
    "LOCATION,London Gatwick,,GBR,IWEC Data,037760,51.15,-0.18,0.0,62.0";

// The direct normal radiation (Wh/m2) of day `day`, hour `hour` in epw_lines' rows.
inline double test_direct_normal(int day, int hour) { return day * 100 + hour + 0.5; }

// One hourly row with the global horizontal (field 14), direct normal (15) and diffuse
// horizontal (16) radiation and the albedo (33) as written.
inline std::string epw_row(int month, int day, int hour, const std::string& global,
                           const std::string& direct, const std::string& diffuse,
                           const std::string& albedo) {
  return "1999," + std::to_string(month) + "," + std::to_string(day) + "," + std::to_string(hour) +
         ",0,?9?9?9?9E0?9?9?9?9?9?9?9?9?9?9?9?9?9?9*9?9?9,6.0,4.0,87,101800,0,0,316," + global +
         "," + direct + "," + diffuse +
         ",0,0,0,0,240,4.1,8,8,11.2,77777,9,999999999,0,0.0960,0,88," + albedo + ",0.0,0.0";
}

// One hourly row, with `direct_normal` as field 15 as written (and 1111, 2222 and 0.000 in
// fields 14, 16 and 33).
inline std::string epw_row(int month, int day, int hour, const std::string& direct_normal) {
  return epw_row(month, day, hour, "1111", direct_normal, "2222", "0.000");
}

// The 8 header lines.
inline std::vector<std::string> epw_header() {
  return {kEpwLocation,
          "DESIGN CONDITIONS,0",
          "TYPICAL/EXTREME PERIODS,0",
          "GROUND TEMPERATURES,0",
          "HOLIDAYS/DAYLIGHT SAVINGS,No,0,0,0",
          "COMMENTS 1,Synthetic hours for tests",
          "COMMENTS 2,Radiation fields 14 15 16 differ",
          "DATA PERIODS,1,1,Data,Sunday, 1/ 1,12/31"};
}

// A whole file as lines: the header, then hours 1 to 24 of `days` days from `month`/
// `first_day` (within the month), each with its test_direct_normal.
inline std::vector<std::string> epw_lines(int month = 1, int first_day = 1, int days = 3) {
  std::vector<std::string> lines = epw_header();
  for (int day = first_day; day < first_day + days; ++day) {
    for (int hour = 1; hour <= 24; ++hour) {
      std::string value = std::to_string(test_direct_normal(day, hour));
      value.erase(value.find_last_not_of('0') + 1);  // "101.500000" -> "101.5"
      lines.push_back(epw_row(month, day, hour, value));
    }
  }
  return lines;
}

inline std::string joined(const std::vector<std::string>& lines, const std::string& eol = "\n") {
  std::string text;
  for (const std::string& line : lines) text += line + eol;
  return text;
}

}  // namespace shadowgen::test
