#pragma once

// An accessor's elements read from their bytes with every bound checked that tinygltf
// leaves unchecked (glTF 2.0 specification, 3.6 "Binary Data Storage"): the buffer view
// inside its buffer, the accessor's elements inside its buffer view (byteStride
// included), sparse indices and values inside theirs, sparse indices increasing and
// below the accessor's count. An accessor without a buffer view is zeros but for its
// sparse values, and holds no more elements than the file's buffers hold bytes (its
// faces would be zeros made up, without end). Components convert as the specification says (3.11
// "Animations", normalized integers): a float as it is, a normalized integer to [-1, 1] or [0, 1],
// any other integer to its value. Nothing is copied: elements are read where they are.

#include <tiny_gltf.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace shadowgen::gltf::detail {

// Where messages point: the file and what holds the accessor ("node 'roof' (1), mesh
// 'box' (0), primitive 0"). Problems are InputError(file, "", subject + ": " + ...).
struct Place {
  std::string file;
  std::string subject;

  [[noreturn]] void fail(const std::string& problem) const;
};

class AccessorData {
 public:
  // Accessor `index` of `model`, read as `role` ("POSITION", "indices"): InputError at
  // `place` when the index, a buffer view or a bound is wrong.
  AccessorData(const tinygltf::Model& model, int index, std::string_view role, const Place& place);

  std::size_t count() const { return count_; }
  int type() const { return type_; }                      // TINYGLTF_TYPE_*
  int component_type() const { return component_type_; }  // TINYGLTF_COMPONENT_TYPE_*
  bool normalized() const { return normalized_; }
  // The accessor's name for messages: "POSITION accessor 3".
  const std::string& label() const { return label_; }

  // Component `component` of element `element` (< count()), converted as above.
  double value(std::size_t element, int component) const;
  // How far the stored value may be from the value meant, by the component type's
  // precision: half a unit in the last place of a float32 (|value|·2^-24, at least the
  // 2^-150 of a subnormal), half a step of a normalized integer, 0 for other integers.
  double rounding(double value) const;
  // Element `element` of an unsigned integer scalar accessor (indices).
  std::uint64_t unsigned_value(std::size_t element) const;

 private:
  // The bytes of element `element` (before sparse substitution), or null for zeros.
  const unsigned char* element_bytes(std::size_t element) const;
  double component_at(const unsigned char* bytes, int component) const;

  std::string label_;
  std::size_t count_ = 0;
  int type_ = 0;
  int component_type_ = 0;
  bool normalized_ = false;
  std::size_t component_bytes_ = 0;
  const unsigned char* base_ = nullptr;  // null: zeros
  std::size_t stride_ = 0;
  // Sparse substitutes: increasing element numbers, and their values' bytes.
  std::vector<std::uint64_t> sparse_elements_;
  const unsigned char* sparse_values_ = nullptr;
};

// Bytes per component of a TINYGLTF_COMPONENT_TYPE_*, 0 for another number.
std::size_t component_bytes(int component_type);
// "FLOAT", "UNSIGNED_SHORT", ...; the number itself for another.
std::string component_type_name(int component_type);

}  // namespace shadowgen::gltf::detail
