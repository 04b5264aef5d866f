#pragma once

// The header of a PLY file (ply_reader.h): its format and the elements it announces,
// each with its properties and what the mesh reader takes from them. Read apart from the
// body, which it describes: the body reader only follows what this gives.

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "mesh_text.h"

namespace shadowgen::scene::detail::ply {

enum class Type { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };

// Bytes a value of the type takes in a binary body.
std::size_t size_of(Type t);

bool is_integer(Type t);

// The lowest and highest value of an integer type.
std::pair<std::int64_t, std::int64_t> range_of(Type t);

// What a property is for.
enum class Role { kNone, kX, kY, kZ, kIndices };

struct Property {
  std::string name;
  Type type = Type::kFloat32;
  bool list = false;
  Type count_type = Type::kUint8;
  Role role = Role::kNone;
};

struct Element {
  std::string name;
  std::int64_t count = 0;
  std::vector<Property> properties;
};

enum class Format { kAscii, kLittleEndian, kBigEndian };

struct Header {
  Format format = Format::kAscii;
  std::vector<Element> elements;  // in the order the body gives them
};

// Reads the header from its first line ("ply") through "end_header", leaving `lines` at
// the body. Checks that the vertex element has x, y and z and the face element its index
// list. Throws InputError(file, "", what is wrong), naming the line.
Header read_header(LineReader& lines, const std::string& file);

}  // namespace shadowgen::scene::detail::ply
