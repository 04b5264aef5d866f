#include "detail/nul_watching_input.h"

#include <cstring>

namespace shadowgen::json::detail {

// 64 KiB: a few inflate outputs' worth, so that the copy costs little beside the parse.
NulWatchingInput::Buffer::Buffer(std::istream& from) : source(from), bytes(std::size_t{1} << 16) {}

NulWatchingInput::Buffer::int_type NulWatchingInput::Buffer::underflow() {
  if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
  source.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  const auto got = static_cast<std::size_t>(source.gcount());
  if (got == 0) return traits_type::eof();
  if (!saw_nul && std::memchr(bytes.data(), '\0', got) != nullptr) saw_nul = true;
  setg(bytes.data(), bytes.data(), bytes.data() + got);
  return traits_type::to_int_type(*gptr());
}

NulWatchingInput::NulWatchingInput(std::istream& source) : std::istream(nullptr), buffer_(source) {
  rdbuf(&buffer_);
}

}  // namespace shadowgen::json::detail
