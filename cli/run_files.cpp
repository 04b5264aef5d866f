#include "cli/run_files.h"

#include <utility>

#include "cli/command.h"
#include "shadowgen/output/atomic_file.h"

namespace shadowgen::cli {

void refuse_unsafe_outputs(const std::vector<OutputFile>& writes,
                           const std::vector<std::string>& reads) {
  for (std::size_t i = 0; i < writes.size(); ++i) {
    const OutputFile& output = writes[i];
    for (const std::string& input : reads) {
      if (same_file(output.path, input)) {
        throw UsageError(output.option + " " + output.path + ": is the input " + input +
                         "; it would be replaced");
      }
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (same_output(writes[j].path, output.path)) {
        throw UsageError(writes[j].option + " " + writes[j].path + " and " + output.option + " " +
                         output.path + " name the same file; one would be lost");
      }
    }
  }
}

void guard_outputs(LoadOptions& options, const RunFiles& files) {
  refuse_unsafe_outputs(files.writes, files.reads);
  if (files.writes.empty()) return;
  options.on_scene = [writes = files.writes,
                      then = std::move(options.on_scene)](const Scene& scene) {
    refuse_unsafe_outputs(writes, scene.files);
    if (then) then(scene);
  };
}

void guard_outputs(api::LoadSettings& settings, const RunFiles& files) {
  refuse_unsafe_outputs(files.writes, files.reads);
  if (files.writes.empty()) return;
  settings.on_scene = [writes = files.writes,
                       then = std::move(settings.on_scene)](const api::Scene& scene) {
    refuse_unsafe_outputs(writes, scene.files());
    if (then) then(scene);
  };
}

}  // namespace shadowgen::cli
