#pragma once

// The faces of a file's city objects (CityJSON 2.0 specification, "City Objects"),
// collected over one CityJSON file or over the features of a CityJSONSeq file:
//
// - Each city object with geometry gives the surfaces of its chosen geometries: those of
//   the level of detail SourceOptions::lod names, or else of its highest level among its
//   geometries that bound surfaces (several geometries of that level all count), in the
//   order of its "geometry" array. A child (a BuildingPart, a BuildingInstallation, ...)
//   gives its own surfaces, as its own object; a parent without geometry gives none.
// - Face k of object `id` (k from 0 over the surfaces of its chosen geometries, solids,
//   shells and surfaces in order) is "<id>/<k>", described as "object '<id>' surface <k>";
//   its origin is {"cityjson", id, the top of its "parents" chain (itself when it has no
//   parent), the type of its semantic surface or ""}.
// - A surface's exterior ring is its outer loop, kept as written: CityJSON orients a
//   Solid's surfaces counter-clockwise seen from outside, so the face's front side (its
//   outer loop counter-clockwise) is the outside; the other rings are its holes.
// - Objects come in the order of their ids (the order the JSON reader keeps an object's
//   keys in), within a CityJSONSeq feature too, features in the order of their lines.
// - Keys a city object or a geometry does not define draw a warning (an error under
//   strict), except keys starting with "+" and every key of an object whose type does
//   (an Extension's: CityJSON 2.0, "Extensions"); "attributes" are not looked into.

#include <cstddef>
#include <glm/vec3.hpp>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "detail/geometry.h"
#include "shadowgen/json/json_reader.h"
#include "shadowgen/model/source_model.h"

namespace shadowgen::cityjson::detail {

// The axis-aligned bounds of the vertices of the faces collected.
struct Bounds {
  glm::dvec3 low{0.0};
  glm::dvec3 high{0.0};
  bool empty = true;

  void add(const glm::dvec3& p);
};

class CityObjectFaces {
 public:
  CityObjectFaces(std::string file, const SourceOptions& options);

  // Every city object of `city_objects`, a "CityObjects" member, whose geometries index
  // `vertices` and `templates` (null when the file has none). `line` is the line of a
  // CityJSONSeq feature (0 for a CityJSON file): it goes to each face, and an object id
  // already read on another line is an error.
  void read(const JsonValue& city_objects, const GeometryVertices& vertices,
            const GeometryTemplates* templates, std::size_t line);

  // After the last read: appends a warning line for the objects that gave no face though
  // they have geometry; InputError when SourceOptions::lod names a level no geometry has.
  void finish(std::vector<std::string>& warnings) const;

  std::vector<SourceFace>& faces() { return faces_; }
  const Bounds& bounds() const { return bounds_; }

 private:
  struct Object;
  void add_faces(const Object& object, const std::string& group, const GeometryVertices& vertices,
                 const GeometryTemplates* templates, std::size_t line);

  std::string file_;
  const SourceOptions& options_;
  std::vector<SourceFace> faces_;
  Bounds bounds_;
  std::unordered_map<std::string, std::size_t> lines_of_ids_;  // CityJSONSeq only
  std::set<std::string> lods_seen_;
  bool any_chosen_ = false;                 // some object has a geometry of the level chosen
  std::vector<std::string> without_faces_;  // ids of objects with geometry but no face
};

}  // namespace shadowgen::cityjson::detail
