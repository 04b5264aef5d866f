#pragma once

// glTF 2.0 model files (.gltf with its buffers, .glb) read into scene terms
// (docs/gltf.md): every triangle of every mesh that a node of the file's scene places,
// through the node hierarchy's transforms, turned from glTF's +y up to the scene's +z up.
//
//   SourceModel model = gltf::read_gltf("models/house.glb", {});
//   model.faces[0].id == "roof/0"   // "<node name or index>/<k>"
//
// The scene: the file's `scene`, else scene 0; a file without scenes is refused (the
// specification's library of entities, nothing placed). Nodes are walked depth first,
// children in order; a node's faces are its mesh's primitives in order, each primitive's
// triangles in order (strips and fans as the specification turns them into triangles),
// numbered k = 0, 1, ... over the node. A node's world matrix with a negative
// determinant (a mirror) keeps each face's front side: its corners are taken in reverse.
// glTF's (x, y, z) is the scene's (x, -z, y).
//
// Face ids: "<label>/<k>", the label the node's name, or its index when it has none; a
// node whose label an earlier node of the walk already has is labelled "<label>#<index>".
// Each face's origin is {"gltf", the node's name (or index), the mesh's name, ""}.
//
// vertex_rounding: a float32 position component c is within |c|·2^-24 of the value meant
// (half a unit in the last place), a normalized integer within half its step; that error
// vector, carried through the node's linear part A, grows at most by A's Frobenius norm.
//
// Refused, each an InputError naming the file and the node, mesh and primitive at fault:
// a file that is not glTF 2.0 JSON or a well-formed .glb (a truncated one), a buffer file
// missing or of another size than its byteLength, an extension the file requires that
// shadowgen does not read (Draco, meshopt: only KHR_mesh_quantization and extensions of
// materials, textures and lights, which change no geometry, are read past), points and
// lines, an accessor reaching outside its buffer view or buffer, an index out of range,
// a non-finite position, a node reached twice (a cycle). Morph targets and skins are
// ignored with a warning: the base positions at the node's transform are read.

#include <filesystem>

#include "shadowgen/model/source_model.h"

namespace shadowgen::gltf {

SourceModel read_gltf(const std::filesystem::path& file, const SourceOptions& options);

}  // namespace shadowgen::gltf
