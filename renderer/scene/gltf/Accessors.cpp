// glTF accessors (Accessors.h).
#include "scene/gltf/Accessors.h"

#include <cstring>
#include <limits>

#include "scene/gltf/Hardening.h"

namespace sl::gltf {
namespace {

const char* typeName(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return "SCALAR";
    case TINYGLTF_TYPE_VEC2:
      return "VEC2";
    case TINYGLTF_TYPE_VEC3:
      return "VEC3";
    case TINYGLTF_TYPE_VEC4:
      return "VEC4";
    case TINYGLTF_TYPE_MAT2:
      return "MAT2";
    case TINYGLTF_TYPE_MAT3:
      return "MAT3";
    case TINYGLTF_TYPE_MAT4:
      return "MAT4";
    default:
      return "unknown";
  }
}

/// Bytes of bufferView `viewIndex`, checked against its buffer.
const unsigned char* viewBytes(const tinygltf::Model& model, int viewIndex,
                               const std::string& label, std::size_t& length) {
  if (viewIndex < 0 || std::size_t(viewIndex) >= model.bufferViews.size())
    fail(label + ": bufferView " + std::to_string(viewIndex) + " is out of range (" +
         std::to_string(model.bufferViews.size()) + " bufferViews)");
  const tinygltf::BufferView& view = model.bufferViews[std::size_t(viewIndex)];
  if (view.buffer < 0 || std::size_t(view.buffer) >= model.buffers.size())
    fail(label + ": bufferView " + std::to_string(viewIndex) + " names buffer " +
         std::to_string(view.buffer) + ", which is out of range (" +
         std::to_string(model.buffers.size()) + " buffers)");
  const std::vector<unsigned char>& data = model.buffers[std::size_t(view.buffer)].data;
  if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
    fail(label + ": bufferView " + std::to_string(viewIndex) + " (bytes " +
         std::to_string(view.byteOffset) + ".." +
         std::to_string(view.byteOffset + view.byteLength) + ") is out of range of buffer " +
         std::to_string(view.buffer) + " (" + std::to_string(data.size()) + " bytes)");
  length = view.byteLength;
  return data.data() + view.byteOffset;
}

/// Calls visit(elementIndex, elementBytes) for every element of accessor `index`, then for
/// every sparse substitution (so later calls override earlier ones). All ranges are checked.
template <class Visit>
void forEachElement(const tinygltf::Model& model, int index, const std::string& what,
                    Visit&& visit) {
  if (index < 0 || std::size_t(index) >= model.accessors.size())
    fail(what + ": accessor " + std::to_string(index) + " is out of range (" +
         std::to_string(model.accessors.size()) + " accessors)");
  const tinygltf::Accessor& acc = model.accessors[std::size_t(index)];
  const std::string label = "accessor " + std::to_string(index) + " (" + what + ")";
  int componentSize = tinygltf::GetComponentSizeInBytes(std::uint32_t(acc.componentType));
  int components = tinygltf::GetNumComponentsInType(std::uint32_t(acc.type));
  if (componentSize <= 0 || components <= 0) fail(label + " has an invalid componentType or type");
  const std::size_t elementSize = std::size_t(componentSize) * std::size_t(components);
  if (acc.count > kMaxAccessorElements)
    fail(label + ": count " + std::to_string(acc.count) + " is implausibly large");

  if (acc.bufferView >= 0) {
    std::size_t length = 0;
    const unsigned char* bytes = viewBytes(model, acc.bufferView, label, length);
    std::size_t declaredStride = model.bufferViews[std::size_t(acc.bufferView)].byteStride;
    std::size_t stride = declaredStride ? declaredStride : elementSize;
    if (stride < elementSize)
      fail(label + ": byteStride " + std::to_string(stride) + " is smaller than one element (" +
           std::to_string(elementSize) + " bytes)");
    if (acc.count > 0) {
      std::size_t needed = acc.byteOffset + stride * (acc.count - 1) + elementSize;
      if (acc.byteOffset > length || needed > length)
        fail(label + " is out of range of bufferView " + std::to_string(acc.bufferView) +
             ": needs " + std::to_string(needed) + " bytes, has " + std::to_string(length));
    }
    for (std::size_t i = 0; i < acc.count; ++i) visit(i, bytes + acc.byteOffset + i * stride);
  } else {
    // No bufferView: all zeros (usually the base of a sparse accessor). Nothing in the file
    // backs the count, so it gets a tighter limit.
    if (acc.count > kMaxAccessorElements / 16)
      fail(label + ": count " + std::to_string(acc.count) +
           " without a bufferView is implausibly large");
    std::vector<unsigned char> zeros(elementSize, 0);
    for (std::size_t i = 0; i < acc.count; ++i) visit(i, zeros.data());
  }

  if (!acc.sparse.isSparse) return;
  const std::string sparseLabel = label + " sparse";
  if (acc.sparse.count < 0 || std::size_t(acc.sparse.count) > acc.count)
    fail(sparseLabel + ": count " + std::to_string(acc.sparse.count) +
         " exceeds the accessor's count " + std::to_string(acc.count));
  const std::size_t n = std::size_t(acc.sparse.count);
  int indexSize =
      tinygltf::GetComponentSizeInBytes(std::uint32_t(acc.sparse.indices.componentType));
  if (acc.sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
      acc.sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      acc.sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    fail(sparseLabel + ": indices must be unsigned byte, short or int");
  std::size_t indicesLength = 0, valuesLength = 0;
  const unsigned char* indexBytes =
      viewBytes(model, acc.sparse.indices.bufferView, sparseLabel + " indices", indicesLength);
  const unsigned char* valueBytes =
      viewBytes(model, acc.sparse.values.bufferView, sparseLabel + " values", valuesLength);
  if (acc.sparse.indices.byteOffset < 0 || acc.sparse.values.byteOffset < 0)
    fail(sparseLabel + ": negative byteOffset");
  std::size_t indexOffset = std::size_t(acc.sparse.indices.byteOffset);
  std::size_t valueOffset = std::size_t(acc.sparse.values.byteOffset);
  if (indexOffset + n * std::size_t(indexSize) > indicesLength)
    fail(sparseLabel + " indices are out of range of bufferView " +
         std::to_string(acc.sparse.indices.bufferView));
  if (valueOffset + n * elementSize > valuesLength)
    fail(sparseLabel + " values are out of range of bufferView " +
         std::to_string(acc.sparse.values.bufferView));
  for (std::size_t j = 0; j < n; ++j) {
    const unsigned char* p = indexBytes + indexOffset + j * std::size_t(indexSize);
    std::uint32_t target = 0;
    if (indexSize == 1) {
      target = *p;
    } else if (indexSize == 2) {
      std::uint16_t v;
      std::memcpy(&v, p, 2);
      target = v;
    } else {
      std::memcpy(&target, p, 4);
    }
    if (target >= acc.count)
      fail(sparseLabel + ": index " + std::to_string(target) + " is out of range (count " +
           std::to_string(acc.count) + ")");
    visit(std::size_t(target), valueBytes + valueOffset + j * elementSize);
  }
}

float readComponent(const unsigned char* p, int componentType, bool normalized) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      std::int8_t v;
      std::memcpy(&v, p, 1);
      return normalized ? std::max(float(v) / 127.0f, -1.0f) : float(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
      std::uint8_t v = *p;
      return normalized ? float(v) / 255.0f : float(v);
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      std::int16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? std::max(float(v) / 32767.0f, -1.0f) : float(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      std::uint16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? float(v) / 65535.0f : float(v);
    }
    case TINYGLTF_COMPONENT_TYPE_INT: {
      std::int32_t v;
      std::memcpy(&v, p, 4);
      return normalized ? float(std::max(double(v) / 2147483647.0, -1.0)) : float(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      std::uint32_t v;
      std::memcpy(&v, p, 4);
      return normalized ? float(double(v) / 4294967295.0) : float(v);
    }
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
      float v;
      std::memcpy(&v, p, 4);
      return v;
    }
    case TINYGLTF_COMPONENT_TYPE_DOUBLE: {
      double v;
      std::memcpy(&v, p, 8);
      return float(v);
    }
    default:
      return 0.0f;
  }
}

}  // namespace

/// Accessor `index` as floats, `components` per element; its type must be `expectedType`.
std::vector<float> readFloats(const tinygltf::Model& model, int index, const std::string& what,
                              int expectedType) {
  if (index >= 0 && std::size_t(index) < model.accessors.size()) {
    const tinygltf::Accessor& acc = model.accessors[std::size_t(index)];
    if (acc.type != expectedType)
      fail("accessor " + std::to_string(index) + " (" + what + ") has type " + typeName(acc.type) +
           ", expected " + typeName(expectedType));
  }
  std::vector<float> out;
  int components = tinygltf::GetNumComponentsInType(std::uint32_t(expectedType));
  bool sized = false;
  forEachElement(model, index, what, [&](std::size_t i, const unsigned char* p) {
    const tinygltf::Accessor& acc = model.accessors[std::size_t(index)];
    if (!sized) {
      out.assign(acc.count * std::size_t(components), 0.0f);
      sized = true;
    }
    int componentSize = tinygltf::GetComponentSizeInBytes(std::uint32_t(acc.componentType));
    for (int c = 0; c < components; ++c)
      out[i * std::size_t(components) + std::size_t(c)] =
          readComponent(p + c * componentSize, acc.componentType, acc.normalized);
  });
  return out;
}

std::vector<std::uint32_t> readIndices(const tinygltf::Model& model, int index,
                                       const std::string& what) {
  if (index >= 0 && std::size_t(index) < model.accessors.size()) {
    const tinygltf::Accessor& acc = model.accessors[std::size_t(index)];
    if (acc.type != TINYGLTF_TYPE_SCALAR)
      fail("accessor " + std::to_string(index) + " (" + what + ") has type " + typeName(acc.type) +
           ", expected SCALAR");
    if (acc.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        acc.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        acc.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
      fail("accessor " + std::to_string(index) + " (" + what +
           ") must hold unsigned byte, short or int indices");
  }
  std::vector<std::uint32_t> out;
  forEachElement(model, index, what, [&](std::size_t i, const unsigned char* p) {
    const tinygltf::Accessor& acc = model.accessors[std::size_t(index)];
    if (out.size() != acc.count) out.resize(acc.count);
    if (acc.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
      out[i] = *p;
    } else if (acc.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
      std::uint16_t v;
      std::memcpy(&v, p, 2);
      out[i] = v;
    } else {
      std::memcpy(&out[i], p, 4);
    }
  });
  return out;
}

}  // namespace sl::gltf
