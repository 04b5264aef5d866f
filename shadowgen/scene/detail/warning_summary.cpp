#include "detail/warning_summary.h"

#include <algorithm>
#include <utility>

#include "detail/face_builder.h"
#include "shadowgen/scene/read_options.h"

namespace shadowgen::scene::detail {

WarningSummary::WarningSummary(std::string file, std::string group)
    : file_(std::move(file)), group_(std::move(group)) {}

void WarningSummary::add(const std::string& face_id, std::string line) {
  const std::string prefix = face_message(file_, face_id, "");
  std::string what = line.rfind(prefix, 0) == 0 ? line.substr(prefix.size()) : line;
  std::string kind = what.substr(0, std::min(what.find(" ("), what.find(':')));
  auto it =
      std::find_if(kinds_.begin(), kinds_.end(), [&kind](const Kind& k) { return k.name == kind; });
  if (it == kinds_.end()) it = kinds_.insert(kinds_.end(), Kind{std::move(kind), {}, {}});
  it->face_ids.push_back(face_id);
  it->lines.push_back(std::move(line));
}

void WarningSummary::append_to(std::vector<std::string>& warnings, bool verbose) const {
  for (const Kind& kind : kinds_) {
    const std::size_t n = kind.face_ids.size();
    if (verbose || n <= static_cast<std::size_t>(kWarningsListed)) {
      warnings.insert(warnings.end(), kind.lines.begin(), kind.lines.end());
      continue;
    }
    std::string what = std::to_string(n) + " " + group_ + ": " + kind.name + ":";
    for (int i = 0; i < kWarningsListed; ++i) {
      what += " " + kind.face_ids[static_cast<std::size_t>(i)] + ",";
    }
    warnings.push_back(face_message(file_, "", what + " ... (--verbose lists all)"));
  }
}

}  // namespace shadowgen::scene::detail
