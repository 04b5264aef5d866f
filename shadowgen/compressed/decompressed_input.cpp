#include "shadowgen/compressed/decompressed_input.h"

#include <zlib.h>

#include <cstdint>
#include <new>
#include <sstream>
#include <streambuf>
#include <utility>
#include <vector>

#include "shadowgen/model/input_error.h"

namespace shadowgen::compressed {
namespace {

constexpr unsigned char kGzipMagic[] = {0x1f, 0x8b};  // RFC 1952, section 2.3.1
// zlib's window bits for reading a gzip member: 16 added to the largest window.
constexpr int kGzipWindowBits = 15 + 16;
constexpr std::size_t kBufferBytes = std::size_t{1} << 18;

}  // namespace

bool is_gzip(std::string_view bytes) {
  return bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == kGzipMagic[0] &&
         static_cast<unsigned char>(bytes[1]) == kGzipMagic[1];
}

// The source's bytes in `in_` (the first two read ahead to tell gzip from text); in gzip,
// each member inflated in turn into `out_`, which the stream reads.
class DecompressedInput::Buffer : public std::streambuf {
 public:
  Buffer(std::unique_ptr<std::istream> source, std::string name)
      : source_(std::move(source)), name_(std::move(name)), in_(kBufferBytes), out_(kBufferBytes) {
    fill_input();
    gzip_ = is_gzip(std::string_view(in_.data(), in_end_));
    if (gzip_ && inflateInit2(&stream_, kGzipWindowBits) != Z_OK) throw std::bad_alloc();
  }
  ~Buffer() override {
    if (gzip_) inflateEnd(&stream_);
  }
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  bool gzip() const { return gzip_; }

 protected:
  int_type underflow() override {
    if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
    const std::size_t got = gzip_ ? inflate_some() : copy_some();
    if (got == 0) return traits_type::eof();
    setg(out_.data(), out_.data(), out_.data() + got);
    delivered_ += got;
    return traits_type::to_int_type(out_[0]);
  }

  pos_type seekoff(off_type offset, std::ios_base::seekdir way,
                   std::ios_base::openmode which) override {
    if (!(which & std::ios_base::in)) return pos_type(off_type(-1));
    if (way == std::ios_base::cur && offset == 0) {  // tellg
      return pos_type(static_cast<off_type>(delivered_ - (egptr() - gptr())));
    }
    if (way == std::ios_base::beg && offset == 0) return rewind();
    return pos_type(off_type(-1));
  }

  pos_type seekpos(pos_type position, std::ios_base::openmode which) override {
    if (!(which & std::ios_base::in) || position != pos_type(0)) return pos_type(off_type(-1));
    return rewind();
  }

 private:
  // Reads more of the source after what `in_` holds unread. False at its end.
  bool fill_input() {
    if (in_begin_ > 0) {  // keep what is left at the front
      std::copy(in_.begin() + static_cast<std::ptrdiff_t>(in_begin_),
                in_.begin() + static_cast<std::ptrdiff_t>(in_end_), in_.begin());
      in_end_ -= in_begin_;
      in_begin_ = 0;
    }
    source_->read(in_.data() + in_end_, static_cast<std::streamsize>(in_.size() - in_end_));
    const auto got = static_cast<std::size_t>(source_->gcount());
    if (source_->bad()) throw InputError(name_, "", "cannot read the file");
    in_end_ += got;
    return got > 0;
  }

  std::size_t copy_some() {
    if (in_begin_ == in_end_ && !fill_input()) return 0;
    const std::size_t got = in_end_ - in_begin_;
    std::copy(in_.begin() + static_cast<std::ptrdiff_t>(in_begin_),
              in_.begin() + static_cast<std::ptrdiff_t>(in_end_), out_.begin());
    source_offset_ += got;
    in_begin_ = in_end_ = 0;
    return got;
  }

  // Inflates until some text comes out or the source ends; members follow one another.
  std::size_t inflate_some() {
    for (;;) {
      if (in_begin_ == in_end_ && !fill_input()) {
        if (in_member_) {
          throw InputError(name_, "",
                           "the gzip data ends before its last member does (a truncated file)");
        }
        return 0;
      }
      if (!in_member_) {  // the next member begins here
        if (member_start_ != kNone) inflateReset(&stream_);
        member_start_ = source_offset_;
        in_member_ = true;
      }
      const std::size_t available = in_end_ - in_begin_;
      stream_.next_in = reinterpret_cast<Bytef*>(in_.data() + in_begin_);
      stream_.avail_in = static_cast<uInt>(available);
      stream_.next_out = reinterpret_cast<Bytef*>(out_.data());
      stream_.avail_out = static_cast<uInt>(out_.size());
      const int result = inflate(&stream_, Z_NO_FLUSH);
      const std::size_t used = available - stream_.avail_in;
      in_begin_ += used;
      source_offset_ += used;
      const std::size_t made = out_.size() - stream_.avail_out;
      if (result == Z_STREAM_END) {
        in_member_ = false;
      } else if (result == Z_MEM_ERROR) {
        throw std::bad_alloc();
      } else if (result != Z_OK && result != Z_BUF_ERROR) {
        throw InputError(name_, "",
                         "corrupt gzip data in the member at byte " +
                             std::to_string(member_start_) + ": " +
                             (stream_.msg != nullptr ? stream_.msg : "inflate failed"));
      }
      if (made > 0) return made;
    }
  }

  pos_type rewind() {
    source_->clear();
    source_->seekg(0);
    if (source_->fail()) return pos_type(off_type(-1));
    in_begin_ = in_end_ = 0;
    source_offset_ = delivered_ = 0;
    in_member_ = false;
    member_start_ = kNone;
    setg(nullptr, nullptr, nullptr);
    return pos_type(0);
  }

  static constexpr std::uint64_t kNone = ~std::uint64_t{0};
  std::unique_ptr<std::istream> source_;
  std::string name_;
  std::vector<char> in_, out_;
  std::size_t in_begin_ = 0, in_end_ = 0;  // the bytes of in_ not yet used
  std::uint64_t source_offset_ = 0;        // of in_[in_begin_] in the source
  std::uint64_t delivered_ = 0;            // bytes put in out_ since the start
  bool gzip_ = false;
  z_stream stream_{};
  bool in_member_ = false;
  std::uint64_t member_start_ = kNone;  // the source offset of the member being read
};

DecompressedInput::DecompressedInput(std::unique_ptr<std::istream> source, std::string name)
    : std::istream(nullptr), buffer_(std::make_unique<Buffer>(std::move(source), std::move(name))) {
  rdbuf(buffer_.get());
  exceptions(std::ios_base::badbit);  // a broken file's error, not a silent end
}

DecompressedInput::DecompressedInput(std::ifstream file, std::string name)
    : DecompressedInput(std::make_unique<std::ifstream>(std::move(file)), std::move(name)) {}

DecompressedInput::~DecompressedInput() = default;

bool DecompressedInput::compressed() const { return buffer_->gzip(); }

std::string decompressed_text(std::string text, const std::string& name) {
  if (!is_gzip(text)) return text;
  DecompressedInput in(std::make_unique<std::istringstream>(std::move(text)), name);
  std::string out;
  std::vector<char> piece(kBufferBytes);
  while (in) {
    in.read(piece.data(), static_cast<std::streamsize>(piece.size()));
    out.append(piece.data(), static_cast<std::size_t>(in.gcount()));
  }
  return out;
}

}  // namespace shadowgen::compressed
