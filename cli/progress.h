#pragma once

// Progress of a long run on a terminal (generate, and report, compare, export, render and
// merge): one line on stderr, rewritten in place ("\r") as each light is generated or the
// run goes on to its next stage, ended with a newline when the run is done. Nothing is
// shown when stderr is not a terminal (a file, a pipe, CI logs) or with --quiet, so
// scripted runs see only warnings and errors.

#include <chrono>
#include <cstddef>
#include <functional>
#include <mutex>
#include <ostream>
#include <string>

#include "shadowgen/shadowgen.h"
#include "shadowgen/shadows/generate.h"

namespace shadowgen::cli {

struct ProgressLine {
  std::string scene;            // the scene's file name, as the user knows it
  std::size_t scene_index = 0;  // 0-based; shown as "[2/3]" when scene_count > 1
  std::size_t scene_count = 1;
  std::size_t lights_done = 0;
  std::size_t lights_total = 0;
  std::size_t faces = 0;  // faces considered for the last light done (within its range)
  bool any_light_done = false;
  // What the run does now where it counts no lights ("splitting faces by light sets");
  // empty while lights are generated.
  std::string stage;
  double seconds = 0.0;  // since the scene's generation (or the run's first stage) started
};

// The text of the line, without "\r" or "\n":
//   "[2/3] courtyard.json: lights 3/8, last light 1204 faces, 2.4 s"
//   "db.json: splitting faces by light sets, 2.4 s"   (a stage)
// Seconds with one decimal, independent of the C locale.
std::string format_progress(const ProgressLine& line);

// Whether standard error is a terminal (isatty).
bool stderr_is_terminal();

// The display of one scene's generation. Pass `out` = nullptr for silence; otherwise the
// line is drawn at once (0 lights done) and redrawn by light_done. Thread-safe: the
// generator calls on_light_done from its workers (under its own lock, but this does not
// rely on it). The destructor ends an open line, so an error message printed afterwards
// starts on a line of its own.
class ProgressDisplay {
 public:
  ProgressDisplay(std::ostream* out, ProgressLine line);
  ~ProgressDisplay();
  ProgressDisplay(const ProgressDisplay&) = delete;
  ProgressDisplay& operator=(const ProgressDisplay&) = delete;

  void light_done(const LightStats& stats);
  // Lights from now on: `total` of them, none done yet (a scene read, its generation begun).
  void count_lights(std::size_t total);
  // A stage of the run from now on, redrawn at once.
  void stage(std::string what);
  // Ends the line with a newline, so that a warning printed next has a line of its own;
  // the next redraw starts a new line.
  void interrupt();
  // Ends the line with a newline; later calls and the destructor do nothing.
  void finish();

  // A callback for GenerateOptions::on_light_done that feeds this display, or an empty
  // function when the display is silent (the generator then skips the call).
  std::function<void(std::size_t, const LightStats&)> callback();

 private:
  void draw();  // caller holds mutex_

  std::ostream* out_;
  ProgressLine line_;
  std::chrono::steady_clock::time_point start_;
  std::size_t drawn_width_ = 0;  // characters of the last line drawn, to blank leftovers
  bool open_ = false;
  std::mutex mutex_;
};

// A light done by the library's generation, as the progress line counts it.
LightStats light_stats(const api::LightDone& done);

}  // namespace shadowgen::cli
