#include "detail/path_data.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "shadowgen/model/number_text.h"

namespace shadowgen::view::detail {
namespace {

// A vertex in whole steps of the grid.
struct Step {
  std::int64_t x = 0, y = 0;
  bool operator==(const Step&) const = default;
};

constexpr double kLargestStep = 1073741824.0;  // 2^30
// Steps are written as pixels with three decimals.
static_assert(kPathGrid == 1000.0);
constexpr std::uint64_t kStepsPerPixel = 1000;

// Whether b lies on the line through a and c (or equals either): exact, as every
// difference is below 2^31 and each product below 2^62.
bool straight(const Step& a, const Step& b, const Step& c) {
  return (b.x - a.x) * (c.y - a.y) == (b.y - a.y) * (c.x - a.x);
}

// The loop on the grid, without the vertices that add no area (repeated, or on a straight
// line through their neighbours, around the loop's start too); empty where fewer than
// three are left.
std::vector<Step> loop_on_grid(const clipper::Loop2& loop) {
  std::vector<Step> out;
  for (const clipper::Point2& p : loop) {
    const Step s{std::llround(p.x * kPathGrid), std::llround(p.y * kPathGrid)};
    out.push_back(s);
    while (out.size() >= 3 && straight(out[out.size() - 3], out[out.size() - 2], out.back())) {
      out.erase(out.end() - 2);
    }
    if (out.size() == 2 && out[0] == out[1]) out.pop_back();
  }
  // Around the start: the last vertex between its neighbours, then the first.
  std::size_t first = 0;
  for (bool changed = true; changed && out.size() - first >= 3;) {
    changed = false;
    if (straight(out[out.size() - 2], out.back(), out[first])) {
      out.pop_back();
      changed = true;
    } else if (straight(out.back(), out[first], out[first + 1])) {
      ++first;
      changed = true;
    }
  }
  if (out.size() - first < 3) return {};
  return std::vector<Step>(out.begin() + static_cast<std::ptrdiff_t>(first), out.end());
}

// `steps` as pixels, with no more digits than it needs and no zero before the point
// ("12.5", ".25", "-.125", "3").
void append_steps(std::string& out, std::int64_t steps) {
  if (steps < 0) out += '-';
  const std::uint64_t magnitude = static_cast<std::uint64_t>(std::llabs(steps));
  const std::uint64_t whole = magnitude / kStepsPerPixel, fraction = magnitude % kStepsPerPixel;
  if (whole != 0 || fraction == 0) out += std::to_string(whole);
  if (fraction == 0) return;
  std::string digits = std::to_string(fraction + kStepsPerPixel).substr(1);  // three digits
  while (digits.back() == '0') digits.pop_back();
  out += '.';
  out += digits;
}

// Path data in whole steps: the command letter where it changes, the numbers apart where
// they would run together (not before a minus sign).
class GridWriter {
 public:
  explicit GridWriter(std::string& out) : out_(out) {}

  void loop(const std::vector<Step>& loop) {
    if (first_) {
      command('M');
      number(loop[0].x);
      number(loop[0].y);
      first_ = false;
    } else {
      command('m');
      number(loop[0].x - start_.x);
      number(loop[0].y - start_.y);
    }
    start_ = loop[0];
    for (std::size_t i = 1; i < loop.size(); ++i) {
      const std::int64_t dx = loop[i].x - loop[i - 1].x, dy = loop[i].y - loop[i - 1].y;
      if (dy == 0) {
        command('h');
        number(dx);
      } else if (dx == 0) {
        command('v');
        number(dy);
      } else {
        command('l');
        number(dx);
        number(dy);
      }
    }
    command('z');
  }

 private:
  void command(char c) {
    if (c == last_ && c != 'z') return;
    out_ += c;
    last_ = c;
    separate_ = false;
  }

  void number(std::int64_t steps) {
    if (separate_ && steps >= 0) out_ += ' ';
    append_steps(out_, steps);
    separate_ = true;
  }

  std::string& out_;
  bool first_ = true;
  Step start_;
  char last_ = '\0';
  bool separate_ = false;
};

bool fits_grid(std::span<const clipper::PolygonWithHoles2> shapes) {
  const auto fits = [](const clipper::Loop2& loop) {
    for (const clipper::Point2& p : loop) {
      if (!(std::abs(p.x * kPathGrid) < kLargestStep && std::abs(p.y * kPathGrid) < kLargestStep)) {
        return false;
      }
    }
    return true;
  };
  for (const clipper::PolygonWithHoles2& shape : shapes) {
    if (!fits(shape.outer)) return false;
    for (const clipper::Loop2& hole : shape.holes) {
      if (!fits(hole)) return false;
    }
  }
  return true;
}

void append_exact_loop(std::string& out, const clipper::Loop2& loop) {
  for (std::size_t i = 0; i < loop.size(); ++i) {
    out += i == 0 ? (out.empty() || out.back() == '"' ? "M" : " M") : (i == 1 ? " L" : " ");
    append_shortest(out, loop[i].x);
    out += ',';
    append_shortest(out, loop[i].y);
  }
  out += " Z";
}

}  // namespace

void append_exact_path_data(std::string& out, std::span<const clipper::PolygonWithHoles2> shapes) {
  for (const clipper::PolygonWithHoles2& shape : shapes) {
    append_exact_loop(out, shape.outer);
    for (const clipper::Loop2& hole : shape.holes) append_exact_loop(out, hole);
  }
}

void append_grid_path_data(std::string& out, std::span<const clipper::PolygonWithHoles2> shapes) {
  if (!fits_grid(shapes)) {
    append_exact_path_data(out, shapes);
    return;
  }
  GridWriter writer(out);
  const auto write = [&](const clipper::Loop2& loop) {
    const std::vector<Step> steps = loop_on_grid(loop);
    if (!steps.empty()) writer.loop(steps);
  };
  for (const clipper::PolygonWithHoles2& shape : shapes) {
    write(shape.outer);
    for (const clipper::Loop2& hole : shape.holes) write(hole);
  }
}

}  // namespace shadowgen::view::detail
