#include "detail/source_readers.h"

#include <string>

#include "shadowgen/cityjson/cityjson_reader.h"
#include "shadowgen/energyplus/energyplus_reader.h"
#include "shadowgen/gltf/gltf_reader.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen::scene::detail {

SourceModel read_source(SourceFormat format, const std::filesystem::path& file,
                        const SourceOptions& options) {
  switch (format) {
    case SourceFormat::kMesh:
      break;
    case SourceFormat::kGltf:
      return gltf::read_gltf(file, options);
    case SourceFormat::kEnergyPlus:
      return energyplus::read_energyplus(file, options);
    case SourceFormat::kCityJson:
      return cityjson::read_cityjson(file, options);
  }
  throw InputError(file.string(), "", "is not a model file of another tool");
}

}  // namespace shadowgen::scene::detail
