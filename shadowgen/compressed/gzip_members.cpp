#include "shadowgen/compressed/gzip_members.h"

#include <tbb/task_arena.h>
#include <zlib.h>

#include <atomic>
#include <exception>
#include <limits>
#include <new>
#include <stdexcept>
#include <utility>

namespace shadowgen::compressed {
namespace {

// zlib's window bits for a deflate stream with a gzip header and trailer (zlib.h,
// deflateInit2: 16 added to the largest window, 2^15 bytes).
constexpr int kGzipWindowBits = 15 + 16;
constexpr int kMemoryLevel = 8;  // zlib's default

}  // namespace

std::string gzip_member(std::string_view text, int level) {
  if (level < kFastestGzipLevel || level > kSmallestGzipLevel) {
    throw std::invalid_argument("gzip level " + std::to_string(level) + " is not 1 to 9");
  }
  if (text.size() > std::numeric_limits<uInt>::max() / 2) {
    throw std::invalid_argument("a gzip member of more than 2 GiB of text");
  }
  z_stream stream{};
  if (deflateInit2(&stream, level, Z_DEFLATED, kGzipWindowBits, kMemoryLevel, Z_DEFAULT_STRATEGY) !=
      Z_OK) {
    throw std::bad_alloc();
  }
  // deflateBound with a gzip header: room for the whole member in one call.
  std::string member(deflateBound(&stream, static_cast<uLong>(text.size())), '\0');
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(text.data()));
  stream.avail_in = static_cast<uInt>(text.size());
  stream.next_out = reinterpret_cast<Bytef*>(member.data());
  stream.avail_out = static_cast<uInt>(member.size());
  const int result = deflate(&stream, Z_FINISH);
  member.resize(stream.total_out);
  deflateEnd(&stream);
  if (result != Z_STREAM_END) throw std::logic_error("deflate did not end within its bound");
  return member;
}

// States of a member: waiting for a thread, being compressed, compressed (or failed).
struct GzipMembers::Member {
  enum State : int { kWaiting, kCompressing, kDone };
  std::string text;
  std::string gzip;
  std::exception_ptr failure;
  std::atomic<int> state{kWaiting};

  // Compresses the member unless another thread has taken it; true if this one did.
  bool compress(int level) {
    int waiting = kWaiting;
    if (!state.compare_exchange_strong(waiting, kCompressing)) return false;
    try {
      gzip = gzip_member(text, level);
    } catch (...) {
      failure = std::current_exception();
    }
    std::string().swap(text);
    state.store(kDone);
    state.notify_all();
    return true;
  }
};

GzipMembers::GzipMembers(Sink sink, int level, std::size_t member_bytes)
    : sink_(std::move(sink)),
      level_(level),
      member_bytes_(member_bytes),
      in_flight_limit_(2 * static_cast<std::size_t>(tbb::this_task_arena::max_concurrency())) {
  if (member_bytes_ == 0) throw std::invalid_argument("gzip members of no bytes");
  (void)gzip_member({}, level_);  // the level checked before any text
}

GzipMembers::~GzipMembers() { tasks_.wait(); }

void GzipMembers::write(std::string_view text) {
  while (!text.empty()) {
    if (text_.capacity() < member_bytes_) text_.reserve(member_bytes_);
    const std::size_t room = member_bytes_ - text_.size();
    const std::size_t taken = std::min(room, text.size());
    text_.append(text.substr(0, taken));
    text.remove_prefix(taken);
    if (text_.size() == member_bytes_) start_member();
  }
}

void GzipMembers::finish() {
  if (!text_.empty() || !any_member_) start_member();
  while (!members_.empty()) pass_on_oldest();
  tasks_.wait();
}

void GzipMembers::start_member() {
  auto member = std::make_shared<Member>();
  member->text = std::move(text_);
  text_ = std::string();
  any_member_ = true;
  members_.push_back(member);
  const int level = level_;
  tasks_.run([member, level] { member->compress(level); });
  // Members already done go out at once; beyond the limit, the oldest is waited for.
  while (!members_.empty() &&
         (members_.front()->state.load() == Member::kDone || members_.size() > in_flight_limit_)) {
    pass_on_oldest();
  }
}

void GzipMembers::pass_on_oldest() {
  const std::shared_ptr<Member> member = members_.front();
  // On one thread, or with every thread busy, this thread compresses it itself.
  member->compress(level_);
  for (int state = member->state.load(); state != Member::kDone; state = member->state.load()) {
    member->state.wait(state);
  }
  members_.pop_front();
  if (member->failure) std::rethrow_exception(member->failure);
  sink_(member->gzip);
}

}  // namespace shadowgen::compressed
