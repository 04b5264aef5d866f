#include "cli/output_by_extension.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "cli/command.h"
#include "shadowgen/model/one_line.h"
#include "shadowgen/output/atomic_file.h"

namespace shadowgen::cli {
namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

[[noreturn]] void refuse_gzip(const std::string& option, const std::string& path,
                              const FormatOutput& format) {
  throw UsageError(option + " " + one_line(path) + ": a " + format.name +
                   " is compressed already; it is not written as gzip");
}

}  // namespace

CLI::Option* add_outputs_option(CLI::App& command, std::vector<std::string>& outputs,
                                const std::string& what) {
  return command.add_option("-o,--output", outputs, what)->allow_extra_args(false);
}

void assign_outputs(const std::vector<std::string>& outputs, std::vector<FormatOutput>& formats) {
  for (FormatOutput& format : formats) {
    if (format.path.empty()) continue;
    format.named_by = format.option;
    if (format.binary && gzip_named(format.path)) refuse_gzip(format.option, format.path, format);
  }
  for (const std::string& output : outputs) {
    const bool gzip = gzip_named(output);
    const std::filesystem::path named = output;
    const std::filesystem::path format_named = gzip ? named.stem() : named;
    const std::string extension = lower(format_named.extension().string());
    const auto format = std::find_if(formats.begin(), formats.end(), [&](const FormatOutput& f) {
      return f.extension == extension;
    });
    if (format == formats.end()) {
      std::string known;
      for (const FormatOutput& f : formats) {
        known += (known.empty() ? "" : " or ") + f.extension + " (" + f.name + ")";
      }
      throw UsageError("-o " + one_line(output) + ": the extension tells what to write: " + known);
    }
    if (gzip && format->binary) refuse_gzip("-o", output, *format);
    if (!format->path.empty()) {
      throw UsageError(format->named_by + " " + one_line(format->path) + " and -o " +
                       one_line(output) + " both name the " + format->name + "; give one");
    }
    format->path = output;
    format->named_by = "-o";
  }
}

}  // namespace shadowgen::cli
