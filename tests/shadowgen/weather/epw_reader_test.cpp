// Tests of the EnergyPlus weather file reader (shadowgen/weather/epw_reader.h): every
// field it reads from a synthetic file, the line endings and markers real files carry,
// and every mistake named with the file, the line and the problem, word for word.

#include "shadowgen/weather/epw_reader.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>
#include <thread>
#include <vector>

#include "shadowgen/model/input_error.h"
#include "tests/shadowgen/weather/epw_text.h"
#include "tests/support/temp_folder.h"

namespace shadowgen::weather {
namespace {

using test::epw_lines;
using test::epw_row;
using test::joined;

constexpr const char* kFile = "test.epw";

Weather parse(const std::string& text) { return parse_epw(text, kFile); }

// The rows for hours 1 to 24 of one day with a constant direct normal radiation.
std::vector<std::string> day_rows(int month, int day) {
  std::vector<std::string> rows;
  for (int hour = 1; hour <= 24; ++hour) rows.push_back(epw_row(month, day, hour, "300"));
  return rows;
}

std::vector<std::string> plus(std::vector<std::string> lines,
                              const std::vector<std::string>& more) {
  lines.insert(lines.end(), more.begin(), more.end());
  return lines;
}

// ---- What is read -----------------------------------------------------------------------

TEST(EpwReader, ReadsTheLocationAsTheSite) {
  const Weather weather = parse(joined(epw_lines()));
  EXPECT_EQ(weather.file, kFile);
  EXPECT_EQ(weather.city, "London Gatwick");
  EXPECT_EQ(weather.state_province, "");
  EXPECT_EQ(weather.country, "GBR");
  EXPECT_EQ(weather.source, "IWEC Data");
  EXPECT_EQ(weather.wmo, "037760");
  EXPECT_EQ(weather.site.latitude_deg, 51.15);
  EXPECT_EQ(weather.site.longitude_deg, -0.18);
  EXPECT_EQ(weather.site.utc_offset_h, 0.0);
  EXPECT_EQ(weather.site.elevation_m, 62.0);
  EXPECT_EQ(weather.site.north_axis_deg, 0.0);
}

TEST(EpwReader, ReadsEveryHourWithItsDirectNormalRadiationFromField15) {
  const Weather weather = parse(joined(epw_lines(1, 1, 3)));
  ASSERT_EQ(weather.hours.size(), 72u);
  for (std::size_t i = 0; i < weather.hours.size(); ++i) {
    const WeatherHour& hour = weather.hours[i];
    const int day = 1 + static_cast<int>(i / 24);
    const int h = 1 + static_cast<int>(i % 24);
    EXPECT_EQ(hour.month, 1);
    EXPECT_EQ(hour.day, day);
    EXPECT_EQ(hour.hour, h);
    EXPECT_EQ(hour.minute, 0);
    EXPECT_EQ(hour.line, 9 + i);
    ASSERT_TRUE(hour.direct_normal_wh_m2.has_value());
    EXPECT_EQ(*hour.direct_normal_wh_m2, test::test_direct_normal(day, h));  // not 1111 or 2222
  }
}

TEST(EpwReader, KeepsTheMinuteAsGiven) {
  std::vector<std::string> lines = epw_lines(1, 1, 1);
  lines[8].replace(lines[8].find(",0,?9"), 3, ",60,");
  EXPECT_EQ(parse(joined(lines)).hours[0].minute, 60);
}

// EPW marks a missing radiation value 9999 (anything from 9999 up); EnergyPlus sets a
// negative one to 0. Both are kept as unknown, an error only where an instant needs them.
TEST(EpwReader, MissingAndNegativeRadiationAreUnknown) {
  std::vector<std::string> lines = epw_lines(1, 1, 1);
  lines[8] = epw_row(1, 1, 1, "9999");
  lines[9] = epw_row(1, 1, 2, "99999");
  lines[10] = epw_row(1, 1, 3, "-1");
  lines[11] = epw_row(1, 1, 4, "9998.9");
  lines[12] = epw_row(1, 1, 5, "0");
  const Weather weather = parse(joined(lines));
  EXPECT_FALSE(weather.hours[0].direct_normal_wh_m2.has_value());
  EXPECT_FALSE(weather.hours[1].direct_normal_wh_m2.has_value());
  EXPECT_FALSE(weather.hours[2].direct_normal_wh_m2.has_value());
  EXPECT_EQ(weather.hours[3].direct_normal_wh_m2, 9998.9);
  EXPECT_EQ(weather.hours[4].direct_normal_wh_m2, 0.0);
}

// Row `hour` of day 1 of January (direct normal 101.5) with field `field` (from 1)
// replaced by `value`.
std::string row_with_field(int field, const std::string& value, int hour = 1) {
  std::string row = epw_row(1, 1, hour, "101.5");
  std::size_t start = 0;
  for (int i = 1;; ++i) {
    const std::size_t comma = row.find(',', start);
    if (i == field) {
      row.replace(start, (comma == std::string::npos ? row.size() : comma) - start, value);
      return row;
    }
    start = comma + 1;
  }
}

// Fields 14 (global horizontal, 1111 in every test row), 16 (diffuse horizontal, 2222) and
// 33 (albedo, 0.000) beside field 15.
TEST(EpwReader, ReadsGlobalAndDiffuseHorizontalRadiationAndTheAlbedo) {
  std::vector<std::string> lines = epw_lines(1, 1, 1);
  lines[9] = row_with_field(33, "0.23", 2);
  lines[10] = row_with_field(33, "999", 3);
  lines[11] = row_with_field(16, "9999", 4);
  lines[12] = row_with_field(14, "-3", 5);
  const Weather weather = parse(joined(lines));
  const WeatherHour& first = weather.hours[0];
  EXPECT_EQ(first.global_horizontal_wh_m2, 1111.0);
  EXPECT_EQ(first.direct_normal_wh_m2, test::test_direct_normal(1, 1));  // field 15
  EXPECT_EQ(first.diffuse_horizontal_wh_m2, 2222.0);
  EXPECT_EQ(first.albedo, 0.0);
  EXPECT_EQ(weather.hours[1].albedo, 0.23);
  EXPECT_FALSE(weather.hours[2].albedo.has_value());  // 999: missing
  EXPECT_FALSE(weather.hours[3].diffuse_horizontal_wh_m2.has_value());
  EXPECT_EQ(weather.hours[3].global_horizontal_wh_m2, 1111.0);
  EXPECT_FALSE(weather.hours[4].global_horizontal_wh_m2.has_value());
  EXPECT_EQ(weather.hours[4].diffuse_horizontal_wh_m2, 2222.0);
}

void expect_same(const Weather& a, const Weather& b) {
  EXPECT_EQ(a.city, b.city);
  EXPECT_EQ(a.site.latitude_deg, b.site.latitude_deg);
  ASSERT_EQ(a.hours.size(), b.hours.size());
  for (std::size_t i = 0; i < a.hours.size(); ++i) {
    EXPECT_EQ(a.hours[i].hour, b.hours[i].hour);
    EXPECT_EQ(a.hours[i].line, b.hours[i].line);
    EXPECT_EQ(a.hours[i].direct_normal_wh_m2, b.hours[i].direct_normal_wh_m2);
  }
}

TEST(EpwReader, AcceptsCrlfAByteOrderMarkAndEmptyLinesAtTheEnd) {
  const Weather plain = parse(joined(epw_lines()));
  expect_same(parse(joined(epw_lines(), "\r\n")), plain);
  expect_same(parse("\xEF\xBB\xBF" + joined(epw_lines(), "\r\n")), plain);
  expect_same(parse(joined(epw_lines()) + "\n \r\n\n"), plain);
  std::string no_last_newline = joined(epw_lines());
  no_last_newline.pop_back();
  expect_same(parse(no_last_newline), plain);
}

TEST(EpwReader, AcceptsTheHolidaysHeaderAsTheDataDictionarySpellsIt) {
  std::vector<std::string> lines = epw_lines();
  lines[4] = "HOLIDAYS/DAYLIGHT SAVING,No,0,0,0";
  EXPECT_EQ(parse(joined(lines)).hours.size(), 72u);
}

TEST(EpwReader, FebruaryTheTwentyNinthMayBeThereOrNot) {
  EXPECT_EQ(parse(joined(plus(epw_lines(2, 28, 1), day_rows(3, 1)))).hours.size(), 48u);
  const Weather leap = parse(joined(plus(epw_lines(2, 28, 2), day_rows(3, 1))));
  ASSERT_EQ(leap.hours.size(), 72u);
  EXPECT_EQ(leap.hours[24].day, 29);
}

TEST(EpwReader, ARunOfHoursMayTurnTheYear) {
  const Weather weather = parse(joined(plus(epw_lines(12, 31, 1), day_rows(1, 1))));
  ASSERT_EQ(weather.hours.size(), 48u);
  EXPECT_EQ(weather.hours[24].month, 1);
  EXPECT_EQ(weather.hours[24].day, 1);
}

TEST(EpwReader, ReadsAFileAndNamesItByItsPath) {
  const test::TempFolder folder("shadowgen-epw-reader");
  const std::filesystem::path path = folder.write("gatwick.epw", joined(epw_lines()));
  const Weather weather = read_epw(path);
  EXPECT_EQ(weather.file, path.string());
  EXPECT_EQ(weather.hours.size(), 72u);
  try {
    (void)read_epw(folder.path() / "absent.epw");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), (folder.path() / "absent.epw").string() + ": no such file");
  }
}

// The message of read_epw's error on `path`; "no error" where it reads.
std::string read_error(const std::filesystem::path& path) {
  try {
    (void)read_epw(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// An EPW file has a known size (kLargestEpwFile): one larger is refused before it is
// read, one of that size exactly (empty lines may end the file) is read.
TEST(EpwReader, AFileLargerThanAnyWeatherFileIsRefusedUnread) {
  const test::TempFolder folder("shadowgen-epw-reader");
  std::string text = joined(epw_lines());
  text.resize(kLargestEpwFile, '\n');
  const std::filesystem::path at_bound = folder.write("at_bound.epw", text);
  EXPECT_EQ(read_epw(at_bound).hours.size(), 72u);
  text += '\n';
  const std::filesystem::path beyond = folder.write("beyond.epw", text);
  EXPECT_EQ(read_error(beyond),
            beyond.string() + ": is larger than a weather file can be (more than 9519107 bytes)");
}

// A pipe fed without end is read no further than an EPW file can be long: the reader
// stops there, naming it. The writer's end sees the pipe closed.
TEST(EpwReader, APipeWithoutEndIsReadOnlyUpToTheBound) {
  const test::TempFolder folder("shadowgen-epw-reader");
  const std::filesystem::path fifo = folder.path() / "endless.epw";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  std::atomic<std::size_t> written{0};
  struct sigaction ignore {};
  struct sigaction before {};
  ignore.sa_handler = SIG_IGN;
  ASSERT_EQ(sigaction(SIGPIPE, &ignore, &before), 0);
  std::thread writer([&] {
    const int fd = open(fifo.c_str(), O_WRONLY);
    const std::string lines(std::size_t{1} << 16, '\n');
    while (fd >= 0 && write(fd, lines.data(), lines.size()) > 0) written += lines.size();
    if (fd >= 0) close(fd);
  });
  EXPECT_EQ(read_error(fifo),
            fifo.string() + ": is larger than a weather file can be (more than 9519107 bytes)");
  writer.join();
  sigaction(SIGPIPE, &before, nullptr);
  EXPECT_GT(written.load(), kLargestEpwFile);
  EXPECT_LT(written.load(), 2 * kLargestEpwFile);  // the pipe's buffer at most beyond it
}

TEST(EpwReader, AFolderOrADeviceIsNoWeatherFile) {
  const test::TempFolder folder("shadowgen-epw-reader");
  EXPECT_EQ(read_error(folder.path()), folder.path().string() + ": is a folder, not a file");
  for (const char* device : {"/dev/zero", "/dev/urandom"}) {
    EXPECT_EQ(read_error(device),
              std::string(device) + ": is not a regular file (a character device)");
  }
}

#if !defined(__SANITIZE_ADDRESS__)
// Reads `path` with 1 MiB of address space left to the process, printing the message of
// the InputError it throws and exiting 1; exits 0 if it reads, 2 if the limit cannot be set.
// (Not under AddressSanitizer, which reserves far more address space than the limit.)
[[noreturn]] void read_with_1_mib_left(const std::filesystem::path& path) {
  std::ifstream statm("/proc/self/statm");  // the address space in use, in pages
  std::size_t pages = 0;
  statm >> pages;
  const rlim_t limit =
      static_cast<rlim_t>(pages) * static_cast<rlim_t>(getpagesize()) + (rlim_t{1} << 20);
  rlimit tight{};
  tight.rlim_cur = limit;
  tight.rlim_max = limit;
  if (setrlimit(RLIMIT_AS, &tight) != 0) std::_Exit(2);
  try {
    (void)read_epw(path);
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    std::_Exit(1);
  }
  std::_Exit(0);
}
#endif

// Under a limit on the address space that leaves no room for the file's text, the error
// names the weather file, not whatever input the caller read before it.
TEST(EpwReaderDeathTest, RunningOutOfMemoryNamesTheWeatherFile) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer reserves far more address space than the limit";
#else
  const test::TempFolder folder("shadowgen-epw-reader");
  std::string text = joined(epw_lines());
  text.resize(kLargestEpwFile, '\n');
  const std::filesystem::path path = folder.write("large.epw", text);
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(read_with_1_mib_left(path), ::testing::ExitedWithCode(1),
              "large\\.epw: out of memory: this input needs more memory than the process may use");
#endif
}

// ---- Errors -----------------------------------------------------------------------------

struct EpwError {
  const char* name;
  std::string text;
  std::string message;  // after "test.epw: "
};

std::ostream& operator<<(std::ostream& out, const EpwError& error) { return out << error.name; }

// The synthetic file (3 days of January: rows on lines 9 to 80, hour h of day 1 on line
// 8 + h) with line `index` (from 0) replaced, removed (nullptr) or preceded by `insert`.
std::string with_line(std::size_t index, const char* replacement) {
  std::vector<std::string> lines = epw_lines();
  if (replacement == nullptr) {
    lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(index));
  } else {
    lines[index] = replacement;
  }
  return joined(lines);
}

std::string with_inserted(std::size_t index, const std::string& line) {
  std::vector<std::string> lines = epw_lines();
  lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(index), line);
  return joined(lines);
}

std::string row_without_last_field() {
  std::string row = epw_row(1, 1, 1, "101.5");
  return row.erase(row.rfind(','));
}

std::string with_first_row(const std::string& row) { return with_line(8, row.c_str()); }

std::string header_only(std::size_t lines) {
  std::vector<std::string> all = epw_lines();
  all.resize(lines);
  return joined(all);
}

const std::string kHeaderNote =
    "an EPW weather file begins with 8 header lines (LOCATION to DATA PERIODS)";

const std::vector<EpwError> kErrors = {
    {"Empty", "", "empty file; " + kHeaderNote},
    {"ThreeLines", header_only(3), "the file ends after 3 lines; " + kHeaderNote},
    {"OneLine", header_only(1), "the file ends after 1 line; " + kHeaderNote},
    {"NoRows", header_only(8), "no hourly rows after the 8 header lines"},
    {"NotLocationFirst", with_line(0, "COMMENTS 1,x"),
     "line 1: expected the LOCATION header line, found 'COMMENTS 1'"},
    {"HeaderOutOfOrder", with_line(2, "GROUND TEMPERATURES,0"),
     "line 3: expected the TYPICAL/EXTREME PERIODS header line, found 'GROUND TEMPERATURES'"},
    {"HeaderMissing", with_line(5, nullptr),
     "line 6: expected the COMMENTS 1 header line, found 'COMMENTS 2'"},
    {"ShortLocation", with_line(0, "LOCATION,London Gatwick,,GBR,IWEC Data,037760,51.15"),
     "line 1: the LOCATION line has 7 fields; it needs 10 (LOCATION, city, state or province, "
     "country, source, WMO, latitude, longitude, time zone, elevation)"},
    {"LatitudeOutOfRange", with_line(0, "LOCATION,X,,GBR,IWEC,037760,95,-0.18,0.0,62.0"),
     "line 1: latitude 95 must lie between -90 and 90 degrees"},
    {"LongitudeOutOfRange", with_line(0, "LOCATION,X,,GBR,IWEC,037760,51.15,-180.5,0.0,62.0"),
     "line 1: longitude -180.5 must lie between -180 and 180 degrees"},
    {"TimeZoneTooFarEast", with_line(0, "LOCATION,X,,GBR,IWEC,037760,51.15,-0.18,14.5,62.0"),
     "line 1: time zone 14.5 must lie between -12 and 14 hours"},
    {"TimeZoneTooFarWest", with_line(0, "LOCATION,X,,GBR,IWEC,037760,51.15,-0.18,-13,62.0"),
     "line 1: time zone -13 must lie between -12 and 14 hours"},
    {"ElevationOutOfRange", with_line(0, "LOCATION,X,,GBR,IWEC,037760,51.15,-0.18,0,-2000"),
     "line 1: elevation -2000 must lie between -1000 and 9999.9 m"},
    {"LatitudeNotANumber", with_line(0, "LOCATION,X,,GBR,IWEC,037760,N51,-0.18,0.0,62.0"),
     "line 1: latitude 'N51' is not a number"},
    {"LatitudeNaN", with_line(0, "LOCATION,X,,GBR,IWEC,037760,nan,-0.18,0.0,62.0"),
     "line 1: latitude 'nan' is not a number"},
    {"ElevationEmpty", with_line(0, "LOCATION,X,,GBR,IWEC,037760,51.15,-0.18,0.0, "),
     "line 1: elevation is empty; it must be a number"},
    {"SubHourly", with_line(7, "DATA PERIODS,1,4,Data,Sunday, 1/ 1,12/31"),
     "line 8: 4 records per hour; only hourly weather files (1 record per hour) are read"},
    {"ShortDataPeriods", with_line(7, "DATA PERIODS,1"),
     "line 8: the DATA PERIODS line has 2 fields; it needs at least 3 (DATA PERIODS, number of "
     "data periods, records per hour)"},
    {"RecordsPerHourNotWhole", with_line(7, "DATA PERIODS,1,one,Data,Sunday, 1/ 1,12/31"),
     "line 8: records per hour 'one' is not a whole number"},
    {"ShortRow", with_first_row(row_without_last_field()),
     "line 9: 34 fields; an hourly row has 35"},
    {"LongRow", with_first_row(epw_row(1, 1, 1, "101.5") + ",0"),
     "line 9: 36 fields; an hourly row has 35"},
    {"YearNotWhole", with_first_row(row_with_field(1, "1999.5")),
     "line 9: year '1999.5' is not a whole number"},
    {"MonthOutOfRange", with_first_row(row_with_field(2, "13")),
     "line 9: month 13 must lie between 1 and 12"},
    {"DayOutOfRange", with_first_row(row_with_field(3, "0")),
     "line 9: day 0 must lie between 1 and 31"},
    {"NotADate", with_first_row(epw_row(2, 30, 1, "0")), "line 9: month 2 has no day 30"},
    {"HourZero", with_first_row(row_with_field(4, "0")),
     "line 9: hour 0 must lie between 1 and 24"},
    {"HourTwentyFive", with_first_row(row_with_field(4, "25")),
     "line 9: hour 25 must lie between 1 and 24"},
    {"HourNotWhole", with_first_row(row_with_field(4, "1.5")),
     "line 9: hour '1.5' is not a whole number"},
    {"MinuteOutOfRange", with_first_row(row_with_field(5, "61")),
     "line 9: minute 61 must lie between 0 and 60"},
    {"DirectNormalNotANumber", with_first_row(row_with_field(15, "abc")),
     "line 9: direct normal radiation (field 15) 'abc' is not a number"},
    {"DirectNormalEmpty", with_first_row(row_with_field(15, "")),
     "line 9: direct normal radiation (field 15) is empty; it must be a number"},
    {"GlobalHorizontalNotANumber", with_first_row(row_with_field(14, "x1")),
     "line 9: global horizontal radiation (field 14) 'x1' is not a number"},
    {"DiffuseHorizontalNotANumber", with_first_row(row_with_field(16, "2;5")),
     "line 9: diffuse horizontal radiation (field 16) '2;5' is not a number"},
    {"DiffuseHorizontalEmpty", with_first_row(row_with_field(16, "")),
     "line 9: diffuse horizontal radiation (field 16) is empty; it must be a number"},
    {"AlbedoNotANumber", with_first_row(row_with_field(33, "snow")),
     "line 9: albedo (field 33) 'snow' is not a number"},
    {"AlbedoAboveOne", with_first_row(row_with_field(33, "1.5")),
     "line 9: albedo (field 33) 1.5 must lie between 0 and 1 (999: missing)"},
    {"AlbedoNegative", with_first_row(row_with_field(33, "-0.1")),
     "line 9: albedo (field 33) -0.1 must lie between 0 and 1 (999: missing)"},
    {"MissingHour", with_line(20, nullptr),
     "line 21: expected the hour after month 1 day 1 hour 12 (line 20), found month 1 day 1 "
     "hour 14; the rows must run hour by hour"},
    {"MissingDay", with_line(32, epw_row(1, 3, 1, "0").c_str()),
     "line 33: expected the hour after month 1 day 1 hour 24 (line 32), found month 1 day 3 "
     "hour 1; the rows must run hour by hour"},
    {"DuplicateHour", with_inserted(20, epw_row(1, 1, 12, "0")),
     "line 21: month 1 day 1 hour 12 again (first on line 20); a weather file holds a year at "
     "most, and its years are not read"},
    {"EmptyLineAmongRows", with_inserted(20, ""), "line 21: an empty line among the hourly rows"},
};

class EpwErrorTest : public ::testing::TestWithParam<EpwError> {};

TEST_P(EpwErrorTest, NamesTheFileTheLineAndTheProblem) {
  const EpwError& error = GetParam();
  try {
    (void)parse(error.text);
    FAIL() << "no error for " << error.name;
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), std::string(kFile) + ": " + error.message);
    EXPECT_EQ(e.file(), kFile);
  }
}

INSTANTIATE_TEST_SUITE_P(All, EpwErrorTest, ::testing::ValuesIn(kErrors),
                         [](const auto& test) { return std::string(test.param.name); });

}  // namespace
}  // namespace shadowgen::weather
