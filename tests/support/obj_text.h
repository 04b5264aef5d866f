#pragma once

// A plain reader of the OBJ and MTL text that `shadowgen export --obj` writes, written
// independently of the writer so that tests read the files back as a viewer would:
// `g` groups, `usemtl` materials, `v` / `vn` records and `f v//n ...` triangles (1-based,
// also negative relative indices), MTL `newmtl` and `Kd`. Header-only, no glm, so that the
// end-to-end CLI tests can use it too. Problems go to `errors`, one line each.

#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <map>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace shadowgen::test {

using Vec3 = std::array<double, 3>;

struct ObjTriangle {
  std::array<Vec3, 3> corners;
  std::array<Vec3, 3> normals;  // the vn of each corner
  std::string material;
};

struct ObjGroup {
  std::string name;
  std::vector<ObjTriangle> triangles;
};

struct ObjText {
  std::string mtllib;
  std::vector<Vec3> vertices;
  std::vector<Vec3> normals;
  std::vector<ObjGroup> groups;  // in file order; one per `g` statement
  std::vector<std::string> errors;
};

inline bool read_double(std::string_view token, double& value) {
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && end == token.data() + token.size();
}

inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline Vec3 minus(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Twice the area vector of the triangle: its direction is the side from which the corners
// run counter-clockwise.
inline Vec3 area_vector(const ObjTriangle& t) {
  return cross(minus(t.corners[1], t.corners[0]), minus(t.corners[2], t.corners[0]));
}
inline double area(const ObjTriangle& t) {
  return 0.5 * std::sqrt(dot(area_vector(t), area_vector(t)));
}

// Area per material within one group.
inline std::map<std::string, double> material_areas(const ObjGroup& group) {
  std::map<std::string, double> areas;
  for (const ObjTriangle& t : group.triangles) areas[t.material] += area(t);
  return areas;
}

inline ObjText parse_obj(const std::string& text) {
  ObjText obj;
  std::istringstream in(text);
  std::string line, material;
  int number = 0;
  auto error = [&obj, &number](const std::string& what) {
    obj.errors.push_back("line " + std::to_string(number) + ": " + what);
  };
  auto index = [](long i, std::size_t count) -> long {
    return i < 0 ? static_cast<long>(count) + i : i - 1;
  };
  while (std::getline(in, line)) {
    ++number;
    std::istringstream words(line);
    std::string tag;
    if (!(words >> tag) || tag[0] == '#') continue;
    if (tag == "v" || tag == "vn") {
      Vec3 v{};
      std::string token;
      for (double& c : v) {
        if (!(words >> token) || !read_double(token, c)) error("bad number in " + tag);
      }
      if (words >> token) error("more than three numbers in " + tag);
      (tag == "v" ? obj.vertices : obj.normals).push_back(v);
    } else if (tag == "g") {
      std::string name;
      words >> name;
      std::string more;
      if (words >> more) error("group name with a space");
      obj.groups.push_back({name, {}});
    } else if (tag == "usemtl") {
      words >> material;
    } else if (tag == "mtllib") {
      words >> obj.mtllib;
    } else if (tag == "f") {
      if (obj.groups.empty()) error("face before any group");
      if (material.empty()) error("face without a material");
      ObjTriangle t;
      t.material = material;
      std::string corner;
      int k = 0;
      while (words >> corner) {
        if (k == 3) {
          error("face with more than three corners");
          break;
        }
        const std::size_t slashes = corner.find("//");
        if (slashes == std::string::npos) {
          error("corner without v//vn: " + corner);
          break;
        }
        const long v = index(std::stol(corner.substr(0, slashes)), obj.vertices.size());
        const long n = index(std::stol(corner.substr(slashes + 2)), obj.normals.size());
        if (v < 0 || v >= static_cast<long>(obj.vertices.size()) || n < 0 ||
            n >= static_cast<long>(obj.normals.size())) {
          error("index out of range: " + corner);
          break;
        }
        t.corners[static_cast<std::size_t>(k)] = obj.vertices[static_cast<std::size_t>(v)];
        t.normals[static_cast<std::size_t>(k)] = obj.normals[static_cast<std::size_t>(n)];
        ++k;
      }
      if (k != 3) {
        error("face with fewer than three corners");
      } else if (!obj.groups.empty()) {
        obj.groups.back().triangles.push_back(t);
      }
    } else {
      error("unknown statement " + tag);
    }
  }
  return obj;
}

// Kd of every material, by name; a repeated name is an error.
struct MtlText {
  std::map<std::string, Vec3> kd;
  std::vector<std::string> order;  // newmtl names in file order
  std::vector<std::string> errors;
};

inline MtlText parse_mtl(const std::string& text) {
  MtlText mtl;
  std::istringstream in(text);
  std::string line, current;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string tag;
    if (!(words >> tag) || tag[0] == '#') continue;
    if (tag == "newmtl") {
      words >> current;
      if (mtl.kd.count(current) != 0) mtl.errors.push_back("repeated material " + current);
      mtl.kd[current] = {-1, -1, -1};
      mtl.order.push_back(current);
    } else if (tag == "Kd") {
      Vec3 kd{};
      std::string token;
      for (double& c : kd) {
        if (!(words >> token) || !read_double(token, c)) mtl.errors.push_back("bad Kd");
      }
      if (current.empty()) {
        mtl.errors.push_back("Kd before newmtl");
      } else {
        mtl.kd[current] = kd;
      }
    }
  }
  return mtl;
}

}  // namespace shadowgen::test
