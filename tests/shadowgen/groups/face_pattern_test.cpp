// Face patterns (shadowgen/groups/face_pattern.h): '*' stops at '/', '**' does not, '?' is
// one character other than '/', '\' quotes, and the whole id must match.

#include "shadowgen/groups/face_pattern.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace shadowgen::groups {
namespace {

bool matches(const std::string& pattern, const std::string& id) {
  return FacePattern(pattern).matches(id);
}

TEST(FacePattern, AStarMatchesAnyRunWithoutASlash) {
  EXPECT_TRUE(matches("garden*", "garden"));
  EXPECT_TRUE(matches("garden*", "garden-bed"));
  EXPECT_FALSE(matches("garden*", "garden/0"));  // a mesh's faces are one level down
  EXPECT_FALSE(matches("garden*", "the garden"));
  EXPECT_TRUE(matches("lawn/*", "lawn/0"));
  EXPECT_TRUE(matches("lawn/*", "lawn/"));
  EXPECT_FALSE(matches("lawn/*", "lawn/edge/3"));
  EXPECT_TRUE(matches("*/*/1", "district/church/1"));
  EXPECT_FALSE(matches("*/1", "district/church/1"));
  EXPECT_TRUE(matches("*", "wall"));
  EXPECT_FALSE(matches("*", "lawn/0"));
}

TEST(FacePattern, TwoOrMoreStarsMatchAnyRunSlashesIncluded) {
  EXPECT_TRUE(matches("lawn/**", "lawn/edge/3"));
  EXPECT_TRUE(matches("lawn/**", "lawn/0"));
  EXPECT_FALSE(matches("lawn/**", "lawn"));
  EXPECT_TRUE(matches("**", "district/church/1"));
  EXPECT_TRUE(matches("***", "district/church/1"));
  EXPECT_TRUE(matches("district/**/1", "district/church/1"));
  EXPECT_TRUE(matches("district/**/1", "district/church/tower/1"));
  EXPECT_FALSE(matches("district/**/1", "district/church/10"));
}

TEST(FacePattern, AQuestionMarkIsOneCharacterOtherThanASlash) {
  EXPECT_TRUE(matches("house-?", "house-a"));
  EXPECT_TRUE(matches("house-?", "house-\xC3\xA9"));  // é, two bytes in UTF-8
  EXPECT_FALSE(matches("house-?", "house-ab"));
  EXPECT_FALSE(matches("house-?", "house-"));
  EXPECT_FALSE(matches("lawn?0", "lawn/0"));
}

TEST(FacePattern, TheWholeIdMustMatchByteForByte) {
  EXPECT_TRUE(matches("garden", "garden"));
  EXPECT_FALSE(matches("gard", "garden"));
  EXPECT_FALSE(matches("Garden", "garden"));
  EXPECT_FALSE(matches("garden", "garden "));
}

TEST(FacePattern, ABackslashQuotesTheNextCharacter) {
  EXPECT_TRUE(matches("a\\*", "a*"));
  EXPECT_FALSE(matches("a\\*", "ab"));
  EXPECT_TRUE(matches("what\\?", "what?"));
  EXPECT_FALSE(matches("what\\?", "whats"));
  EXPECT_TRUE(matches("a\\\\b", "a\\b"));
  EXPECT_TRUE(matches("origin\\.group", "origin.group"));
}

TEST(FacePattern, AnEmptyPatternOrALoneBackslashAtTheEndIsRefused) {
  EXPECT_EQ(FacePattern::problem(""), "a face pattern must not be empty");
  EXPECT_EQ(FacePattern::problem("a\\"),
            "a face pattern must not end in a lone '\\' (\"\\\\\" stands for a backslash)");
  EXPECT_EQ(FacePattern::problem("a\\\\"), std::nullopt);
  EXPECT_THROW(FacePattern(""), std::invalid_argument);
  EXPECT_THROW(FacePattern("x\\"), std::invalid_argument);
}

}  // namespace
}  // namespace shadowgen::groups
