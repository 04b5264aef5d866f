// libFuzzer target for clipper/clip.h.
//
// Bytes become two polygon sets (fuzz_input.h). Inputs outside clip()'s contract
// (region_validity.h: loops simple, holes inside, loops meeting at points only) are
// skipped. For the rest, with S the subject and C the clip:
//   - every output loop of clip(S, C), clip(C, S) and clip(P, C ++ C) for each polygon P
//     of S has at least three vertices, no repeated consecutive vertex, no spike (a
//     vertex where the loop turns straight back), is simple, and runs counter-clockwise when outer,
//     clockwise when a hole;
//   - in grid mode, each output set is also well formed as a whole (holes inside,
//     polygons disjoint). There every exact crossing is a rational of denominator at most
//     512, so no predicate on the output of one clip lies within rounding distance of a
//     tie and the check is fair; off the grid, rounded crossings may graze each other;
//   - area(inside) + area(outside) = area(S), for clip(S, C) and for clip(C, S);
//     area of clip(S, C).inside = area of clip(C, S).inside; and the per-polygon clips
//     against the doubled (self-overlapping) clip list add up to clip(S, C).
//
// Areas are exact (exact_area.h), so the only slack is the one clip.h grants: each
// constructed vertex v lies within
//     delta_v = 4u·L + 17u·|v|,   u = 2^-53, L = the longest input edge,
// of its exact position (its crossing's rounding, within its hot pixel of 12u of its
// largest coordinate's magnitude, whose half-diagonal is below 17u·|v|), and moving it changes
// twice a loop's area by at most delta_v·(|e_prev| + |e_next| + delta_v), e_prev and
// e_next its two edges. The tolerance of an area identity is twice the sum of that over
// the output vertices involved (a factor 2 of safety). A crossing may round onto an
// input vertex and be merged with it,
// so every output vertex counts as constructed, except in grid mode: there an exact
// crossing that is not a grid point lies at least 1/512 from one, so an output vertex
// equal to an input vertex is exact, and with no other vertex the areas must agree
// exactly. In terms of the coordinates' magnitude M = max |coordinate|: L and every edge
// are at most 2√2·M long and |v| ≤ √2·M, so the tolerance on an area is below 200·V·u·M²
// for V output vertices (about 2.2e-14·V·M²). Off the grid a piece of the exact result may
// also be thin enough to vanish when its crossings round; its area is bounded the same
// way by its own constructed vertices, so each identity gets a floor of
// 2·K·delta_max·(2L + delta_max), K being the number of subject and clip edges that meet,
// a vertex within the snap distance of an edge counting as meeting it (resolution.h)
// (twice that for the list of clips, compared with a clip snapped separately), plus the
// area of every input loop thin enough to lie within its own rounding bound, which the
// snapping may close up whole.
//
// A broken invariant prints its name, the decoded input and the offending output, then
// traps. Environment: SHADOWGEN_FUZZ_SKIP=name,name skips checks (see `enabled`);
// SHADOWGEN_FUZZ_VERBOSE=1 prints every well-formed input with its areas.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <initializer_list>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_set>
#include <vector>

#include "clipper/clip.h"
#include "clipper/normalize.h"
#include "clipper/predicates.h"
#include "tests/fuzz/clip_fuzz_case.h"
#include "tests/fuzz/exact_area.h"
#include "tests/fuzz/fuzz_input.h"
#include "tests/fuzz/region_validity.h"
#include "tests/fuzz/resolution.h"

namespace shadowgen::fuzz {
namespace {

using clipper::ClipResult;
using clipper::Point2Hash;

const char* mode_name(CoordinateMode mode) {
  switch (mode) {
    case CoordinateMode::kGrid:
      return "grid";
    case CoordinateMode::kScaled:
      return "scaled";
    case CoordinateMode::kPerturbed:
      return "perturbed";
    case CoordinateMode::kRaw:
      return "raw";
  }
  return "?";
}

// Checks named in SHADOWGEN_FUZZ_SKIP (comma separated) are not run, so that fuzzing can
// go on past a bug already reported. The names, as a failure prints them: throws,
// loop-size, repeated-vertex, spike, simple-loop, orientation,
// well-formed-output, area-conservation, area-symmetry, multi-clip (everything about the
// overload with a list of clips). A name may carry a coordinate mode, as in
// raw:simple-loop, to skip the check in that mode only.
bool enabled(std::string_view check, CoordinateMode mode) {
  // Built with append: g++ 12 warns (falsely, -Wrestrict) on "," + std::string.
  static const std::string skip = [] {
    const char* value = std::getenv("SHADOWGEN_FUZZ_SKIP");
    std::string s(1, ',');
    s.append(value != nullptr ? value : "").push_back(',');
    return s;
  }();
  std::string key(1, ',');
  key.append(check).push_back(',');
  std::string moded(1, ',');
  moded.append(mode_name(mode)).push_back(':');
  moded.append(check).push_back(',');
  return skip.find(key) == std::string::npos && skip.find(moded) == std::string::npos;
}

void print_loop(const char* label, const Loop2& loop) {
  std::fprintf(stderr, "    %s {", label);
  for (std::size_t i = 0; i < loop.size(); ++i) {
    std::fprintf(stderr, "%s{%.17g, %.17g}", i ? ", " : "", loop[i].x, loop[i].y);
  }
  std::fprintf(stderr, "}\n");
}

void print_set(const char* name, const PolygonSet2& set) {
  std::fprintf(stderr, "  %s: %zu polygon(s)\n", name, set.size());
  for (const PolygonWithHoles2& polygon : set) {
    print_loop("outer", polygon.outer);
    for (const Loop2& hole : polygon.holes) print_loop(" hole", hole);
  }
}

class ClipCase {
 public:
  explicit ClipCase(const FuzzInput& input) : input_(input) {
    for (const PolygonSet2* set : {&input.subject, &input.clip}) {
      for (const PolygonWithHoles2& polygon : *set) {
        note_input_loop(polygon.outer);
        for (const Loop2& hole : polygon.holes) note_input_loop(hole);
      }
    }
    if (input.mode != CoordinateMode::kGrid) {
      // A vertex within the snap distance of an edge meets it at the clipper's resolution
      // (resolution.h), and counts as such a meeting.
      const double meeting_edges = static_cast<double>(
          count_meeting_edges() + count_sub_resolution_pairs(input.subject, input.clip));
      const double delta_max =
          4 * kUnitRoundoff * longest_edge_ + 17 * kUnitRoundoff * farthest_vertex_;
      vanished_piece_floor_ = 2 * meeting_edges * delta_max * (2 * longest_edge_ + delta_max);
      // An input loop whose area is within its own rounding bound is thinner than the
      // pixels of its vertices, and the snapping may close it up: all of it may vanish.
      vanished_piece_floor_ += 2 * thin_input_area_;
    }
  }

  void run() {
    const PolygonSet2& s = input_.subject;
    const PolygonSet2& c = input_.clip;
    const ClipResult forward = checked_clip("clip(S, C)", [&] { return clipper::clip(s, c); });
    const ClipResult backward = checked_clip("clip(C, S)", [&] { return clipper::clip(c, s); });

    const ExactSum area_s = twice_area(s);
    const ExactSum area_c = twice_area(c);
    const ExactSum in_sc = twice_area(forward.inside);
    const ExactSum out_sc = twice_area(forward.outside);
    const ExactSum in_cs = twice_area(backward.inside);
    const ExactSum out_cs = twice_area(backward.outside);
    const double tol_in_sc = tolerance(forward.inside);
    const double tol_out_sc = tolerance(forward.outside);
    const double tol_in_cs = tolerance(backward.inside);
    const double tol_out_cs = tolerance(backward.outside);

    if (enabled("area-conservation", input_.mode)) {
      expect_equal("area-conservation", "area(S & C) + area(S - C) = area(S)",
                   {{&in_sc, 1}, {&out_sc, 1}, {&area_s, -1}},
                   tol_in_sc + tol_out_sc + vanished_piece_floor_, forward);
      expect_equal("area-conservation", "area(C & S) + area(C - S) = area(C)",
                   {{&in_cs, 1}, {&out_cs, 1}, {&area_c, -1}},
                   tol_in_cs + tol_out_cs + vanished_piece_floor_, backward);
    }
    if (enabled("area-symmetry", input_.mode)) {
      expect_equal("area-symmetry", "area(S & C) = area(C & S)", {{&in_sc, 1}, {&in_cs, -1}},
                   tol_in_sc + tol_in_cs + vanished_piece_floor_, forward);
    }

    if (enabled("multi-clip", input_.mode)) {
      // One subject polygon against a list of clips that overlap each other (each clip
      // twice): the union is C, so the pieces must add up to clip(S, C).
      std::vector<PolygonWithHoles2> doubled(c.begin(), c.end());
      doubled.insert(doubled.end(), c.begin(), c.end());
      ExactSum in_each;
      ExactSum out_each;
      double tol_each = 0.0;
      for (const PolygonWithHoles2& polygon : s) {
        const ClipResult piece = checked_clip("clip(P, C ++ C)", [&] {
          return clipper::clip(polygon, std::span<const PolygonWithHoles2>(doubled));
        });
        in_each.add(twice_area(piece.inside), 1);
        out_each.add(twice_area(piece.outside), 1);
        tol_each += tolerance(piece.inside) + tolerance(piece.outside);
      }
      // Each side is snapped on its own (P with the clips, S with C), so a piece may
      // vanish on either: twice the floor.
      expect_equal("multi-clip", "sum over P of area(P & (C ++ C)) = area(S & C)",
                   {{&in_each, 1}, {&in_sc, -1}}, tol_each + tol_in_sc + 2 * vanished_piece_floor_,
                   forward);
      expect_equal("multi-clip", "sum over P of area(P - (C ++ C)) = area(S - C)",
                   {{&out_each, 1}, {&out_sc, -1}},
                   tol_each + tol_out_sc + 2 * vanished_piece_floor_, forward);
    }

    if (std::getenv("SHADOWGEN_FUZZ_VERBOSE") != nullptr) {
      std::fprintf(stderr, "clip_fuzzer: well formed, mode %s\n", mode_name(input_.mode));
      print_set("subject", s);
      print_set("clip", c);
      std::fprintf(stderr, "  area S %.17g, C %.17g, S&C %.17g, S-C %.17g, C-S %.17g\n",
                   0.5 * area_s.approx(), 0.5 * area_c.approx(), 0.5 * in_sc.approx(),
                   0.5 * out_sc.approx(), 0.5 * out_cs.approx());
    }
  }

 private:
  struct Term {
    const ExactSum* value;
    int sign;
  };

  static constexpr double kUnitRoundoff = std::numeric_limits<double>::epsilon() / 2;

  void note_input_loop(const Loop2& loop) {
    // Exactly: far from the origin a shoelace in doubles loses a thin loop's area entirely.
    const double area = 0.5 * std::fabs(twice_signed_area(loop).approx());
    if (area <= clipper::rounding_area_bound(loop)) thin_input_area_ += area;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      input_vertices_.insert(loop[i]);
      farthest_vertex_ = std::max(farthest_vertex_, std::hypot(loop[i].x, loop[i].y));
      const Point2& next = loop[(i + 1) % loop.size()];
      longest_edge_ = std::max(longest_edge_, std::hypot(next.x - loop[i].x, next.y - loop[i].y));
    }
  }

  // Pairs of a subject edge and a clip edge that share a point: at most the number of
  // crossings the exact result is built from.
  std::size_t count_meeting_edges() const {
    auto loops_of = [](const PolygonSet2& set) {
      std::vector<const Loop2*> loops;
      for (const PolygonWithHoles2& polygon : set) {
        loops.push_back(&polygon.outer);
        for (const Loop2& hole : polygon.holes) loops.push_back(&hole);
      }
      return loops;
    };
    std::size_t count = 0;
    for (const Loop2* a : loops_of(input_.subject)) {
      for (const Loop2* b : loops_of(input_.clip)) {
        for (std::size_t i = 0; i < a->size(); ++i) {
          for (std::size_t j = 0; j < b->size(); ++j) {
            if (segments_meet((*a)[i], (*a)[(i + 1) % a->size()], (*b)[j],
                              (*b)[(j + 1) % b->size()])) {
              ++count;
            }
          }
        }
      }
    }
    return count;
  }

  // Checks the outputs of one call. Everything that goes wrong in the overload with a list
  // of clips is filed under multi-clip, so that it can be skipped as one.
  template <class Clip>
  ClipResult checked_clip(const char* call, Clip&& clip_call) {
    call_ = call;
    ClipResult result;
    try {
      result = clip_call();
    } catch (const std::exception& e) {
      if (check("throws")) violation("throws", "exception", e.what(), nullptr);
    }
    expect_valid_output("inside", result.inside);
    expect_valid_output("outside", result.outside);
    return result;
  }

  bool check(std::string_view name) const {
    return multi_clip() ? true : enabled(name, input_.mode);
  }

  bool multi_clip() const { return std::string_view(call_) == "clip(P, C ++ C)"; }

  void expect_valid_output(const char* part, const PolygonSet2& set) {
    for (const PolygonWithHoles2& polygon : set) {
      expect_valid_loop(part, polygon.outer, true, set);
      for (const Loop2& hole : polygon.holes) expect_valid_loop(part, hole, false, set);
    }
    if (input_.mode == CoordinateMode::kGrid && check("well-formed-output") &&
        !is_well_formed(set)) {
      violation("well-formed-output", part,
                "the set is not well formed (holes inside, polygons disjoint)", &set);
    }
  }

  void expect_valid_loop(const char* part, const Loop2& loop, bool outer, const PolygonSet2& set) {
    const std::size_t n = loop.size();
    if (n < 3) {
      if (check("loop-size")) {
        violation("loop-size", part, "a loop has fewer than three vertices", &set);
      }
      return;
    }
    if (check("repeated-vertex")) {
      for (std::size_t i = 0; i < n; ++i) {
        if (loop[i] == loop[(i + 1) % n]) {
          violation("repeated-vertex", part, "a loop repeats a vertex consecutively", &set);
        }
      }
    }
    if (check("spike")) {
      for (std::size_t i = 0; i < n; ++i) {
        const Point2& a = loop[i];
        const Point2& b = loop[(i + 1) % n];
        const Point2& c = loop[(i + 2) % n];
        if (clipper::orient2d(a, b, c) == Orientation::kCollinear &&
            (a.x - b.x) * (c.x - b.x) + (a.y - b.y) * (c.y - b.y) >= 0.0) {
          violation("spike", part, "a loop turns straight back at a vertex", &set);
        }
      }
    }
    if (check("simple-loop") && !is_simple_loop(loop)) {
      violation("simple-loop", part, "a loop is not simple", &set);
    }
    if (check("orientation") && clipper::is_counter_clockwise(loop) != outer) {
      violation("orientation", part,
                outer ? "an outer loop is clockwise" : "a hole is counter-clockwise", &set);
    }
  }

  // Twice the area error clip.h allows for `set` (see the top of the file), doubled.
  double tolerance(const PolygonSet2& set) const {
    constexpr double u = kUnitRoundoff;
    double bound = 0.0;
    auto add_loop = [&](const Loop2& loop) {
      const std::size_t n = loop.size();
      for (std::size_t i = 0; i < n; ++i) {
        const Point2& v = loop[i];
        if (input_.mode == CoordinateMode::kGrid && input_vertices_.count(v) != 0) continue;
        const Point2& prev = loop[(i + n - 1) % n];
        const Point2& next = loop[(i + 1) % n];
        const double delta = 4 * u * longest_edge_ + 17 * u * std::hypot(v.x, v.y);
        bound += delta * (std::hypot(v.x - prev.x, v.y - prev.y) +
                          std::hypot(next.x - v.x, next.y - v.y) + delta);
      }
    };
    for (const PolygonWithHoles2& polygon : set) {
      add_loop(polygon.outer);
      for (const Loop2& hole : polygon.holes) add_loop(hole);
    }
    return 2 * bound;
  }

  void expect_equal(const char* check_name, const char* what, std::initializer_list<Term> terms,
                    double tolerance, const ClipResult& result) const {
    ExactSum difference;
    for (const Term& term : terms) difference.add(*term.value, term.sign);
    const bool holds =
        tolerance == 0.0 ? difference.sign() == 0 : std::fabs(difference.approx()) <= tolerance;
    if (holds) return;
    std::fprintf(stderr, "clip_fuzzer [%s]: %s: twice the areas differ by %.17g, tolerance %.17g\n",
                 check_name, what, difference.approx(), tolerance);
    print_input();
    print_set("inside", result.inside);
    print_set("outside", result.outside);
    __builtin_trap();
  }

  void print_input() const {
    std::fprintf(stderr, "  mode %s\n", mode_name(input_.mode));
    print_set("subject S", input_.subject);
    print_set("clip C", input_.clip);
  }

  [[noreturn]] void violation(const char* check_name, const char* part, const char* what,
                              const PolygonSet2* set) const {
    std::fprintf(stderr, "clip_fuzzer [%s]: %s, %s: %s\n", multi_clip() ? "multi-clip" : check_name,
                 call_, part, what);
    print_input();
    if (set != nullptr) print_set(part, *set);
    __builtin_trap();
  }

  const FuzzInput& input_;
  std::unordered_set<Point2, Point2Hash> input_vertices_;
  double longest_edge_ = 0.0;
  double farthest_vertex_ = 0.0;
  double vanished_piece_floor_ = 0.0;
  double thin_input_area_ = 0.0;  // of the loops within their own rounding bound
  const char* call_ = "";
};

}  // namespace

bool run_clip_case(std::span<const std::uint8_t> bytes) {
  const std::optional<FuzzInput> input = decode_fuzz_input(bytes);
  if (!input || !is_well_formed(input->subject) || !is_well_formed(input->clip)) return false;
  ClipCase(*input).run();
  return true;
}

}  // namespace shadowgen::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  shadowgen::fuzz::run_clip_case(std::span<const std::uint8_t>(data, size));
  return 0;
}
