#pragma once

// Whole-file output that never leaves a partial file behind.
//
// What a destination path names decides how it is written:
//  - "-" is standard output: the text is written to descriptor 1 (after flushing
//    std::cout and C's stdout, so nothing printed earlier comes after it). A file really
//    named "-" is reached as "./-".
//  - A link on /proc is a handle on an open file, not a name: it is written in place,
//    never renamed over. One of this process's own descriptors (/dev/stdout, /dev/stderr,
//    /dev/fd/N, /proc/self/fd/N: links to /proc/self/fd) is written as "-" is, through the
//    descriptor itself at its offset as it stands: a regular file behind it keeps what
//    was written there before and gets the text after it, as from a shell redirection
//    (`{ echo before; shadowgen … -o /dev/stdout; } > out.txt` gives "before" and then
//    the text). Any other link on /proc (another process's descriptor) is opened and
//    appended to. A descriptor that is not open is an error ("cannot open it").
//  - A symbolic link is followed to its final target (a dangling link to the file it
//    would name): the target is replaced and the link stays a link.
//  - A regular file, or no file yet, is replaced whole: the content goes to a fresh
//    temporary file in the target's folder (so the rename stays on one file system),
//    which takes the old file's permission bits (and owner and group where the process
//    may set them: as root), is flushed to disk, and then replaces the target with one
//    rename. A reader sees the old file or the complete new one; on any failure the
//    temporary file is removed and the target is untouched. A new file gets the
//    ordinary permissions (0666 less the umask). Extended attributes and ACLs are not
//    carried over, and a replaced file loses its other hard links (as with editors).
//  - Anything else that exists (a character device such as /dev/null, a FIFO, ...) is
//    written through: opened, written and closed in place, since it cannot be replaced
//    by a rename without destroying it. Such a write is not atomic; every write and the
//    close are checked, so /dev/full fails with "No space left on device".
//  - A folder is refused.
//
// Compression: a path whose name ends in ".gz" (gzip_named) gets the content as gzip
// (RFC 1952), in independent members compressed on the calling task arena's threads at
// kGzipOutputLevel (shadowgen/compressed/gzip_members.h), so that `gzip -dc FILE.gz` gives
// exactly the bytes the plain file would have held; the rules above apply to the
// compressed bytes as they do to plain text. This holds for every function below and so
// for every file the project writes through them: databases, reports, SVG pictures,
// models. A binary format that gains nothing from it (a PNG, a binary glTF) is for the
// caller to refuse under such a name.
//
// Signals: the paths of the temporary files being written are kept in a fixed,
// preallocated table. Handlers for the signals whose default action ends the process
// (SIGHUP, SIGINT, SIGQUIT, SIGTERM, SIGALRM, SIGUSR1, SIGUSR2, SIGXCPU, SIGVTALRM,
// SIGPROF, SIGIO, SIGPWR, SIGSTKFLT, and the faults SIGABRT, SIGBUS, SIGFPE, SIGILL,
// SIGSEGV, SIGSYS, SIGTRAP) remove them and then end the process by the same signal, as
// it would have ended without them. SIGPIPE and SIGXFSZ are ignored instead, so that a
// write to a pipe nobody reads, or beyond the file size limit (`ulimit -f`), fails
// ("write failed: Broken pipe", "write failed: File too large") as any failed write does:
// the temporary file is removed and the error names the path. All of this is installed
// the first time an output is opened, or earlier by install_temporary_file_cleanup, and
// only where a signal has its default action: a signal ignored (nohup, a background job)
// or with the program's own handler is left as it is; a program with its own handler can
// call remove_temporary_files() from it. A SIGPIPE or SIGXFSZ ignored here is ignored in
// the programs this process starts, too. Only what no handler sees (SIGKILL, a power
// cut, a real-time signal) can leave a temporary file, named ".NAME.tmp-PID-N-RANDOM"
// beside the destination.
//
// Every function throws std::runtime_error "cannot write 'PATH': WHAT: REASON" (or
// "cannot write standard output: ...") naming the path as given.

#include <filesystem>
#include <functional>
#include <string_view>
#include <vector>

namespace shadowgen {

// The level files named *.gz are written at. Measured on a day of sun-hours regions of the
// 30,000-face district (132 MB of text, members of 4 MiB; bench/RESULTS.md): level 1 makes
// 6.5 times the scene in 1.3 CPU seconds, 6 (zlib's default) 5.5 times in 5.4 s, 9 5.5
// times in 6.8 s. Level 1 keeps the database well within 10 times its scene, and its
// compression keeps pace with the one thread that writes the text (the other compresses),
// so that a gzip database is written in the wall time of a plain one; 6 would make the
// compression four times the work for 15 % fewer bytes. Reports and pictures are smaller
// than databases and take the same level.
inline constexpr int kGzipOutputLevel = 1;

// Whether `path` names a file to be written as gzip: its name ends in ".gz" (lower case,
// as gzip names its files).
bool gzip_named(const std::filesystem::path& path);

void write_file_atomically(const std::filesystem::path& path, std::string_view content);

// Receives the content piece by piece, in order.
using OutputSink = std::function<void(std::string_view)>;

// As write_file_atomically, for content made while it is written: `produce` is called
// once with a sink for it. If `produce` throws, the temporary file is removed, the
// destination is untouched (a written-through device has had what was written so far)
// and the exception propagates.
void stream_file_atomically(const std::filesystem::path& path,
                            const std::function<void(const OutputSink&)>& produce);

// One file of a set written together; `content` must outlive the call.
struct OutputText {
  std::filesystem::path path;
  std::string_view content;
};

// Writes several files as one: every destination is examined and every temporary file
// written, flushed and closed first; only then are they committed, in the order given
// (renamed into place, or written through for devices and standard output). A failure
// before the commits leaves every destination untouched and no temporary file behind.
// The commits themselves are not jointly atomic: a failure or a crash in the middle of
// them (a rename refused, a device that fails) leaves the files committed before it new
// and those after it old. Put the file that refers to the others last (the OBJ after its
// MTL), so that any reader sees either the old files or a consistent new set. A path
// that names the same file as an earlier one is refused before anything is written.
void write_files_atomically(const std::vector<OutputText>& files);

// Whether `path` is "-", standard input or output.
bool is_standard_stream(const std::filesystem::path& path);

// Whether writing `a` and writing `b` would write one file, so that one write would lose
// the other: as same_file, the links to follow followed as a write follows them, and "-"
// being the file behind descriptor 1 (so "-" is "-", and is /dev/stdout).
bool same_output(const std::filesystem::path& a, const std::filesystem::path& b);

// Whether the two paths name the same file: by device and inode when both exist
// (following symbolic links, so a link or a hard link to a file is that file), otherwise
// by their canonical spellings ("." and ".." and the existing part's links resolved).
// "-" is never the same file as anything: as an input it is standard input, as an output
// standard output.
bool same_file(const std::filesystem::path& a, const std::filesystem::path& b);

// Installs the signal handling described above (handlers, SIGPIPE and SIGXFSZ ignored)
// where those signals have their default action; idempotent. Opening an output installs
// it already; a program may call this at its start to settle its signal handling up
// front (so that standard output written with std::cout also fails on a closed pipe
// rather than ending the process without a word).
void install_temporary_file_cleanup();

// Removes the temporary files being written right now. Async-signal-safe, for a
// program's own signal handler; the interrupted writes then fail when they continue.
void remove_temporary_files() noexcept;

}  // namespace shadowgen
