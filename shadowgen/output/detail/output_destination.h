#pragma once

// What a destination path of an output names (shadowgen/output/atomic_file.h): standard
// output, one of this process's descriptors, a new or an existing regular file, a device,
// FIFO or socket, or a handle on /proc; symbolic links followed by hand.

#include <sys/stat.h>

#include <filesystem>
#include <string_view>

namespace shadowgen::output::detail {

// What a destination path names.
enum class DestinationKind {
  kDescriptor,  // "-", or a link to one of this process's descriptors (/dev/stdout)
  kNewFile,     // nothing there yet: a new regular file
  kReplace,     // an existing regular file
  kThrough,     // an existing device, FIFO or socket
  kProcLink,    // another /proc link to an open file (another process's descriptor)
};

struct Destination {
  std::filesystem::path shown;   // as given, for messages
  std::filesystem::path target;  // after following symbolic links
  DestinationKind kind = DestinationKind::kNewFile;
  int fd = -1;              // kDescriptor
  struct stat existing {};  // kReplace and kThrough
};

// Whether `path` is "-", standard output.
bool is_dash(const std::filesystem::path& path);

// Throws std::runtime_error "cannot write 'PATH': what: strerror(error)" ("standard
// output" for "-").
[[noreturn]] void fail_to_write(const std::filesystem::path& path, std::string_view what,
                                int error);

// Follows links as the kernel does (at most 40), but by hand: the rename must act on the
// final target, since renaming onto the link would replace the link itself. A link on
// /proc is not followed: it is a handle on an open file, written in place. A path that
// names no file (a folder, a loop of links, a descriptor not open) fails (fail_to_write).
Destination resolve(const std::filesystem::path& path);

// The file a destination's content goes to, as same_file compares it: a descriptor by its
// link on /proc, anything else by the path its links lead to.
std::filesystem::path written_file(const Destination& destination);

}  // namespace shadowgen::output::detail
