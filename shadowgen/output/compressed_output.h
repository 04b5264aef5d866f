#pragma once

// Files written compressed as their name asks: a path ending in ".gz" is written as gzip
// (RFC 1952) in independent members compressed on the calling task arena's threads
// (shadowgen/compressed/gzip_members.h), so that `zcat FILE.gz` gives exactly the bytes
// the plain file would have held; any other path gets the plain text. Either way the file
// is written as stream_file_atomically writes it (shadowgen/output/atomic_file.h): never
// half-written.

#include <filesystem>
#include <functional>

#include "shadowgen/output/atomic_file.h"

namespace shadowgen {

// The level files named *.gz are written at. Measured on a day of sun-hours regions of the
// 30,000-face district (132 MB of text, members of 4 MiB; bench/RESULTS.md): level 1 makes
// 6.5 times the scene in 1.3 CPU seconds, 6 (zlib's default) 5.5 times in 5.4 s, 9 5.5
// times in 6.8 s. Level 1 keeps the database well within 10 times its scene, and its
// compression keeps pace with the one thread that writes the text (the other compresses),
// so that a gzip database is written in the wall time of a plain one; 6 would make the
// compression four times the work for 15 % fewer bytes.
inline constexpr int kDatabaseGzipLevel = 1;

// Whether `path` names a file to be written as gzip: its name ends in ".gz".
bool gzip_named(const std::filesystem::path& path);

// As stream_file_atomically, compressed at `level` where gzip_named(path).
void stream_file_compressed_as_named(const std::filesystem::path& path,
                                     const std::function<void(const OutputSink&)>& produce,
                                     int level = kDatabaseGzipLevel);

}  // namespace shadowgen
