// The project's only translation unit that includes OpenMesh.

#include "mesh_reader.h"

#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/Options.hh>
#include <OpenMesh/Core/IO/importer/BaseImporter.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <cctype>
#include <fstream>
#include <iterator>
#include <sstream>

#include "obj_reader.h"
#include "off_reader.h"
#include "ply_reader.h"
#include "shadowgen/json/document.h"
#include "shadowgen/model/input_error.h"
#include "stl_reader.h"

namespace shadowgen::scene::detail {

namespace {

using OpenMesh::EdgeHandle;
using OpenMesh::FaceHandle;
using OpenMesh::HalfedgeHandle;
using OpenMesh::VertexHandle;

// What OpenMesh's readers deliver, recorded as it comes: vertices and faces in file order.
// A mesh-building importer (OpenMesh::IO::ImporterT) refuses faces that would make the
// mesh non-manifold ("complex" faces) or repeat a vertex; this one accepts every face, so
// none is lost. Everything but positions and faces (normals, colours, texture data) is
// ignored.
class PolygonSoupImporter final : public OpenMesh::IO::BaseImporter {
 public:
  explicit PolygonSoupImporter(MeshSoup& soup) : soup_(soup) {}

  VertexHandle add_vertex(const OpenMesh::Vec3f& p) override {
    return add(glm::dvec3(p[0], p[1], p[2]));
  }
  VertexHandle add_vertex(const OpenMesh::Vec3d& p) override {
    return add(glm::dvec3(p[0], p[1], p[2]));
  }
  VertexHandle add_vertex() override { return add(glm::dvec3(0.0)); }
  void set_point(VertexHandle v, const OpenMesh::Vec3f& p) override {
    if (v.is_valid() && static_cast<std::size_t>(v.idx()) < soup_.vertices.size()) {
      soup_.vertices[static_cast<std::size_t>(v.idx())] = glm::dvec3(p[0], p[1], p[2]);
    }
  }

  FaceHandle add_face(const VHandles& vertices) override {
    MeshFaceRecord face;
    face.vertices.reserve(vertices.size());
    for (const VertexHandle& v : vertices) face.vertices.push_back(v.idx());
    soup_.faces.push_back(std::move(face));
    return FaceHandle(static_cast<int>(soup_.faces.size() - 1));
  }

  std::size_t n_vertices() const override { return soup_.vertices.size(); }
  std::size_t n_faces() const override { return soup_.faces.size(); }
  std::size_t n_edges() const override { return 0; }

  // Connectivity and attributes: not recorded.
  HalfedgeHandle add_edge(VertexHandle, VertexHandle) override { return HalfedgeHandle(); }
  FaceHandle add_face(HalfedgeHandle) override { return FaceHandle(); }
  void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<OpenMesh::Vec2f>&) override {}
  void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<OpenMesh::Vec3f>&) override {}
  void set_face_texindex(FaceHandle, int) override {}
  void set_halfedge(VertexHandle, HalfedgeHandle) override {}
  void set_normal(VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(VertexHandle, const OpenMesh::Vec3d&) override {}
  void set_color(VertexHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(VertexHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_color(VertexHandle, const OpenMesh::Vec4f&) override {}
  void set_texcoord(VertexHandle, const OpenMesh::Vec2f&) override {}
  void set_texcoord(VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_status(VertexHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_next(HalfedgeHandle, HalfedgeHandle) override {}
  void set_face(HalfedgeHandle, FaceHandle) override {}
  void request_face_texcoords2D() override {}
  void set_texcoord(HalfedgeHandle, const OpenMesh::Vec2f&) override {}
  void set_texcoord(HalfedgeHandle, const OpenMesh::Vec3f&) override {}
  void set_status(HalfedgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_color(EdgeHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(EdgeHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(EdgeHandle, const OpenMesh::Vec3f&) override {}
  void set_color(EdgeHandle, const OpenMesh::Vec4f&) override {}
  void set_status(EdgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_normal(FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(FaceHandle, const OpenMesh::Vec3d&) override {}
  void set_color(FaceHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(FaceHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_color(FaceHandle, const OpenMesh::Vec4f&) override {}
  void set_status(FaceHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void add_texture_information(int, std::string) override {}

 private:
  VertexHandle add(const glm::dvec3& p) {
    soup_.vertices.push_back(p);
    return VertexHandle(static_cast<int>(soup_.vertices.size() - 1));
  }

  MeshSoup& soup_;
};

// OpenMesh's readers report problems on its own log streams; we report them as
// InputErrors, so its streams are silenced while it reads, and restored after.
class QuietOpenMesh {
 public:
  QuietOpenMesh()
      : err_(::omerr().is_enabled()), log_(::omlog().is_enabled()), out_(::omout().is_enabled()) {
    ::omerr().disable();
    ::omlog().disable();
    ::omout().disable();
  }
  ~QuietOpenMesh() {
    if (err_) ::omerr().enable();
    if (log_) ::omlog().enable();
    if (out_) ::omout().enable();
  }
  QuietOpenMesh(const QuietOpenMesh&) = delete;
  QuietOpenMesh& operator=(const QuietOpenMesh&) = delete;

 private:
  bool err_, log_, out_;
};

std::string lower_extension(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

MeshSoup read_with_openmesh(const std::filesystem::path& file, const std::string& ext) {
  if (!std::filesystem::is_regular_file(file)) {
    throw InputError(file.string(), "", "cannot open the mesh file");
  }
  MeshSoup soup;
  PolygonSoupImporter importer(soup);
  OpenMesh::IO::Options options;
  bool read = false;
  {
    const QuietOpenMesh quiet;
    read = OpenMesh::IO::IOManager().read(file.string(), importer, options);
  }
  if (!read) {
    throw InputError(file.string(), "",
                     ext.empty() ? "cannot tell the mesh format without a file extension "
                                   "(OBJ, OFF, PLY and STL are read)"
                                 : "OpenMesh cannot read this file as '" + ext +
                                       "' (unsupported format, or a malformed file)");
  }
  return soup;
}

}  // namespace

MeshSoup read_mesh(const std::filesystem::path& file, const std::string& mesh_id) {
  const std::string ext = lower_extension(file);
  MeshSoup soup;
  std::string faces_are = "face records";
  if (ext == ".obj") {
    soup = detail::parse_obj(read_text_file(file, "mesh file"), file, mesh_id);
    faces_are = "'f' lines";
  } else if (ext == ".stl") {
    soup = detail::parse_stl(read_text_file(file, "mesh file"), file, mesh_id);
    faces_are = "facets";
  } else if (ext == ".off") {
    soup = detail::parse_off(read_text_file(file, "mesh file"), file, mesh_id);
    faces_are = "faces (its header announces none)";
  } else if (ext == ".ply") {
    soup = detail::parse_ply(read_text_file(file, "mesh file"), file, mesh_id);
    faces_are = "'face' elements";
  } else {
    soup = read_with_openmesh(file, ext);
  }
  // A mesh is referenced for its faces: one without any is a mistake (a wrong file, or
  // one that is not a mesh of its format at all), never a silent nothing.
  if (soup.faces.empty()) {
    throw InputError(file.string(), "",
                     "mesh '" + mesh_id + "' has no faces: the file has no " + faces_are);
  }
  return soup;
}

}  // namespace shadowgen::scene::detail
