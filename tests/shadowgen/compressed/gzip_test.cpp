// gzip files (shadowgen/compressed/): text written in members compressed in parallel reads
// back as it was, through every member; a truncated or corrupt file is an error naming it
// and what is wrong; a file that is not gzip reads as it is.

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "shadowgen/compressed/decompressed_input.h"
#include "shadowgen/compressed/gzip_members.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen::compressed {
namespace {

// Text that compresses as a database does: numbers in lines, repeated but not uniform.
std::string sample_text(std::size_t bytes) {
  std::string text;
  for (std::size_t i = 0; text.size() < bytes; ++i) {
    text += "[" + std::to_string(i * 7919 % 100003) + ".25, " + std::to_string(i % 17) + "],\n";
  }
  text.resize(bytes);
  return text;
}

// The members GzipMembers makes of `text`, handed over in pieces of `piece` bytes, on
// `threads` threads.
std::string gzip_of(const std::string& text, std::size_t member_bytes, std::size_t piece,
                    int threads, int level = 6) {
  std::string out;
  tbb::task_arena(threads).execute([&] {
    GzipMembers members([&out](std::string_view bytes) { out.append(bytes); }, level, member_bytes);
    for (std::size_t at = 0; at < text.size(); at += piece) {
      members.write(std::string_view(text).substr(at, piece));
    }
    members.finish();
  });
  return out;
}

// Read as the JSON reader reads (istream::read; `out << in.rdbuf()` would swallow errors).
std::string read_all(std::istream& in) {
  std::string text, piece(4096, '\0');
  while (in) {
    in.read(piece.data(), static_cast<std::streamsize>(piece.size()));
    text.append(piece, 0, static_cast<std::size_t>(in.gcount()));
  }
  return text;
}

std::string read_back(const std::string& bytes, const std::string& name = "db.json.gz") {
  DecompressedInput in(std::make_unique<std::istringstream>(bytes), name);
  return read_all(in);
}

// The message DecompressedInput throws reading `bytes` whole.
std::string read_error(const std::string& bytes) {
  try {
    read_back(bytes);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Gzip, OneMemberReadsBack) {
  const std::string text = sample_text(100000);
  const std::string gzip = gzip_member(text, 6);
  EXPECT_TRUE(is_gzip(gzip));
  EXPECT_LT(gzip.size(), text.size() / 3);
  DecompressedInput in(std::make_unique<std::istringstream>(gzip), "db.json.gz");
  EXPECT_TRUE(in.compressed());
  EXPECT_EQ(read_all(in), text);
}

TEST(Gzip, MembersAreThePiecesCompressedOneByOneInOrder) {
  const std::string text = sample_text(10000);
  std::string expected;
  for (std::size_t at = 0; at < text.size(); at += 1000) {
    expected += gzip_member(std::string_view(text).substr(at, 1000), 6);
  }
  EXPECT_EQ(gzip_of(text, 1000, 333, 4), expected);  // ten members
  EXPECT_EQ(read_back(expected), text);              // all ten read, in turn
}

TEST(Gzip, BytesDoNotDependOnThreadsOrPieces) {
  const std::string text = sample_text(300001);
  const std::string one = gzip_of(text, 4096, 100000, 1);
  EXPECT_EQ(gzip_of(text, 4096, 1, 4), one);
  EXPECT_EQ(gzip_of(text, 4096, 4096, 2), one);
  EXPECT_EQ(gzip_of(text, 4096, 5000, 8), one);
  EXPECT_EQ(read_back(one), text);
}

TEST(Gzip, EmptyTextIsOneEmptyMember) {
  const std::string gzip = gzip_of("", 1000, 1, 2);
  EXPECT_EQ(gzip, gzip_member("", 6));
  EXPECT_TRUE(is_gzip(gzip));
  EXPECT_EQ(read_back(gzip), "");
}

TEST(Gzip, LevelsOutsideOneToNineAreRefused) {
  EXPECT_THROW(gzip_member("x", 0), std::invalid_argument);
  EXPECT_THROW(gzip_member("x", 10), std::invalid_argument);
  EXPECT_THROW(GzipMembers([](std::string_view) {}, 0), std::invalid_argument);
}

TEST(Gzip, TruncatedFileIsAnErrorNamingIt) {
  const std::string gzip = gzip_of(sample_text(50000), 10000, 50000, 2);
  const std::string message =
      "db.json.gz: the gzip data ends before its last member does (a truncated file)";
  EXPECT_EQ(read_error(gzip.substr(0, gzip.size() - 1)), message);  // in the trailer
  EXPECT_EQ(read_error(gzip.substr(0, gzip.size() / 2)), message);  // in a member
  EXPECT_EQ(read_error(gzip.substr(0, 2)), message);                // the magic alone
}

TEST(Gzip, CorruptFileIsAnErrorNamingItAndWhat) {
  const std::string first = gzip_member(sample_text(20000), 6);
  const std::string second = gzip_member(sample_text(30000), 6);
  std::string crc = first + second;
  crc[first.size() + second.size() - 8] ^= 1;  // the second member's CRC-32
  EXPECT_EQ(read_error(crc), "db.json.gz: corrupt gzip data in the member at byte " +
                                 std::to_string(first.size()) + ": incorrect data check");
  std::string length = first + second;
  length[first.size() - 1] ^= 1;  // the first member's length
  EXPECT_EQ(read_error(length),
            "db.json.gz: corrupt gzip data in the member at byte 0: incorrect length check");
  EXPECT_EQ(read_error(first + "{\"format\": 1}"),
            "db.json.gz: corrupt gzip data in the member at byte " + std::to_string(first.size()) +
                ": incorrect header check");
}

TEST(Gzip, TextThatIsNotGzipReadsAsItIs) {
  const std::string text = sample_text(700000);  // more than the reader's buffers
  DecompressedInput in(std::make_unique<std::istringstream>(text), "db.json");
  EXPECT_FALSE(in.compressed());
  EXPECT_EQ(read_all(in), text);
  EXPECT_EQ(read_back("{"), "{");
  EXPECT_EQ(read_back(""), "");
  EXPECT_EQ(read_back("\x1f"), "\x1f");
  EXPECT_EQ(decompressed_text(text, "db.json"), text);
}

TEST(Gzip, RewindsToReadAgainAndTellsWhereItIs) {
  const std::string text = sample_text(600000);
  for (const std::string& bytes : {gzip_of(text, 100000, 600000, 2), text}) {
    DecompressedInput in(std::make_unique<std::istringstream>(bytes), "db.json.gz");
    std::string start(1000, '\0');
    in.read(start.data(), 1000);
    EXPECT_EQ(start, text.substr(0, 1000));
    EXPECT_EQ(in.tellg(), 1000);
    EXPECT_EQ(read_all(in), text.substr(1000));
    in.clear();
    in.seekg(0);
    EXPECT_EQ(in.tellg(), 0);
    EXPECT_EQ(read_all(in), text);
  }
}

TEST(Gzip, TextInMemoryDecompressed) {
  const std::string text = sample_text(5000);
  EXPECT_EQ(decompressed_text(gzip_of(text, 1000, 5000, 2), "-"), text);
  EXPECT_THROW(decompressed_text(gzip_member(text, 6).substr(0, 100), "-"), InputError);
}

}  // namespace
}  // namespace shadowgen::compressed
