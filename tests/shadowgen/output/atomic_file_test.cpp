// Whole-file output (shadowgen/output/atomic_file.h): the destination holds the old or the
// new content, never a part, and no temporary file is left behind, not even when a signal
// ends the process; links stay links, devices stay devices, "-" is standard output.

#include "shadowgen/output/atomic_file.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
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

  // A folder in the way is refused, not replaced or written into.
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

std::string error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "(no error)";
}

bool is_character_device(const fs::path& path) {
  struct stat status {};
  return ::lstat(path.c_str(), &status) == 0 && S_ISCHR(status.st_mode);
}

// -o onto a link replaced the link with a regular file; the link's target is what the
// user meant, and the link must stay.
TEST_F(AtomicFile, ALinkStaysALinkAndItsTargetIsReplaced) {
  const fs::path real = dir_ / "real.txt";
  write_file_atomically(real, "old\n");
  fs::create_symlink("real.txt", dir_ / "link.txt");
  fs::create_symlink("link.txt", dir_ / "link-to-link.txt");

  write_file_atomically(dir_ / "link.txt", "new\n");
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.txt"));
  EXPECT_EQ(fs::read_symlink(dir_ / "link.txt"), "real.txt");
  EXPECT_EQ(contents(real), "new\n");

  write_file_atomically(dir_ / "link-to-link.txt", "newer\n");
  EXPECT_TRUE(fs::is_symlink(dir_ / "link-to-link.txt"));
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.txt"));
  EXPECT_EQ(contents(real), "newer\n");
  EXPECT_EQ(file_count(), 3u);
}

TEST_F(AtomicFile, ALinkIntoAnotherFolderIsWrittenThere) {
  fs::create_directories(dir_ / "sub");
  write_file_atomically(dir_ / "sub" / "deep.txt", "old");
  fs::create_symlink(fs::path("sub") / "deep.txt", dir_ / "link.txt");
  // A dangling link makes the file it names, as a shell's redirection does.
  fs::create_symlink(fs::path("sub") / "made.txt", dir_ / "dangling.txt");

  write_file_atomically(dir_ / "link.txt", "new");
  write_file_atomically(dir_ / "dangling.txt", "made");
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.txt"));
  EXPECT_TRUE(fs::is_symlink(dir_ / "dangling.txt"));
  EXPECT_EQ(contents(dir_ / "sub" / "deep.txt"), "new");
  EXPECT_EQ(contents(dir_ / "sub" / "made.txt"), "made");
  EXPECT_EQ(file_count(), 3u);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_ / "sub"), fs::directory_iterator()), 2);
}

// Replacing /dev/null by a rename would, as root, leave the system a regular file there.
TEST_F(AtomicFile, ADeviceIsWrittenThroughAndStaysADevice) {
  ASSERT_TRUE(is_character_device("/dev/null"));
  write_file_atomically("/dev/null", "discarded\n");
  EXPECT_TRUE(is_character_device("/dev/null"));
  for (const auto& entry : fs::directory_iterator("/dev")) {
    EXPECT_NE(entry.path().filename().string().rfind(".null.tmp-", 0), 0u) << entry.path();
  }
}

TEST_F(AtomicFile, AFifoIsWrittenThrough) {
  const fs::path fifo = dir_ / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // The reading end opened first (without waiting for a writer); the text is smaller
  // than a pipe's buffer, so the write completes without a reading thread.
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  const std::string text(4000, 'f');
  EXPECT_NO_THROW(write_file_atomically(fifo, text));
  std::string received;
  char buffer[8192];
  for (ssize_t got; (got = ::read(reader, buffer, sizeof buffer)) > 0;) {
    received.append(buffer, static_cast<std::size_t>(got));
  }
  ::close(reader);
  EXPECT_EQ(received, text);
  struct stat status {};
  ASSERT_EQ(::lstat(fifo.c_str(), &status), 0);
  EXPECT_TRUE(S_ISFIFO(status.st_mode));
  EXPECT_EQ(file_count(), 1u);
}

// /dev/full accepts an open and fails every write: success would be a lie.
TEST_F(AtomicFile, AFullDeviceIsAnError) {
  if (!is_character_device("/dev/full")) GTEST_SKIP() << "no /dev/full here";
  const std::string error = error_of([] { write_file_atomically("/dev/full", "x"); });
  EXPECT_NE(error.find("/dev/full"), std::string::npos) << error;
  EXPECT_NE(error.find(std::strerror(ENOSPC)), std::string::npos) << error;
  EXPECT_TRUE(is_character_device("/dev/full"));
}

TEST_F(AtomicFile, KeepsThePermissionsOfTheReplacedFile) {
  for (const auto mode : {fs::perms(0640), fs::perms(0600), fs::perms(0444), fs::perms(0755)}) {
    const fs::path path = dir_ / "kept.txt";
    fs::remove(path);
    { std::ofstream(path) << "old"; }
    fs::permissions(path, mode);
    write_file_atomically(path, "new");
    EXPECT_EQ(fs::status(path).permissions() & fs::perms::all, mode);
    EXPECT_EQ(contents(path), "new");
  }
  EXPECT_EQ(file_count(), 1u);
}

TEST_F(AtomicFile, RootKeepsTheOwnerOfTheReplacedFile) {
  if (::geteuid() != 0) GTEST_SKIP() << "only root may give a file away";
  const fs::path path = dir_ / "owned.txt";
  { std::ofstream(path) << "old"; }
  ASSERT_EQ(::chown(path.c_str(), 65534, 65534), 0);
  ASSERT_EQ(::chmod(path.c_str(), 0640), 0);
  write_file_atomically(path, "new");
  struct stat status {};
  ASSERT_EQ(::stat(path.c_str(), &status), 0);
  EXPECT_EQ(status.st_uid, 65534u);
  EXPECT_EQ(status.st_gid, 65534u);
  EXPECT_EQ(status.st_mode & 07777, 0640u);
  EXPECT_EQ(contents(path), "new");
}

TEST_F(AtomicFile, SameFileSeesThroughLinksAndSpellings) {
  const fs::path a = dir_ / "a.json";
  const fs::path b = dir_ / "b.json";
  write_file_atomically(a, "a");
  write_file_atomically(b, "b");
  fs::create_symlink("a.json", dir_ / "soft.json");
  fs::create_hard_link(a, dir_ / "hard.json");

  EXPECT_TRUE(same_file(a, a));
  EXPECT_TRUE(same_file(a, dir_ / "soft.json"));
  EXPECT_TRUE(same_file(dir_ / "hard.json", a));
  EXPECT_TRUE(same_file(a, dir_ / "." / "sub" / ".." / "a.json"));
  EXPECT_FALSE(same_file(a, b));
  // Not there yet: compared by spelling.
  EXPECT_TRUE(same_file(dir_ / "new.json", dir_ / "." / "new.json"));
  EXPECT_FALSE(same_file(dir_ / "new.json", dir_ / "other.json"));
  EXPECT_FALSE(same_file(dir_ / "new.json", a));
  // Standard input is not standard output.
  EXPECT_FALSE(same_file("-", "-"));
  EXPECT_TRUE(is_standard_stream("-"));
  EXPECT_FALSE(is_standard_stream("./-"));
}

// Runs `action` with descriptor 1 sent to a pipe; returns what reached it.
std::string capture_standard_output(const std::function<void()>& action) {
  std::cout.flush();
  std::fflush(stdout);
  int ends[2];
  if (::pipe(ends) != 0) throw std::runtime_error("pipe");
  const int saved = ::dup(STDOUT_FILENO);
  ::dup2(ends[1], STDOUT_FILENO);
  ::close(ends[1]);
  try {
    action();
  } catch (...) {
    ::dup2(saved, STDOUT_FILENO);
    ::close(saved);
    ::close(ends[0]);
    throw;
  }
  ::dup2(saved, STDOUT_FILENO);
  ::close(saved);
  std::string received;
  char buffer[4096];
  for (ssize_t got; (got = ::read(ends[0], buffer, sizeof buffer)) > 0;) {
    received.append(buffer, static_cast<std::size_t>(got));
  }
  ::close(ends[0]);
  return received;
}

TEST_F(AtomicFile, DashIsStandardOutput) {
  const std::string received = capture_standard_output([] {
    std::cout << "before\n";  // printed earlier, so it comes first
    write_file_atomically("-", "the text\n");
    write_files_atomically({{"-", "and more\n"}});
  });
  EXPECT_EQ(received, "before\nthe text\nand more\n");
  EXPECT_EQ(file_count(), 0u);
}

// /dev/stdout is a link to /proc/self/fd/1, which names the open file behind descriptor 1,
// not a path to rename over: a shell's `{ echo before; … -o /dev/stdout; echo after; }
// > out.txt` keeps "before" and "after" around the text, and a pipe gets the text.
TEST_F(AtomicFile, ALinkToAnOpenDescriptorIsWrittenAtItsOffset) {
  const fs::path path = dir_ / "out.txt";
  std::cout.flush();
  std::fflush(stdout);
  const int file = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  ASSERT_GE(file, 0);
  ASSERT_EQ(::write(file, "before\n", 7), 7);
  struct stat before {};
  ASSERT_EQ(::fstat(file, &before), 0);
  const int saved = ::dup(STDOUT_FILENO);
  ::dup2(file, STDOUT_FILENO);
  std::string error;
  try {
    write_file_atomically("/dev/stdout", "one\n");
    write_file_atomically("/proc/self/fd/" + std::to_string(file), "two\n");
    write_files_atomically({{"/dev/fd/" + std::to_string(file), "three\n"}});
    stream_file_atomically("/dev/stdout", [](const OutputSink& sink) { sink("four\n"); });
  } catch (const std::exception& e) {
    error = e.what();
  }
  const bool after_written = ::write(STDOUT_FILENO, "after\n", 6) == 6;
  ::dup2(saved, STDOUT_FILENO);
  ::close(saved);
  ::close(file);
  EXPECT_EQ(error, "");
  EXPECT_TRUE(after_written);
  EXPECT_EQ(contents(path), "before\none\ntwo\nthree\nfour\nafter\n");
  struct stat now {};
  ASSERT_EQ(::stat(path.c_str(), &now), 0);
  EXPECT_EQ(now.st_ino, before.st_ino);  // written in place, not replaced
  EXPECT_EQ(file_count(), 1u);

  const std::string piped =
      capture_standard_output([] { write_file_atomically("/dev/stdout", "through a pipe\n"); });
  EXPECT_EQ(piped, "through a pipe\n");
}

TEST_F(AtomicFile, ADescriptorThatIsNotOpenIsAnError) {
  const int unused = ::dup(STDERR_FILENO);
  ASSERT_GE(unused, 0);
  ::close(unused);
  const std::string path = "/dev/fd/" + std::to_string(unused);
  EXPECT_EQ(error_of([&] { write_file_atomically(path, "x"); }),
            "cannot write '" + path + "': cannot open it: " + std::strerror(ENOENT));
}

// Two outputs are one file when a write of one would overwrite the other's: "-" is the
// file behind descriptor 1, as /dev/stdout is.
TEST_F(AtomicFile, SameOutputSeesStandardOutputAndLinks) {
  const fs::path a = dir_ / "a.txt";
  write_file_atomically(a, "a");
  fs::create_symlink("a.txt", dir_ / "soft.txt");
  fs::create_hard_link(a, dir_ / "hard.txt");
  EXPECT_TRUE(same_output("-", "-"));
  EXPECT_TRUE(same_output("-", "/dev/stdout"));
  EXPECT_TRUE(same_output("/proc/self/fd/1", "-"));
  EXPECT_TRUE(same_output(a, dir_ / "soft.txt"));
  EXPECT_TRUE(same_output(dir_ / "hard.txt", a));
  EXPECT_TRUE(same_output(dir_ / "new.txt", dir_ / "." / "new.txt"));
  EXPECT_FALSE(same_output(a, dir_ / "new.txt"));
  EXPECT_FALSE(same_output("-", a));
}

TEST_F(AtomicFile, AFailingStandardOutputIsAnError) {
  if (!is_character_device("/dev/full")) GTEST_SKIP() << "no /dev/full here";
  std::cout.flush();
  std::fflush(stdout);
  const int full = ::open("/dev/full", O_WRONLY);
  ASSERT_GE(full, 0);
  const int saved = ::dup(STDOUT_FILENO);
  ::dup2(full, STDOUT_FILENO);
  ::close(full);
  const std::string error = error_of([] { write_file_atomically("-", "x"); });
  ::dup2(saved, STDOUT_FILENO);
  ::close(saved);
  EXPECT_NE(error.find("standard output"), std::string::npos) << error;
  EXPECT_NE(error.find(std::strerror(ENOSPC)), std::string::npos) << error;
}

TEST_F(AtomicFile, WritesSeveralFilesTogether) {
  const fs::path mtl = dir_ / "out.mtl";
  const fs::path obj = dir_ / "out.obj";
  write_files_atomically({{mtl, "mtl 1"}, {obj, "obj 1"}});
  EXPECT_EQ(contents(mtl), "mtl 1");
  EXPECT_EQ(contents(obj), "obj 1");
  const std::string second = "obj 2";
  write_files_atomically({{mtl, "mtl 2"}, {obj, second}});
  EXPECT_EQ(contents(mtl), "mtl 2");
  EXPECT_EQ(contents(obj), "obj 2");
  EXPECT_EQ(file_count(), 2u);
}

// A failed OBJ write used to delete the user's existing MTL.
TEST_F(AtomicFile, AFailedSetLeavesEveryFileAsItWas) {
  const fs::path mtl = dir_ / "out.mtl";
  const fs::path obj = dir_ / "out.obj";
  write_file_atomically(mtl, "old mtl");
  write_file_atomically(obj, "old obj");

  // The second temporary file cannot be made: the first, already written, goes too.
  EXPECT_THROW(write_files_atomically({{mtl, "new mtl"}, {dir_ / "no" / "out.obj", "x"}}),
               std::runtime_error);
  // A folder in the way is found before anything is written.
  fs::create_directories(dir_ / "taken");
  EXPECT_THROW(write_files_atomically({{mtl, "new mtl"}, {dir_ / "taken", "x"}}),
               std::runtime_error);
  // One file named twice (here through a link) would be written twice.
  fs::create_symlink("out.mtl", dir_ / "alias.mtl");
  EXPECT_THROW(write_files_atomically({{mtl, "new mtl"}, {dir_ / "alias.mtl", "x"}}),
               std::runtime_error);

  EXPECT_EQ(contents(mtl), "old mtl");
  EXPECT_EQ(contents(obj), "old obj");
  EXPECT_EQ(file_count(), 4u);  // out.mtl, out.obj, taken, alias.mtl
}

TEST_F(AtomicFile, StreamsContentAndDiscardsItWhenTheProducerFails) {
  const fs::path path = dir_ / "streamed.txt";
  stream_file_atomically(path, [](const OutputSink& sink) {
    sink("one ");
    sink("two\n");
  });
  EXPECT_EQ(contents(path), "one two\n");

  const std::string error = error_of([&] {
    stream_file_atomically(path, [](const OutputSink& sink) {
      sink("partial");
      throw std::runtime_error("the producer stopped");
    });
  });
  EXPECT_EQ(error, "the producer stopped");
  EXPECT_EQ(contents(path), "one two\n");
  EXPECT_EQ(file_count(), 1u);
}

// A child process writes slowly and is ended by `signal_number` in the middle: it must
// die of that signal, leaving the old destination and no temporary file.
void expect_signal_removes_the_temporary(const fs::path& dir, int signal_number) {
  const fs::path path = dir / "slow.txt";
  write_file_atomically(path, "old\n");
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::close(ready[0]);
    // As in a program started normally (a background job may inherit an ignored SIGINT).
    ::signal(signal_number, SIG_DFL);
    const struct rlimit no_core { 0, 0 };  // SIGQUIT and SIGXCPU would dump one
    ::setrlimit(RLIMIT_CORE, &no_core);
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    try {
      stream_file_atomically(path, [&](const OutputSink& sink) {
        sink(std::string(1 << 20, 'n'));
        const char byte = 'r';
        if (::write(ready[1], &byte, 1) != 1) ::_exit(4);
        for (int i = 0; i < 20000; ++i) {  // about 20 s at most, should the signal not come
          ::usleep(1000);
          sink("n");
        }
      });
    } catch (...) {
      ::_exit(5);
    }
    ::_exit(6);
  }
  ::close(ready[1]);
  char byte = 0;
  const ssize_t got = ::read(ready[0], &byte, 1);
  ::close(ready[0]);
  if (got == 1) {
    // The temporary file exists now, beside the destination.
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 2);
    ::kill(child, signal_number);
  } else {
    ADD_FAILURE() << "the child did not start writing";
    ::kill(child, SIGKILL);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFSIGNALED(status)) << "status " << status;
  if (WIFSIGNALED(status)) {
    EXPECT_EQ(WTERMSIG(status), signal_number);
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "old\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST_F(AtomicFile, SigtermRemovesTheTemporaryFile) {
  expect_signal_removes_the_temporary(dir_, SIGTERM);
}

TEST_F(AtomicFile, SigintRemovesTheTemporaryFile) {
  expect_signal_removes_the_temporary(dir_, SIGINT);
}

TEST_F(AtomicFile, SighupRemovesTheTemporaryFile) {
  expect_signal_removes_the_temporary(dir_, SIGHUP);
}

TEST_F(AtomicFile, SigquitRemovesTheTemporaryFile) {
  expect_signal_removes_the_temporary(dir_, SIGQUIT);
}

TEST_F(AtomicFile, SigalrmRemovesTheTemporaryFile) {
  expect_signal_removes_the_temporary(dir_, SIGALRM);
}

TEST_F(AtomicFile, Sigusr1RemovesTheTemporaryFile) {
  expect_signal_removes_the_temporary(dir_, SIGUSR1);
}

TEST_F(AtomicFile, SigxcpuRemovesTheTemporaryFile) {
  expect_signal_removes_the_temporary(dir_, SIGXCPU);
}

// What `action` did in a child process where `signal_number` has its default action, as
// in a program started normally: "exit N", "signal N", or the message it threw.
std::string outcome_in_child(int signal_number, const std::function<void()>& action) {
  int message[2];
  if (::pipe(message) != 0) return "no pipe";
  const pid_t child = ::fork();
  if (child < 0) return "no fork";
  if (child == 0) {
    ::close(message[0]);
    ::signal(signal_number, SIG_DFL);
    try {
      action();
    } catch (const std::exception& e) {
      const std::string what = e.what();
      if (::write(message[1], what.data(), what.size()) < 0) ::_exit(4);
      ::_exit(0);
    }
    ::_exit(3);
  }
  ::close(message[1]);
  std::string received;
  char buffer[1024];
  for (ssize_t got; (got = ::read(message[0], buffer, sizeof buffer)) > 0;) {
    received.append(buffer, static_cast<std::size_t>(got));
  }
  ::close(message[0]);
  int status = 0;
  if (::waitpid(child, &status, 0) != child) return "no wait";
  if (WIFSIGNALED(status)) return "signal " + std::to_string(WTERMSIG(status));
  if (WEXITSTATUS(status) != 0) return "exit " + std::to_string(WEXITSTATUS(status));
  return received;
}

// Beyond the file size limit (`ulimit -f`) the write fails with a message naming the file,
// instead of SIGXFSZ ending the process with its temporary file left behind.
TEST_F(AtomicFile, TheFileSizeLimitIsAWriteErrorAndLeavesNoTemporaryFile) {
  const fs::path path = dir_ / "big.txt";
  write_file_atomically(path, "old\n");
  const std::string outcome = outcome_in_child(SIGXFSZ, [&] {
    const struct rlimit limit { 1 << 16, 1 << 16 };
    if (::setrlimit(RLIMIT_FSIZE, &limit) != 0) throw std::runtime_error("no limit");
    write_file_atomically(path, std::string(1 << 20, 'x'));
  });
  EXPECT_EQ(outcome, "cannot write '" + path.string() + "': write failed: " + std::strerror(EFBIG));
  EXPECT_EQ(contents(path), "old\n");
  EXPECT_EQ(file_count(), 1u);
}

// A pipe whose reader has gone: the write fails with a message, instead of SIGPIPE ending
// the process without a word.
TEST_F(AtomicFile, APipeNobodyReadsIsAWriteError) {
  const fs::path fifo = dir_ / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string outcome = outcome_in_child(SIGPIPE, [&] {
    int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
    if (reader < 0) throw std::runtime_error("no reader");
    stream_file_atomically(fifo, [&](const OutputSink& sink) {
      sink("read\n");
      ::close(reader);
      sink("never read\n");
    });
  });
  EXPECT_EQ(outcome, "cannot write '" + fifo.string() + "': write failed: " + std::strerror(EPIPE));
  EXPECT_EQ(file_count(), 1u);
}

// nohup and background jobs ignore signals on purpose; writing a file must not undo it.
TEST_F(AtomicFile, AnIgnoredSignalStaysIgnored) {
  const fs::path path = dir_ / "out.txt";
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::signal(SIGHUP, SIG_IGN);
    ::signal(SIGTERM, SIG_DFL);
    try {
      write_file_atomically(path, "x");
    } catch (...) {
      ::_exit(3);
    }
    struct sigaction hup {};
    struct sigaction term {};
    ::sigaction(SIGHUP, nullptr, &hup);
    ::sigaction(SIGTERM, nullptr, &term);
    if (hup.sa_handler != SIG_IGN) ::_exit(1);
    if (term.sa_handler == SIG_DFL) ::_exit(2);  // the default one gets the cleanup
    ::_exit(0);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_EQ(contents(path), "x");
}

}  // namespace
}  // namespace shadowgen
