#include "energyplus_surface_names.h"

#include <map>

#include "shadowgen/model/input_error.h"

namespace shadowgen::output::detail {
namespace {

std::string surface_name(const Face& face, const std::string& file) {
  const std::string& id = face.origin.format == "energyplus" ? face.origin.object : face.id;
  auto refuse = [&](const std::string& why) {
    throw InputError(file, face.id, "cannot be an EnergyPlus surface name: " + why);
  };
  if (id.empty()) refuse("it is empty");
  if (id.front() == ' ' || id.back() == ' ') refuse("EnergyPlus trims spaces around names");
  std::string name;
  for (const char c : id) {
    if (c == ',') refuse("it holds a comma, which separates fields");
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) refuse("it holds a control character");
    name += (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
  }
  return name;
}

}  // namespace

std::vector<std::string> energyplus_surface_names(const Scene& scene) {
  std::vector<std::string> out;
  out.reserve(scene.faces.size());
  std::map<std::string, const Face*> taken;
  for (const Face& face : scene.faces) {
    std::string name = surface_name(face, scene.file);
    const auto [at, added] = taken.emplace(name, &face);
    if (!added) {
      throw InputError(scene.file, face.id,
                       "is the EnergyPlus surface name " + name + " in upper case, as face '" +
                           at->second->id + "' is");
    }
    out.push_back(std::move(name));
  }
  return out;
}

}  // namespace shadowgen::output::detail
