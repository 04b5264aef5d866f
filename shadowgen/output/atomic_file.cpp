#include "shadowgen/output/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <random>
#include <stdexcept>
#include <string_view>
#include <system_error>

namespace shadowgen {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, std::string_view what, int error) {
  throw std::runtime_error("cannot write '" + path.string() + "': " + std::string(what) + ": " +
                           std::strerror(error));
}

// ".<name>.tmp-<pid>-<n>-<random>": hidden, recognisable, and unique enough that
// O_EXCL only has to guard against the astronomically unlikely collision.
std::filesystem::path temporary_name(const std::filesystem::path& path) {
  static std::atomic<unsigned long> counter{0};
  static thread_local std::mt19937_64 random{std::random_device{}()};
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on `"." + std::string`.
  std::string name(1, '.');
  name += path.filename().string();
  name += ".tmp-";
  name += std::to_string(static_cast<long>(::getpid()));
  name += '-';
  name += std::to_string(counter.fetch_add(1));
  name += '-';
  name += std::to_string(random() % 1000000007ULL);
  return path.parent_path() / name;
}

// Closes the descriptor and removes the temporary file unless the rename succeeded.
class TemporaryFile {
 public:
  explicit TemporaryFile(const std::filesystem::path& destination) {
    for (int attempt = 0; attempt < 100; ++attempt) {
      path_ = temporary_name(destination);
      // 0666 and the process's umask: the same permissions as an ordinary new file.
      fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
      if (fd_ >= 0) return;
      if (errno != EEXIST) fail(destination, "cannot create a temporary file", errno);
    }
    fail(destination, "cannot create a temporary file", EEXIST);
  }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  ~TemporaryFile() {
    close();
    if (!kept_) {
      std::error_code ignored;
      std::filesystem::remove(path_, ignored);
    }
  }

  int fd() const { return fd_; }
  const std::filesystem::path& path() const { return path_; }
  // Returns 0 or the errno of a failed close (which may report a delayed write error).
  int close() {
    if (fd_ < 0) return 0;
    const int result = ::close(fd_);
    fd_ = -1;
    return result == 0 ? 0 : errno;
  }
  void keep() { kept_ = true; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  bool kept_ = false;
};

}  // namespace

void write_file_atomically(const std::filesystem::path& path, const std::string& content) {
  if (path.empty() || !path.has_filename()) fail(path, "not a file name", EINVAL);
  TemporaryFile temporary(path);

  const char* data = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t written = ::write(temporary.fd(), data, left);
    if (written < 0) {
      if (errno == EINTR) continue;
      fail(path, "write failed", errno);
    }
    data += written;
    left -= static_cast<std::size_t>(written);
  }
  // Flushed before the rename, so that a crash cannot leave a renamed but empty file.
  if (::fsync(temporary.fd()) != 0) fail(path, "fsync failed", errno);
  if (const int error = temporary.close(); error != 0) fail(path, "close failed", error);
  if (::rename(temporary.path().c_str(), path.c_str()) != 0) fail(path, "rename failed", errno);
  temporary.keep();
}

}  // namespace shadowgen
