#include "cli/run_progress.h"

#include <iostream>
#include <utility>

namespace shadowgen::cli {

std::ostream* progress_stream(bool quiet) {
  return !quiet && stderr_is_terminal() ? &std::cerr : nullptr;
}

RunProgress::RunProgress(std::string input, std::ostream* out)
    : input_(std::move(input)), out_(out) {}

void RunProgress::show(const ProgressLine& line) {
  if (out_ == nullptr) return;
  display_.emplace(out_, line);
}

void RunProgress::watch(LoadOptions& options) {
  if (out_ == nullptr) return;
  options.on_scene = [this, then = std::move(options.on_scene)](const Scene& scene) {
    if (then) then(scene);
    lights(scene.lights.size());
  };
  options.generate.on_light_done = [this](std::size_t, const LightStats& stats) {
    if (display_) display_->light_done(stats);
  };
  if (options.on_warning) {
    options.on_warning = [this, then = std::move(options.on_warning)](const std::string& warning) {
      if (display_) display_->interrupt();
      then(warning);
    };
  }
}

void RunProgress::watch(api::LoadSettings& settings) {
  if (out_ == nullptr) return;
  settings.on_scene = [this, then = std::move(settings.on_scene)](const api::Scene& scene) {
    if (then) then(scene);
    lights(scene.light_ids().size());
  };
  settings.generate.on_light_done = [this](const api::LightDone& done) {
    if (display_) display_->light_done(light_stats(done));
  };
  if (settings.read.on_warning) {
    settings.read.on_warning =
        [this, then = std::move(settings.read.on_warning)](const std::string& warning) {
          if (display_) display_->interrupt();
          then(warning);
        };
  }
}

void RunProgress::stage(const std::string& what) {
  if (out_ == nullptr) return;
  if (display_) {
    display_->stage(what);
    return;
  }
  ProgressLine line;
  line.scene = input_;
  line.stage = what;
  show(line);
}

std::function<void(std::size_t, const LightStats&)> RunProgress::lights(std::size_t total) {
  if (out_ == nullptr) return {};
  if (display_) {
    display_->count_lights(total);
  } else {
    ProgressLine line;
    line.scene = input_;
    line.lights_total = total;
    show(line);
  }
  return display_->callback();
}

void RunProgress::finish() {
  if (display_) display_->finish();
}

}  // namespace shadowgen::cli
