#pragma once

// -o/--output is how every subcommand names its output file. A subcommand that writes
// several formats (render: SVG and PNG; export: OBJ) tells them by the file's extension,
// and may take -o once per format; its older options that name one format's file
// (--svg, --png, --obj) keep naming it. -o and such an option for the same format is a
// usage error naming both, as are two -o for one format and an extension of no format.
// A name ending in ".gz" after the extension (`-o plan.svg.gz`) is that format written as
// gzip (shadowgen/output/atomic_file.h), but for a binary format, which it refuses.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace shadowgen::cli {

// One format a subcommand writes, and the file it goes to.
struct FormatOutput {
  std::string name;       // as messages say it: "SVG picture"
  std::string extension;  // ".svg", compared without regard to case
  std::string option;     // the older option naming this format's file: "--svg"
  std::string path;       // the file; empty when none is named
  std::string named_by;   // the option that named it ("-o" or `option`), for messages
  bool binary = false;    // gzip gains nothing: a name ending in ".gz" is refused
};

// -o/--output on `command` for a subcommand writing several formats: given once per
// format, each time one file (never the words after it, which may be the input).
CLI::Option* add_outputs_option(CLI::App& command, std::vector<std::string>& outputs,
                                const std::string& what);

// `formats` with their `path` as the older options gave them (empty: not given), and
// `outputs` the -o files: each -o file given to the format of its extension. Sets
// `named_by` of every format named. Throws UsageError:
//   "-o x.jpg: the extension tells what to write: .svg (SVG picture) or .png (PNG picture)"
//   "-o x.svg and --svg y.svg both name the SVG picture; give one"
//   "-o x.png.gz: a PNG picture is compressed already; it is not written as gzip"
void assign_outputs(const std::vector<std::string>& outputs, std::vector<FormatOutput>& formats);

}  // namespace shadowgen::cli
