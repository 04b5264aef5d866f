#pragma once

// The harness of the end-to-end tests of the `shadowgen` command: each test gets a fresh
// folder, runs the built executable (SHADOWGEN_EXECUTABLE) there through the shell with
// stdout and stderr caught in files, and reads back what it printed and wrote, including
// the CSV of `shadowgen report`.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "tests/support/relative_error.h"

namespace shadowgen::test {

namespace fs = std::filesystem;

// What one run of the command gave: its exit code (-1 when it did not exit normally),
// and all it printed on stdout and on stderr.
struct Outcome {
  int code = -1;
  std::string out;
  std::string err;
};

// `arg` as one word for sh, in single quotes.
std::string quoted(const std::string& arg);

// Runs `command` with sh; its exit code, -1 when it did not exit normally.
int shell(const std::string& command);

// The whole file, byte for byte; "" when it cannot be read.
std::string contents(const fs::path& path);

// Writes `text` to `path`, byte for byte.
void write_file(const fs::path& path, const std::string& text);

// Runs shadowgen with `args` and `standard_input` as its stdin (by default none: /dev/null);
// stdout and stderr go through the files out and err in `run_dir`, so that they stay apart
// from the files the tests look at.
Outcome run_shadowgen(const std::vector<std::string>& args, const fs::path& run_dir,
                      const fs::path& standard_input = "/dev/null");

// Runs shadowgen with a pseudo-terminal as its stdin, stdout and stderr, as when a person
// runs it; `out` gets all it printed, `err` stays empty.
Outcome run_shadowgen_on_terminal(const std::vector<std::string>& args);

// A new, empty folder TempDir()/<prefix>-<test name>-<pid> for the running test, holding an
// empty run/ for run_shadowgen's output ('/' of a parameterised test's name becomes '-').
fs::path fresh_test_folder(const std::string& prefix);

// The names of the entries of `folder` but `left_out`, sorted.
std::vector<std::string> sorted_names(const fs::path& folder, const fs::path& left_out);

// One CSV record split into fields, with RFC 4180 quoting undone.
std::vector<std::string> csv_fields(const std::string& line);

// Every line of `text` split into fields as csv_fields splits one (no field holds a line
// break).
std::vector<std::vector<std::string>> csv_rows(const std::string& text);

// A row of `shadowgen report`'s CSV.
struct ReportRow {
  std::string face, light;
  double area = 0.0, lit_area = 0.0, lit_fraction = 0.0;
};

// The rows of the report's CSV; a wrong header or a row without five fields fails the test
// (the row is skipped).
std::vector<ReportRow> parse_report(const std::string& csv);

// Area of the region of an SVG <path>'s data `d` ("M x,y L x,y ... Z M ...", or relative:
// "M x y h dx v dy l dx dy z m ..."): its first subpath is the outer loop, the others
// holes. A number it cannot read fails the test.
double svg_path_area(const std::string& d);

// The subpaths of an SVG <path>'s data `d` (polygons: M, L, H, V, Z and their relative
// forms), each a loop of (x, y); a number it cannot read fails the test.
std::vector<std::vector<std::pair<double, double>>> svg_path_loops(const std::string& d);

// Area of a path of several polygons with holes (a picture's path per colour): the sum of
// its subpaths' signed areas, outer loops positive in pixel coordinates (y down) and
// holes negative, as shadowgen writes them.
double svg_paths_area(const std::string& d);

// A PNG file read back with libpng as 8-bit RGB; `ok` false where it cannot be read.
struct Png {
  bool ok = false;
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
};
Png read_png(const fs::path& path);

// xmllint finds `file` well-formed; its complaints go through `scratch` into the message.
void ExpectWellFormedXml(const fs::path& file, const fs::path& scratch);

// A test (or, with Base = ::testing::TestWithParam<T>, a parameterised one) with its own
// folder dir_ from fresh_test_folder(prefix), removed after a test that passed and kept
// for a look after one that failed.
template <class Base = ::testing::Test>
class CliFolderTest : public Base {
 protected:
  explicit CliFolderTest(std::string prefix) : prefix_(std::move(prefix)) {}

  void SetUp() override { dir_ = fresh_test_folder(prefix_); }
  void TearDown() override {
    if (!::testing::Test::HasFailure()) fs::remove_all(dir_);
  }

  // Writes `text` to dir_/name; returns that path.
  fs::path write(const std::string& name, const std::string& text) const {
    const fs::path path = dir_ / name;
    write_file(path, text);
    return path;
  }

  // Runs shadowgen with `args`, its stdout and stderr caught in dir_/run.
  Outcome run(const std::vector<std::string>& args) const {
    return run_shadowgen(args, dir_ / "run");
  }

  // The bytes of what `command` writes to `file` (standard output where `file` is empty),
  // from `database`: the file's name in the command is the placeholder "DB". Expects the
  // command to succeed.
  std::string output(std::vector<std::string> command, const fs::path& database,
                     const fs::path& file = {}) const {
    for (std::string& arg : command) {
      if (arg == "DB") arg = database.string();
    }
    fs::remove(file.empty() ? dir_ / "none" : file);
    const Outcome o = run(command);
    EXPECT_EQ(o.code, 0) << o.err;
    return file.empty() ? o.out : contents(file);
  }

  // The files in `folder` (default: the test's folder, without its run/ folder): what the
  // command left behind.
  std::vector<std::string> files(const fs::path& folder = {}) const {
    return sorted_names(folder.empty() ? dir_ : folder, dir_ / "run");
  }

  fs::path dir_;

 private:
  std::string prefix_;
};

}  // namespace shadowgen::test
