#include "shadowgen/model/method.h"

namespace shadowgen {

std::string_view method_name(MethodKind kind) {
  switch (kind) {
    case MethodKind::kRays:
      return "rays";
    case MethodKind::kShadowMap:
      return "shadow-map";
    case MethodKind::kExact:
      break;
  }
  return "exact";
}

std::optional<MethodKind> method_kind(std::string_view name) {
  for (const MethodKind kind : {MethodKind::kExact, MethodKind::kRays, MethodKind::kShadowMap}) {
    if (method_name(kind) == name) return kind;
  }
  return std::nullopt;
}

std::string method_label(const Method& method) {
  std::string label(method_name(method.kind));
  if (!method.exact()) label.append(" ").append(std::to_string(method.samples));
  if (method.kind == MethodKind::kShadowMap) {
    label.append(" @ ").append(std::to_string(method.resolution));
  }
  return label;
}

std::string view_trial_label(const ViewTrial& trial) {
  std::string label = trial.method;
  if (trial.resolution > 0) label.append(" @ ").append(std::to_string(trial.resolution));
  return label;
}

}  // namespace shadowgen
