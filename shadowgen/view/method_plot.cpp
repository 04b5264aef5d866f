#include "shadowgen/view/method_plot.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>
#include <vector>

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

}  // namespace

std::string comparison_svg(const MethodComparison& comparison) {
  std::vector<double> seconds, errors;
  for (const MethodTrial& t : comparison.trials) {
    seconds.push_back(std::max(t.seconds, 1e-6));
    if (t.mean_error > 0.0) errors.push_back(t.mean_error);
    if (t.max_error > 0.0) errors.push_back(t.max_error);
  }
  const double plot_bottom = kHeight - kBottom;
  const LogAxis x = LogAxis::over(seconds, kLeft, kWidth - kRight);
  const LogAxis y = LogAxis::over(errors, plot_bottom, kTop);
  std::ostringstream svg;
  svg << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" << px(kWidth)
      << "\" height=\"" << px(kHeight) << "\" viewBox=\"0 0 " << px(kWidth) << ' ' << px(kHeight)
      << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
      << "<rect x=\"0\" y=\"0\" width=\"" << px(kWidth) << "\" height=\"" << px(kHeight)
      << "\" fill=\"#ffffff\"/>\n"
      << "<text x=\"" << px(kLeft) << "\" y=\"24\" font-size=\"14\">Error against time, "
      << comparison.pairs << " (face, light) pairs</text>\n";
  // Grid and decade labels.
  for (int e = x.first; e <= x.last; ++e) {
    const std::string at = px(x.at(std::pow(10.0, e)));
    svg << "<line x1=\"" << at << "\" y1=\"" << px(kTop) << "\" x2=\"" << at << "\" y2=\""
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
  svg << "<rect x=\"" << px(kLeft) << "\" y=\"" << px(kTop) << "\" width=\""
      << px(kWidth - kRight - kLeft) << "\" height=\"" << px(plot_bottom - kTop)
      << "\" fill=\"none\" stroke=\"#000000\"/>\n"
      << "<text x=\"" << px(kLeft - 6) << "\" y=\"" << px(plot_bottom + kExactStrip / 2 + 4)
      << "\" text-anchor=\"end\">0</text>\n"
      << "<text x=\"" << px((kLeft + kWidth - kRight) / 2) << "\" y=\"" << px(kHeight - 20)
      << "\" text-anchor=\"middle\">seconds (log)</text>\n"
      << "<text transform=\"translate(20," << px((kTop + plot_bottom) / 2)
      << ") rotate(-90)\" text-anchor=\"middle\">mean |error| of lit fractions (log)</text>\n";

  // Where each trial stands: on the plot, or on the strip for error 0.
  struct Mark {
    double x, y;
    const MethodTrial* trial;
  };
  std::vector<Mark> marks;
  for (const MethodTrial& t : comparison.trials) {
    const double mx = x.at(std::max(t.seconds, 1e-6));
    const double my = t.mean_error > 0.0 ? y.at(t.mean_error) : plot_bottom + kExactStrip / 2;
    marks.push_back({mx, my, &t});
  }
  std::vector<Mark> front;
  for (const Mark& m : marks) {
    if (m.trial->pareto) front.push_back(m);
  }
  std::sort(front.begin(), front.end(), [](const Mark& a, const Mark& b) { return a.x < b.x; });
  if (front.size() > 1) {
    svg << "<polyline fill=\"none\" stroke=\"#d62728\" stroke-width=\"1.5\" points=\"";
    for (std::size_t i = 0; i < front.size(); ++i) {
      svg << (i ? " " : "") << px(front[i].x) << ',' << px(front[i].y);
    }
    svg << "\" data-pareto-front=\"\"/>\n";
  }
  for (const Mark& m : marks) {
    const MethodTrial& t = *m.trial;
    if (t.max_error > t.mean_error) {
      svg << "<line x1=\"" << px(m.x) << "\" y1=\"" << px(m.y) << "\" x2=\"" << px(m.x)
          << "\" y2=\"" << px(y.at(t.max_error))
          << "\" stroke=\"#7f7f7f\" stroke-dasharray=\"3,2\"/>\n";
    }
    const char* colour = t.method.kind == MethodKind::kExact  ? "#2ca02c"
                         : t.method.kind == MethodKind::kRays ? "#1f77b4"
                                                              : "#ff7f0e";
    svg << "<circle cx=\"" << px(m.x) << "\" cy=\"" << px(m.y) << "\" r=\"5\" stroke=\"" << colour
        << "\" stroke-width=\"2\" fill=\"" << (t.pareto ? colour : "#ffffff") << "\" data-method=\""
        << method_label(t.method) << "\" data-seconds=\"" << short_number(t.seconds)
        << "\" data-mean-error=\"" << short_number(t.mean_error) << "\" data-max-error=\""
        << short_number(t.max_error) << "\" data-pareto=\"" << (t.pareto ? 1 : 0) << "\"/>\n"
        << "<text x=\"" << px(m.x + 8) << "\" y=\"" << px(m.y + 4) << "\">"
        << method_label(t.method) << "</text>\n";
  }
  // Legend.
  const double lx = kWidth - kRight + 16;
  svg << "<g data-legend=\"methods\">\n"
      << "<circle cx=\"" << px(lx) << "\" cy=\"" << px(kTop + 10)
      << "\" r=\"5\" fill=\"#7f7f7f\" stroke=\"#7f7f7f\"/><text x=\"" << px(lx + 10) << "\" y=\""
      << px(kTop + 14) << "\">Pareto-optimal</text>\n"
      << "<circle cx=\"" << px(lx) << "\" cy=\"" << px(kTop + 30)
      << "\" r=\"5\" fill=\"#ffffff\" stroke=\"#7f7f7f\" stroke-width=\"2\"/><text x=\""
      << px(lx + 10) << "\" y=\"" << px(kTop + 34) << "\">beaten</text>\n"
      << "<line x1=\"" << px(lx) << "\" y1=\"" << px(kTop + 44) << "\" x2=\"" << px(lx)
      << "\" y2=\"" << px(kTop + 60) << "\" stroke=\"#7f7f7f\" stroke-dasharray=\"3,2\"/><text x=\""
      << px(lx + 10) << "\" y=\"" << px(kTop + 56) << "\">up to max |error|</text>\n"
      << "</g>\n</svg>\n";
  return svg.str();
}

void write_comparison_svg(const MethodComparison& comparison, const std::filesystem::path& path) {
  write_file_atomically(path, comparison_svg(comparison));
}

}  // namespace shadowgen
