// glTF 2.0 loading through tinygltf 2.7: parse (.gltf or .glb), check, and flatten the node
// hierarchy into world-space triangle lists, materials, images, the light (KHR_lights_punctual),
// camera bookmarks and camera paths. Spec: https://registry.khronos.org/glTF/specs/2.0/
#include "GltfLoader.h"

#include "algo/InputFile.h"
#include "algo/TriangleBvh.h"
#include "scene/DataDir.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string_view>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <tiny_gltf.h>

namespace sl {
namespace {

namespace fs = std::filesystem;

/// Extensions a file may list in `extensionsRequired`. The first three are implemented
/// (punctual lights: the first directional one, else the first spot or point, lights the scene;
/// texture transforms are baked into the base colour uvs; quantized attributes are read like any
/// normalized accessor). The last two only change shading that ShadowLab does its own way, so
/// ignoring them cannot change geometry, alpha cut-outs or shadows. Everything else (Draco,
/// meshopt, BasisU, WebP, ...) would leave geometry or textures unreadable: such files are refused.
constexpr std::array<std::string_view, 5> kAcceptedRequiredExtensions = {
    "KHR_lights_punctual", "KHR_texture_transform", "KHR_mesh_quantization",
    "KHR_materials_emissive_strength", "KHR_materials_unlit"};

/// An accessor larger than this is treated as corrupt rather than allocated.
constexpr std::size_t kMaxAccessorElements = std::size_t(1) << 28;

// Limits against hostile files. Each is named in the message that refuses a file.
/// The .gltf/.glb file and every external buffer or image file it names.
constexpr std::uint64_t kMaxFileBytes = std::uint64_t(1) << 30;
/// Nesting of JSON arrays and objects (the JSON parsers recurse; real files need < 20).
constexpr int kMaxJsonDepth = 256;
/// Arrays and objects in the JSON, counted before parsing: tinygltf's DOM and model take
/// ~0.7 KiB per container, so a 22 MB chain of 1,000,000 nodes took 1.2 GB and 100,000
/// cameras on 100,000 nodes (600,000) 800 MiB with the GL context. 2^18 keeps any accepted
/// file under 500 MiB (40,000 cameras, 240,000 containers: tests/fixtures/hostile); real
/// scenes have a few thousand nodes.
constexpr std::size_t kMaxJsonContainers = std::size_t(1) << 18;
/// A "uri" that is not a data: URI names a file relative to the scene: no path is longer than
/// PATH_MAX (4096 on Linux). Longer ones are refused in the JSON text, before tinygltf copies
/// them (a 40 MB URI took 500 MiB through its DOM, model, path and "File not found" message).
constexpr std::size_t kMaxUriBytes = 4096;
/// Node instances in the flattened hierarchy.
constexpr std::size_t kMaxNodeInstances = std::size_t(1) << 20;
/// Triangles in the flattened scene (all instances together).
constexpr std::size_t kMaxTriangles = std::size_t(1) << 25;
/// Memory a flattened triangle costs, all copies together (the flattened mesh, GPU buffers, the
/// reference's BVH): a 1 M-triangle mesh on 8 nodes took 3.9 GB, ~490 bytes a triangle.
constexpr std::uint64_t kBytesPerTriangle = 490;
/// Memory a flattened primitive costs besides its triangles, all copies together (its mesh
/// record and vectors, its GPU buffers and vertex array, the reference's geometry): one mesh
/// of 5,000 and of 10,000 one-triangle primitives, `render` at 64x36, peaked at 513,584 and
/// 820,240 KB: ~61 KiB a primitive (the same without the reference). 100,000 of them (a
/// 4.7 MB file) grew to 3.9 GB and died of std::bad_alloc; by this estimate, 5.8 GiB.
constexpr std::uint64_t kBytesPerPrimitive = std::uint64_t(61) << 10;
/// The memory the flattened scene may take by those estimates (~8.7 M triangles): refused
/// before anything is allocated (32 nodes of that mesh, under kMaxTriangles, would have taken
/// ~15 GB).
constexpr std::uint64_t kMaxSceneBytes = std::uint64_t(4) << 30;
/// Longest side and pixel count of a decoded image (larger ones are not decoded).
constexpr int kMaxImageSide = 16384;
constexpr std::uint64_t kMaxImagePixels = std::uint64_t(1) << 26;
/// Pixels of all the images of one file together (256 MiB as RGBA8): a PNG of 8192x8192 zeros
/// is 260 KB, so without it a few MB of images would decode to gigabytes.
constexpr std::uint64_t kMaxTotalImagePixels = std::uint64_t(1) << 26;
/// Input quoted in a message is cut to this many bytes.
constexpr std::size_t kMaxQuotedBytes = 120;
/// How far from the origin (largest |x|, |y| or |z| of the bounds, metres) the geometry may
/// reach. Positions, shadow maps and depths are floats in world space, and a float's spacing
/// grows with its magnitude: below 1e5 m (2^16..2^17) it is 2^-7 m, about 8 mm. Measured
/// with `default` moved 5e4 m away: uniform at 2048² 0.163 % error (0.164 % at the
/// origin), at 8192² 0.52 % (0.04 %): the raster's precision, not the reference's, which
/// offsets its rays by float spacings (metrics/ShadowReference). At 1e6 m the error grows
/// to 7 % (uniform) and 15 % (rtw-backward); at 1e7 m (1 m spacing) the image is blank.
/// Rendering camera-relative would lift this; until then such a scene is refused, saying to
/// recentre it.
constexpr double kMaxSceneExtentM = 1e5;

/// Internal failure; loadGltf() turns it into SceneLoadResult::error with the file name.
struct LoadFailure {
  std::string message;
};

[[noreturn]] void fail(std::string message) {
  throw LoadFailure{std::move(message)};
}

/// "2.5 s".
std::string secondsText(float s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g s", double(s));
  return buf;
}

std::string inQuotes(const std::string& s) {
  return "'" + s + "'";
}

/// In quotes, cut to kMaxQuotedBytes, control characters shown as '?'.
std::string quoteInput(const std::string& s) {
  std::string out = s.substr(0, kMaxQuotedBytes);
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  return "'" + out + (s.size() > kMaxQuotedBytes ? "...'" : "'");
}

/// Newlines and runs of blanks collapsed so an error stays on one line.
std::string oneLine(const std::string& text) {
  std::string out;
  bool pendingBreak = false;
  for (char c : text) {
    if (c == '\n' || c == '\r') {
      pendingBreak = !out.empty();
      continue;
    }
    if (pendingBreak) {
      while (!out.empty() && (out.back() == ' ' || out.back() == '.')) out.pop_back();
      out += "; ";
      pendingBreak = false;
    }
    out += c;
  }
  while (!out.empty() && (out.back() == ' ' || out.back() == ';')) out.pop_back();
  return out;
}

void addLines(std::vector<std::string>& to, const std::string& text) {
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    if (!line.empty()) to.push_back(cutText(std::move(line)));
    start = end + 1;
  }
}

std::string lowerExtension(const fs::path& p) {
  std::string ext = p.extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// ---------------------------------------------------------------------------------------
// Accessors

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

// ---------------------------------------------------------------------------------------
// Transforms

glm::dmat4 localMatrix(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) return glm::make_mat4(node.matrix.data());  // column-major
  glm::dmat4 m(1.0);
  if (node.translation.size() == 3)
    m = glm::translate(m,
                       glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
  if (node.rotation.size() == 4) {
    glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    if (glm::length(q) > 0.0) m *= glm::mat4_cast(glm::normalize(q));
  }
  if (node.scale.size() == 3)
    m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
  return m;
}

bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// Position and rotation (scale removed) of a world matrix.
void decomposePose(const glm::dmat4& world, glm::vec3& position, glm::quat& rotation) {
  position = glm::vec3(world[3]);
  glm::dmat3 r(world);
  for (int c = 0; c < 3; ++c) {
    double len = glm::length(r[c]);
    r[c] = len > 0.0 ? r[c] / len : glm::dvec3(c == 0, c == 1, c == 2);
  }
  if (glm::determinant(r) < 0.0) r[0] = -r[0];
  rotation = glm::quat(glm::normalize(glm::quat_cast(r)));
}

// ---------------------------------------------------------------------------------------
// The flattening

struct NodeInstance {
  int node = -1;
  glm::dmat4 world{1.0};
  glm::dmat4 parentWorld{1.0};
};

/// How a material maps its base colour texture: which TEXCOORD set, which transform.
struct UvRule {
  int texCoord = 0;
  glm::mat3 transform{1.0f};  ///< KHR_texture_transform as a 2D affine matrix
};

class Flattener {
 public:
  Flattener(const tinygltf::Model& model, Scene& scene) : model_(model), scene_(scene) {}

  void run() {
    convertImages();
    convertMaterials();
    collectInstances();
    checkTriangleEstimate();
    for (const NodeInstance& inst : instances_) addMeshInstance(inst);
    if (scene_.triangleCount() == 0)
      fail("no triangles (the file has no triangle meshes in its scene)");
    for (const MeshPrimitive& prim : scene_.primitives)
      for (const glm::vec3& p : prim.positions) scene_.bounds.extend(p);
    checkExtent();
    addLights();
    addCameras();
    addPaths();
  }

 private:
  void warn(const std::string& text) { scene_.warnings.push_back(text); }

  /// Refuses geometry reaching farther from the origin than kMaxSceneExtentM.
  void checkExtent() const {
    const Aabb& b = scene_.bounds;
    const double reach =
        std::max({std::abs(double(b.min.x)), std::abs(double(b.min.y)), std::abs(double(b.min.z)),
                  std::abs(double(b.max.x)), std::abs(double(b.max.y)), std::abs(double(b.max.z))});
    if (!(reach > kMaxSceneExtentM)) return;
    auto number = [](double v) {
      char text[64];
      std::snprintf(text, sizeof text, std::abs(v) < 1e15 ? "%.0f" : "%.3g", v);
      return std::string(text);
    };
    auto point = [&](const glm::vec3& p) {
      return "(" + number(p.x) + ", " + number(p.y) + ", " + number(p.z) + ")";
    };
    fail("the geometry reaches " + number(reach) + " m from the origin (bounds " + point(b.min) +
         " to " + point(b.max) + " m), beyond the limit of " + number(kMaxSceneExtentM) +
         " m"
         " (kMaxSceneExtentM): float precision would distort the shadows; recentre the scene "
         "near the origin");
  }

  void warnOnce(const std::string& key, const std::string& text) {
    if (warnedKeys_.insert(key).second) warn(text);
  }

  std::string nodeName(int index) const {
    const tinygltf::Node& n = model_.nodes[std::size_t(index)];
    return n.name.empty() ? "node " + std::to_string(index) : inQuotes(n.name);
  }

  void convertImages() {
    for (std::size_t i = 0; i < model_.images.size(); ++i) {
      const tinygltf::Image& src = model_.images[i];
      SceneImage img;
      img.name = !src.name.empty() ? src.name
                 : (!src.uri.empty() && src.uri.rfind("data:", 0) != 0)
                     ? src.uri
                     : "image " + std::to_string(i);
      int comps = src.component, bytesPerComp = src.bits == 16 ? 2 : 1;
      std::size_t pixels =
          src.width > 0 && src.height > 0 ? std::size_t(src.width) * std::size_t(src.height) : 0;
      if (pixels == 0 || comps < 1 || comps > 4 || (src.bits != 8 && src.bits != 16) ||
          src.image.size() < pixels * std::size_t(comps * bytesPerComp)) {
        warn("image " + inQuotes(img.name) +
             " could not be decoded; textures using it are left out");
        scene_.images.push_back(std::move(img));
        continue;
      }
      img.width = src.width;
      img.height = src.height;
      img.rgba.resize(pixels * 4);
      for (std::size_t p = 0; p < pixels; ++p) {
        std::uint8_t c[4] = {0, 0, 0, 255};
        for (int k = 0; k < comps; ++k) {
          // 16-bit images keep their high byte (the host is little-endian, as tinygltf assumes).
          std::size_t at = (p * std::size_t(comps) + std::size_t(k)) * std::size_t(bytesPerComp);
          c[k] = bytesPerComp == 2 ? src.image[at + 1] : src.image[at];
        }
        if (comps == 1) c[1] = c[2] = c[0];               // grey
        if (comps == 2) c[3] = c[1], c[1] = c[2] = c[0];  // grey + alpha
        std::memcpy(&img.rgba[p * 4], c, 4);
      }
      scene_.images.push_back(std::move(img));
    }
  }

  void convertMaterials() {
    for (std::size_t i = 0; i < model_.materials.size(); ++i) {
      const tinygltf::Material& src = model_.materials[i];
      Material m;
      m.name = src.name.empty() ? "material " + std::to_string(i) : src.name;
      const std::vector<double>& f = src.pbrMetallicRoughness.baseColorFactor;
      if (f.size() == 4)
        m.baseColorFactor = glm::vec4(float(f[0]), float(f[1]), float(f[2]), float(f[3]));
      UvRule rule;
      const tinygltf::TextureInfo& tex = src.pbrMetallicRoughness.baseColorTexture;
      if (tex.index >= 0) {
        int image = -1;
        if (std::size_t(tex.index) < model_.textures.size())
          image = model_.textures[std::size_t(tex.index)].source;
        if (image >= 0 && std::size_t(image) < scene_.images.size() &&
            scene_.images[std::size_t(image)].width > 0) {
          m.baseColorTexture = image;
        } else {
          warn("material " + inQuotes(m.name) + ": base colour texture " +
               std::to_string(tex.index) + " has no usable image; it is left out");
        }
        rule.texCoord = tex.texCoord;
        auto it = tex.extensions.find("KHR_texture_transform");
        if (it != tex.extensions.end() && it->second.IsObject())
          readTextureTransform(it->second, rule);
      }
      if (src.alphaMode == "MASK") {
        m.alphaMode = AlphaMode::Mask;
      } else if (src.alphaMode == "BLEND") {
        m.alphaMode = AlphaMode::Blend;
      } else if (src.alphaMode != "OPAQUE" && !src.alphaMode.empty()) {
        warn("material " + inQuotes(m.name) + ": unknown alphaMode " + inQuotes(src.alphaMode) +
             ", using OPAQUE");
      }
      m.alphaCutoff = float(src.alphaCutoff);
      m.doubleSided = src.doubleSided;
      scene_.materials.push_back(std::move(m));
      uvRules_.push_back(rule);
    }
  }

  static void readTextureTransform(const tinygltf::Value& ext, UvRule& rule) {
    glm::vec2 offset(0.0f), scale(1.0f);
    float rotation = 0.0f;
    auto vec2Of = [&](const char* key, glm::vec2& out) {
      const tinygltf::Value& v = ext.Get(key);
      if (v.IsArray() && v.ArrayLen() == 2 && v.Get(0).IsNumber() && v.Get(1).IsNumber())
        out = glm::vec2(float(v.Get(0).GetNumberAsDouble()), float(v.Get(1).GetNumberAsDouble()));
    };
    vec2Of("offset", offset);
    vec2Of("scale", scale);
    if (ext.Get("rotation").IsNumber()) rotation = float(ext.Get("rotation").GetNumberAsDouble());
    if (ext.Get("texCoord").IsNumber()) rule.texCoord = ext.Get("texCoord").GetNumberAsInt();
    // uv' = T * R * S * uv with R = [cos sin; -sin cos] written row by row: "counter-clockwise"
    // in glTF's v-down uv space, as the TextureTransformTest sample model, Babylon, Blender
    // and three.js do (the extension's GLSL listing reads the other way; KhronosGroup/glTF#1563).
    float c = std::cos(rotation), s = std::sin(rotation);
    rule.transform =
        glm::mat3(glm::vec3(c * scale.x, -s * scale.x, 0.0f),
                  glm::vec3(s * scale.y, c * scale.y, 0.0f), glm::vec3(offset.x, offset.y, 1.0f));
  }

  void collectInstances() {
    std::vector<int> roots;
    if (!model_.scenes.empty()) {
      int sceneIndex = model_.defaultScene;
      if (sceneIndex < 0 || std::size_t(sceneIndex) >= model_.scenes.size()) {
        if (sceneIndex >= 0)
          warn("default scene " + std::to_string(sceneIndex) + " does not exist; using scene 0");
        sceneIndex = 0;
      }
      roots = model_.scenes[std::size_t(sceneIndex)].nodes;
    } else {
      // No scenes: every node that is nobody's child is a root.
      std::vector<bool> isChild(model_.nodes.size(), false);
      for (const tinygltf::Node& n : model_.nodes)
        for (int c : n.children)
          if (c >= 0 && std::size_t(c) < isChild.size()) isChild[std::size_t(c)] = true;
      for (std::size_t i = 0; i < model_.nodes.size(); ++i)
        if (!isChild[i]) roots.push_back(int(i));
    }
    visitTree(roots);
  }

  /// "node 7" or "node 7 'name'": the index always, since names need not be unique.
  std::string nodeLabel(int index) const {
    const tinygltf::Node& n = model_.nodes[std::size_t(index)];
    return "node " + std::to_string(index) + (n.name.empty() ? "" : " " + quoteInput(n.name));
  }

  /// glTF's rules for a node's transform, which the flattening relies on: a matrix
  /// decomposes into translation, rotation and scale (affine: last row 0, 0, 0, 1), a
  /// rotation is a unit quaternion, every value is finite. A zero or non-finite quaternion and
  /// a projective matrix are refused; a rotation of another length is normalised with a warning.
  void checkNodeTransform(int index) {
    const tinygltf::Node& node = model_.nodes[std::size_t(index)];
    auto allFinite = [](const std::vector<double>& v) {
      return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
    };
    auto listed = [](const std::vector<double>& v) {
      std::string text;
      for (double x : v) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.6g", x);
        text += (text.empty() ? "" : ", ") + std::string(buf);
      }
      return text;
    };
    const std::pair<const char*, const std::vector<double>*> fields[] = {
        {"matrix", &node.matrix},
        {"translation", &node.translation},
        {"rotation", &node.rotation},
        {"scale", &node.scale}};
    for (const auto& [name, values] : fields)
      if (!allFinite(*values))
        fail(nodeLabel(index) + ": " + name + " has a value that is not finite");
    if (node.matrix.size() == 16) {
      const std::vector<double>& m = node.matrix;  // column-major: the last row is 3, 7, 11, 15
      const std::vector<double> lastRow{m[3], m[7], m[11], m[15]};
      if (std::abs(m[3]) > 1e-6 || std::abs(m[7]) > 1e-6 || std::abs(m[11]) > 1e-6 ||
          std::abs(m[15] - 1.0) > 1e-6)
        fail(nodeLabel(index) + ": matrix is not affine (its last row is " + listed(lastRow) +
             ", not 0, 0, 0, 1): glTF requires a node matrix to decompose into translation, "
             "rotation and scale");
    }
    if (node.rotation.size() == 4) {
      const double len = glm::length(
          glm::dvec4(node.rotation[0], node.rotation[1], node.rotation[2], node.rotation[3]));
      if (!(len > 1e-12))
        fail(nodeLabel(index) + ": rotation (" + listed(node.rotation) +
             ") is not a unit quaternion (length 0): glTF requires a unit quaternion");
      if (std::abs(len - 1.0) > 1e-3)
        warnOnce("rotation length", nodeLabel(index) + ": rotation of length " + listed({len}) +
                                        " normalised (glTF requires unit quaternions; other "
                                        "nodes like it are not listed)");
    }
  }

  /// Depth-first, parents before children (the order a recursive walk gives), with an
  /// explicit stack so that a chain of a million nodes cannot overflow the call stack. glTF
  /// requires the hierarchy to be a set of disjoint trees: a node reached a second time (a
  /// DAG, whose instances would double with each level, or a cycle) is refused.
  void visitTree(const std::vector<int>& roots) {
    const std::size_t nodeCount = model_.nodes.size();
    auto checkIndex = [&](int index, const std::string& where) {
      if (index < 0 || std::size_t(index) >= nodeCount)
        fail(where + "node " + std::to_string(index) + " is out of range (" +
             std::to_string(nodeCount) + " nodes)");
    };
    std::vector<int> parentOf(nodeCount, -2);  // -2 unvisited, -1 a root
    std::vector<bool> onPath(nodeCount, false);
    struct Frame {
      std::size_t instance;   ///< index into instances_
      std::size_t nextChild;  ///< next entry of the node's children to visit
    };
    std::vector<Frame> stack;
    auto enter = [&](int index, int parent, const glm::dmat4& parentWorld) {
      if (parentOf[std::size_t(index)] != -2) {
        if (onPath[std::size_t(index)])
          fail("the node hierarchy has a cycle through " + nodeLabel(index) +
               ": glTF requires a tree");
        int first = parentOf[std::size_t(index)];
        std::string firstWhere =
            first < 0 ? "a root of the scene" : "a child of " + nodeLabel(first);
        std::string secondWhere =
            parent < 0 ? "a root of the scene" : "a child of " + nodeLabel(parent);
        fail(nodeLabel(index) + " is reachable twice (" + firstWhere + " and " + secondWhere +
             "): glTF requires the node hierarchy to be a tree");
      }
      if (instances_.size() >= kMaxNodeInstances)
        fail("more than " + std::to_string(kMaxNodeInstances) +
             " node instances in the scene: refused (kMaxNodeInstances)");
      parentOf[std::size_t(index)] = parent;
      onPath[std::size_t(index)] = true;
      checkNodeTransform(index);
      NodeInstance inst;
      inst.node = index;
      inst.parentWorld = parentWorld;
      inst.world = parentWorld * localMatrix(model_.nodes[std::size_t(index)]);
      instances_.push_back(inst);
      stack.push_back({instances_.size() - 1, 0});
    };
    for (int root : roots) {
      checkIndex(root, "the scene's root ");
      enter(root, -1, glm::dmat4(1.0));
      while (!stack.empty()) {
        Frame& top = stack.back();
        const int index = instances_[top.instance].node;
        const std::vector<int>& children = model_.nodes[std::size_t(index)].children;
        if (top.nextChild == children.size()) {
          onPath[std::size_t(index)] = false;
          stack.pop_back();
          continue;
        }
        const int child = children[top.nextChild++];
        checkIndex(child, "child of " + nodeLabel(index) + ": ");
        const glm::dmat4 world = instances_[top.instance].world;  // enter() may reallocate
        enter(child, index, world);
      }
    }
  }

  /// Refuses, before anything is read or allocated, a scene whose instances would flatten to
  /// more than kMaxTriangles triangles (a mesh instanced by many nodes). The estimate comes
  /// from the accessors' counts; addPrimitive() checks the exact total as it goes.
  void checkTriangleEstimate() const {
    auto countOf = [&](int accessor) -> std::size_t {
      if (accessor < 0 || std::size_t(accessor) >= model_.accessors.size()) return 0;
      return model_.accessors[std::size_t(accessor)].count;
    };
    std::vector<std::size_t> perMesh(model_.meshes.size(), 0);
    std::vector<std::size_t> primitivesOf(model_.meshes.size(), 0);
    for (std::size_t m = 0; m < model_.meshes.size(); ++m) {
      primitivesOf[m] = model_.meshes[m].primitives.size();
      for (const tinygltf::Primitive& prim : model_.meshes[m].primitives) {
        int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
        auto pos = prim.attributes.find("POSITION");
        std::size_t n = prim.indices >= 0              ? countOf(prim.indices)
                        : pos != prim.attributes.end() ? countOf(pos->second)
                                                       : 0;
        std::size_t t =
            mode == TINYGLTF_MODE_TRIANGLES ? n / 3
            : (mode == TINYGLTF_MODE_TRIANGLE_STRIP || mode == TINYGLTF_MODE_TRIANGLE_FAN) && n >= 3
                ? n - 2
                : 0;
        perMesh[m] = std::min(perMesh[m] + std::min(t, kMaxAccessorElements), kMaxAccessorElements);
      }
    }
    std::size_t total = 0;
    std::uint64_t primitives = 0;
    for (const NodeInstance& inst : instances_) {
      const int mesh = model_.nodes[std::size_t(inst.node)].mesh;
      if (mesh < 0 || std::size_t(mesh) >= perMesh.size()) continue;
      total += perMesh[std::size_t(mesh)];
      primitives += primitivesOf[std::size_t(mesh)];
      const std::uint64_t bytes =
          std::uint64_t(total) * kBytesPerTriangle + primitives * kBytesPerPrimitive;
      if (total <= kMaxTriangles && bytes > kMaxSceneBytes) {
        char gib[32];
        std::snprintf(gib, sizeof gib, "%.1f", double(bytes) / double(1u << 30));
        fail("the flattened scene would have " + std::to_string(total) + "+ triangles in " +
             std::to_string(primitives) + "+ primitives (" + std::to_string(instances_.size()) +
             " node instances; a mesh counts once per node that uses it), about " + gib +
             " GiB at ~" + std::to_string(kBytesPerTriangle) + " bytes a triangle and ~" +
             std::to_string(kBytesPerPrimitive >> 10) +
             " KiB a primitive (kBytesPerPrimitive): over the limit of " +
             byteLimitText(kMaxSceneBytes) + " (kMaxSceneBytes)");
      }
      if (total > kMaxTriangles)
        fail("the flattened scene would have more than " + std::to_string(kMaxTriangles) +
             " triangles (" + std::to_string(instances_.size()) +
             " node instances; a mesh counts once per node that uses it): refused "
             "(kMaxTriangles)");
    }
  }

  void addMeshInstance(const NodeInstance& inst) {
    const tinygltf::Node& node = model_.nodes[std::size_t(inst.node)];
    if (node.mesh < 0) return;
    if (std::size_t(node.mesh) >= model_.meshes.size())
      fail(nodeName(inst.node) + ": mesh " + std::to_string(node.mesh) + " is out of range (" +
           std::to_string(model_.meshes.size()) + " meshes)");
    if (node.skin >= 0)
      warnOnce("skin" + std::to_string(inst.node),
               nodeName(inst.node) + ": skin ignored, the mesh is shown in its rest pose");
    const tinygltf::Mesh& mesh = model_.meshes[std::size_t(node.mesh)];
    std::string meshName = mesh.name.empty() ? "mesh " + std::to_string(node.mesh) : mesh.name;
    std::string baseName = node.name.empty() ? meshName : node.name;
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
      std::string label = "mesh " + inQuotes(meshName) + " primitive " + std::to_string(p);
      std::string name = mesh.primitives.size() > 1 ? baseName + "#" + std::to_string(p) : baseName;
      addPrimitive(mesh.primitives[p], label, name, inst.world);
    }
  }

  void addPrimitive(const tinygltf::Primitive& src, const std::string& label,
                    const std::string& name, const glm::dmat4& world) {
    int mode = src.mode < 0 ? TINYGLTF_MODE_TRIANGLES : src.mode;
    if (mode == TINYGLTF_MODE_POINTS || mode == TINYGLTF_MODE_LINE ||
        mode == TINYGLTF_MODE_LINE_LOOP || mode == TINYGLTF_MODE_LINE_STRIP) {
      warn(label + ": " + (mode == TINYGLTF_MODE_POINTS ? "points" : "lines") +
           " skipped (only triangles are drawn)");
      return;
    }
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        mode != TINYGLTF_MODE_TRIANGLE_FAN) {
      warn(label + ": unknown primitive mode " + std::to_string(mode) + " skipped");
      return;
    }
    auto posIt = src.attributes.find("POSITION");
    if (posIt == src.attributes.end()) {
      warn(label + ": no POSITION attribute, skipped");
      return;
    }
    if (!src.targets.empty())
      warnOnce("morph" + label,
               label + ": morph targets ignored, the mesh is shown in its rest pose");

    MeshPrimitive prim;
    prim.name = name;
    std::vector<float> raw =
        readFloats(model_, posIt->second, "POSITION of " + label, TINYGLTF_TYPE_VEC3);
    const std::size_t vertexCount = raw.size() / 3;
    for (std::size_t v = 0; v < vertexCount; ++v) {
      glm::vec3 p(raw[3 * v], raw[3 * v + 1], raw[3 * v + 2]);
      if (!finite(p))
        fail(label + ": POSITION of vertex " + std::to_string(v) + " is not finite (NaN or inf)");
    }

    // Indices, as a triangle list.
    std::vector<std::uint32_t> order;
    if (src.indices >= 0) {
      order = readIndices(model_, src.indices, "indices of " + label);
      for (std::size_t k = 0; k < order.size(); ++k)
        if (order[k] >= vertexCount)
          fail(label + ": index " + std::to_string(order[k]) + " (element " + std::to_string(k) +
               ") is out of range: the primitive has " + std::to_string(vertexCount) + " vertices");
    } else {
      order.resize(vertexCount);
      for (std::size_t v = 0; v < vertexCount; ++v) order[v] = std::uint32_t(v);
    }
    std::vector<std::uint32_t> tri;
    if (mode == TINYGLTF_MODE_TRIANGLES) {
      if (order.size() % 3 != 0)
        warn(label + ": " + std::to_string(order.size()) +
             " indices is not a multiple of 3; the last partial triangle is dropped");
      tri.assign(order.begin(), order.begin() + std::ptrdiff_t(order.size() / 3 * 3));
    } else {
      // Strip: triangle i = (i, i+1+i%2, i+2-i%2); fan: (i+1, i+2, 0). Restart-style
      // degenerate triangles are dropped.
      for (std::size_t i = 0; i + 2 < order.size(); ++i) {
        std::uint32_t a, b, c;
        if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
          a = order[i], b = order[i + 1 + i % 2], c = order[i + 2 - i % 2];
        } else {
          a = order[i + 1], b = order[i + 2], c = order[0];
        }
        if (a == b || b == c || a == c) continue;
        tri.insert(tri.end(), {a, b, c});
      }
    }
    if (tri.empty()) {
      warn(label + ": no triangles, skipped");
      return;
    }
    if (tri.size() / 3 > kMaxTriangles - triangles_)
      fail(label + ": the flattened scene would have more than " + std::to_string(kMaxTriangles) +
           " triangles (all node instances together): refused (kMaxTriangles)");
    triangles_ += tri.size() / 3;

    // Normals and texture coordinates.
    std::vector<float> normals;
    if (auto it = src.attributes.find("NORMAL"); it != src.attributes.end()) {
      normals = readFloats(model_, it->second, "NORMAL of " + label, TINYGLTF_TYPE_VEC3);
      if (normals.size() != raw.size())
        fail(label + ": NORMAL has " + std::to_string(normals.size() / 3) +
             " elements, POSITION has " + std::to_string(vertexCount));
    }
    UvRule rule;
    if (src.material >= 0 && std::size_t(src.material) < uvRules_.size())
      rule = uvRules_[std::size_t(src.material)];
    std::vector<float> uvs;
    std::string uvName = "TEXCOORD_" + std::to_string(rule.texCoord);
    if (auto it = src.attributes.find(uvName); it != src.attributes.end()) {
      uvs = readFloats(model_, it->second, uvName + " of " + label, TINYGLTF_TYPE_VEC2);
      if (uvs.size() / 2 != vertexCount)
        fail(label + ": " + uvName + " has " + std::to_string(uvs.size() / 2) +
             " elements, POSITION has " + std::to_string(vertexCount));
    }

    // To world space. Normals go by the inverse transpose; a mirroring transform flips
    // the winding so that front faces stay counter-clockwise.
    glm::mat4 m(world);
    glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(m)));
    const bool mirrored = glm::determinant(glm::dmat3(world)) < 0.0;
    prim.positions.resize(vertexCount);
    for (std::size_t v = 0; v < vertexCount; ++v) {
      glm::vec3 p = glm::vec3(m * glm::vec4(raw[3 * v], raw[3 * v + 1], raw[3 * v + 2], 1.0f));
      if (!finite(p))
        fail(label + ": the node transform makes vertex " + std::to_string(v) +
             " not finite (NaN or inf)");
      prim.positions[v] = p;
    }
    if (!normals.empty()) {
      prim.normals.resize(vertexCount);
      bool fixed = false;
      for (std::size_t v = 0; v < vertexCount; ++v) {
        glm::vec3 n =
            normalMatrix * glm::vec3(normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]);
        float len = glm::length(n);
        if (!(len > 1e-20f) || !std::isfinite(len)) {
          n = glm::vec3(0.0f, 1.0f, 0.0f);
          fixed = true;
        } else {
          n /= len;
        }
        prim.normals[v] = n;
      }
      if (fixed) warn(label + ": zero or non-finite normals replaced by +y");
    }
    if (!uvs.empty()) {
      prim.uvs.resize(vertexCount);
      for (std::size_t v = 0; v < vertexCount; ++v)
        prim.uvs[v] = glm::vec2(rule.transform * glm::vec3(uvs[2 * v], uvs[2 * v + 1], 1.0f));
    }
    if (mirrored)
      for (std::size_t t = 0; t + 2 < tri.size(); t += 3) std::swap(tri[t + 1], tri[t + 2]);
    prim.indices = std::move(tri);
    if (prim.normals.empty()) computeFlatNormals(prim);
    if (src.material >= 0 && std::size_t(src.material) >= scene_.materials.size()) {
      warn(label + ": material " + std::to_string(src.material) +
           " does not exist, using the default");
    } else {
      prim.material = src.material;
    }
    scene_.primitives.push_back(std::move(prim));
  }

  /// The spec's rule for primitives without normals: flat shading. Each triangle gets its
  /// own three vertices whose normal is the (counter-clockwise) face normal.
  static void computeFlatNormals(MeshPrimitive& prim) {
    MeshPrimitive flat;
    flat.name = prim.name;
    const std::size_t n = prim.indices.size();
    flat.positions.reserve(n);
    flat.normals.reserve(n);
    if (!prim.uvs.empty()) flat.uvs.reserve(n);
    for (std::size_t t = 0; t + 2 < n; t += 3) {
      std::uint32_t i[3] = {prim.indices[t], prim.indices[t + 1], prim.indices[t + 2]};
      glm::vec3 face = glm::cross(prim.positions[i[1]] - prim.positions[i[0]],
                                  prim.positions[i[2]] - prim.positions[i[0]]);
      float len = glm::length(face);
      glm::vec3 normal = len > 0.0f && std::isfinite(len) ? face / len : glm::vec3(0, 1, 0);
      for (std::uint32_t k : i) {
        flat.indices.push_back(std::uint32_t(flat.positions.size()));
        flat.positions.push_back(prim.positions[k]);
        flat.normals.push_back(normal);
        if (!prim.uvs.empty()) flat.uvs.push_back(prim.uvs[k]);
      }
    }
    prim.positions = std::move(flat.positions);
    prim.normals = std::move(flat.normals);
    prim.uvs = std::move(flat.uvs);
    prim.indices = std::move(flat.indices);
  }

  /// KHR_lights_punctual: the scene's light is its first directional light (the sun), or,
  /// when it has none, its first spot or point light (in node order). Position and axis
  /// come from the node's world transform (lights shine along the node's -z); cone angles
  /// and range from the light (range is not scaled by the node, as the extension says).
  void addLights() {
    struct Candidate {
      Light light;
      std::string label;  ///< "spot light 'lamp'"
    };
    std::vector<Candidate> found;
    for (const NodeInstance& inst : instances_) {
      const tinygltf::Node& node = model_.nodes[std::size_t(inst.node)];
      auto it = node.extensions.find("KHR_lights_punctual");
      if (it == node.extensions.end() || !it->second.IsObject()) continue;
      const tinygltf::Value& ref = it->second.Get("light");
      if (!ref.IsNumber()) continue;
      int index = ref.GetNumberAsInt();
      if (index < 0 || std::size_t(index) >= model_.lights.size()) {
        warn(nodeName(inst.node) + ": light " + std::to_string(index) + " does not exist, ignored");
        continue;
      }
      const tinygltf::Light& gl = model_.lights[std::size_t(index)];
      std::string name = gl.name.empty() ? "light " + std::to_string(index) : inQuotes(gl.name);
      std::optional<LightType> type = lightTypeFromName(gl.type);
      if (!type) {
        warn("light " + name + " of unknown type '" + gl.type + "' ignored");
        continue;
      }
      const std::string label = gl.type + " light " + name;
      // glTF lights shine along their node's -z: the light lies towards +z.
      glm::dvec3 towards = glm::dvec3(inst.world * glm::dvec4(0.0, 0.0, 1.0, 0.0));
      glm::dvec3 position = glm::dvec3(inst.world * glm::dvec4(0.0, 0.0, 0.0, 1.0));
      double len = glm::length(towards);
      if (*type != LightType::Point && (!(len > 0.0) || !std::isfinite(len))) {
        warn(label + " has a degenerate node transform, ignored");
        continue;
      }
      Light light;
      if (*type == LightType::Directional) {
        light = Light::directionalFromTowards(glm::vec3(towards / len));
      } else {
        light.type = *type;
        light.positionM = glm::vec3(position);
        light.rangeM = float(gl.range);
        if (*type == LightType::Spot) {
          light.direction = -glm::vec3(towards / len);
          light.outerConeDeg = float(glm::degrees(gl.spot.outerConeAngle));
          light.innerConeDeg = float(glm::degrees(gl.spot.innerConeAngle));
          // glTF allows up to 90 degrees; every light ShadowLab renders stays within
          // kMaxSpotConeDeg (Light::validate refuses wider cones from other inputs).
          if (light.outerConeDeg > kMaxSpotConeDeg && light.outerConeDeg <= 90.0f) {
            char angle[32];
            std::snprintf(angle, sizeof angle, "%.7g", double(light.outerConeDeg));
            warn(label + ": outer cone angle " + angle + " degrees narrowed to " +
                 std::to_string(int(kMaxSpotConeDeg)) +
                 " (kMaxSpotConeDeg: one perspective shadow map covers less than a "
                 "half-space)");
            light.outerConeDeg = kMaxSpotConeDeg;
            light.innerConeDeg = std::min(light.innerConeDeg, light.outerConeDeg);
          }
        }
        if (gl.intensity <= 0.0) warn(label + " has no intensity; it still casts shadows");
      }
      if (auto err = light.validate()) {
        warn(label + " ignored: " + *err);
        continue;
      }
      found.push_back({light, label});
    }
    std::size_t chosen = found.size();
    for (std::size_t i = 0; i < found.size() && chosen == found.size(); ++i)
      if (found[i].light.type == LightType::Directional) chosen = i;
    if (chosen == found.size() && !found.empty()) chosen = 0;
    for (std::size_t i = 0; i < found.size(); ++i) {
      if (i == chosen) continue;
      warn(found[i].label +
           " ignored (ShadowLab lights the scene with one light: " + found[chosen].label + ")");
    }
    if (chosen < found.size()) scene_.light = found[chosen].light;
    if (!scene_.light)
      warn("no directional light (KHR_lights_punctual): the scene has no sun of its own");
  }

  /// Distance along a ray to the first triangle (either side), or +inf. The hierarchy is
  /// built on the first call: a ray per camera through every triangle was O(cameras x
  /// triangles), 111 s for 10^5 cameras each on a node with a mesh.
  float firstHit(const glm::vec3& origin, const glm::vec3& dir) {
    if (!bvh_) {
      std::vector<TriangleMeshView> meshes;
      meshes.reserve(scene_.primitives.size());
      for (const MeshPrimitive& prim : scene_.primitives)
        meshes.push_back({prim.positions, prim.indices});
      bvh_.emplace(std::move(meshes));
    }
    return bvh_->firstHit(origin, dir);
  }

  /// A far plane that reaches every corner of the scene bounds from `position`.
  float farFromBounds(const glm::vec3& position, float nearM) const {
    float far = 0.0f;
    for (const glm::vec3& c : scene_.bounds.corners())
      far = std::max(far, glm::distance(position, c));
    return std::max(far * 1.05f, nearM * 10.0f);
  }

  struct CameraLens {
    float fovYDeg = 50.0f, nearM = 0.1f, farM = 0.0f;  ///< farM 0 = from the scene bounds
  };

  /// The lens of a perspective camera, or nothing (with a warning) for other cameras.
  std::optional<CameraLens> lensOf(int cameraIndex, const std::string& where) {
    if (cameraIndex < 0 || std::size_t(cameraIndex) >= model_.cameras.size()) {
      warn(where + ": camera " + std::to_string(cameraIndex) + " does not exist, ignored");
      return std::nullopt;
    }
    const tinygltf::Camera& cam = model_.cameras[std::size_t(cameraIndex)];
    if (cam.type != "perspective") {
      warnOnce("ortho" + std::to_string(cameraIndex),
               where + ": " + (cam.type.empty() ? "untyped" : cam.type) +
                   " camera ignored (only perspective cameras become bookmarks)");
      return std::nullopt;
    }
    CameraLens lens;
    double fov = glm::degrees(cam.perspective.yfov);
    if (fov > 1.0 && fov < 170.0) {
      lens.fovYDeg = float(fov);
    } else {
      warn(where + ": yfov out of range, using 50 degrees");
    }
    // glTF: 0 < znear < zfar (zfar absent: infinite, the far plane then comes from the
    // scene's bounds). Anything else is said, not silently replaced.
    const double znear = cam.perspective.znear, zfar = cam.perspective.zfar;
    auto metres = [](double v) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%g m", v);
      return std::string(buf);
    };
    if (!(znear > 0.0) || !std::isfinite(znear)) {
      warn(where + ": znear " + metres(znear) + " is not above 0, using " + metres(lens.nearM));
    } else if (znear < double(Camera::kMinNearM)) {
      lens.nearM = Camera::kMinNearM;
      warn(where + ": znear " + metres(znear) + " is below " + metres(Camera::kMinNearM) +
           ", using that");
    } else {
      lens.nearM = float(znear);
    }
    if (zfar > double(lens.nearM) && zfar <= double(Camera::kMaxFarM)) {
      lens.farM = float(zfar);
    } else if (zfar > double(Camera::kMaxFarM)) {
      lens.farM = Camera::kMaxFarM;
      warn(where + ": zfar " + metres(zfar) + " is beyond " + metres(Camera::kMaxFarM) +
           ", using that");
    } else if (zfar != 0.0) {
      warn(where + ": zfar " + metres(zfar) + " is not beyond znear " + metres(lens.nearM) +
           ", ignored (the far plane comes from the scene's bounds)");
    }
    return lens;
  }

  std::string cameraName(const NodeInstance& inst) const {
    const tinygltf::Node& node = model_.nodes[std::size_t(inst.node)];
    const tinygltf::Camera& cam = model_.cameras[std::size_t(node.camera)];
    if (!cam.name.empty()) return cam.name;
    if (!node.name.empty()) return node.name;
    return "camera " + std::to_string(scene_.cameras.size() + 1);
  }

  /// `nearM`, raised (with a warning) to far / Camera::kMaxFarOverNear where the depth buffer
  /// could not tell the far half of the view apart (a 1e-6 m znear with a 200 m zfar).
  float nearWithinDepthPrecision(float nearM, float farM, const std::string& where) {
    if (!Camera::depthPrecisionError(nearM, farM)) return nearM;
    const float raised = farM / Camera::kMaxFarOverNear;
    char buf[160];
    std::snprintf(buf, sizeof buf,
                  ": znear %.3g m raised to %.3g m (far %.3g m; kMaxFarOverNear, float depth "
                  "precision)",
                  double(nearM), double(raised), double(farM));
    warn(where + buf);
    return raised;
  }

  void addCameras() {
    for (const NodeInstance& inst : instances_) {
      const tinygltf::Node& node = model_.nodes[std::size_t(inst.node)];
      if (node.camera < 0) continue;
      std::optional<CameraLens> lens = lensOf(node.camera, nodeName(inst.node));
      if (!lens) continue;
      glm::vec3 position;
      glm::quat rotation;
      decomposePose(inst.world, position, rotation);
      float far = lens->farM > 0.0f ? lens->farM : farFromBounds(position, lens->nearM);
      lens->nearM = nearWithinDepthPrecision(lens->nearM, far, "camera " + nodeName(inst.node));
      glm::vec3 forward = glm::normalize(rotation * glm::vec3(0.0f, 0.0f, -1.0f));
      // Orbit target: what the camera looks at, else the point nearest the scene centre.
      float dist = firstHit(position, forward);
      if (!(dist > lens->nearM && dist < far))
        dist = std::max(glm::dot(scene_.bounds.center() - position, forward), 1.0f);
      CameraBookmark bookmark;
      bookmark.name = cameraName(inst);
      bookmark.camera = cameraFromPose(position, rotation, lens->fovYDeg, lens->nearM, far, dist);
      if (auto problem = bookmark.camera.validate()) {
        warn("camera " + inQuotes(bookmark.name) + " ignored: " + Camera::withoutPrefix(*problem));
        continue;
      }
      scene_.cameras.push_back(std::move(bookmark));
    }
  }

  /// One animation channel's keyframes, already read.
  struct Track {
    std::vector<float> times;
    std::vector<glm::vec4> values;  ///< xyz for translation, xyzw for rotation
    bool step = false;
    bool rotation = false;

    glm::vec4 at(float t) const {
      if (t <= times.front()) return values.front();
      if (t >= times.back()) return values.back();
      std::size_t k =
          std::size_t(std::upper_bound(times.begin(), times.end(), t) - times.begin()) - 1;
      if (step) return values[k];
      float span = times[k + 1] - times[k];
      float u = span > 0.0f ? (t - times[k]) / span : 0.0f;
      if (!rotation) return glm::mix(values[k], values[k + 1], u);
      glm::quat a(values[k].w, values[k].x, values[k].y, values[k].z);
      glm::quat b(values[k + 1].w, values[k + 1].x, values[k + 1].y, values[k + 1].z);
      glm::quat q = glm::slerp(glm::normalize(a), glm::normalize(b), u);
      return glm::vec4(q.x, q.y, q.z, q.w);
    }
  };

  Track readTrack(const tinygltf::Animation& anim, const tinygltf::AnimationChannel& channel,
                  const std::string& label) {
    if (channel.sampler < 0 || std::size_t(channel.sampler) >= anim.samplers.size())
      fail(label + ": sampler " + std::to_string(channel.sampler) + " is out of range");
    const tinygltf::AnimationSampler& sampler = anim.samplers[std::size_t(channel.sampler)];
    Track track;
    track.rotation = channel.target_path == "rotation";
    track.step = sampler.interpolation == "STEP";
    bool cubic = sampler.interpolation == "CUBICSPLINE";
    if (cubic) warn(label + ": CUBICSPLINE keys are followed linearly (tangents ignored)");
    track.times = readFloats(model_, sampler.input, "times of " + label, TINYGLTF_TYPE_SCALAR);
    int type = track.rotation ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3;
    std::vector<float> out = readFloats(model_, sampler.output, "values of " + label, type);
    std::size_t comps = track.rotation ? 4 : 3;
    std::size_t perKey = cubic ? 3 : 1;  // cubic: in-tangent, value, out-tangent
    if (track.times.empty() || out.size() != track.times.size() * comps * perKey)
      fail(label + ": " + std::to_string(track.times.size()) + " key times but " +
           std::to_string(out.size() / comps) + " values");
    for (std::size_t k = 0; k < track.times.size(); ++k) {
      if (!std::isfinite(track.times[k]) || (k > 0 && track.times[k] < track.times[k - 1]))
        fail(label + ": key times must be finite and increasing");
      const float* v = &out[(k * perKey + (cubic ? 1 : 0)) * comps];
      for (std::size_t c = 0; c < comps; ++c)
        if (!std::isfinite(v[c]))
          fail(label + ": key " + std::to_string(k) + " (at " + secondsText(track.times[k]) +
               ") has a value that is not finite");
      track.values.emplace_back(v[0], v[1], v[2], track.rotation ? v[3] : 0.0f);
    }
    return track;
  }

  void addPaths() {
    // Parent world matrix of each camera node (its first instance).
    std::map<int, const NodeInstance*> cameraNodes;
    for (const NodeInstance& inst : instances_)
      if (model_.nodes[std::size_t(inst.node)].camera >= 0) cameraNodes.emplace(inst.node, &inst);

    for (std::size_t a = 0; a < model_.animations.size(); ++a) {
      const tinygltf::Animation& anim = model_.animations[a];
      std::string animName = anim.name.empty() ? "animation " + std::to_string(a) : anim.name;
      std::map<int, std::vector<Track>> translation, rotation;  // by camera node
      for (std::size_t c = 0; c < anim.channels.size(); ++c) {
        const tinygltf::AnimationChannel& ch = anim.channels[c];
        std::string label = "animation " + inQuotes(animName) + " channel " + std::to_string(c);
        if (ch.target_node < 0 || std::size_t(ch.target_node) >= model_.nodes.size())
          fail(label + ": target node " + std::to_string(ch.target_node) + " is out of range");
        if (!cameraNodes.count(ch.target_node)) {
          warnOnce("anim" + std::to_string(a),
                   "animation " + inQuotes(animName) +
                       " moves non-camera nodes; they are shown in their rest pose");
          continue;
        }
        if (ch.target_path == "translation") {
          translation[ch.target_node].push_back(readTrack(anim, ch, label));
        } else if (ch.target_path == "rotation") {
          rotation[ch.target_node].push_back(readTrack(anim, ch, label));
        } else {
          warn(label + ": " + ch.target_path + " of a camera ignored");
        }
      }
      std::set<int> animated;
      for (auto& [node, tracks] : translation) animated.insert(node);
      for (auto& [node, tracks] : rotation) animated.insert(node);
      for (int node : animated) {
        const NodeInstance& inst = *cameraNodes.at(node);
        std::optional<CameraLens> lens =
            lensOf(model_.nodes[std::size_t(node)].camera, nodeName(node));
        if (!lens) continue;
        const Track* tTrack = translation.count(node) ? &translation[node].back() : nullptr;
        const Track* rTrack = rotation.count(node) ? &rotation[node].back() : nullptr;
        CameraPath path;
        path.name = animated.size() > 1 ? animName + " (" + cameraName(inst) + ")" : animName;
        path.keys = sampleKeys(inst, tTrack, rTrack);
        path.fovYDeg = lens->fovYDeg;
        path.nearM = lens->nearM;
        float far = lens->farM;
        if (!(far > 0.0f))
          for (const CameraKey& k : path.keys)
            far = std::max(far, farFromBounds(k.position, lens->nearM));
        path.farM = far;
        path.nearM =
            nearWithinDepthPrecision(path.nearM, far, "camera path " + inQuotes(path.name));
        scene_.paths.push_back(std::move(path));
      }
    }
  }

  /// Keys at every keyframe time of either track. A STEP track also gets a key just before
  /// each jump, so that CameraPath's linear interpolation reproduces the step.
  std::vector<CameraKey> sampleKeys(const NodeInstance& inst, const Track* tTrack,
                                    const Track* rTrack) const {
    std::vector<float> times;
    for (const Track* tr : {tTrack, rTrack}) {
      if (!tr) continue;
      for (std::size_t k = 0; k < tr->times.size(); ++k) {
        times.push_back(tr->times[k]);
        if (tr->step && k > 0)
          times.push_back(std::nextafter(tr->times[k], -std::numeric_limits<float>::infinity()));
      }
    }
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    const tinygltf::Node& node = model_.nodes[std::size_t(inst.node)];
    std::vector<CameraKey> keys;
    for (float t : times) {
      tinygltf::Node posed = node;
      posed.matrix.clear();
      if (node.matrix.size() == 16) {
        // Animated nodes use TRS; a matrix node's animation replaces its decomposition.
        glm::vec3 p;
        glm::quat q;
        decomposePose(localMatrix(node), p, q);
        posed.translation = {p.x, p.y, p.z};
        posed.rotation = {q.x, q.y, q.z, q.w};
      }
      if (tTrack) {
        glm::vec4 v = tTrack->at(t);
        posed.translation = {v.x, v.y, v.z};
      }
      if (rTrack) {
        glm::vec4 v = rTrack->at(t);
        posed.rotation = {v.x, v.y, v.z, v.w};
      }
      CameraKey key;
      key.timeS = t;
      decomposePose(inst.parentWorld * localMatrix(posed), key.position, key.rotation);
      const float pose[7] = {key.position.x, key.position.y, key.position.z, key.rotation.x,
                             key.rotation.y, key.rotation.z, key.rotation.w};
      if (!std::all_of(std::begin(pose), std::end(pose), [](float v) { return std::isfinite(v); }))
        fail("camera " + inQuotes(cameraName(inst)) + ": its animated pose at " + secondsText(t) +
             " is not finite");
      keys.push_back(key);
    }
    return keys;
  }

  const tinygltf::Model& model_;
  Scene& scene_;
  std::vector<NodeInstance> instances_;
  std::size_t triangles_ = 0;  ///< in scene_.primitives so far
  std::vector<UvRule> uvRules_;
  std::set<std::string> warnedKeys_;
  std::optional<TriangleBvh> bvh_;  ///< for firstHit(), built when first needed
};

// ---------------------------------------------------------------------------------------
// Files

/// The whole of a regular file of at most kMaxFileBytes (sl::readRegularFile: devices, FIFOs
/// and sockets are refused before anything is read). `what` prefixes every message ("" for
/// the scene file, whose name loadGltf() adds).
std::vector<unsigned char> readRegularFile(const fs::path& path, const std::string& what) {
  try {
    return sl::readRegularFile(path, kMaxFileBytes, "kMaxFileBytes");
  } catch (const InputFileError& e) {
    fail(what + e.what());
  }
}

/// The offset and length of the first "uri" string value in JSON `text` that is longer than
/// kMaxUriBytes and not a data: URI, or {npos, 0}. One pass over the tokens' strings (escapes
/// skipped, so a quote inside a string is not a token); lengths are the raw JSON bytes.
std::pair<std::size_t, std::size_t> overlongUri(std::string_view text) {
  constexpr std::size_t npos = std::string_view::npos;
  // The string starting at the quote `at`: its content's end (the closing quote) or npos.
  auto stringEnd = [&](std::size_t at) {
    for (std::size_t k = at + 1; k < text.size(); ++k) {
      if (text[k] == '\\')
        ++k;
      else if (text[k] == '"')
        return k;
    }
    return npos;
  };
  auto skipBlanks = [&](std::size_t k) {
    while (k < text.size() &&
           (text[k] == ' ' || text[k] == '\t' || text[k] == '\n' || text[k] == '\r'))
      ++k;
    return k;
  };
  for (std::size_t k = 0; k < text.size(); ++k) {
    if (text[k] != '"') continue;
    const std::size_t end = stringEnd(k);
    if (end == npos) break;
    const bool uriKey = text.substr(k + 1, end - k - 1) == "uri";
    k = end;
    if (!uriKey) continue;
    std::size_t v = skipBlanks(end + 1);
    if (v >= text.size() || text[v] != ':') continue;
    v = skipBlanks(v + 1);
    if (v >= text.size() || text[v] != '"') continue;
    const std::size_t valueEnd = stringEnd(v);
    if (valueEnd == npos) break;
    const std::size_t length = valueEnd - v - 1;
    if (length > kMaxUriBytes && text.substr(v + 1, 5) != "data:") return {v + 1, length};
    k = valueEnd;
  }
  return {npos, 0};
}

/// Refuses JSON nested deeper than kMaxJsonDepth (before any recursive parser sees it) or
/// holding more than kMaxJsonContainers arrays and objects (before any parser allocates).
void checkJsonDepth(const unsigned char* bytes, std::size_t size, const std::string& what) {
  const std::string_view text(reinterpret_cast<const char*>(bytes), size);
  std::size_t at = jsonDepthExcess(text, kMaxJsonDepth);
  if (at != std::string_view::npos)
    fail(what + " is nested deeper than " + std::to_string(kMaxJsonDepth) + " levels (at byte " +
         std::to_string(at) + "): refused (kMaxJsonDepth)");
  at = jsonContainerExcess(text, kMaxJsonContainers);
  if (at != std::string_view::npos)
    fail(what + " holds more than " + std::to_string(kMaxJsonContainers) +
         " arrays and objects (at byte " + std::to_string(at) + "): refused (kMaxJsonContainers)");
  if (const auto [uriAt, length] = overlongUri(text); uriAt != std::string_view::npos)
    fail(what + " has a URI of " + std::to_string(length) + " bytes (" +
         quoteInput(std::string(text.substr(uriAt, kMaxQuotedBytes + 1))) + " at byte " +
         std::to_string(uriAt) + "), longer than any file path: refused (kMaxUriBytes " +
         std::to_string(kMaxUriBytes) + ")");
}

/// Why an external (non-data:) URI is refused, or "" if it is a relative path that stays
/// inside the scene's directory. `uri` is already percent-decoded (by tinygltf).
std::string uriProblem(const std::string& uri) {
  static const std::string allowed =
      "only relative paths inside the scene's directory and data: URIs are read";
  if (uri.empty()) return "is empty";
  // A scheme: a letter, then letters, digits, '+', '-' or '.', then ':' (a Windows drive
  // letter such as "C:" is caught here too).
  std::size_t colon = uri.find(':');
  if (colon != std::string::npos && colon > 0 && std::isalpha(static_cast<unsigned char>(uri[0]))) {
    bool scheme = true;
    for (std::size_t k = 1; k < colon; ++k) {
      unsigned char c = static_cast<unsigned char>(uri[k]);
      if (!std::isalnum(c) && c != '+' && c != '-' && c != '.') scheme = false;
    }
    if (scheme) {
      std::string name = uri.substr(0, colon);
      for (char& c : name) c = char(std::tolower(static_cast<unsigned char>(c)));
      if (name == "data")
        return "is a data: URI that could not be decoded (only base64 data: URIs are read)";
      return "is refused: a " + name.substr(0, 20) + ": URI (" + allowed + ")";
    }
  }
  if (uri[0] == '/' || uri[0] == '\\') return "is refused: an absolute path (" + allowed + ")";
  std::size_t start = 0;
  while (start <= uri.size()) {
    std::size_t end = uri.find_first_of("/\\", start);
    if (end == std::string::npos) end = uri.size();
    if (uri.compare(start, end - start, "..") == 0)
      return "is refused: '..' leaves the scene's directory (" + allowed + ")";
    start = end + 1;
  }
  if (uri.find('\0') != std::string::npos) return "is refused: it contains a NUL byte";
  return "";
}

/// tinygltf's file system, restricted: external files are looked up only in the scene's
/// directory (never the working directory), only relative URIs that stay inside it are
/// accepted, and they are read with readRegularFile(). The first refusal is kept in `error`
/// because tinygltf reports a missing image only as a warning.
struct ExternalFiles {
  std::string prefix;  ///< the scene's directory, ending with '/'
  std::string error;
  std::vector<std::string> read_;  ///< the files read, in order

  void refuse(const std::string& message) {
    if (error.empty()) error = message;
  }

  /// The URI of a path tinygltf built as JoinPath(dir, uri); nullopt for other directories.
  std::optional<std::string> uriOf(const std::string& path) const {
    if (path.compare(0, prefix.size(), prefix) != 0) return std::nullopt;
    return path.substr(prefix.size());
  }

  static bool exists(const std::string& path, void* user) {
    auto& self = *static_cast<ExternalFiles*>(user);
    std::optional<std::string> uri = self.uriOf(path);
    if (!uri) return false;
    if (std::string problem = uriProblem(*uri); !problem.empty()) {
      self.refuse("external file URI " + quoteInput(*uri) + " " + problem);
      return false;
    }
    std::error_code ec;
    return fs::exists(fs::path(path), ec);
  }

  static std::string expand(const std::string& path, void*) { return path; }  // no wordexp

  static bool read(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                   void* user) {
    auto& self = *static_cast<ExternalFiles*>(user);
    std::string uri = self.uriOf(path).value_or(path);
    try {
      // Inside the scene's folder after symbolic links too: a link to a system file is
      // not the scene's.
      std::error_code ec;
      const fs::path folder = fs::weakly_canonical(fs::absolute(self.prefix), ec);
      const fs::path target = fs::weakly_canonical(fs::absolute(path), ec);
      const auto [end, at] =
          std::mismatch(folder.begin(), folder.end(), target.begin(), target.end());
      if (!ec && end != folder.end() && !end->empty())
        fail("external file " + quoteInput(uri) +
             " leads outside the scene's folder (a symbolic link): refused");
      *out = readRegularFile(path, "external file " + quoteInput(uri) + " ");
      self.read_.push_back(path);
      return true;
    } catch (const LoadFailure& f) {
      self.refuse(f.message);
      if (err) *err += f.message;
    } catch (const std::bad_alloc&) {
      self.refuse("external file " + quoteInput(uri) + ": out of memory");
    }
    return false;
  }

  static bool write(std::string* err, const std::string&, const std::vector<unsigned char>&,
                    void*) {
    if (err) *err += "writing is not supported";
    return false;
  }
};

std::uint32_t readBigEndian(const unsigned char* p, int bytes) {
  std::uint32_t v = 0;
  for (int k = 0; k < bytes; ++k) v = (v << 8) | p[k];
  return v;
}

/// Width and height from a PNG or JPEG header, without decoding; nullopt if neither.
std::optional<std::pair<std::uint32_t, std::uint32_t>> imageSize(const unsigned char* b,
                                                                 std::size_t n) {
  static const unsigned char png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (n >= 24 && std::memcmp(b, png, 8) == 0 && std::memcmp(b + 12, "IHDR", 4) == 0)
    return std::make_pair(readBigEndian(b + 16, 4), readBigEndian(b + 20, 4));
  if (n < 4 || b[0] != 0xFF || b[1] != 0xD8) return std::nullopt;
  std::size_t at = 2;  // JPEG: walk the marker segments to the first start-of-frame
  while (at + 4 <= n) {
    if (b[at] != 0xFF) return std::nullopt;
    const unsigned char marker = b[at + 1];
    if (marker == 0xFF) {  // fill byte
      ++at;
      continue;
    }
    if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD9)) {  // no length
      at += 2;
      continue;
    }
    const std::size_t length = readBigEndian(b + at + 2, 2);
    const bool startOfFrame =
        marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
    if (startOfFrame) {
      if (at + 9 > n) return std::nullopt;
      return std::make_pair(readBigEndian(b + at + 7, 2), readBigEndian(b + at + 5, 2));
    }
    if (length < 2) return std::nullopt;
    at += 2 + length;
  }
  return std::nullopt;
}

/// tinygltf's image decoder, except that an undecodable image is a warning, not a failure.
/// Only PNG and JPEG (glTF's image formats) are decoded, and only up to kMaxImageSide and
/// kMaxImagePixels, and kMaxTotalImagePixels for all of a file's images (`user`: the pixels
/// decoded so far, a std::uint64_t): the header is read first, so a small file cannot make the
/// decoder allocate gigabytes.
bool decodeImageLeniently(tinygltf::Image* image, const int imageIndex, std::string* err,
                          std::string* warn, int reqWidth, int reqHeight,
                          const unsigned char* bytes, int size, void* user) {
  (void)err;
  const std::string label = "image " + std::to_string(imageIndex) + " not decoded: ";
  auto dims = imageSize(bytes, size > 0 ? std::size_t(size) : 0);
  if (!dims) {
    if (warn) *warn += label + "neither PNG nor JPEG\n";
    return true;
  }
  auto [w, h] = *dims;
  if (w == 0 || h == 0 || w > std::uint32_t(kMaxImageSide) || h > std::uint32_t(kMaxImageSide) ||
      std::uint64_t(w) * h > kMaxImagePixels) {
    if (warn)
      *warn += label + std::to_string(w) + "x" + std::to_string(h) +
               " pixels is beyond the limit of " + std::to_string(kMaxImageSide) +
               " per side (kMaxImageSide) and " + std::to_string(kMaxImagePixels) +
               " pixels (kMaxImagePixels)\n";
    return true;
  }
  auto* totalPixels = static_cast<std::uint64_t*>(user);
  if (totalPixels) {
    if (*totalPixels + std::uint64_t(w) * h > kMaxTotalImagePixels) {
      if (warn)
        *warn += label + std::to_string(w) + "x" + std::to_string(h) +
                 " pixels would take the file's images beyond " +
                 std::to_string(kMaxTotalImagePixels) + " pixels in all (kMaxTotalImagePixels)\n";
      return true;
    }
    *totalPixels += std::uint64_t(w) * h;  // counted when tried: a failed decode allocated too
  }
  std::string why;
  if (tinygltf::LoadImageData(image, imageIndex, &why, warn, reqWidth, reqHeight, bytes, size,
                              nullptr))
    return true;
  if (warn) *warn += label + why + "\n";
  return true;
}

std::uint32_t readU32(const std::vector<unsigned char>& bytes, std::size_t at) {
  std::uint32_t v;
  std::memcpy(&v, bytes.data() + at, 4);
  return v;
}

/// The GLB container checks tinygltf reports less clearly.
void checkGlbHeader(const std::vector<unsigned char>& bytes) {
  const std::size_t size = bytes.size();
  if (size < 12)
    fail("truncated .glb: " + std::to_string(size) + " bytes, the header alone needs 12");
  std::uint32_t version = readU32(bytes, 4), length = readU32(bytes, 8);
  if (version != 2) fail("unsupported glTF binary version " + std::to_string(version));
  if (length > size)
    fail("truncated .glb: the header declares " + std::to_string(length) +
         " bytes but the file has " + std::to_string(size));
  if (length < size)
    fail("malformed .glb: the header declares " + std::to_string(length) +
         " bytes but the file has " + std::to_string(size) + " (" + std::to_string(size - length) +
         " bytes after the declared end)");
  if (length < 20) fail("truncated .glb: no JSON chunk");
  std::uint32_t jsonLength = readU32(bytes, 12), jsonType = readU32(bytes, 16);
  if (jsonType != 0x4E4F534Au) fail("malformed .glb: the first chunk is not JSON");
  if (std::uint64_t(jsonLength) + 20u > length)
    fail("truncated .glb: the JSON chunk (" + std::to_string(jsonLength) +
         " bytes) runs past the end of the file");
}

std::string describeParseError(const std::string& tinygltfError) {
  std::string msg = cutText(oneLine(tinygltfError), 2 * kMaxQuotedBytes);
  if (msg.empty()) return "could not be parsed as glTF";
  if (std::size_t p = msg.find("[json.exception."); p != std::string::npos) {
    std::size_t close = msg.find("] ", p);
    if (close != std::string::npos) msg.erase(p, close + 2 - p);
    return "malformed JSON: " + msg;
  }
  if (msg.find("JSON") != std::string::npos || msg.find("json") != std::string::npos)
    return "malformed JSON: " + msg;
  return "invalid glTF: " + msg;
}

void refuseUnsupportedRequiredExtensions(const tinygltf::Model& model) {
  std::vector<std::string> unsupported;
  for (const std::string& ext : model.extensionsRequired)
    if (std::find(kAcceptedRequiredExtensions.begin(), kAcceptedRequiredExtensions.end(), ext) ==
        kAcceptedRequiredExtensions.end())
      unsupported.push_back(inQuotes(ext));
  if (unsupported.empty()) return;
  std::string list;
  for (const std::string& e : unsupported) list += (list.empty() ? "" : ", ") + e;
  fail(std::string("requires unsupported extension") + (unsupported.size() > 1 ? "s " : " ") +
       list);
}

std::shared_ptr<Scene> loadOrFail(const fs::path& path) {
  std::error_code ec;
  fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) fail("file not found");
  if (fs::is_directory(status)) fail("is a directory, not a glTF file");
  std::vector<unsigned char> bytes = readRegularFile(path, "");
  if (bytes.empty()) fail("empty file");
  if (bytes.size() > std::numeric_limits<unsigned int>::max()) fail("file larger than 4 GiB");

  const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  if (!binary && lowerExtension(path) == ".glb") {
    if (bytes.size() < 4) fail("truncated .glb: " + std::to_string(bytes.size()) + " bytes");
    fail("not a glTF binary (the file does not start with 'glTF')");
  }
  if (binary) {
    checkGlbHeader(bytes);
    checkJsonDepth(bytes.data() + 20, readU32(bytes, 12), "the JSON chunk");
  } else {
    checkJsonDepth(bytes.data(), bytes.size(), "the JSON");
  }

  tinygltf::TinyGLTF parser;
  std::uint64_t decodedPixels = 0;
  parser.SetImageLoader(&decodeImageLeniently, &decodedPixels);
  std::string baseDir = path.parent_path().string();
  if (baseDir.empty()) baseDir = ".";
  ExternalFiles files;
  files.prefix = baseDir.back() == '/' ? baseDir : baseDir + "/";
  parser.SetFsCallbacks({&ExternalFiles::exists, &ExternalFiles::expand, &ExternalFiles::read,
                         &ExternalFiles::write, &files});
  tinygltf::Model model;
  std::string err, warnText;
  bool ok = binary ? parser.LoadBinaryFromMemory(&model, &err, &warnText, bytes.data(),
                                                 static_cast<unsigned int>(bytes.size()), baseDir)
                   : parser.LoadASCIIFromString(&model, &err, &warnText,
                                                reinterpret_cast<const char*>(bytes.data()),
                                                static_cast<unsigned int>(bytes.size()), baseDir);
  // The required extensions are parsed early, so they explain a failure best.
  refuseUnsupportedRequiredExtensions(model);
  if (!files.error.empty()) fail(files.error);
  if (!ok) fail(describeParseError(err));

  auto scene = std::make_shared<Scene>();
  scene->name = path.stem().string();
  scene->sourcePath = path.string();
  scene->inputFiles.push_back(path.string());
  for (const std::string& f : files.read_) scene->inputFiles.push_back(f);
  addLines(scene->warnings, warnText);
  Flattener(model, *scene).run();
  return scene;
}

bool hasGltfExtension(const fs::path& p) {
  std::string ext = lowerExtension(p);
  return ext == ".gltf" || ext == ".glb";
}

}  // namespace

SceneLoadResult loadGltf(const std::filesystem::path& path) {
  SceneLoadResult result;
  try {
    result.scene = loadOrFail(path);
  } catch (const LoadFailure& f) {
    result.error = path.string() + ": " + cutText(oneLine(f.message));
  } catch (const std::bad_alloc&) {
    result.error = path.string() + ": out of memory while loading";
  } catch (const std::exception& e) {
    result.error = path.string() + ": " + cutText(oneLine(e.what()));
  } catch (...) {
    result.error = path.string() + ": unknown error while loading";
  }
  if (!result.error.empty()) result.scene.reset();
  return result;
}

std::filesystem::path builtinSceneDir(const char* environmentValue) {
#ifdef SHADOWLAB_SCENE_DIR
  return dataDir("scenes", environmentValue, SHADOWLAB_SCENE_DIR);
#else
  return dataDir("scenes", environmentValue, "scenes");
#endif
}

std::filesystem::path builtinSceneDir() {
  return builtinSceneDir(std::getenv("SHADOWLAB_SCENE_DIR"));
}

std::vector<std::string> builtinSceneNames(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code fileEc;
    if (it->is_regular_file(fileEc) && hasGltfExtension(it->path()))
      names.push_back(it->path().stem().string());
  }
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

SceneLoadResult loadSceneByNameOrPath(const std::string& nameOrPath,
                                      const std::filesystem::path& sceneDir) {
  const fs::path asPath(nameOrPath);
  const bool looksLikePath = hasGltfExtension(asPath) ||
                             nameOrPath.find('/') != std::string::npos ||
                             nameOrPath.find('\\') != std::string::npos;
  if (looksLikePath) return loadGltf(asPath);

  if (!nameOrPath.empty()) {
    for (const char* ext : {".gltf", ".glb"}) {
      fs::path candidate = sceneDir / (nameOrPath + ext);
      std::error_code ec;
      if (fs::is_regular_file(candidate, ec)) {
        SceneLoadResult result = loadGltf(candidate);
        if (result) result.scene->name = nameOrPath;
        return result;
      }
    }
    std::error_code ec;
    if (fs::exists(asPath, ec)) return loadGltf(asPath);  // e.g. a file without extension
  }

  std::vector<std::string> names = builtinSceneNames(sceneDir);
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  SceneLoadResult result;
  result.error = "unknown scene '" + nameOrPath + "': not a built-in scene (" +
                 (list.empty() ? "none found in " + sceneDir.string() : list) +
                 ") nor a .gltf/.glb file";
  return result;
}

}  // namespace sl
