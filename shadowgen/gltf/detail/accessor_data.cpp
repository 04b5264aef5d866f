#include "detail/accessor_data.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "shadowgen/model/input_error.h"

namespace shadowgen::gltf::detail {
namespace {

std::size_t components_of(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return 1;
    case TINYGLTF_TYPE_VEC2:
      return 2;
    case TINYGLTF_TYPE_VEC3:
      return 3;
    case TINYGLTF_TYPE_VEC4:
    case TINYGLTF_TYPE_MAT2:
      return 4;
    case TINYGLTF_TYPE_MAT3:
      return 9;
    case TINYGLTF_TYPE_MAT4:
      return 16;
    default:
      return 0;
  }
}

template <class T>
T load(const unsigned char* bytes) {
  T value;
  std::memcpy(&value, bytes, sizeof value);
  return value;
}

// The bytes [offset, offset + length) of buffer view `index`, checked to lie inside it and
// the view inside its buffer; `what` names them in messages.
const unsigned char* view_bytes(const tinygltf::Model& model, int index, std::size_t offset,
                                std::size_t length, const std::string& what, const Place& place) {
  if (index < 0 || static_cast<std::size_t>(index) >= model.bufferViews.size()) {
    place.fail(what + " names buffer view " + std::to_string(index) + ", of " +
               std::to_string(model.bufferViews.size()));
  }
  const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(index)];
  const std::string view_label = "buffer view " + std::to_string(index);
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size()) {
    place.fail(view_label + " names buffer " + std::to_string(view.buffer) + ", of " +
               std::to_string(model.buffers.size()));
  }
  const std::vector<unsigned char>& data =
      model.buffers[static_cast<std::size_t>(view.buffer)].data;
  if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset) {
    place.fail(view_label + " (bytes " + std::to_string(view.byteOffset) + " to " +
               std::to_string(view.byteOffset) + " + " + std::to_string(view.byteLength) +
               ") lies outside buffer " + std::to_string(view.buffer) + " of " +
               std::to_string(data.size()) + " bytes");
  }
  if (offset > view.byteLength || length > view.byteLength - offset) {
    place.fail(what + " (bytes " + std::to_string(offset) + " to " + std::to_string(offset) +
               " + " + std::to_string(length) + ") lies outside " + view_label + " of " +
               std::to_string(view.byteLength) + " bytes");
  }
  return data.data() + view.byteOffset + offset;
}

// The bytes an element at `offset` of `count` elements `element_bytes` long, `stride`
// apart, takes: checked not to overflow (count > 0).
std::size_t span_bytes(std::size_t count, std::size_t stride, std::size_t element_bytes,
                       const std::string& what, const Place& place) {
  const std::size_t limit = static_cast<std::size_t>(-1);
  if (count - 1 > (limit - element_bytes) / stride) {
    place.fail(what + " holds " + std::to_string(count) + " elements, more than any buffer");
  }
  return (count - 1) * stride + element_bytes;
}

}  // namespace

void Place::fail(const std::string& problem) const {
  throw InputError(file, "", subject + ": " + problem);
}

std::size_t component_bytes(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return 4;
    default:  // INT (5124) and DOUBLE (5130) are no glTF 2.0 accessor types
      return 0;
  }
}

std::string component_type_name(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return "FLOAT";
    default:
      return std::to_string(component_type);
  }
}

AccessorData::AccessorData(const tinygltf::Model& model, int index, std::string_view role,
                           const Place& place)
    : label_(std::string(role) + " accessor " + std::to_string(index)) {
  if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) {
    place.fail(std::string(role) + " names accessor " + std::to_string(index) + ", of " +
               std::to_string(model.accessors.size()));
  }
  const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(index)];
  count_ = accessor.count;
  type_ = accessor.type;
  component_type_ = accessor.componentType;
  normalized_ = accessor.normalized;
  component_bytes_ = component_bytes(component_type_);
  const std::size_t components = components_of(type_);
  if (component_bytes_ == 0) {
    place.fail(label_ + " has component type " + component_type_name(component_type_) +
               ", not one of glTF 2.0");
  }
  if (components == 0) place.fail(label_ + " has an unknown type");
  const std::size_t element_bytes = components * component_bytes_;

  if (accessor.bufferView < -1) {  // -1 is tinygltf's "none"
    place.fail(label_ + " names buffer view " + std::to_string(accessor.bufferView));
  }
  if (accessor.bufferView >= 0 && count_ > 0) {
    const int view_index = accessor.bufferView;
    const std::size_t view_stride =
        static_cast<std::size_t>(view_index) < model.bufferViews.size()
            ? model.bufferViews[static_cast<std::size_t>(view_index)].byteStride
            : 0;
    stride_ = view_stride == 0 ? element_bytes : view_stride;
    if (stride_ < element_bytes) {
      place.fail(label_ + ": its buffer view's byteStride of " + std::to_string(stride_) +
                 " is less than the " + std::to_string(element_bytes) + " bytes of an element");
    }
    const std::size_t span = span_bytes(count_, stride_, element_bytes, label_, place);
    base_ = view_bytes(model, view_index, accessor.byteOffset, span, label_, place);
  }

  if (accessor.bufferView < 0) {
    // Zeros but for sparse values: bounded by the bytes of the buffers, so that what is
    // made of the file grows with the file, never beyond it.
    std::size_t buffer_bytes = 0;
    for (const tinygltf::Buffer& buffer : model.buffers) buffer_bytes += buffer.data.size();
    if (count_ > buffer_bytes) {
      place.fail(label_ + " has no buffer view and " + std::to_string(count_) +
                 " elements, more than the " + std::to_string(buffer_bytes) +
                 " bytes of the file's buffers: they would be zeros made up");
    }
  }

  if (accessor.sparse.isSparse) {
    const std::string sparse_label = label_ + "'s sparse";
    const int sparse_count = accessor.sparse.count;
    if (sparse_count < 1 || static_cast<std::size_t>(sparse_count) > count_) {
      place.fail(sparse_label + " count " + std::to_string(sparse_count) +
                 " is not from 1 to the accessor's count, " + std::to_string(count_));
    }
    const auto n = static_cast<std::size_t>(sparse_count);
    const int index_type = accessor.sparse.indices.componentType;
    const std::size_t index_bytes = component_bytes(index_type);
    if (index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
      place.fail(sparse_label + " indices have component type " + component_type_name(index_type) +
                 ", not an unsigned integer type");
    }
    if (accessor.sparse.indices.byteOffset < 0 || accessor.sparse.values.byteOffset < 0) {
      place.fail(sparse_label + " has a negative byteOffset");
    }
    const unsigned char* indices =
        view_bytes(model, accessor.sparse.indices.bufferView,
                   static_cast<std::size_t>(accessor.sparse.indices.byteOffset), n * index_bytes,
                   sparse_label + " indices", place);
    sparse_values_ = view_bytes(model, accessor.sparse.values.bufferView,
                                static_cast<std::size_t>(accessor.sparse.values.byteOffset),
                                n * element_bytes, sparse_label + " values", place);
    sparse_elements_.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      const unsigned char* at = indices + i * index_bytes;
      const std::uint64_t element = index_bytes == 1   ? load<std::uint8_t>(at)
                                    : index_bytes == 2 ? load<std::uint16_t>(at)
                                                       : load<std::uint32_t>(at);
      if (element >= count_) {
        place.fail(sparse_label + " index " + std::to_string(i) + " is " + std::to_string(element) +
                   ", beyond the accessor's " + std::to_string(count_) + " elements");
      }
      if (!sparse_elements_.empty() && element <= sparse_elements_.back()) {
        place.fail(sparse_label + " indices do not increase: index " + std::to_string(i) + " is " +
                   std::to_string(element) + ", after " + std::to_string(sparse_elements_.back()));
      }
      sparse_elements_.push_back(element);
    }
  }
}

const unsigned char* AccessorData::element_bytes(std::size_t element) const {
  if (!sparse_elements_.empty()) {
    auto it = std::lower_bound(sparse_elements_.begin(), sparse_elements_.end(), element);
    if (it != sparse_elements_.end() && *it == element) {
      const auto position = static_cast<std::size_t>(it - sparse_elements_.begin());
      return sparse_values_ + position * components_of(type_) * component_bytes_;
    }
  }
  return base_ == nullptr ? nullptr : base_ + element * stride_;
}

double AccessorData::component_at(const unsigned char* bytes, int component) const {
  if (bytes == nullptr) return 0.0;
  const unsigned char* at = bytes + static_cast<std::size_t>(component) * component_bytes_;
  switch (component_type_) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return load<float>(at);
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const double c = load<std::int8_t>(at);
      return normalized_ ? std::max(c / 127.0, -1.0) : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
      const double c = load<std::uint8_t>(at);
      return normalized_ ? c / 255.0 : c;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      const double c = load<std::int16_t>(at);
      return normalized_ ? std::max(c / 32767.0, -1.0) : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      const double c = load<std::uint16_t>(at);
      return normalized_ ? c / 65535.0 : c;
    }
    default: {  // UNSIGNED_INT
      const double c = load<std::uint32_t>(at);
      return normalized_ ? c / 4294967295.0 : c;
    }
  }
}

double AccessorData::value(std::size_t element, int component) const {
  return component_at(element_bytes(element), component);
}

double AccessorData::rounding(double value) const {
  if (component_type_ == TINYGLTF_COMPONENT_TYPE_FLOAT) {
    return std::max(std::ldexp(std::fabs(value), -24), std::ldexp(1.0, -150));
  }
  if (!normalized_) return 0.0;
  switch (component_type_) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return 0.5 / 127.0;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 0.5 / 255.0;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      return 0.5 / 32767.0;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 0.5 / 65535.0;
    default:
      return 0.5 / 4294967295.0;
  }
}

std::uint64_t AccessorData::unsigned_value(std::size_t element) const {
  const unsigned char* bytes = element_bytes(element);
  if (bytes == nullptr) return 0;
  switch (component_type_) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return load<std::uint8_t>(bytes);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return load<std::uint16_t>(bytes);
    default:
      return load<std::uint32_t>(bytes);
  }
}

}  // namespace shadowgen::gltf::detail
