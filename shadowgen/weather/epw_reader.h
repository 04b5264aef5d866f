#pragma once

// Reading an EnergyPlus weather file (EPW), as the EnergyPlus Auxiliary Programs
// documentation defines it ("EnergyPlus Weather File (EPW) Data Dictionary"): 8 header
// lines (LOCATION, DESIGN CONDITIONS, TYPICAL/EXTREME PERIODS, GROUND TEMPERATURES,
// HOLIDAYS/DAYLIGHT SAVINGS, COMMENTS 1, COMMENTS 2, DATA PERIODS), then one row of 35
// comma-separated fields per hour. Read here (docs/scene-format.md, "Weather file"):
// - LOCATION: city, state or province, country, source and WMO as text; latitude (north
//   positive, -90 to 90), longitude (east positive, -180 to 180), time zone (hours from
//   GMT, -12 to 14, as EnergyPlus's Site:Location allows) and elevation (m, -1000 to
//   9999.9) as the Site, with north_axis_deg 0;
// - DATA PERIODS: the records per hour, which must be 1 (hourly files only);
// - each row's month, day, hour (1 to 24), minute (0 to 60), the global horizontal
//   (field 14), direct normal (15) and diffuse horizontal (16) radiation in Wh/m2, each a
//   number, missing where 9999 or more or negative, and the albedo (33), a number from 0
//   to 1 or 999 or more for missing (fields counted from 1: year, month, day, hour,
//   minute, the data source flags, then the dry bulb temperature as field 7). The year
//   (field 1) must be a whole number and is otherwise not read; the other fields are not
//   read.
// The rows must run hour by hour, each the hour after the one before it (hour 1 of the
// next day after hour 24, February 29 present or not, January 1 after December 31), and
// no hour may come twice: a file holds at most a year.
// A UTF-8 byte order mark and CRLF (or CR) line endings are accepted; empty lines may end
// the file. Every problem is an InputError naming the file and the line.

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

#include "shadowgen/model/scene.h"

namespace shadowgen::weather {

// The most bytes an EPW file is read to. An EPW file has a known size: a UTF-8 byte order
// mark, 8 header lines and one row per hour of at most a leap year, 366 × 24 = 8,784 rows.
// A header line is given up to 64 KiB (its free text, COMMENTS 1 and 2, makes the longest;
// real ones hold under 2,000 bytes), a row up to 1 KiB (35 fields of numbers and one of
// data source flags; real rows hold under 250 bytes), line ends included: 9,519,107 bytes
// in all. A file larger than that is refused before it is read, and a stream (a FIFO,
// standard input) once that much has come, so a path that never ends (a pipe fed without
// end) is not read on.
inline constexpr std::size_t kLongestEpwHeaderLine = std::size_t{1} << 16;
inline constexpr std::size_t kLongestEpwRow = std::size_t{1} << 10;
inline constexpr std::size_t kLargestEpwFile =
    3 + 8 * kLongestEpwHeaderLine + std::size_t{366} * 24 * kLongestEpwRow;
static_assert(kLargestEpwFile == 9'519'107);

// The file at `path` ("-": standard input), read whole up to kLargestEpwFile bytes. Every
// error names the file: one it cannot read (shadowgen/json/document.h, read_text_file: a
// folder, a device, larger than kLargestEpwFile), one too large for the memory the
// process may use (kOutOfMemoryProblem), and parse_epw's.
Weather read_epw(const std::filesystem::path& path);

// The same from the file's text; `file` names it in messages and in Weather::file.
Weather parse_epw(std::string_view text, const std::string& file);

}  // namespace shadowgen::weather
