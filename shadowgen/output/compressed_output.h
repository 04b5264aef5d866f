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
// 30,000-face district (bench/RESULTS.md): level 6 (zlib's default) makes the file 3 %
// larger than 9 in a quarter of its time, and 1 makes it 25 % larger than 6 for half the
// time; 6 keeps the database within 10 × its scene at the cost of one core for the
// compression, which other threads take.
inline constexpr int kDatabaseGzipLevel = 6;

// Whether `path` names a file to be written as gzip: its name ends in ".gz".
bool gzip_named(const std::filesystem::path& path);

// As stream_file_atomically, compressed at `level` where gzip_named(path).
void stream_file_compressed_as_named(const std::filesystem::path& path,
                                     const std::function<void(const OutputSink&)>& produce,
                                     int level = kDatabaseGzipLevel);

}  // namespace shadowgen
