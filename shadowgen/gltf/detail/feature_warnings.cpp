#include "detail/feature_warnings.h"

#include <utility>

namespace shadowgen::gltf::detail {
namespace {

constexpr std::size_t kListed = 3;  // as the scene reader's kWarningsListed

}  // namespace

FeatureWarnings::FeatureWarnings(std::string file, std::string things, std::string what)
    : file_(std::move(file)), things_(std::move(things)), what_(std::move(what)) {}

void FeatureWarnings::add(std::string subject) { subjects_.push_back(std::move(subject)); }

void FeatureWarnings::append_to(std::vector<std::string>& warnings) const {
  if (subjects_.size() <= kListed) {
    for (const std::string& subject : subjects_) {
      warnings.push_back(file_ + ": " + subject + ": " + what_);
    }
    return;
  }
  std::string line =
      file_ + ": " + std::to_string(subjects_.size()) + " " + things_ + ": " + what_ + ": ";
  for (std::size_t i = 0; i < kListed; ++i) line += subjects_[i] + "; ";
  warnings.push_back(line + "...");
}

}  // namespace shadowgen::gltf::detail
