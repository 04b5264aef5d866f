#include "shadowgen/energyplus/energyplus_reader.h"

#include <new>
#include <vector>

#include "detail/epjson_objects.h"
#include "detail/idf_objects.h"
#include "detail/model_builder.h"
#include "shadowgen/json/document.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen::energyplus {
namespace {

constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";

bool is_epjson(std::string_view text) {
  if (text.starts_with(kByteOrderMark)) text.remove_prefix(kByteOrderMark.size());
  const std::size_t first = text.find_first_not_of(" \t\r\n\f");
  return first != std::string_view::npos && text[first] == '{';
}

}  // namespace

SourceModel parse_energyplus(std::string_view text, const std::string& file,
                             const SourceOptions& options) {
  std::vector<std::string> warnings;
  std::vector<detail::InputObject> objects;
  if (is_epjson(text)) {
    objects = detail::epjson_objects(text, file, options.strict, warnings);
  } else {
    if (text.starts_with(kByteOrderMark)) text.remove_prefix(kByteOrderMark.size());
    objects = detail::idf_objects(text, file);
  }
  SourceModel model = detail::build_model(objects, file);
  warnings.insert(warnings.end(), model.warnings.begin(), model.warnings.end());
  model.warnings = std::move(warnings);
  return model;
}

SourceModel read_energyplus(const std::filesystem::path& file, const SourceOptions& options) {
  const std::string name = file.string();
  try {
    const std::string text = read_text_file(file, "EnergyPlus file", kLargestEnergyPlusFile);
    return parse_energyplus(text, name, options);
  } catch (const std::bad_alloc&) {
    throw InputError(name, "", std::string(kOutOfMemoryProblem));
  }
}

}  // namespace shadowgen::energyplus
