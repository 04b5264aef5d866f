// The progress line of `shadowgen generate` (cli/progress.h): its text, and the in-place
// redrawing, written to a string stream instead of a terminal.

#include "cli/progress.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace shadowgen::cli {
namespace {

// The line of a scene's run before any light is done.
ProgressLine starting(const std::string& scene, std::size_t lights_total) {
  ProgressLine line;
  line.scene = scene;
  line.lights_total = lights_total;
  return line;
}

TEST(FormatProgress, OneScene) {
  ProgressLine line = starting("scenes/courtyard.json", 8);
  line.seconds = 0.04;
  EXPECT_EQ(format_progress(line), "scenes/courtyard.json: lights 0/8, 0.0 s");

  line.lights_done = 3;
  line.faces = 1204;
  line.any_light_done = true;
  line.seconds = 2.36;
  EXPECT_EQ(format_progress(line),
            "scenes/courtyard.json: lights 3/8, last light 1204 faces, 2.4 s");
}

TEST(FormatProgress, SeveralScenesShowWhichOne) {
  ProgressLine line;
  line.scene = "b.json";
  line.scene_index = 1;
  line.scene_count = 3;
  line.lights_done = 2;
  line.lights_total = 2;
  line.faces = 0;
  line.any_light_done = true;
  line.seconds = 125.0;
  EXPECT_EQ(format_progress(line), "[2/3] b.json: lights 2/2, last light 0 faces, 125.0 s");
}

TEST(FormatProgress, NonsenseSecondsShowAsZero) {
  ProgressLine line;
  line.scene = "a.json";
  line.seconds = -1.0;
  EXPECT_EQ(format_progress(line), "a.json: lights 0/0, 0.0 s");
}

// Elapsed seconds vary from run to run, so the drawn text is checked up to them.
TEST(ProgressDisplay, RedrawsInPlaceAndEndsTheLine) {
  std::ostringstream out;
  const ProgressLine line = starting("scene.json", 2);
  {
    ProgressDisplay display(&out, line);
    const auto callback = display.callback();
    ASSERT_TRUE(callback);
    LightStats stats;
    stats.faces_considered = 5;
    callback(1, stats);
    stats.faces_considered = 7;
    callback(0, stats);
    display.finish();
    display.finish();  // once only
  }
  const std::string text = out.str();
  EXPECT_EQ(text.rfind("\rscene.json: lights 0/2, ", 0), 0u) << text;
  const std::size_t first = text.find("\rscene.json: lights 1/2, last light 5 faces, ");
  const std::size_t second = text.find("\rscene.json: lights 2/2, last light 7 faces, ");
  EXPECT_NE(first, std::string::npos) << text;
  EXPECT_NE(second, std::string::npos) << text;
  EXPECT_LT(first, second);
  EXPECT_EQ(text.back(), '\n');
  EXPECT_EQ(text.find('\n'), text.size() - 1) << text;  // one line, redrawn in place
}

TEST(ProgressDisplay, ALongerLineIsBlankedWhenAShorterOneFollows) {
  std::ostringstream out;
  ProgressDisplay display(&out, starting("s.json", 10));
  LightStats stats;
  stats.faces_considered = 123456789;
  display.light_done(stats);  // "..., last light 123456789 faces, ..."
  stats.faces_considered = 1;
  display.light_done(stats);  // eight characters shorter
  const std::string text = out.str();
  const std::size_t last = text.rfind('\r');
  const std::size_t before = text.rfind('\r', last - 1);
  const std::string longer = text.substr(before + 1, last - before - 1);
  const std::string shorter = text.substr(last + 1);
  EXPECT_EQ(longer.rfind("s.json: lights 1/10, last light 123456789 faces, ", 0), 0u) << text;
  // The shorter line, then exactly enough blanks to cover what is left of the longer one.
  const std::size_t end = shorter.find_last_not_of(' ') + 1;
  EXPECT_EQ(shorter.substr(0, end).rfind("s.json: lights 2/10, last light 1 faces, ", 0), 0u)
      << text;
  EXPECT_EQ(shorter.size(), longer.size()) << text;
  EXPECT_GE(shorter.size() - end, 8u) << text;
  EXPECT_EQ(text.find('\n'), std::string::npos) << text;  // still one open line
}

TEST(ProgressDisplay, SilentWithoutAStream) {
  ProgressDisplay display(nullptr, starting("scene.json", 1));
  EXPECT_FALSE(display.callback());  // the generator then skips the call altogether
  EXPECT_NO_THROW(display.light_done(LightStats{}));
  EXPECT_NO_THROW(display.finish());
}

TEST(ProgressDisplay, TheDestructorEndsAnOpenLine) {
  std::ostringstream out;
  {
    ProgressDisplay display(&out, starting("scene.json", 3));
    display.light_done(LightStats{});
  }  // as when generation throws
  const std::string text = out.str();
  EXPECT_EQ(text.rfind("\rscene.json: lights 0/3, ", 0), 0u) << text;
  EXPECT_NE(text.find("\rscene.json: lights 1/3, last light 0 faces, "), std::string::npos) << text;
  EXPECT_EQ(text.find('\n'), text.size() - 1) << text;  // one newline, at the very end
}

}  // namespace
}  // namespace shadowgen::cli
