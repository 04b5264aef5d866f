// Whole-file output (shadowgen/atomic_file.h): the destination holds the old or the new
// content, never a part, and no temporary file is left behind.

#include "shadowgen/output/atomic_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace shadowgen {
namespace {

namespace fs = std::filesystem;

class AtomicFile : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::path(::testing::TempDir()) /
           (std::string("shadowgen-atomic-") + info->name() + "-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add);
    fs::remove_all(dir_);
  }

  std::size_t file_count() const {
    return static_cast<std::size_t>(
        std::distance(fs::directory_iterator(dir_), fs::directory_iterator()));
  }
  static std::string contents(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  fs::path dir_;
};

TEST_F(AtomicFile, WritesAndReplaces) {
  const fs::path path = dir_ / "out.txt";
  write_file_atomically(path, "first\n");
  EXPECT_EQ(contents(path), "first\n");
  std::string big(3 << 20, 'x');
  big.back() = '\n';
  write_file_atomically(path, big);
  EXPECT_EQ(contents(path), big);
  write_file_atomically(path, "");
  EXPECT_EQ(contents(path), "");
  EXPECT_EQ(file_count(), 1u);
}

TEST_F(AtomicFile, UsesOrdinaryPermissions) {
  const fs::path path = dir_ / "out.txt";
  write_file_atomically(path, "x");
  const mode_t mask = ::umask(0);
  ::umask(mask);
  const auto expected = static_cast<fs::perms>(0666 & ~mask);
  EXPECT_EQ(fs::status(path).permissions() & fs::perms::all, expected);
}

TEST_F(AtomicFile, FailuresNameThePathAndLeaveNothing) {
  const fs::path missing = dir_ / "no" / "such" / "out.txt";
  try {
    write_file_atomically(missing, "x");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(missing.string()), std::string::npos) << e.what();
  }

  // A folder in the way: the rename fails after the temporary file was written.
  fs::create_directories(dir_ / "taken");
  fs::create_directories(dir_ / "taken" / "inside");
  EXPECT_THROW(write_file_atomically(dir_ / "taken", "x"), std::runtime_error);
  EXPECT_EQ(file_count(), 1u);
  EXPECT_TRUE(fs::is_directory(dir_ / "taken"));
}

TEST_F(AtomicFile, ARelativePathStaysInTheCurrentFolder) {
  const fs::path previous = fs::current_path();
  fs::current_path(dir_);
  write_file_atomically("relative.txt", "r");
  fs::current_path(previous);
  EXPECT_EQ(contents(dir_ / "relative.txt"), "r");
  EXPECT_EQ(file_count(), 1u);
}

}  // namespace
}  // namespace shadowgen
