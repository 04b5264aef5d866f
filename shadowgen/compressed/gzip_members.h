#pragma once

// Text compressed as gzip (RFC 1952) in independent members, made on the calling task
// arena's threads and written in order.
//
// The text is cut into pieces of kGzipMemberBytes; each piece becomes one complete gzip
// member (header, deflate stream, CRC-32 and length), and the members are concatenated,
// as RFC 1952 (section 2.2) allows: `zcat`, `gzip -d` and zlib's inflate with gzip
// headers read them as the one text. Members are independent, so they are compressed in
// parallel while the text is still being made; the bytes written depend only on the text
// and the level (the cut falls at fixed offsets, the header holds no time), never on the
// threads or on how the text arrives.

#include <tbb/task_group.h>

#include <cstddef>
#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <string_view>

namespace shadowgen::compressed {

// Text per member. Deflate looks back 32 KiB, so a member restarting its history every
// 4 MiB loses under 0.1 % of the size to one stream's (a member's header and trailer are
// 18 bytes), while a 100 MB text still makes 25 members for the threads to share.
inline constexpr std::size_t kGzipMemberBytes = std::size_t{4} << 20;

// zlib's levels: 1 fastest, 9 smallest. Files named *.gz are written at kGzipOutputLevel
// (shadowgen/output/atomic_file.h says why).
inline constexpr int kFastestGzipLevel = 1;
inline constexpr int kSmallestGzipLevel = 9;

// One gzip member holding `text`, at `level` (1 to 9).
std::string gzip_member(std::string_view text, int level);

// Receives text piece by piece (write), hands gzip members to `sink` in order. At most
// twice the arena's threads of members are held at once: writing waits (or compresses
// the oldest itself) rather than letting memory grow with the text.
class GzipMembers {
 public:
  using Sink = std::function<void(std::string_view)>;

  GzipMembers(Sink sink, int level, std::size_t member_bytes = kGzipMemberBytes);
  // Waits for the compressions still running; what they made is dropped.
  ~GzipMembers();
  GzipMembers(const GzipMembers&) = delete;
  GzipMembers& operator=(const GzipMembers&) = delete;

  void write(std::string_view text);
  // Compresses what is left and passes every member on. An empty text still makes one
  // (empty) member, so that the output is a gzip file. Nothing may be written after it.
  void finish();

 private:
  struct Member;
  void start_member();
  void pass_on_oldest();

  Sink sink_;
  int level_;
  std::size_t member_bytes_;
  std::size_t in_flight_limit_;
  std::string text_;  // the member being filled
  bool any_member_ = false;
  std::deque<std::shared_ptr<Member>> members_;  // compressing or compressed, in order
  tbb::task_group tasks_;
};

}  // namespace shadowgen::compressed
