#include "output_destination.h"

#include <linux/magic.h>
#include <sys/vfs.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>

namespace shadowgen::output::detail {
namespace {

namespace fs = std::filesystem;

// Whether `folder` lies on /proc, whose symbolic links (/proc/self/fd/1) are not names of
// files but handles on open files: what they seem to point to ("/home/u/out.txt",
// "pipe:[1234]") may not be that file, or no file at all.
bool on_proc(const fs::path& folder) {
  struct statfs status {};
  return ::statfs(folder.empty() ? "." : folder.c_str(), &status) == 0 &&
         status.f_type == PROC_SUPER_MAGIC;
}

bool same_inode(const fs::path& a, const fs::path& b) {
  struct stat status_a {};
  struct stat status_b {};
  return ::stat(a.c_str(), &status_a) == 0 && ::stat(b.c_str(), &status_b) == 0 &&
         status_a.st_dev == status_b.st_dev && status_a.st_ino == status_b.st_ino;
}

// The descriptor that `link`, a link on /proc, stands for when it is one of this
// process's (/proc/self/fd/N, /proc/PID/fd/N, /proc/thread-self/fd/N, /dev/fd/N); -1 when
// it is not.
int own_descriptor(const fs::path& link) {
  const std::string name = link.filename().native();  // filename() is a temporary
  int fd = -1;
  const auto [end, error] = std::from_chars(name.data(), name.data() + name.size(), fd);
  if (error != std::errc() || end != name.data() + name.size() || fd < 0) return -1;
  const fs::path folder = link.parent_path();
  return same_inode(folder, "/proc/self/fd") || same_inode(folder, "/proc/thread-self/fd") ? fd
                                                                                           : -1;
}

}  // namespace

bool is_dash(const fs::path& path) { return path.native() == "-"; }

[[noreturn]] void fail_to_write(const fs::path& path, std::string_view what, int error) {
  std::string message = "cannot write ";
  if (is_dash(path)) {
    message += "standard output";
  } else {
    message += '\'';
    message += path.string();
    message += '\'';
  }
  message += ": ";
  message += what;
  message += ": ";
  message += std::strerror(error);
  throw std::runtime_error(message);
}

Destination resolve(const fs::path& path) {
  Destination destination;
  destination.shown = path;
  destination.target = path;
  if (is_dash(path)) {
    destination.kind = DestinationKind::kDescriptor;
    destination.fd = STDOUT_FILENO;
    return destination;
  }
  constexpr int kMaxLinks = 40;
  for (int links = 0;; ++links) {
    const fs::path& target = destination.target;
    if (target.empty() || !target.has_filename()) fail_to_write(path, "not a file name", EINVAL);
    struct stat status {};
    if (::lstat(target.c_str(), &status) != 0) {
      const int error = errno;
      // Nothing can be made on /proc: a descriptor that is not open (/dev/fd/9).
      if (error == ENOENT && on_proc(target.parent_path()))
        fail_to_write(path, "cannot open it", error);
      if (error == ENOENT) return destination;  // a new file (there, if it is a link's)
      fail_to_write(path, "cannot examine it", error);
    }
    if (S_ISLNK(status.st_mode) && on_proc(target.parent_path())) {
      destination.fd = own_descriptor(target);
      destination.kind =
          destination.fd >= 0 ? DestinationKind::kDescriptor : DestinationKind::kProcLink;
      return destination;
    }
    if (S_ISLNK(status.st_mode)) {
      if (links == kMaxLinks) fail_to_write(path, "cannot follow its symbolic links", ELOOP);
      std::error_code error;
      const fs::path link = fs::read_symlink(target, error);
      if (error) fail_to_write(path, "cannot read its symbolic link", error.value());
      destination.target = link.is_absolute() ? link : target.parent_path() / link;
      continue;
    }
    if (S_ISDIR(status.st_mode)) fail_to_write(path, "not a file", EISDIR);
    destination.existing = status;
    destination.kind =
        S_ISREG(status.st_mode) ? DestinationKind::kReplace : DestinationKind::kThrough;
    return destination;
  }
}

fs::path written_file(const Destination& destination) {
  if (destination.kind == DestinationKind::kDescriptor) {
    return fs::path("/proc/self/fd") / std::to_string(destination.fd);
  }
  return destination.target;
}

}  // namespace shadowgen::output::detail
