#include "shadowgen/output/sun_hours_export.h"

#include <stdexcept>
#include <string>
#include <vector>

#include "detail/obj_text.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/model/number_text.h"
#include "shadowgen/model/one_line.h"
#include "shadowgen/shadows/generate.h"

namespace shadowgen {
namespace {

std::string group_name(const Face& face, const HourBand& band) {
  return obj_name(face.id + "@" + band.name);
}

// One face: its "v" and "vn" lines, then per band it has regions in, a group, its material
// and the regions' triangles.
void append_face(std::string& obj, const Face& face, const std::vector<SunHoursRegion>& regions,
                 const HourBands& bands, output::detail::ObjNumbering& numbering) {
  if (regions.empty()) {
    obj += "g " + group_name(face, bands.bands.front()) + '\n';
    return;
  }
  output::detail::ObjFaceBlock block(face, numbering);
  std::size_t current = bands.bands.size();       // none yet
  for (const SunHoursRegion& region : regions) {  // in increasing hours, so band by band
    const std::size_t b = bands.band_of(region.hours);
    if (b != current) {
      current = b;
      block.add_statement("g", group_name(face, bands.bands[b]));
      block.add_statement("usemtl", obj_name(bands.bands[b].name));
    }
    if (!block.add_polygons(region.polygons)) {
      // Not the input's fault: valid regions always triangulate.
      throw GenerationError("", face.id, "",
                            "a sun-hours region of " + shortest(region.hours) +
                                " h could not be split into triangles");
    }
  }
  block.append_to(obj, numbering);
}

std::string mtl_text(const HourBands& bands) {
  std::string mtl =
      "# shadowgen MTL: one material per band of sun hours, coloured by matplotlib's "
      "viridis\n# from 0 h (dark) to the " +
      shortest(bands.most_hours) + " h the sun path gives at most (bright).\n";
  for (const std::string& line : bands.caption()) mtl += "# " + line + '\n';
  for (const HourBand& band : bands.bands) {
    mtl += "\n# band: " + band.label + '\n';
    output::detail::append_material(mtl, obj_name(band.name), band.colour);
  }
  return mtl;
}

}  // namespace

ObjFiles sun_hours_obj_export(const ShadowedScene& shadowed, const SunPathHours& path,
                              const HourBands& bands, std::string_view mtl_file_name) {
  const Scene& scene = shadowed.scene();
  require_regions(path, shadowed.scene().file, "an export by hour bands");
  if (path.regions.size() != scene.faces.size()) {
    throw std::invalid_argument("sun_hours_obj_export: sun-hours regions not shaped [face]");
  }
  ObjFiles files;
  std::string& obj = files.obj;
  obj += "# shadowgen OBJ export: sun hours of sun path '" + one_line(path.id) + "', by band\n";
  obj += "mtllib ";
  obj += mtl_file_name;
  obj += '\n';
  output::detail::ObjNumbering numbering;
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    append_face(obj, scene.faces[f], path.regions[f], bands, numbering);
  }
  files.mtl = mtl_text(bands);
  return files;
}

}  // namespace shadowgen
