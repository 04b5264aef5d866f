#include "cli/progress.h"

#include <unistd.h>

#include <charconv>
#include <cmath>
#include <utility>

#include "shadowgen/model/number_text.h"

namespace shadowgen::cli {

std::string format_progress(const ProgressLine& line) {
  std::string text;
  if (line.scene_count > 1) {
    text +=
        '[' + std::to_string(line.scene_index + 1) + '/' + std::to_string(line.scene_count) + "] ";
  }
  if (!line.stage.empty()) {
    text += line.scene + ": " + line.stage;
  } else {
    text += line.scene + ": lights " + std::to_string(line.lights_done) + '/' +
            std::to_string(line.lights_total);
    if (line.any_light_done) text += ", last light " + std::to_string(line.faces) + " faces";
  }
  const double shown = std::isfinite(line.seconds) && line.seconds >= 0.0 ? line.seconds : 0.0;
  text += ", " + number_text(shown, std::chars_format::fixed, 1) + " s";
  return text;
}

bool stderr_is_terminal() { return ::isatty(STDERR_FILENO) == 1; }

ProgressDisplay::ProgressDisplay(std::ostream* out, ProgressLine line)
    : out_(out), line_(std::move(line)), start_(std::chrono::steady_clock::now()) {
  const std::lock_guard lock(mutex_);
  draw();
}

ProgressDisplay::~ProgressDisplay() { finish(); }

void ProgressDisplay::light_done(const LightStats& stats) {
  const std::lock_guard lock(mutex_);
  ++line_.lights_done;
  line_.faces = stats.faces_considered;
  line_.any_light_done = true;
  draw();
}

void ProgressDisplay::count_lights(std::size_t total) {
  const std::lock_guard lock(mutex_);
  line_.stage.clear();
  line_.lights_total = total;
  line_.lights_done = 0;
  line_.any_light_done = false;
  draw();
}

void ProgressDisplay::stage(std::string what) {
  const std::lock_guard lock(mutex_);
  line_.stage = std::move(what);
  draw();
}

void ProgressDisplay::interrupt() {
  const std::lock_guard lock(mutex_);
  if (!open_) return;
  *out_ << '\n' << std::flush;
  open_ = false;
  drawn_width_ = 0;
}

void ProgressDisplay::finish() {
  const std::lock_guard lock(mutex_);
  if (!open_) return;
  *out_ << '\n' << std::flush;
  open_ = false;
  out_ = nullptr;
}

std::function<void(std::size_t, const LightStats&)> ProgressDisplay::callback() {
  if (out_ == nullptr) return {};
  return [this](std::size_t, const LightStats& stats) { light_done(stats); };
}

void ProgressDisplay::draw() {
  if (out_ == nullptr) return;
  line_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const std::string text = format_progress(line_);
  // "\r" returns to the line's start; spaces blank what a longer earlier line left.
  std::string padded = '\r' + text;
  if (text.size() < drawn_width_) padded.append(drawn_width_ - text.size(), ' ');
  drawn_width_ = text.size();
  *out_ << padded << std::flush;
  open_ = true;
}

LightStats light_stats(const api::LightDone& done) {
  LightStats stats;
  stats.faces_considered = done.faces_considered;
  stats.lit_polygons = done.lit_polygons;
  stats.seconds = done.seconds;
  return stats;
}

}  // namespace shadowgen::cli
