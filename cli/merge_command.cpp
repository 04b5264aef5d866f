// `shadowgen merge`: the shards of a sun-path run (generate --instants K/N) joined into
// the shadowed database one run makes.

#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <string>
#include <utility>
#include <vector>

#include "cli/command.h"
#include "cli/run_progress.h"
#include "shadowgen/output/database.h"
#include "shadowgen/pipeline/merge_shards.h"

namespace shadowgen::cli {
namespace {

constexpr CommandText kMergeText{
    "merge",
    "Join the N shards that generate --instants K/N wrote for K = 1..N (in any order) into "
    "the shadowed database of the whole run: the same file, byte for byte, as generate "
    "writes without --instants. Every shard must be there once, all of one scene."};

struct MergeArgs {
  std::vector<std::string> inputs;
  std::string output;
  ReadingArgs reading;
};

void run_merge(const MergeArgs& args) {
  LoadOptions options =
      load_options(args.reading, Accept::kShard, {args.inputs, {{"-o", args.output}}});
  RunProgress progress(args.output, progress_stream(args.reading.quiet));
  progress.watch(options);
  const int threads = args.reading.threads ? static_cast<int>(args.reading.threads)
                                           : tbb::info::default_concurrency();
  tbb::task_arena arena(threads);
  ShadowedScene merged = arena.execute([&] {
    std::vector<ShardFile> shards;
    for (const std::string& input : args.inputs) {
      progress.stage("reading shard " + std::to_string(shards.size() + 1) + "/" +
                     std::to_string(args.inputs.size()) + " (" + input + ")");
      shards.push_back({input, load_shadowed(input, options)});
    }
    progress.stage("joining " + std::to_string(shards.size()) + " shards");
    return merge_shards(std::move(shards));
  });
  progress.stage("writing");
  write_database(merged, args.output);
  progress.finish();
}

void add_merge_options(CLI::App& command, MergeArgs& args) {
  command.add_option("input", args.inputs, "the shards (generate --instants K/N), every K once")
      ->required();
  add_output_option(command, args.output, "the shadowed database to write")->required();
  command.add_flag("--strict", args.reading.strict, "reading warnings are errors");
  command.add_option("--threads", args.reading.threads,
                     "worker threads joining the faces' sums (0: one per hardware thread); the "
                     "result does not depend on them");
  command.add_flag("-q,--quiet", args.reading.quiet,
                   "do not print reading warnings or the progress line");
}

}  // namespace

Command add_merge_command(CLI::App& app) {
  return make_command<MergeArgs>(app, kMergeText, add_merge_options, run_merge);
}

}  // namespace shadowgen::cli
