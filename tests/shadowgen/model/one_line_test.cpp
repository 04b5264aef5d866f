// Messages stay on one line whatever the ids and paths in them hold.

#include "shadowgen/model/one_line.h"

#include <gtest/gtest.h>

#include <string>

#include "shadowgen/model/input_error.h"
#include "shadowgen/shadows/generate.h"

namespace shadowgen {
namespace {

TEST(OneLine, EscapesControlCharactersAndKeepsTheRest) {
  using namespace std::string_literals;
  EXPECT_EQ(one_line("plain id"), "plain id");
  EXPECT_EQ(one_line("two\nlines\r\ttab"), "two\\nlines\\r\\ttab");
  EXPECT_EQ(one_line("bell\a nul\0 del\x7f esc\x1b"s), "bell\\x07 nul\\x00 del\\x7f esc\\x1b");
  EXPECT_EQ(one_line("caf\xc3\xa9 \xe6\xbc\xa2"), "caf\xc3\xa9 \xe6\xbc\xa2");
}

// An id with a line break once split a message in two, the second line passing for a
// message of its own.
TEST(OneLine, ErrorMessagesAreOneLineWhateverTheIdsHold) {
  const InputError input("dir\n/scene.json", "wall\nshadowgen: all is well", "not planar");
  EXPECT_EQ(std::string(input.what()),
            "dir\\n/scene.json: face 'wall\\nshadowgen: all is well': not planar");
  EXPECT_EQ(input.face_id(), "wall\nshadowgen: all is well");  // as given

  const GenerationError generation("s.json", "f\r", "sun\t1", "snap rounding did not settle");
  EXPECT_EQ(std::string(generation.what()),
            "s.json: face 'f\\r', light 'sun\\t1': snap rounding did not settle");
}

}  // namespace
}  // namespace shadowgen
