// The flattening (Flattener.h): images, materials, the node hierarchy into world-space
// instances, their mesh primitives into world-space triangle lists, and the limits on what
// the flattened scene may hold.
#include "scene/gltf/Flattener.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "algo/InputFile.h"
#include "scene/gltf/Accessors.h"

namespace sl::gltf {

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

void Flattener::run() {
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

void Flattener::checkExtent() const {
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

void Flattener::convertImages() {
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
      warn("image " + inQuotes(img.name) + " could not be decoded; textures using it are left out");
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

void Flattener::convertMaterials() {
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
        warn("material " + inQuotes(m.name) + ": base colour texture " + std::to_string(tex.index) +
             " has no usable image; it is left out");
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

void Flattener::readTextureTransform(const tinygltf::Value& ext, UvRule& rule) {
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

void Flattener::collectInstances() {
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

void Flattener::checkNodeTransform(int index) {
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

void Flattener::visitTree(const std::vector<int>& roots) {
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
      std::string firstWhere = first < 0 ? "a root of the scene" : "a child of " + nodeLabel(first);
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

void Flattener::checkTriangleEstimate() const {
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

void Flattener::addMeshInstance(const NodeInstance& inst) {
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

void Flattener::addPrimitive(const tinygltf::Primitive& src, const std::string& label,
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

void Flattener::computeFlatNormals(MeshPrimitive& prim) {
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

}  // namespace sl::gltf
