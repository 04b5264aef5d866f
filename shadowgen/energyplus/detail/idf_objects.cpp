#include "detail/idf_objects.h"

#include <optional>

#include "detail/file_version.h"
#include "detail/idf_text.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen::energyplus::detail {
namespace {

std::string at_line(std::size_t line) { return "line " + std::to_string(line) + ": "; }

// The coordinates' names in the IDD: "Vertex 2 Y-coordinate".
std::string coordinate_name(std::size_t index) {
  static const char* const kAxes[] = {"X", "Y", "Z"};
  return "Vertex " + std::to_string(index / 3 + 1) + " " + kAxes[index % 3] + "-coordinate";
}

InputObject input_object(const ClassSpec& spec, IdfObject& idf, Version version) {
  InputObject object;
  object.spec = &spec;
  object.line = idf.fields[0].line;
  std::size_t next = 1;
  if (spec.named && next < idf.fields.size()) object.name = idf.fields[next++].text;
  for (const FieldSpec* field : fields_in(spec, version)) {
    if (next >= idf.fields.size()) break;
    IdfField& value = idf.fields[next++];
    if (value.text.empty()) continue;
    object.fields.emplace(std::string(field->key), InputField{std::move(value.text), value.line,
                                                              std::string(field->idf_name)});
  }
  if (spec.vertices != VertexFields::kNone) {
    for (std::size_t i = 0; next < idf.fields.size(); ++i, ++next) {
      IdfField& value = idf.fields[next];
      object.coordinates.push_back({std::move(value.text), value.line, coordinate_name(i)});
    }
  }
  return object;
}

}  // namespace

Version checked_version(const InputField& field, const std::string& file) {
  const std::string where = field.line > 0 ? at_line(field.line) : "";
  const std::optional<Version> version = parse_version(field.text);
  if (!version) {
    throw InputError(file, "",
                     where + "Version '" + field.text + "' is not a version (such as 9.6 or 24.1)");
  }
  if (*version < kOldestVersion || kNewestVersion < *version) {
    throw InputError(file, "",
                     where + "Version " + field.text + ": EnergyPlus files of versions " +
                         version_text(kOldestVersion) + " to " + version_text(kNewestVersion) +
                         " are read (EnergyPlus's IDFVersionUpdater brings an older file up to "
                         "date)");
  }
  return *version;
}

std::vector<InputObject> idf_objects(std::string_view text, const std::string& file) {
  std::vector<IdfObject> idf = split_idf(text, file);

  const ClassSpec* version_class = find_class("Version");
  std::optional<Version> version;
  std::size_t version_line = 0;
  for (IdfObject& object : idf) {
    if (find_class(object.fields[0].text) != version_class) continue;
    if (version) {
      throw InputError(file, "",
                       at_line(object.fields[0].line) +
                           "a second Version object (the first is on line " +
                           std::to_string(version_line) + ")");
    }
    version_line = object.fields[0].line;
    if (object.fields.size() < 2 || object.fields[1].text.empty()) {
      throw InputError(file, "", at_line(version_line) + "the Version object gives no version");
    }
    version = checked_version({object.fields[1].text, object.fields[1].line, ""}, file);
  }
  if (!version) {
    throw InputError(file, "",
                     "no Version object: an IDF file's Version says where each object's fields "
                     "are");
  }

  std::vector<InputObject> objects;
  for (IdfObject& object : idf) {
    const ClassSpec* spec = find_class(object.fields[0].text);
    if (spec == nullptr) continue;
    objects.push_back(input_object(*spec, object, *version));
  }
  return objects;
}

}  // namespace shadowgen::energyplus::detail
