#include "temporary_files.h"

#include <limits.h>
#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <system_error>

#include "shadowgen/output/atomic_file.h"

namespace shadowgen {
namespace {

// The temporary files being written, for the signal handlers. A handler may only use
// async-signal-safe calls, so the table is preallocated and each slot's state is a
// lock-free atomic: claimed with a compare-and-swap (no lock a handler could interrupt),
// filled, then published as live; the handler unlinks the live ones.

constexpr int kSlotFree = 0;
constexpr int kSlotFilling = 1;
constexpr int kSlotLive = 2;

struct TemporarySlot {
  std::atomic<int> state{kSlotFree};
  std::array<char, PATH_MAX> path{};
};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler reads slot states");

// More writes at once than this (threads writing many files together) go unprotected
// against signals; they are still removed on every failure the program sees.
constexpr std::size_t kSlots = 64;
std::array<TemporarySlot, kSlots> temporary_slots;

// The signals whose default action ends the process (signal(7)), real-time ones aside:
// their handler removes the temporary files first. The faults are among them, so that a
// crash in the middle of a write leaves nothing either.
constexpr std::array kCleanupSignals = {
    SIGHUP, SIGINT, SIGQUIT,   SIGTERM, SIGALRM, SIGUSR1, SIGUSR2, SIGXCPU, SIGVTALRM, SIGPROF,
    SIGIO,  SIGPWR, SIGSTKFLT, SIGABRT, SIGBUS,  SIGFPE,  SIGILL,  SIGSEGV, SIGSYS,    SIGTRAP};

// Signals a failed write raises, ignored so that the write fails with an error the
// writer reports instead: EPIPE (a pipe nobody reads) and EFBIG (beyond RLIMIT_FSIZE).
constexpr std::array kIgnoredSignals = {SIGPIPE, SIGXFSZ};

// Whether `signal_number` still has its default action, which alone is replaced: an
// ignored signal (nohup, a background job) stays ignored, and a program's own handler
// stays in charge.
bool has_default_action(int signal_number) {
  struct sigaction current {};
  if (::sigaction(signal_number, nullptr, &current) != 0) return false;
  return (current.sa_flags & SA_SIGINFO) == 0 && current.sa_handler == SIG_DFL;
}

extern "C" void remove_temporaries_and_reraise(int signal_number) {
  const int saved_errno = errno;
  remove_temporary_files();
  // SA_RESETHAND restored the default action on entry, and the signal is blocked while
  // this handler runs: raised again, it ends the process as soon as the handler returns,
  // with the status a parent expects from that signal.
  ::raise(signal_number);
  errno = saved_errno;
}

}  // namespace

namespace output::detail {

int register_temporary(const std::filesystem::path& path) {
  // Absolute, so that a change of the working folder cannot send the unlink elsewhere.
  std::error_code error;
  const std::filesystem::path absolute = std::filesystem::absolute(path, error);
  if (error || absolute.native().size() >= PATH_MAX) return -1;
  for (std::size_t i = 0; i < kSlots; ++i) {
    TemporarySlot& slot = temporary_slots[i];
    int expected = kSlotFree;
    if (!slot.state.compare_exchange_strong(expected, kSlotFilling)) continue;
    std::memcpy(slot.path.data(), absolute.c_str(), absolute.native().size() + 1);
    slot.state.store(kSlotLive, std::memory_order_release);
    return static_cast<int>(i);
  }
  return -1;
}

void unregister_temporary(int slot) {
  if (slot >= 0) temporary_slots[static_cast<std::size_t>(slot)].state.store(kSlotFree);
}

}  // namespace output::detail

void install_temporary_file_cleanup() {
  for (const int signal_number : kIgnoredSignals) {
    if (has_default_action(signal_number)) ::signal(signal_number, SIG_IGN);
  }
  for (const int signal_number : kCleanupSignals) {
    if (!has_default_action(signal_number)) continue;
    struct sigaction action {};
    action.sa_handler = remove_temporaries_and_reraise;
    sigemptyset(&action.sa_mask);
    // One cleanup at a time: the other signals wait while a handler runs.
    for (const int other : kCleanupSignals) sigaddset(&action.sa_mask, other);
    action.sa_flags = SA_RESETHAND | SA_RESTART;
    ::sigaction(signal_number, &action, nullptr);
  }
}

void remove_temporary_files() noexcept {
  for (TemporarySlot& slot : temporary_slots) {
    if (slot.state.load(std::memory_order_acquire) == kSlotLive) ::unlink(slot.path.data());
  }
}

}  // namespace shadowgen
