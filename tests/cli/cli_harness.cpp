#include "tests/cli/cli_harness.h"

#include <png.h>
#include <pty.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string_view>
#include <utility>

namespace shadowgen::test {

std::string quoted(const std::string& arg) {
  std::string q = "'";
  for (const char c : arg) {
    if (c == '\'') {
      q += "'\\''";
    } else {
      q += c;
    }
  }
  return q + "'";
}

int shell(const std::string& command) {
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void write_file(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

Outcome run_shadowgen(const std::vector<std::string>& args, const fs::path& run_dir,
                      const fs::path& standard_input) {
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on `" " + std::string`.
  std::string command = quoted(SHADOWGEN_EXECUTABLE);
  for (const std::string& arg : args) {
    command += ' ';
    command += quoted(arg);
  }
  command += " >";
  command += quoted((run_dir / "out").string());
  command += " 2>";
  command += quoted((run_dir / "err").string());
  command += " <";
  command += quoted(standard_input.string());
  Outcome result;
  result.code = shell(command);
  result.out = contents(run_dir / "out");
  result.err = contents(run_dir / "err");
  return result;
}

Outcome run_shadowgen_on_terminal(const std::vector<std::string>& args) {
  std::vector<std::string> argv_text = {SHADOWGEN_EXECUTABLE};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& arg : argv_text) argv.push_back(arg.data());
  argv.push_back(nullptr);

  int terminal = -1;
  const pid_t child = ::forkpty(&terminal, nullptr, nullptr, nullptr);
  if (child == 0) {
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  Outcome result;
  if (child < 0) return result;
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(terminal, buffer, sizeof buffer);
    if (n > 0) {
      result.out.append(buffer, static_cast<std::size_t>(n));
    } else if (n < 0 && errno == EINTR) {
      continue;
    } else {
      break;  // EIO once the child has closed its side
    }
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  ::close(terminal);
  result.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

fs::path fresh_test_folder(const std::string& prefix) {
  std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  std::replace(name.begin(), name.end(), '/', '-');
  const fs::path dir =
      fs::path(::testing::TempDir()) / (prefix + "-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "run");
  return dir;
}

std::vector<std::string> sorted_names(const fs::path& folder, const fs::path& left_out) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (entry.path() != left_out) names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> fields(1);
  bool in_quotes = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (in_quotes) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        in_quotes = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      in_quotes = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

std::vector<std::vector<std::string>> csv_rows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) rows.push_back(csv_fields(line));
  return rows;
}

std::vector<ReportRow> parse_report(const std::string& csv) {
  std::vector<ReportRow> rows;
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "face_id,light_id,area,lit_area,lit_fraction");
  while (std::getline(in, line)) {
    const std::vector<std::string> f = csv_fields(line);
    EXPECT_EQ(f.size(), 5u) << line;
    if (f.size() != 5) continue;
    rows.push_back({f[0], f[1], std::stod(f[2]), std::stod(f[3]), std::stod(f[4])});
  }
  return rows;
}

std::vector<std::vector<std::pair<double, double>>> svg_path_loops(const std::string& d) {
  std::vector<std::vector<std::pair<double, double>>> loops;
  double x = 0.0, y = 0.0;              // the current point
  double start_x = 0.0, start_y = 0.0;  // the subpath's first point
  char command = '\0';
  std::vector<double> numbers;  // those of the command being read
  const auto take = [&]() {     // the command's numbers read so far, if it has them all
    const bool pair = command != 'h' && command != 'H' && command != 'v' && command != 'V';
    if (numbers.size() < (pair ? 2u : 1u)) return;
    const bool relative = command >= 'a' && command <= 'z';
    switch (command) {
      case 'M':
      case 'm':
        x = (relative ? x : 0.0) + numbers[0];
        y = (relative ? y : 0.0) + numbers[1];
        start_x = x;
        start_y = y;
        loops.emplace_back();
        command = relative ? 'l' : 'L';  // the pairs after a move are lines
        break;
      case 'L':
      case 'l':
        x = (relative ? x : 0.0) + numbers[0];
        y = (relative ? y : 0.0) + numbers[1];
        break;
      case 'H':
      case 'h':
        x = (relative ? x : 0.0) + numbers[0];
        break;
      case 'V':
      case 'v':
        y = (relative ? y : 0.0) + numbers[0];
        break;
      default:
        ADD_FAILURE() << "a number after command '" << command << "'";
        numbers.clear();
        return;
    }
    numbers.clear();
    if (!loops.empty()) loops.back().emplace_back(x, y);
  };
  const char* p = d.data();
  const char* end = p + d.size();
  while (p < end) {
    if (*p == ' ' || *p == ',') {
      ++p;
      continue;
    }
    if (std::string_view("MmLlHhVvZz").find(*p) != std::string_view::npos) {
      if (!numbers.empty()) ADD_FAILURE() << "a command cut short before '" << *p << "'";
      numbers.clear();
      command = *p++;
      if (command == 'Z' || command == 'z') {
        x = start_x;
        y = start_y;
      }
      continue;
    }
    double v = 0.0;
    const auto [next, error] = std::from_chars(p, end, v);
    if (error != std::errc()) {
      ADD_FAILURE() << "not a number at: " << std::string(p, std::min<std::size_t>(20, end - p));
      return loops;
    }
    numbers.push_back(v);
    p = next;
    take();
  }
  // A closed loop does not repeat its first point.
  for (auto& loop : loops) {
    if (loop.size() > 1 && loop.back() == loop.front()) loop.pop_back();
  }
  return loops;
}

namespace {

// Twice the signed area of a loop, from its first point.
double twice_signed_area(const std::vector<std::pair<double, double>>& loop) {
  double twice = 0.0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const auto& [x0, y0] = loop[i];
    const auto& [x1, y1] = loop[(i + 1) % loop.size()];
    twice +=
        (x0 - loop[0].first) * (y1 - loop[0].second) - (x1 - loop[0].first) * (y0 - loop[0].second);
  }
  return twice;
}

}  // namespace

double svg_paths_area(const std::string& d) {
  double area = 0.0;
  for (const auto& loop : svg_path_loops(d)) area += 0.5 * twice_signed_area(loop);
  return area;
}

Png read_png(const fs::path& path) {
  Png result;
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, path.c_str())) return result;
  png.format = PNG_FORMAT_RGB;
  result.rgb.resize(PNG_IMAGE_SIZE(png));
  result.width = static_cast<int>(png.width);
  result.height = static_cast<int>(png.height);
  result.ok = png_image_finish_read(&png, nullptr, result.rgb.data(), 0, nullptr) != 0;
  return result;
}

double svg_path_area(const std::string& d) {
  const std::vector<std::vector<std::pair<double, double>>> loops = svg_path_loops(d);
  double area = 0.0;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    area += (l == 0 ? 0.5 : -0.5) * std::abs(twice_signed_area(loops[l]));
  }
  return area;
}

void ExpectWellFormedXml(const fs::path& file, const fs::path& scratch) {
  EXPECT_EQ(shell("xmllint --noout " + quoted(file.string()) + " 2>" + quoted(scratch.string())), 0)
      << file << ": " << contents(scratch);
}

}  // namespace shadowgen::test
