// Files written compressed as their name asks (shadowgen/output/atomic_file.h): a path
// ending in ".gz" gets gzip members that decompress to the plain file's bytes, any other
// the plain text, whichever of the writer's functions writes it; a failure leaves nothing
// behind.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "shadowgen/compressed/decompressed_input.h"
#include "shadowgen/compressed/gzip_members.h"
#include "shadowgen/output/atomic_file.h"
#include "tests/support/temp_folder.h"

namespace shadowgen {
namespace {

namespace fs = std::filesystem;

class CompressedOutput : public ::testing::Test {
 protected:
  static std::string contents(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
  // Writes `text` to `path` in pieces of 1000 bytes.
  static void write(const fs::path& path, const std::string& text) {
    stream_file_atomically(path, [&text](const OutputSink& sink) {
      for (std::size_t at = 0; at < text.size(); at += 1000) {
        sink(std::string_view(text).substr(at, 1000));
      }
    });
  }

  test::TempFolder folder_{"shadowgen-compressed"};
  const fs::path& dir_ = folder_.path();
};

TEST_F(CompressedOutput, NamesEndingInGzAreCompressed) {
  EXPECT_TRUE(gzip_named("db.json.gz"));
  EXPECT_TRUE(gzip_named("out/db.gz"));
  EXPECT_FALSE(gzip_named("db.json"));
  EXPECT_FALSE(gzip_named("db.json.gzip"));
  EXPECT_FALSE(gzip_named("db.GZ"));
  EXPECT_FALSE(gzip_named("-"));
}

TEST_F(CompressedOutput, GzFileHoldsTheMembersOfThePlainText) {
  std::string text;
  for (int i = 0; text.size() < 3 * compressed::kGzipMemberBytes / 2; ++i) {
    text += "{\"id\":\"f" + std::to_string(i) + "\",\"xyz\":[" + std::to_string(i % 977) + "]}\n";
  }
  write(dir_ / "a.json", text);
  write(dir_ / "a.json.gz", text);
  EXPECT_EQ(contents(dir_ / "a.json"), text);
  const std::string gzip = contents(dir_ / "a.json.gz");
  // Two members: the first kGzipMemberBytes of the text, then the rest.
  EXPECT_EQ(
      gzip,
      compressed::gzip_member(text.substr(0, compressed::kGzipMemberBytes), kGzipOutputLevel) +
          compressed::gzip_member(text.substr(compressed::kGzipMemberBytes), kGzipOutputLevel));
  EXPECT_EQ(compressed::decompressed_text(gzip, "a.json.gz"), text);
}

TEST_F(CompressedOutput, WholeTextsAndSetsOfFilesAreCompressedAlike) {
  const std::string text = "face_id,area\nroof,12.5\n";
  write_file_atomically(dir_ / "r.csv.gz", text);
  EXPECT_EQ(contents(dir_ / "r.csv.gz"), compressed::gzip_member(text, kGzipOutputLevel));
  write_files_atomically({{dir_ / "a.mtl", "mtl"}, {dir_ / "a.obj.gz", text}});
  EXPECT_EQ(contents(dir_ / "a.mtl"), "mtl");
  EXPECT_EQ(contents(dir_ / "a.obj.gz"), compressed::gzip_member(text, kGzipOutputLevel));
}

TEST_F(CompressedOutput, FailureLeavesNothingBehind) {
  write(dir_ / "old.json.gz", "old");
  EXPECT_THROW(stream_file_atomically(dir_ / "old.json.gz",
                                      [](const OutputSink& sink) {
                                        sink(std::string(5000000, 'x'));
                                        throw std::runtime_error("stopped");
                                      }),
               std::runtime_error);
  EXPECT_EQ(compressed::decompressed_text(contents(dir_ / "old.json.gz"), "old"), "old");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);
}

}  // namespace
}  // namespace shadowgen
