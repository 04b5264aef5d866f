#include "shadowgen/view/method_plot.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>
#include <vector>

#include "detail/xml_text.h"
#include "shadowgen/model/number_text.h"
#include "shadowgen/output/atomic_file.h"

namespace shadowgen {
namespace {

constexpr double kWidth = 720, kHeight = 480;
constexpr double kLeft = 80, kRight = 200, kTop = 40, kBottom = 110;  // margins
constexpr double kExactStrip = 40;  // below the plot: the trials of error 0

// A log axis over whole decades that hold every value (positive ones only).
struct LogAxis {
  int first = 0, last = 1;  // decades 10^first .. 10^last
  double from = 0, to = 1;  // pixels

  static LogAxis over(const std::vector<double>& values, double from, double to) {
    double lo = 0, hi = 0;
    bool any = false;
    for (const double v : values) {
      if (!(v > 0.0)) continue;
      lo = any ? std::min(lo, v) : v;
      hi = any ? std::max(hi, v) : v;
      any = true;
    }
    LogAxis axis;
    axis.from = from;
    axis.to = to;
    if (!any) return axis;
    axis.first = static_cast<int>(std::floor(std::log10(lo)));
    axis.last = std::max(axis.first + 1, static_cast<int>(std::ceil(std::log10(hi))));
    return axis;
  }
  double at(double v) const {
    const double t = (std::log10(v) - first) / (last - first);
    return from + t * (to - from);
  }
};

std::string px(double v) { return number_text(v, std::chars_format::fixed, 1); }

std::string short_number(double v) { return number_text(v, std::chars_format::general, 3); }

std::string decade(int e) {
  if (e == 0) return "1";
  std::string text = "1e";
  text.append(std::to_string(e));
  return text;
}

// One trial as a panel draws it.
struct PlotPoint {
  std::string label;
  double seconds = 0.0, error = 0.0, max_error = 0.0;  // max_error 0: no line up to it
  bool pareto = false;
  const char* colour = "#7f7f7f";
  std::string data;  // the point's data-* attributes
};

// A panel of the plot, `top` pixels down: its title, the trials at (seconds, error) on
// log-log axes, each labelled, a line up to its largest error where it has one; the
// Pareto-optimal ones filled and joined; those of error 0 on a strip below the axis.
void draw_panel(std::ostringstream& svg, double top, const std::string& title,
                const std::string& y_label, const std::vector<PlotPoint>& points) {
  std::vector<double> seconds, errors;
  for (const PlotPoint& p : points) {
    seconds.push_back(std::max(p.seconds, 1e-6));
    if (p.error > 0.0) errors.push_back(p.error);
    if (p.max_error > 0.0) errors.push_back(p.max_error);
  }
  const double plot_top = top + kTop, plot_bottom = top + kHeight - kBottom;
  const LogAxis x = LogAxis::over(seconds, kLeft, kWidth - kRight);
  const LogAxis y = LogAxis::over(errors, plot_bottom, plot_top);
  svg << "<text x=\"" << px(kLeft) << "\" y=\"" << px(top + 24) << "\" font-size=\"14\">" << title
      << "</text>\n";
  // Grid and decade labels.
  for (int e = x.first; e <= x.last; ++e) {
    const std::string at = px(x.at(std::pow(10.0, e)));
    svg << "<line x1=\"" << at << "\" y1=\"" << px(plot_top) << "\" x2=\"" << at << "\" y2=\""
        << px(plot_bottom + kExactStrip) << "\" stroke=\"#dddddd\"/>\n"
        << "<text x=\"" << at << "\" y=\"" << px(plot_bottom + kExactStrip + 18)
        << "\" text-anchor=\"middle\">" << decade(e) << "</text>\n";
  }
  for (int e = y.first; e <= y.last; ++e) {
    const std::string at = px(y.at(std::pow(10.0, e)));
    svg << "<line x1=\"" << px(kLeft) << "\" y1=\"" << at << "\" x2=\"" << px(kWidth - kRight)
        << "\" y2=\"" << at << "\" stroke=\"#dddddd\"/>\n"
        << "<text x=\"" << px(kLeft - 6) << "\" y=\"" << at << "\" text-anchor=\"end\">"
        << decade(e) << "</text>\n";
  }
  svg << "<rect x=\"" << px(kLeft) << "\" y=\"" << px(plot_top) << "\" width=\""
      << px(kWidth - kRight - kLeft) << "\" height=\"" << px(plot_bottom - plot_top)
      << "\" fill=\"none\" stroke=\"#000000\"/>\n"
      << "<text x=\"" << px(kLeft - 6) << "\" y=\"" << px(plot_bottom + kExactStrip / 2 + 4)
      << "\" text-anchor=\"end\">0</text>\n"
      << "<text x=\"" << px((kLeft + kWidth - kRight) / 2) << "\" y=\"" << px(top + kHeight - 20)
      << "\" text-anchor=\"middle\">seconds (log)</text>\n"
      << "<text transform=\"translate(20," << px((plot_top + plot_bottom) / 2)
      << ") rotate(-90)\" text-anchor=\"middle\">" << y_label << "</text>\n";

  // Where each trial stands: on the plot, or on the strip for error 0.
  struct Mark {
    double x, y;
    const PlotPoint* point;
  };
  std::vector<Mark> marks;
  for (const PlotPoint& p : points) {
    const double mx = x.at(std::max(p.seconds, 1e-6));
    const double my = p.error > 0.0 ? y.at(p.error) : plot_bottom + kExactStrip / 2;
    marks.push_back({mx, my, &p});
  }
  std::vector<Mark> front;
  for (const Mark& m : marks) {
    if (m.point->pareto) front.push_back(m);
  }
  std::sort(front.begin(), front.end(), [](const Mark& a, const Mark& b) { return a.x < b.x; });
  if (front.size() > 1) {
    svg << "<polyline fill=\"none\" stroke=\"#d62728\" stroke-width=\"1.5\" points=\"";
    for (std::size_t i = 0; i < front.size(); ++i) {
      svg << (i ? " " : "") << px(front[i].x) << ',' << px(front[i].y);
    }
    svg << "\" data-pareto-front=\"\"/>\n";
  }
  // Labels right of their marks, each moved down a line while it would cover one placed
  // before it (at about 7 pixels a character), left to right.
  struct Box {
    double x0, x1, y0, y1;
  };
  std::vector<Box> placed;
  std::vector<std::size_t> order(marks.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return marks[a].x < marks[b].x; });
  std::vector<double> label_y(marks.size());
  for (const std::size_t i : order) {
    const Mark& m = marks[i];
    Box box{m.x + 8, m.x + 8 + 7.0 * static_cast<double>(m.point->label.size()), m.y - 8, m.y + 5};
    for (int tries = 0; tries < 4; ++tries) {
      const bool covers = std::any_of(placed.begin(), placed.end(), [&](const Box& o) {
        return box.x0 < o.x1 && o.x0 < box.x1 && box.y0 < o.y1 && o.y0 < box.y1;
      });
      if (!covers) break;
      box.y0 += 13;
      box.y1 += 13;
    }
    placed.push_back(box);
    label_y[i] = box.y0 + 12;
  }
  for (std::size_t i = 0; i < marks.size(); ++i) {
    const Mark& m = marks[i];
    const PlotPoint& p = *m.point;
    if (p.max_error > p.error) {
      svg << "<line x1=\"" << px(m.x) << "\" y1=\"" << px(m.y) << "\" x2=\"" << px(m.x)
          << "\" y2=\"" << px(y.at(p.max_error))
          << "\" stroke=\"#7f7f7f\" stroke-dasharray=\"3,2\"/>\n";
    }
    svg << "<circle cx=\"" << px(m.x) << "\" cy=\"" << px(m.y) << "\" r=\"5\" stroke=\"" << p.colour
        << "\" stroke-width=\"2\" fill=\"" << (p.pareto ? p.colour : "#ffffff") << "\" " << p.data
        << " data-pareto=\"" << (p.pareto ? 1 : 0) << "\"/>\n"
        << "<text x=\"" << px(m.x + 8) << "\" y=\"" << px(label_y[i]) << "\">" << p.label
        << "</text>\n";
  }
  // Legend.
  const double lx = kWidth - kRight + 16;
  svg << "<g data-legend=\"methods\">\n"
      << "<circle cx=\"" << px(lx) << "\" cy=\"" << px(plot_top + 10)
      << "\" r=\"5\" fill=\"#7f7f7f\" stroke=\"#7f7f7f\"/><text x=\"" << px(lx + 10) << "\" y=\""
      << px(plot_top + 14) << "\">Pareto-optimal</text>\n"
      << "<circle cx=\"" << px(lx) << "\" cy=\"" << px(plot_top + 30)
      << "\" r=\"5\" fill=\"#ffffff\" stroke=\"#7f7f7f\" stroke-width=\"2\"/><text x=\""
      << px(lx + 10) << "\" y=\"" << px(plot_top + 34) << "\">beaten</text>\n";
  if (std::any_of(points.begin(), points.end(),
                  [](const PlotPoint& p) { return p.max_error > 0.0; })) {
    svg << "<line x1=\"" << px(lx) << "\" y1=\"" << px(plot_top + 44) << "\" x2=\"" << px(lx)
        << "\" y2=\"" << px(plot_top + 60)
        << "\" stroke=\"#7f7f7f\" stroke-dasharray=\"3,2\"/><text x=\"" << px(lx + 10) << "\" y=\""
        << px(plot_top + 56) << "\">up to max |error|</text>\n";
  }
  svg << "</g>\n";
}

// The view methods' colours: exact as the per-face panel has it, one each for the others.
const char* view_colour(const std::string& method) {
  if (method == "exact") return "#2ca02c";
  if (method == "shadow-map") return "#ff7f0e";
  if (method == "volumes") return "#9467bd";
  if (method == "stencil") return "#8c564b";
  if (method == "stencil-silhouettes") return "#e377c2";
  return "#17becf";  // angular
}

}  // namespace

std::string comparison_svg(const MethodComparison& comparison, const ViewComparison* view) {
  const double height = view != nullptr ? 2 * kHeight : kHeight;
  std::ostringstream svg;
  svg << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" << px(kWidth)
      << "\" height=\"" << px(height) << "\" viewBox=\"0 0 " << px(kWidth) << ' ' << px(height)
      << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
      << "<rect x=\"0\" y=\"0\" width=\"" << px(kWidth) << "\" height=\"" << px(height)
      << "\" fill=\"#ffffff\"/>\n";
  std::vector<PlotPoint> faces;
  for (const MethodTrial& t : comparison.trials) {
    PlotPoint p;
    p.label = method_label(t.method);
    p.seconds = t.seconds;
    p.error = t.mean_error;
    p.max_error = t.max_error;
    p.pareto = t.pareto;
    p.colour = t.method.kind == MethodKind::kExact  ? "#2ca02c"
               : t.method.kind == MethodKind::kRays ? "#1f77b4"
                                                    : "#ff7f0e";
    p.data = "data-method=\"" + p.label + "\" data-seconds=\"" + short_number(t.seconds) +
             "\" data-mean-error=\"" + short_number(t.mean_error) + "\" data-max-error=\"" +
             short_number(t.max_error) + "\"";
    faces.push_back(std::move(p));
  }
  draw_panel(svg, 0.0,
             "Error against time, " + std::to_string(comparison.pairs) + " (face, light) pairs",
             "mean |error| of lit fractions (log)", faces);
  if (view != nullptr) {
    std::vector<PlotPoint> views;
    for (const ViewTrial& t : view->trials) {
      PlotPoint p;
      p.label = view_trial_label(t);
      p.seconds = t.seconds;
      p.error = t.agreement.share();
      p.pareto = t.pareto;
      p.colour = view_colour(t.method);
      p.data = "data-view-method=\"" + p.label + "\" data-seconds=\"" + short_number(t.seconds) +
               "\" data-share=\"" + short_number(p.error) + "\"";
      views.push_back(std::move(p));
    }
    draw_panel(svg, kHeight,
               "View " + view::detail::xml_text(view->view) + ", " + std::to_string(view->width) +
                   "×" + std::to_string(view->height) + ": pairs differing from exact against time",
               "share of (pixel, light) pairs differing (log)", views);
  }
  svg << "</svg>\n";
  return svg.str();
}

void write_comparison_svg(const MethodComparison& comparison, const std::filesystem::path& path,
                          const ViewComparison* view) {
  write_file_atomically(path, comparison_svg(comparison, view));
}

}  // namespace shadowgen
