#pragma once

// The warnings of what the reader does not apply (skins, morph targets), one kind at a
// time, as the scene format summarises a kind of warning (docs/scene-format.md,
// "Reading rules"): a kind that more than three nodes or primitives draw is one line,
// how many and the first three; fewer keep a line each.
//
//   house.gltf: node 'arm' (4): its skin is not applied: ...
//   house.gltf: 12 primitives: morph targets are not applied: the base positions are
//   read: node 0, mesh 0, primitive 0; node 1, ...; node 2, ...; ...

#include <cstddef>
#include <string>
#include <vector>

namespace shadowgen::gltf::detail {

class FeatureWarnings {
 public:
  // `file` names the glTF file; `what` the kind ("its skin is not applied: ..."), said of
  // `things` ("nodes", "primitives") when summarised.
  FeatureWarnings(std::string file, std::string things, std::string what);

  void add(std::string subject);  // "node 'arm' (4)"

  void append_to(std::vector<std::string>& warnings) const;

 private:
  std::string file_, things_, what_;
  std::vector<std::string> subjects_;
};

}  // namespace shadowgen::gltf::detail
