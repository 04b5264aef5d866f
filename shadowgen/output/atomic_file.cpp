#include "shadowgen/output/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>

#include "detail/output_destination.h"
#include "detail/temporary_files.h"
#include "shadowgen/compressed/gzip_members.h"

namespace shadowgen {
namespace {

namespace fs = std::filesystem;
using output::detail::Destination;
using output::detail::is_dash;
using output::detail::register_temporary;
using output::detail::resolve;
using output::detail::unregister_temporary;
using output::detail::written_file;
using Kind = output::detail::DestinationKind;

[[noreturn]] void fail(const fs::path& path, std::string_view what, int error) {
  output::detail::fail_to_write(path, what, error);
}

void write_all(int fd, std::string_view data, const fs::path& shown) {
  while (!data.empty()) {
    const ssize_t written = ::write(fd, data.data(), data.size());
    if (written < 0) {
      if (errno == EINTR) continue;
      fail(shown, "write failed", errno);
    }
    data.remove_prefix(static_cast<std::size_t>(written));
  }
}

// ---------------------------------------------------------------------------------------
// An output being written: write() any number of times, finish() to flush and close
// (idempotent), commit() to make it the destination's content. Destroyed uncommitted, it
// leaves the destination as it was (a written-through device keeps what it was given).

class Output {
 public:
  Output() = default;
  Output(const Output&) = delete;
  Output& operator=(const Output&) = delete;
  virtual ~Output() = default;

  virtual void write(std::string_view data) = 0;
  virtual void finish() {}
  virtual void commit() { finish(); }
};

// One of the process's own descriptors, written at its offset as it stands and left open.
class DescriptorOutput final : public Output {
 public:
  explicit DescriptorOutput(const Destination& destination)
      : shown_(destination.shown), fd_(destination.fd) {
    // Whatever the program printed before on standard output or error comes first.
    if (fd_ == STDOUT_FILENO) {
      std::cout.flush();
      if (!std::cout) fail(shown_, "earlier output failed", EIO);
      if (std::fflush(stdout) != 0) fail(shown_, "earlier output failed", errno);
    } else if (fd_ == STDERR_FILENO) {
      std::cerr.flush();
      std::clog.flush();
      (void)std::fflush(stderr);
    }
  }
  void write(std::string_view data) override { write_all(fd_, data, shown_); }

 private:
  fs::path shown_;
  int fd_;
};

class ThroughFile final : public Output {
 public:
  // Opened in place: no O_CREAT and no O_TRUNC, so that should the device have become a
  // regular file since it was examined, that file is neither made nor cut short. A link on
  // /proc that leads to a regular file is appended to, as `>>` would.
  explicit ThroughFile(const Destination& destination) : shown_(destination.shown) {
    const int append = destination.kind == Kind::kProcLink ? O_APPEND : 0;
    do {
      fd_ = ::open(destination.target.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC | append);
    } while (fd_ < 0 && errno == EINTR);
    if (fd_ < 0) fail(shown_, "cannot open it", errno);
  }
  ~ThroughFile() override {
    if (fd_ >= 0) ::close(fd_);
  }

  int fd() const { return fd_; }
  void write(std::string_view data) override { write_all(fd_, data, shown_); }
  void finish() override {
    if (fd_ < 0) return;
    // No fsync: devices and FIFOs do not support it. Close errors still count: a device
    // may report a failed write only here.
    const int result = ::close(fd_);
    fd_ = -1;
    if (result != 0 && errno != EINTR) fail(shown_, "close failed", errno);
  }

 private:
  fs::path shown_;
  int fd_ = -1;
};

// ".<name>.tmp-<pid>-<n>-<random>": hidden, recognisable, and unique enough that O_EXCL
// only has to guard against the astronomically unlikely collision. The name is cut short
// so that the temporary name stays within the 255 bytes a file name may have.
fs::path temporary_name(const fs::path& target) {
  static std::atomic<unsigned long> counter{0};
  static thread_local std::mt19937_64 random{std::random_device{}()};
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on `"." + std::string`.
  std::string name(1, '.');
  name += target.filename().native().substr(0, 160);
  name += ".tmp-";
  name += std::to_string(static_cast<long>(::getpid()));
  name += '-';
  name += std::to_string(counter.fetch_add(1));
  name += '-';
  name += std::to_string(random() % 1000000007ULL);
  return target.parent_path() / name;
}

class TemporaryFile final : public Output {
 public:
  explicit TemporaryFile(const Destination& destination)
      : shown_(destination.shown), target_(destination.target) {
    install_temporary_file_cleanup();
    for (int attempt = 0; attempt < 100 && fd_ < 0; ++attempt) {
      path_ = temporary_name(target_);
      // Registered before it exists: a signal in between only unlinks a missing name.
      slot_ = register_temporary(path_);
      // 0666 and the process's umask: the same permissions as an ordinary new file.
      fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
      if (fd_ >= 0) break;
      const int error = errno;
      unregister_temporary(slot_);
      slot_ = -1;
      if (error != EEXIST && error != EINTR) fail(shown_, "cannot create a temporary file", error);
    }
    if (fd_ < 0) fail(shown_, "cannot create a temporary file", EEXIST);
    if (destination.kind == Kind::kReplace) {
      try {
        take_over(destination.existing);
      } catch (...) {
        discard();  // no destructor runs for a constructor that throws
        throw;
      }
    }
  }
  ~TemporaryFile() override { discard(); }

  void write(std::string_view data) override { write_all(fd_, data, shown_); }

  void finish() override {
    if (fd_ < 0) return;
    // Flushed before the rename, so that a crash cannot leave a renamed but empty file.
    if (::fsync(fd_) != 0) fail(shown_, "fsync failed", errno);
    const int result = ::close(fd_);
    fd_ = -1;
    // Linux closes the descriptor even when close reports EINTR; it is not retried.
    if (result != 0 && errno != EINTR) fail(shown_, "close failed", errno);
  }

  void commit() override {
    finish();
    if (::rename(path_.c_str(), target_.c_str()) != 0) fail(shown_, "rename failed", errno);
    committed_ = true;
    sync_folder();
  }

 private:
  // The replaced file's owner, group and permission bits, set before any content is
  // written so that a private file's text is never readable by others meanwhile. Only
  // root may give a file away; others keep their own user and, where they belong to it,
  // the old group. A set-user-ID or set-group-ID bit is kept only with its owner or group.
  void take_over(const struct stat& old) {
    struct stat mine {};
    if (::fstat(fd_, &mine) != 0) fail(shown_, "cannot examine the temporary file", errno);
    if (mine.st_uid != old.st_uid || mine.st_gid != old.st_gid) {
      if (::fchown(fd_, old.st_uid, old.st_gid) != 0) {
        (void)::fchown(fd_, static_cast<uid_t>(-1), old.st_gid);
      }
      if (::fstat(fd_, &mine) != 0) fail(shown_, "cannot examine the temporary file", errno);
    }
    mode_t mode = old.st_mode & 07777;
    if (mine.st_uid != old.st_uid) mode &= ~static_cast<mode_t>(S_ISUID);
    if (mine.st_gid != old.st_gid) mode &= ~static_cast<mode_t>(S_ISGID);
    if (::fchmod(fd_, mode) != 0) fail(shown_, "cannot set the permissions", errno);
  }

  void discard() noexcept {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    // Unlinked before the slot is freed, so that a signal in between still finds it.
    if (!committed_) ::unlink(path_.c_str());
    unregister_temporary(slot_);
    slot_ = -1;
  }

  // Makes the rename itself durable. Best effort: the new content is complete and in
  // place already, and some file systems do not support syncing a folder.
  void sync_folder() const {
    const fs::path folder = target_.parent_path().empty() ? fs::path(".") : target_.parent_path();
    const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    (void)::fsync(fd);
    ::close(fd);
  }

  fs::path shown_;
  fs::path target_;
  fs::path path_;
  int fd_ = -1;
  int slot_ = -1;
  bool committed_ = false;
};

std::unique_ptr<Output> open_output(Destination destination) {
  // A write to a closed pipe or beyond the file size limit then fails with a message.
  install_temporary_file_cleanup();
  switch (destination.kind) {
    case Kind::kDescriptor:
      return std::make_unique<DescriptorOutput>(destination);
    case Kind::kProcLink:
      return std::make_unique<ThroughFile>(destination);
    case Kind::kThrough: {
      auto through = std::make_unique<ThroughFile>(destination);
      struct stat status {};
      if (::fstat(through->fd(), &status) != 0) fail(destination.shown, "cannot examine it", errno);
      if (!S_ISREG(status.st_mode)) return through;
      // It became a regular file after it was examined: that one is replaced as usual.
      destination.kind = Kind::kReplace;
      destination.existing = status;
      return std::make_unique<TemporaryFile>(destination);
    }
    case Kind::kNewFile:
    case Kind::kReplace:
      break;
  }
  return std::make_unique<TemporaryFile>(destination);
}

// Hands what `produce` makes to `output`, compressed where `path` is gzip_named.
void produce_into(Output& output, const fs::path& path,
                  const std::function<void(const OutputSink&)>& produce) {
  if (!gzip_named(path)) {
    produce([&output](std::string_view data) { output.write(data); });
    return;
  }
  compressed::GzipMembers members([&output](std::string_view data) { output.write(data); },
                                  kGzipOutputLevel);
  produce([&members](std::string_view text) { members.write(text); });
  members.finish();
}

void write_into(Output& output, const fs::path& path, std::string_view content) {
  produce_into(output, path, [content](const OutputSink& sink) { sink(content); });
}

}  // namespace

bool gzip_named(const std::filesystem::path& path) { return path.extension() == ".gz"; }

void write_file_atomically(const std::filesystem::path& path, std::string_view content) {
  const std::unique_ptr<Output> output = open_output(resolve(path));
  write_into(*output, path, content);
  output->commit();
}

void stream_file_atomically(const std::filesystem::path& path,
                            const std::function<void(const OutputSink&)>& produce) {
  const std::unique_ptr<Output> output = open_output(resolve(path));
  produce_into(*output, path, produce);
  output->commit();
}

void write_files_atomically(const std::vector<OutputText>& files) {
  std::vector<Destination> destinations;
  destinations.reserve(files.size());
  for (const OutputText& file : files) {
    destinations.push_back(resolve(file.path));
    const Destination& added = destinations.back();
    for (std::size_t i = 0; i + 1 < destinations.size(); ++i) {
      if (same_file(written_file(destinations[i]), written_file(added))) {
        fail(file.path, "named twice among the files written together", EINVAL);
      }
    }
  }

  // Every temporary file written and closed before any destination is touched.
  std::vector<std::unique_ptr<Output>> prepared(files.size());
  for (std::size_t i = 0; i < files.size(); ++i) {
    const Kind kind = destinations[i].kind;
    if (kind != Kind::kNewFile && kind != Kind::kReplace) continue;
    prepared[i] = std::make_unique<TemporaryFile>(destinations[i]);
    write_into(*prepared[i], files[i].path, files[i].content);
    prepared[i]->finish();
  }
  // Devices and standard output cannot be prepared: they take the text at commit time.
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (prepared[i]) {
      prepared[i]->commit();
    } else {
      const std::unique_ptr<Output> output = open_output(destinations[i]);
      write_into(*output, files[i].path, files[i].content);
      output->commit();
    }
  }
}

bool is_standard_stream(const std::filesystem::path& path) { return is_dash(path); }

bool same_output(const std::filesystem::path& a, const std::filesystem::path& b) {
  try {
    return same_file(written_file(resolve(a)), written_file(resolve(b)));
  } catch (const std::runtime_error&) {
    // A path that cannot be written at all: its write reports why.
    return !is_dash(a) && !is_dash(b) && same_file(a, b);
  }
}

bool same_file(const std::filesystem::path& a, const std::filesystem::path& b) {
  if (is_dash(a) || is_dash(b)) return false;
  struct stat status_a {};
  struct stat status_b {};
  if (::stat(a.c_str(), &status_a) == 0 && ::stat(b.c_str(), &status_b) == 0) {
    return status_a.st_dev == status_b.st_dev && status_a.st_ino == status_b.st_ino;
  }
  const auto comparable = [](const fs::path& path) {
    std::error_code error;
    fs::path resolved = fs::weakly_canonical(path, error);
    return error ? fs::absolute(path, error).lexically_normal() : resolved;
  };
  return comparable(a) == comparable(b);
}

}  // namespace shadowgen
