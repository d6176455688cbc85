// glTF accessors: reading bufferViews, accessors (strided, normalized, sparse) as floats and
// as indices, every range checked against its buffer (a refusal throws LoadFailure).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace sl::gltf {

/// Accessor `index` as floats, `components` per element; its type must be `expectedType`.
std::vector<float> readFloats(const tinygltf::Model& model, int index, const std::string& what,
                              int expectedType);
std::vector<std::uint32_t> readIndices(const tinygltf::Model& model, int index,
                                       const std::string& what);

}  // namespace sl::gltf
