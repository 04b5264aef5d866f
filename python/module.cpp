// The Python module `shadowgen`: the public C++ API (shadowgen/shadowgen.h) in Python, its
// names and meaning unchanged (docs/library.md, "Python"). Work on a scene (reading,
// generation, reports, writing files) runs with the GIL released, so other Python threads
// go on meanwhile; numbers come back as numpy arrays.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <shadowgen/shadowgen.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "errors.h"
#include "result_arrays.h"
#include "scene_arrays.h"

namespace py = pybind11;
using namespace pybind11::literals;

namespace shadowgen::python {
namespace {

// A path as str or os.PathLike.
std::string path_of(const py::object& path) {
  return py::str(py::module_::import("os").attr("fspath")(path));
}

std::vector<std::string> strings_of(const py::object& items) {
  if (items.is_none()) return {};
  if (py::isinstance<py::str>(items)) return {items.cast<std::string>()};
  return items.cast<std::vector<std::string>>();
}

template <class Enum>
Enum named(const std::map<std::string, Enum>& names, const std::string& name,
           const std::string& what) {
  const auto found = names.find(name);
  if (found != names.end()) return found->second;
  std::string known;
  for (const auto& [key, value] : names) known += (known.empty() ? "" : ", ") + key;
  throw py::value_error(what + " '" + name + "' is none of " + known);
}

api::GenerateSettings generate_settings(const std::string& method, int samples, int resolution,
                                        int threads, bool sun_hours_regions,
                                        bool keep_instant_polygons) {
  if (threads < 0) throw py::value_error("threads must be 0 (every hardware thread) or more");
  api::GenerateSettings settings;
  settings.method = named<api::Method>({{"exact", api::Method::kExact},
                                        {"rays", api::Method::kRays},
                                        {"shadow-map", api::Method::kShadowMap}},
                                       method, "method");
  settings.samples = samples;
  settings.resolution = resolution;
  settings.threads = static_cast<unsigned>(threads);
  settings.sun_hours_regions = sun_hours_regions;
  settings.keep_instant_polygons = keep_instant_polygons;
  return settings;
}

// Reading warnings, kept while the GIL is released and given to Python's warnings module
// (as UserWarning) once it is held again.
class Warnings {
 public:
  std::function<void(const std::string&)> collector() {
    return [this](const std::string& warning) {
      const std::lock_guard lock(mutex_);
      warnings_.push_back(warning);
    };
  }
  void issue() const {
    const py::object warn = py::module_::import("warnings").attr("warn");
    for (const std::string& warning : warnings_) warn(warning, "stacklevel"_a = 2);
  }

 private:
  std::mutex mutex_;
  std::vector<std::string> warnings_;
};

api::ReadSettings read_settings(bool strict, const py::object& lights, Warnings& warnings) {
  api::ReadSettings settings;
  settings.strict = strict;
  settings.lights = strings_of(lights);
  settings.on_warning = warnings.collector();
  return settings;
}

// Index of `key` (an int, or an id among `ids`); `what` names the kind in the error.
std::size_t index_of(const py::object& key, const std::vector<std::string>& ids,
                     const std::string& what) {
  if (py::isinstance<py::str>(key)) {
    const auto id = key.cast<std::string>();
    for (std::size_t i = 0; i < ids.size(); ++i) {
      if (ids[i] == id) return i;
    }
    throw py::key_error("no " + what + " '" + id + "'");
  }
  const auto index = key.cast<py::ssize_t>();
  if (index < 0 || static_cast<std::size_t>(index) >= ids.size()) {
    throw py::index_error(what + " index " + std::to_string(index) + " out of range");
  }
  return static_cast<std::size_t>(index);
}

api::Scene read_scene(const py::object& path, bool strict, const py::object& lights) {
  Warnings warnings;
  const api::ReadSettings settings = read_settings(strict, lights, warnings);
  const std::string file = path_of(path);
  std::optional<api::Scene> scene;
  {
    const py::gil_scoped_release unlocked;
    scene = api::read_scene(file, settings);
  }
  warnings.issue();
  return *scene;
}

api::Scene make_scene(const py::object& faces, const py::object& lights, const py::object& site,
                      const py::object& groups, const std::string& name, bool strict) {
  Warnings warnings;
  const api::ReadSettings settings = read_settings(strict, py::none(), warnings);
  const api::SceneData data = scene_data(name, faces, lights, site, groups);
  std::optional<api::Scene> scene;
  {
    const py::gil_scoped_release unlocked;
    scene = api::make_scene(data, settings);
  }
  warnings.issue();
  return *scene;
}

api::Shadows load(const py::object& path, const std::string& method, int samples, int resolution,
                  int threads, const py::object& lights, bool strict, bool sun_hours_regions,
                  bool keep_instant_polygons) {
  Warnings warnings;
  api::LoadSettings settings;
  settings.read = read_settings(strict, lights, warnings);
  settings.generate = generate_settings(method, samples, resolution, threads, sun_hours_regions,
                                        keep_instant_polygons);
  const std::string file = path_of(path);
  std::optional<api::Shadows> shadows;
  {
    const py::gil_scoped_release unlocked;
    shadows = api::load(file, settings);
  }
  warnings.issue();
  return *shadows;
}

LitAreas lit_areas_of(const api::Shadows& shadows) {
  const py::gil_scoped_release unlocked;
  return {shadows.lit_areas()};
}

std::string report(const api::Shadows& shadows, const std::string& format,
                   const py::object& group_by, const std::vector<double>& thresholds,
                   std::size_t top, bool csv_safe, const py::object& weather) {
  api::ReportSettings settings;
  settings.format =
      named<api::ReportFormat>({{"csv", api::ReportFormat::kCsv},
                                {"json", api::ReportFormat::kJson},
                                {"table", api::ReportFormat::kTable},
                                {"sun-hours", api::ReportFormat::kSunHours},
                                {"sun-hours-table", api::ReportFormat::kSunHoursTable},
                                {"irradiation", api::ReportFormat::kIrradiation},
                                {"energyplus", api::ReportFormat::kEnergyPlus}},
                               format, "report format");
  settings.group_by = strings_of(group_by);
  settings.thresholds = thresholds;
  settings.top = top;
  settings.csv_safe = csv_safe;
  if (!weather.is_none()) settings.weather = path_of(weather);
  Warnings warnings;
  settings.on_warning = warnings.collector();
  std::string text;
  {
    const py::gil_scoped_release unlocked;
    text = api::report(shadows, settings);
  }
  warnings.issue();
  return text;
}

// write(file), the GIL released; `path` str or os.PathLike.
void write_file(const py::object& path, const std::function<void(const std::string&)>& write) {
  const std::string file = path_of(path);
  const py::gil_scoped_release unlocked;
  write(file);
}

}  // namespace

void define_module(py::module_& module) {
  module.doc() =
      "Exact polygon shadows (Atherton, Weiler and Greenberg 1978): the public C++ API of "
      "shadowgen in Python (docs/library.md).";
  module.attr("__version__") = SHADOWGEN_VERSION;
  module.def(
      "version", [] { return std::string(api::version()); },
      "The linked library's version, as `shadowgen --version` prints it.");

  register_errors(module);
  register_results(module);

  py::class_<api::Scene>(module, "Scene",
                         "A scene as read and checked, before its shadows are generated.")
      .def_property_readonly("file", &api::Scene::file)
      .def_property_readonly("files", &api::Scene::files)
      .def_property_readonly("face_ids", &api::Scene::face_ids)
      .def_property_readonly("light_ids", &api::Scene::light_ids)
      .def_property_readonly("sun_path_ids", &api::Scene::sun_path_ids)
      .def_property_readonly("view_ids", &api::Scene::view_ids)
      .def("__repr__", [](const api::Scene& scene) {
        return "<shadowgen.Scene " + scene.file() + ": " + std::to_string(scene.face_ids().size()) +
               " faces, " + std::to_string(scene.light_ids().size()) + " lights>";
      });

  py::class_<api::Shadows>(module, "Shadows", "A scene's shadows, generated or read.")
      .def_property_readonly("scene", &api::Shadows::scene)
      .def_property_readonly("exact", &api::Shadows::exact)
      .def_property_readonly("method", &api::Shadows::method)
      .def("lit_areas", &lit_areas_of,
           "Every (face, light), faces outer: the report CSV's rows, the same numbers.")
      .def(
          "lit_polygons",
          [](const api::Shadows& shadows, const py::object& face, const py::object& light) {
            const api::Scene scene = shadows.scene();
            const std::size_t f = index_of(face, scene.face_ids(), "face");
            const std::size_t l = index_of(light, scene.light_ids(), "light");
            std::vector<api::PolygonData> polygons;
            {
              const py::gil_scoped_release unlocked;
              polygons = shadows.lit_polygons(f, l);
            }
            return polygons_object(polygons);
          },
          "face"_a, "light"_a,
          "The lit polygons of a face (index or id) from a light (index or id), in the face's "
          "plane: a list of (outer, [hole, ...]), each loop an (n, 3) array.")
      .def(
          "sun_hours",
          [](const api::Shadows& shadows, const std::vector<double>& thresholds) {
            SunHoursTable table{thresholds, {}};
            const py::gil_scoped_release unlocked;
            table.rows = shadows.sun_hours(thresholds);
            return table;
          },
          "thresholds"_a = std::vector<double>{2.0},
          "Per face and sun path, the sun hours and the area with at least each threshold.")
      .def("__repr__", [](const api::Shadows& shadows) {
        return "<shadowgen.Shadows of " + shadows.scene().file() + ", " + shadows.method() + ">";
      });

  module.def("read_scene", &read_scene, "path"_a, py::kw_only(), "strict"_a = false,
             "lights"_a = py::none(),
             "The scene file at `path` (docs/scene-format.md); `lights` keeps only those.");
  module.def("make_scene", &make_scene, "faces"_a, "lights"_a, py::kw_only(), "site"_a = py::none(),
             "groups"_a = py::none(), "name"_a = "scene", "strict"_a = false,
             "A scene from numbers: faces [(id, outer[, holes])], each loop an (n, 3) array; "
             "lights as the scene file's dicts.");
  module.def(
      "generate",
      [](const api::Scene& scene, const std::string& method, int samples, int resolution,
         int threads, bool sun_hours_regions, bool keep_instant_polygons) {
        const api::GenerateSettings settings = generate_settings(
            method, samples, resolution, threads, sun_hours_regions, keep_instant_polygons);
        const py::gil_scoped_release unlocked;
        return api::generate(scene, settings);
      },
      "scene"_a, py::kw_only(), "method"_a = "exact", "samples"_a = 256, "resolution"_a = 2048,
      "threads"_a = 0, "sun_hours_regions"_a = true, "keep_instant_polygons"_a = false,
      "The shadows of `scene` by `method` (exact, rays, shadow-map) on `threads` threads "
      "(0: every hardware thread; the result is the same for any).");
  module.def("load", &load, "path"_a, py::kw_only(), "method"_a = "exact", "samples"_a = 256,
             "resolution"_a = 2048, "threads"_a = 0, "lights"_a = py::none(), "strict"_a = false,
             "sun_hours_regions"_a = true, "keep_instant_polygons"_a = false,
             "A scene read and generated, or a shadowed database read, told by its format.");
  module.def(
      "lit_areas",
      [](const py::object& scene_path, const std::string& method, int threads, int samples,
         int resolution, const py::object& lights) {
        return lit_areas_of(
            load(scene_path, method, samples, resolution, threads, lights, false, true, false));
      },
      "scene_path"_a, "method"_a = "exact", "threads"_a = 0, py::kw_only(), "samples"_a = 256,
      "resolution"_a = 2048, "lights"_a = py::none(),
      "The lit area on each face from each light of the scene (or database) at `scene_path`: "
      "rows (face_id, light_id, area, lit_area), the report CSV's numbers.");
  module.def(
      "groups",
      [](const api::Scene& scene, const py::object& rules) {
        std::vector<api::Group> groups;
        const std::vector<std::string> rule_list = strings_of(rules);
        {
          const py::gil_scoped_release unlocked;
          groups = api::groups(scene, rule_list);
        }
        py::dict out;
        for (const api::Group& group : groups) {
          const std::vector<std::int64_t> faces(group.faces.begin(), group.faces.end());
          out[py::str(group.id)] =
              py::array_t<std::int64_t>(static_cast<py::ssize_t>(faces.size()), faces.data());
        }
        return out;
      },
      "scene"_a, "rules"_a = py::none(),
      "The groups `rules` give (face patterns, origin.KEY, scene.groups), or the scene's own: "
      "{id: array of face indices}.");
  module.def("report", &report, "shadows"_a, "format"_a = "csv", py::kw_only(),
             "group_by"_a = py::none(), "thresholds"_a = std::vector<double>{2.0}, "top"_a = 10,
             "csv_safe"_a = false, "weather"_a = py::none(),
             "The report's text, as `shadowgen report --format FORMAT` writes it, byte for "
             "byte.");
  module.def(
      "sky_report",
      [](const py::object& path, int subdivisions, bool csv_safe, int threads,
         const py::object& lights, bool strict, bool energyplus, bool energyplus_fine) {
        Warnings warnings;
        api::LoadSettings settings;
        settings.read = read_settings(strict, lights, warnings);
        settings.generate = generate_settings("exact", 256, 2048, threads, false, false);
        const std::string file = path_of(path);
        std::string text;
        {
          const py::gil_scoped_release unlocked;
          text = api::sky_report(file, settings,
                                 {subdivisions, csv_safe, energyplus, energyplus_fine});
        }
        warnings.issue();
        return text;
      },
      "path"_a, py::kw_only(), "subdivisions"_a = api::SkyReportSettings{}.subdivisions,
      "csv_safe"_a = false, "threads"_a = 0, "lights"_a = py::none(), "strict"_a = false,
      "energyplus"_a = false, "energyplus_fine"_a = false,
      "`shadowgen report --format sky` of the scene (or database) at `path`, byte for byte: "
      "each face's sky view factor with exact obstruction, the sky's patches (Reinhart MF:N, "
      "1: Tregenza's 145) generated as lights. With `energyplus`, `--format energyplus-sky`'s "
      "CSV instead: EnergyPlus's diffuse sky shading ratios per surface from its 144 sky "
      "directions, and with `energyplus_fine` the ratio over the `subdivisions` patches beside "
      "them (the command's `--sky`).");
  module.def(
      "radiation_report",
      [](const py::object& path, const py::object& weather, const py::object& albedo,
         int subdivisions, bool csv_safe, int threads, const py::object& lights, bool strict) {
        Warnings warnings;
        api::LoadSettings settings;
        settings.read = read_settings(strict, lights, warnings);
        settings.generate = generate_settings("exact", 256, 2048, threads, false, false);
        api::RadiationReportSettings radiation;
        radiation.subdivisions = subdivisions;
        if (!weather.is_none()) radiation.weather = path_of(weather);
        if (!albedo.is_none()) radiation.albedo = albedo.cast<double>();
        radiation.csv_safe = csv_safe;
        radiation.on_warning = warnings.collector();
        const std::string file = path_of(path);
        std::string text;
        {
          const py::gil_scoped_release unlocked;
          text = api::radiation_report(file, settings, radiation);
        }
        warnings.issue();
        return text;
      },
      "path"_a, py::kw_only(), "weather"_a = py::none(), "albedo"_a = py::none(),
      "subdivisions"_a = api::RadiationReportSettings{}.subdivisions, "csv_safe"_a = false,
      "threads"_a = 0, "lights"_a = py::none(), "strict"_a = false,
      "`shadowgen report --format radiation` of the scene (or database) at `path`, byte for "
      "byte: per face and sun path, direct, diffuse (the Perez sky over the patches) and "
      "ground-reflected irradiation, shaded and unshaded, from `weather` (an EPW file; default: "
      "the scene's) and `albedo` (default: the weather file's, else 0.2).");
  module.def(
      "write_database",
      [](const api::Shadows& shadows, const py::object& path) {
        write_file(path, [&](const std::string& file) { api::write_database(shadows, file); });
      },
      "shadows"_a, "path"_a, "The shadowed database, which load() reads back.");
  module.def(
      "write_obj",
      [](const api::Shadows& shadows, const py::object& path, bool by_light) {
        const api::ObjLayout layout =
            by_light ? api::ObjLayout::kByLight : api::ObjLayout::kLightSets;
        write_file(path, [&](const std::string& file) { api::write_obj(shadows, file, layout); });
      },
      "shadows"_a, "path"_a, py::kw_only(), "by_light"_a = false,
      "An OBJ file and its MTL beside it (exact shadows only).");
  module.def(
      "write_gltf",
      [](const api::Shadows& shadows, const py::object& path) {
        write_file(path, [&](const std::string& file) { api::write_gltf(shadows, file); });
      },
      "shadows"_a, "path"_a, "A glTF file: binary for .glb, JSON for .gltf (exact shadows only).");
  module.def(
      "write_svg",
      [](const api::Shadows& shadows, const py::object& path, const std::string& view, int width,
         int height) {
        write_file(path, [&](const std::string& file) {
          api::write_svg(shadows, file, view, width, height);
        });
      },
      "shadows"_a, "path"_a, "view"_a, py::kw_only(), "width"_a = 800, "height"_a = 600,
      "An SVG picture from the scene's view `view` (exact shadows only).");
}

}  // namespace shadowgen::python

PYBIND11_MODULE(shadowgen, module) { shadowgen::python::define_module(module); }
