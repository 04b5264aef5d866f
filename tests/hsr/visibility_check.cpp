#include "tests/hsr/visibility_check.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <iostream>
#include <limits>
#include <numeric>
#include <random>
#include <sstream>

#include "tests/hsr/ray_oracle.h"
#include "tests/support/cgal_oracle.h"
#include "tests/support/expect.h"
#include "tests/support/svg.h"

namespace shadowgen::test {
namespace {

using clipper::Loop2;
using clipper::Point2;
using clipper::PolygonSet2;
using clipper::PolygonWithHoles2;

constexpr std::size_t kReportedFailures = 8;

struct Box {
  double xmin = std::numeric_limits<double>::infinity();
  double ymin = std::numeric_limits<double>::infinity();
  double xmax = -std::numeric_limits<double>::infinity();
  double ymax = -std::numeric_limits<double>::infinity();

  void add(const Point2& p) {
    xmin = std::min(xmin, p.x);
    ymin = std::min(ymin, p.y);
    xmax = std::max(xmax, p.x);
    ymax = std::max(ymax, p.y);
  }
  void add(const PolygonWithHoles2& polygon) {
    for (const Point2& p : polygon.outer) add(p);
  }
  bool empty() const { return !(xmin <= xmax && ymin <= ymax); }
  double diagonal() const { return std::hypot(xmax - xmin, ymax - ymin); }
  bool contains(const Point2& p) const {
    return xmin <= p.x && p.x <= xmax && ymin <= p.y && p.y <= ymax;
  }
};

double ulp(double x) {
  x = std::fabs(x);
  return std::nextafter(x, std::numeric_limits<double>::infinity()) - x;
}

double segment_distance(const Point2& p, const Point2& a, const Point2& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double length2 = dx * dx + dy * dy;
  double t = length2 > 0.0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / length2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

// Crossing rule over the outer loop and the holes; trusted away from the boundary only.
bool covers(const PolygonWithHoles2& polygon, const Point2& p) {
  bool inside = false;
  auto walk = [&](const Loop2& loop) {
    const std::size_t n = loop.size();
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
      const Point2& a = loop[i];
      const Point2& b = loop[j];
      if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) {
        inside = !inside;
      }
    }
  };
  walk(polygon.outer);
  for (const Loop2& hole : polygon.holes) walk(hole);
  return inside;
}

// A uniform grid over the sampled box, for the two point queries of every sample.
class Grid {
 public:
  Grid(const Box& box, std::size_t items) : box_(box) {
    n_ = static_cast<int>(std::clamp(std::sqrt(static_cast<double>(items)), 8.0, 256.0));
    cells_.resize(static_cast<std::size_t>(n_) * static_cast<std::size_t>(n_));
    sx_ = (box.xmax - box.xmin) / n_;
    sy_ = (box.ymax - box.ymin) / n_;
  }
  int column(double x) const { return index(x, box_.xmin, sx_); }
  int row(double y) const { return index(y, box_.ymin, sy_); }
  int size() const { return n_; }
  // Row r covers y in [row_low(r), row_low(r + 1)); the outer rows reach to infinity.
  double row_low(int r) const {
    if (r <= 0) return -std::numeric_limits<double>::infinity();
    if (r >= n_) return std::numeric_limits<double>::infinity();
    return box_.ymin + r * sy_;
  }
  std::vector<std::uint32_t>& cell(int c, int r) {
    return cells_[static_cast<std::size_t>(r) * static_cast<std::size_t>(n_) +
                  static_cast<std::size_t>(c)];
  }
  const std::vector<std::uint32_t>& cell(const Point2& p) const {
    return cells_[static_cast<std::size_t>(row(p.y)) * static_cast<std::size_t>(n_) +
                  static_cast<std::size_t>(column(p.x))];
  }

 private:
  int index(double v, double low, double step) const {
    if (!(step > 0.0)) return 0;
    const double i = std::floor((v - low) / step);
    if (!(i >= 0.0)) return 0;
    if (i >= n_ - 1) return n_ - 1;
    return static_cast<int>(i);
  }

  Box box_;
  int n_ = 8;
  double sx_ = 1.0, sy_ = 1.0;
  std::vector<std::vector<std::uint32_t>> cells_;
};

// Is a point within `band` of any of the segments? Each segment is entered, row by row,
// into the cells its band-wide neighbourhood meets.
class EdgeIndex {
 public:
  EdgeIndex(const Box& box, std::vector<std::pair<Point2, Point2>> segments, double band)
      : grid_(box, segments.size()), segments_(std::move(segments)), band_(band) {
    for (std::size_t s = 0; s < segments_.size(); ++s) {
      const auto& [a, b] = segments_[s];
      const int r0 = grid_.row(std::min(a.y, b.y) - band);
      const int r1 = grid_.row(std::max(a.y, b.y) + band);
      for (int r = r0; r <= r1; ++r) {
        double x0 = std::min(a.x, b.x), x1 = std::max(a.x, b.x);
        if (a.y != b.y) {
          // The segment's x over the row's strip, grown by the band in y.
          double t0 = (grid_.row_low(r) - band - a.y) / (b.y - a.y);
          double t1 = (grid_.row_low(r + 1) + band - a.y) / (b.y - a.y);
          t0 = std::clamp(t0, 0.0, 1.0);
          t1 = std::clamp(t1, 0.0, 1.0);
          const double xa = a.x + t0 * (b.x - a.x), xb = a.x + t1 * (b.x - a.x);
          x0 = std::min(xa, xb);
          x1 = std::max(xa, xb);
        }
        const int c0 = grid_.column(x0 - band), c1 = grid_.column(x1 + band);
        for (int c = c0; c <= c1; ++c) grid_.cell(c, r).push_back(static_cast<std::uint32_t>(s));
      }
    }
  }

  bool near(const Point2& p) const {
    for (std::uint32_t s : grid_.cell(p)) {
      if (segment_distance(p, segments_[s].first, segments_[s].second) < band_) return true;
    }
    return false;
  }

 private:
  Grid grid_;
  std::vector<std::pair<Point2, Point2>> segments_;
  double band_;
};

// Which fragments cover a point.
class FragmentIndex {
 public:
  FragmentIndex(const Box& box, const std::vector<hsr::Fragment>& fragments)
      : grid_(box, fragments.size()), fragments_(fragments) {
    for (std::size_t f = 0; f < fragments.size(); ++f) {
      Box b;
      b.add(fragments[f].shape);
      if (b.empty()) continue;
      for (int r = grid_.row(b.ymin); r <= grid_.row(b.ymax); ++r) {
        for (int c = grid_.column(b.xmin); c <= grid_.column(b.xmax); ++c) {
          grid_.cell(c, r).push_back(static_cast<std::uint32_t>(f));
        }
      }
    }
  }

  void covering(const Point2& p, std::vector<std::size_t>& out) const {
    out.clear();
    for (std::uint32_t f : grid_.cell(p)) {
      if (covers(fragments_[f].shape, p)) out.push_back(f);
    }
  }

 private:
  Grid grid_;
  const std::vector<hsr::Fragment>& fragments_;
};

std::string format_point(const Point2& p) {
  std::ostringstream out;
  out.precision(17);
  out << '(' << p.x << ", " << p.y << ')';
  return out.str();
}

std::string format_indices(const std::vector<std::size_t>& indices) {
  std::ostringstream out;
  out << '{';
  for (std::size_t i = 0; i < indices.size(); ++i) out << (i ? ", " : "") << indices[i];
  out << '}';
  return out.str();
}

void add_loop_edges(const Loop2& loop, std::vector<std::pair<Point2, Point2>>& edges) {
  for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
    edges.emplace_back(loop[j], loop[i]);
  }
}

void add_edges(const PolygonWithHoles2& polygon, std::vector<std::pair<Point2, Point2>>& edges) {
  add_loop_edges(polygon.outer, edges);
  for (const Loop2& hole : polygon.holes) add_loop_edges(hole, edges);
}

}  // namespace

double VisibilityCheck::area_error() const {
  return image_union > 0.0 ? std::fabs(fragment_sum - image_union) / image_union
                           : std::fabs(fragment_sum);
}

double VisibilityCheck::symmetric_difference_error() const {
  return image_union > 0.0 ? symmetric_difference / image_union : symmetric_difference;
}

double VisibilityCheck::overlap_error() const {
  const double overlap = fragment_sum - fragment_union;
  return image_union > 0.0 ? overlap / image_union : overlap;
}

bool VisibilityCheck::passed(double relative_area_tolerance) const {
  return invalid_images == 0 && invalid_fragments == 0 && area_error() <= relative_area_tolerance &&
         symmetric_difference_error() <= relative_area_tolerance &&
         overlap_error() <= relative_area_tolerance && wrong_polygon == 0 && uncovered == 0 &&
         spurious == 0 && overlapping == 0 && lost == 0;
}

std::string VisibilityCheck::summary() const {
  std::ostringstream out;
  out.precision(2);
  out << std::scientific << "area err " << area_error() << ", symdiff "
      << symmetric_difference_error() << ", overlap " << overlap_error() << " | " << samples
      << " samples: " << checked << " checked, " << near_edge << " near edges, " << ambiguous
      << " ambiguous, " << outside_window << " outside window; wrong " << wrong_polygon
      << ", uncovered " << uncovered << ", spurious " << spurious << ", overlapping " << overlapping
      << "; worst depth gap " << worst_depth_gap << " L (tie " << depth_tie / extent << " L) | "
      << with_image << " with image, " << without_fragments << " without fragments, " << lost
      << " lost";
  if (invalid_images + invalid_fragments > 0) {
    out << " | invalid: " << invalid_images << " images, " << invalid_fragments << " fragments";
  }
  return out.str();
}

std::string describe(const hsr::HsrStats& stats) {
  std::ostringstream out;
  out << "stats: " << stats.input_polygons << " in, " << stats.projected_polygons << " projected, "
      << stats.edge_on << " edge-on, " << stats.outside_view << " outside view; " << stats.templates
      << " templates, " << stats.clips << " clips, " << stats.depth_errors << " depth errors, "
      << stats.depth_splits << " splits, " << stats.cycle_breaks << " cycle breaks; "
      << stats.fragments << " fragments (" << stats.fragments_before_merge << " before merge)";
  return out.str();
}

VisibilityCheck check_visibility(std::span<const hsr::Polygon3> polygons, const hsr::View& view,
                                 const hsr::VisibleSurfaces& result,
                                 const VisibilityCheckOptions& options) {
  VisibilityCheck check;
  auto fail = [&check](const std::string& why, const Point2* where = nullptr) {
    if (check.failures.size() < kReportedFailures) check.failures.push_back(why);
    if (where != nullptr && check.failure_points.size() < 1000)
      check.failure_points.push_back(*where);
  };

  // Tolerances from the scene's size and its largest coordinate.
  glm::dvec3 low(std::numeric_limits<double>::infinity()), high(-low);
  double largest = glm::length(view.eye());
  for (const hsr::Polygon3& polygon : polygons) {
    auto add = [&](const hsr::Loop3& loop) {
      for (const glm::dvec3& p : loop) {
        low = glm::min(low, p);
        high = glm::max(high, p);
        largest = std::max({largest, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
      }
    };
    add(polygon.outer);
    for (const hsr::Loop3& hole : polygon.holes) add(hole);
  }
  if (polygons.empty()) return check;
  const double coordinate_ulp = ulp(largest);
  check.extent = glm::length(high - low);
  check.depth_tie = 1e-11 * check.extent + 64.0 * coordinate_ulp;
  check.margin = 1e-9 * check.extent + 64.0 * coordinate_ulp;

  // Coverage against the exact union of the images.
  std::vector<PolygonSet2> images(polygons.size());
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    images[i] = hsr::project_polygon(polygons[i], view);
    if (const std::string problem = validity_problem(images[i]); !problem.empty()) {
      ++check.invalid_images;
      fail("image of polygon " + std::to_string(i) + " is invalid: " + problem);
      images[i].clear();
    }
  }
  PolygonSet2 fragments, valid_fragments;
  for (std::size_t f = 0; f < result.fragments.size(); ++f) {
    const PolygonWithHoles2& shape = result.fragments[f].shape;
    fragments.push_back(shape);
    if (const std::string problem = validity_problem(shape); !problem.empty()) {
      ++check.invalid_fragments;
      fail("fragment " + std::to_string(f) + " of polygon " +
           std::to_string(result.fragments[f].parent) + " is invalid: " + problem);
    } else {
      valid_fragments.push_back(shape);
    }
  }
  const ExactUnionComparison unions =
      compare_exact_unions(images, std::span<const PolygonSet2>(&valid_fragments, 1));
  check.image_union = unions.a_union;
  check.fragment_union = unions.b_union;
  check.symmetric_difference = unions.symmetric_difference;
  check.fragment_sum = exact_area_of_pieces(fragments);

  // The sampled box: images and fragments, grown by 2%.
  Box box;
  for (const PolygonSet2& image : images) {
    for (const PolygonWithHoles2& p : image) box.add(p);
  }
  for (const PolygonWithHoles2& p : fragments) box.add(p);
  const std::optional<PolygonWithHoles2> window = view.window();
  Box window_box;
  if (window) window_box.add(*window);
  if (!box.empty()) {
    const double grow_x = 0.02 * (box.xmax - box.xmin), grow_y = 0.02 * (box.ymax - box.ymin);
    box.xmin -= grow_x;
    box.xmax += grow_x;
    box.ymin -= grow_y;
    box.ymax += grow_y;
  }
  check.edge_band = 1e-9 * (box.empty() ? 0.0 : box.diagonal()) +
                    64.0 * coordinate_ulp / (view.is_perspective() ? view.near() : 1.0);

  const RayOracle oracle(polygons, view, {check.depth_tie, check.margin});
  if (!box.empty()) {
    std::vector<std::pair<Point2, Point2>> edges;
    for (const PolygonSet2& image : images) {
      for (const PolygonWithHoles2& p : image) add_edges(p, edges);
    }
    for (const PolygonWithHoles2& p : fragments) add_edges(p, edges);
    const EdgeIndex edge_index(box, std::move(edges), check.edge_band);
    const FragmentIndex fragment_index(box, result.fragments);

    std::mt19937_64 rng(options.seed);
    std::uniform_real_distribution<double> ux(box.xmin, box.xmax), uy(box.ymin, box.ymax);
    std::vector<std::size_t> cover;
    for (std::size_t s = 0; s < options.samples; ++s) {
      const Point2 q{ux(rng), uy(rng)};
      ++check.samples;
      if (window && !window_box.contains(q)) {
        ++check.outside_window;
        continue;
      }
      if (edge_index.near(q)) {
        ++check.near_edge;
        continue;
      }
      const RayAnswer answer = oracle.at(q);
      if (answer.ambiguous) {
        ++check.ambiguous;
        continue;
      }
      ++check.checked;
      fragment_index.covering(q, cover);
      if (cover.size() > 1) {
        ++check.overlapping;
        std::vector<std::size_t> parents;
        for (std::size_t f : cover) parents.push_back(result.fragments[f].parent);
        fail("fragments of polygons " + format_indices(parents) + " overlap at " + format_point(q),
             &q);
        continue;
      }
      if (answer.nearest.empty()) {
        if (!cover.empty()) {
          ++check.spurious;
          fail("a fragment of polygon " + std::to_string(result.fragments[cover[0]].parent) +
                   " covers " + format_point(q) + ", where the ray sees nothing",
               &q);
        }
        continue;
      }
      if (cover.empty()) {
        ++check.uncovered;
        fail("no fragment covers " + format_point(q) + ", where the ray sees polygons " +
                 format_indices(answer.nearest),
             &q);
        continue;
      }
      const std::size_t parent = result.fragments[cover[0]].parent;
      const std::optional<double> depth = oracle.plane_depth(parent, q);
      if (depth) {
        check.worst_depth_gap =
            std::max(check.worst_depth_gap, (*depth - answer.depth) / check.extent);
      }
      if (std::find(answer.nearest.begin(), answer.nearest.end(), parent) == answer.nearest.end()) {
        ++check.wrong_polygon;
        std::ostringstream why;
        why.precision(17);
        why << "at " << format_point(q) << " the fragment shows polygon " << parent
            << " (its plane at depth " << (depth ? *depth : NAN) << "), but the ray sees "
            << format_indices(answer.nearest) << " nearest, at depth " << answer.depth;
        fail(why.str(), &q);
      }
    }
  }

  // Lost polygons: an image with area, no fragment, yet seen alone in front somewhere.
  std::vector<bool> has_fragment(polygons.size(), false);
  for (const hsr::Fragment& f : result.fragments) has_fragment[f.parent] = true;
  std::mt19937_64 rng(options.seed ^ 0x9E3779B97F4A7C15ull);
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    if (images[i].empty() || !(exact_area_of_pieces(images[i]) > 0.0)) continue;
    ++check.with_image;
    if (has_fragment[i]) continue;
    ++check.without_fragments;
    for (std::size_t probe = 0; probe < options.lost_probes; ++probe) {
      const std::optional<glm::dvec3> p = oracle.interior_point(i, rng);
      if (!p) break;
      const glm::dvec3 e = view.to_eye_frame(*p);
      if (view.is_perspective() && !(e.z > view.near())) continue;
      const Point2 q = view.project(*p);
      if (window && !window_box.contains(q)) continue;
      const RayAnswer answer = oracle.at(q);
      if (!answer.ambiguous && answer.nearest.size() == 1 && answer.nearest[0] == i) {
        ++check.lost;
        fail("polygon " + std::to_string(i) + " has no fragment, but the ray through " +
                 format_point(q) + " sees it alone in front",
             &q);
        break;
      }
    }
  }
  return check;
}

void ExpectVisibilityMatchesOracles(const Scene& scene, const VisibilityCheckOptions& options) {
  const std::size_t n = scene.polygons.size();
  for (std::size_t v = 0; v < scene.views.size(); ++v) {
    const std::string name = scene.name + "-view" + std::to_string(v);
    SCOPED_TRACE(name);
    const hsr::View view = make_view(scene.views[v]);
    const auto start = std::chrono::steady_clock::now();
    const hsr::VisibleSurfaces result =
        hsr::remove_hidden_surfaces(scene.polygons, view, options.hsr);
    const auto removed = std::chrono::steady_clock::now();
    VisibilityCheckOptions view_options = options;
    view_options.seed = options.seed + v;
    const VisibilityCheck check = check_visibility(scene.polygons, view, result, view_options);
    const auto checked = std::chrono::steady_clock::now();
    auto ms = [](auto a, auto b) {
      return std::chrono::duration_cast<std::chrono::milliseconds>(b - a).count();
    };
    std::cout << "[ " << name << " ] " << check.summary() << " | " << describe(result.stats)
              << " | hsr " << ms(start, removed) << " ms, check " << ms(removed, checked)
              << " ms\n";

    const hsr::HsrStats& stats = result.stats;
    EXPECT_EQ(stats.input_polygons, n);
    EXPECT_EQ(stats.projected_polygons + stats.edge_on + stats.outside_view, n);
    EXPECT_EQ(stats.fragments, result.fragments.size());
    EXPECT_LE(stats.fragments, stats.fragments_before_merge);
    EXPECT_EQ(result.planes.size(), n);
    EXPECT_EQ(result.nearness.size(), n);
    for (const hsr::Fragment& f : result.fragments) {
      ASSERT_LT(f.parent, n);
    }
    // The removal terminated; its work stays near linear in the number of polygons, as
    // hidden_surface.h promises for scenes of bounded depth complexity like these.
    EXPECT_LE(stats.clips, 1000 * n) << describe(stats);
    EXPECT_GE(check.checked, options.samples / 2) << "too few samples could be checked";

    const double tolerance = options.relative_area_tolerance;
    EXPECT_EQ(check.invalid_images, 0u);
    EXPECT_EQ(check.invalid_fragments, 0u);
    // CGAL's set operations need valid polygons: invalid ones are left out of the unions.
    const std::string left_out =
        check.invalid_images + check.invalid_fragments > 0
            ? " (" + std::to_string(check.invalid_images) + " invalid images and " +
                  std::to_string(check.invalid_fragments) + " invalid fragments left out)"
            : "";
    EXPECT_LE(check.area_error(), tolerance)
        << "fragments' total area " << check.fragment_sum << ", union of the images "
        << check.image_union << left_out;
    EXPECT_LE(check.symmetric_difference_error(), tolerance)
        << "(∪ fragments) Δ (∪ images) has area " << check.symmetric_difference << left_out;
    EXPECT_LE(check.overlap_error(), tolerance)
        << "fragments overlap: total area " << check.fragment_sum << ", union "
        << check.fragment_union << left_out;
    EXPECT_EQ(check.wrong_polygon, 0u);
    EXPECT_EQ(check.uncovered, 0u);
    EXPECT_EQ(check.spurious, 0u);
    EXPECT_EQ(check.overlapping, 0u);
    EXPECT_EQ(check.lost, 0u);
    if (!check.passed(tolerance)) {
      PolygonSet2 image_set, fragment_set, points;
      for (const hsr::Polygon3& polygon : scene.polygons) {
        for (PolygonWithHoles2& p : hsr::project_polygon(polygon, view)) {
          image_set.push_back(std::move(p));
        }
      }
      for (const hsr::Fragment& f : result.fragments) fragment_set.push_back(f.shape);
      Box drawn;
      for (const PolygonWithHoles2& p : image_set) drawn.add(p);
      const double r = drawn.empty() ? 1e-3 : 2e-3 * drawn.diagonal();
      for (const Point2& q : check.failure_points) {
        points.push_back(
            {{{q.x - r, q.y - r}, {q.x + r, q.y - r}, {q.x + r, q.y + r}, {q.x - r, q.y + r}}, {}});
      }
      const std::string svg = artifact_path(name + ".svg");
      write_svg(svg, {{&image_set, "none", "#888888", "images"},
                      {&fragment_set, "#4c72b0", "#1b3a6b", "fragments"},
                      {&points, "#c44e52", "#c44e52", "failing samples"}});
      std::ostringstream why;
      for (const std::string& failure : check.failures) why << "  " << failure << '\n';
      ADD_FAILURE() << name << ": first failures:\n" << why.str() << "picture: " << svg;
    }
  }
}

std::vector<double> visible_area_by_parent(const hsr::VisibleSurfaces& result,
                                           std::size_t polygon_count) {
  std::vector<PolygonSet2> by_parent(polygon_count);
  for (const hsr::Fragment& f : result.fragments) by_parent[f.parent].push_back(f.shape);
  std::vector<double> areas(polygon_count, 0.0);
  for (std::size_t i = 0; i < polygon_count; ++i) {
    if (!by_parent[i].empty()) areas[i] = exact_area_of_pieces(by_parent[i]);
  }
  return areas;
}

void ExpectOrderIndependent(const Scene& scene, int shuffles, std::uint64_t seed,
                            double relative_tolerance) {
  const std::size_t n = scene.polygons.size();
  std::mt19937_64 rng(seed);
  for (std::size_t v = 0; v < scene.views.size(); ++v) {
    const std::string name = scene.name + "-view" + std::to_string(v);
    SCOPED_TRACE(name);
    const hsr::View view = make_view(scene.views[v]);
    std::vector<double> image_area(n);
    for (std::size_t i = 0; i < n; ++i) {
      image_area[i] = exact_area_of_pieces(hsr::project_polygon(scene.polygons[i], view));
    }
    const std::vector<double> reference =
        visible_area_by_parent(hsr::remove_hidden_surfaces(scene.polygons, view), n);
    double worst = 0.0;
    std::size_t worst_polygon = 0;
    for (int s = 0; s < shuffles; ++s) {
      std::vector<std::size_t> order(n);
      std::iota(order.begin(), order.end(), std::size_t{0});
      std::shuffle(order.begin(), order.end(), rng);
      std::vector<hsr::Polygon3> shuffled(n);
      for (std::size_t j = 0; j < n; ++j) shuffled[j] = scene.polygons[order[j]];
      const std::vector<double> areas =
          visible_area_by_parent(hsr::remove_hidden_surfaces(shuffled, view), n);
      for (std::size_t j = 0; j < n; ++j) {
        const std::size_t i = order[j];
        const double difference = std::fabs(areas[j] - reference[i]);
        const double relative = image_area[i] > 0.0 ? difference / image_area[i] : difference;
        if (relative > worst) {
          worst = relative;
          worst_polygon = i;
        }
        EXPECT_LE(relative, relative_tolerance)
            << "polygon " << i << " (position " << j << " in shuffle " << s << "): visible area "
            << areas[j] << " shuffled, " << reference[i] << " as given, image area "
            << image_area[i];
      }
    }
    std::cout << "[ " << name << " ] order independence: worst relative difference of a "
              << "polygon's visible area " << worst << " (polygon " << worst_polygon << ", "
              << shuffles << " shuffles)\n";
  }
}

}  // namespace shadowgen::test
