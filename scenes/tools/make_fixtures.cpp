// The glTF loader's test fixtures (tests/data): tiny files, each exercising one feature or one
// failure. Written as JSON by hand (nlohmann::json) rather than through tinygltf's writer, so
// that the loader is tested against files that tinygltf did not produce, including ones its
// writer cannot express (sparse accessors without a bufferView, absent zfar, required
// extensions, broken files).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

namespace sl::gen {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

constexpr int kByte = 5121, kUShort = 5123, kUInt = 5125, kFloat = 5126;

std::string base64(const std::vector<std::uint8_t>& data) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < data.size(); i += 3) {
    std::uint32_t n = std::uint32_t(data[i]) << 16;
    if (i + 1 < data.size()) n |= std::uint32_t(data[i + 1]) << 8;
    if (i + 2 < data.size()) n |= data[i + 2];
    out += table[(n >> 18) & 63];
    out += table[(n >> 12) & 63];
    out += i + 1 < data.size() ? table[(n >> 6) & 63] : '=';
    out += i + 2 < data.size() ? table[n & 63] : '=';
  }
  return out;
}

/// A glTF under construction: JSON plus one binary buffer.
class Fixture {
 public:
  Fixture() {
    j_["asset"] = {{"version", "2.0"}, {"generator", "shadowlab-make-scenes --fixtures"}};
    j_["scene"] = 0;
    j_["scenes"] = json::array({json{{"nodes", json::array()}}});
  }

  json& root() { return j_; }

  template <class T>
  int view(const std::vector<T>& data, int byteStride = 0) {
    while (bin_.size() % 4) bin_.push_back(0);
    std::size_t offset = bin_.size(), bytes = data.size() * sizeof(T);
    bin_.resize(offset + bytes);
    std::memcpy(bin_.data() + offset, data.data(), bytes);
    json v = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}};
    if (byteStride) v["byteStride"] = byteStride;
    return push("bufferViews", v);
  }

  int accessor(int bufferView, int componentType, std::size_t count, const char* type,
               json extra = json::object()) {
    json a = {{"componentType", componentType}, {"count", count}, {"type", type}};
    if (bufferView >= 0) a["bufferView"] = bufferView;
    a.update(extra);
    return push("accessors", a);
  }

  /// A float VEC3 accessor with min/max (POSITION requires them).
  int positions(const std::vector<glm::vec3>& p) {
    std::vector<float> flat;
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const glm::vec3& v : p) {
      flat.insert(flat.end(), {v.x, v.y, v.z});
      lo = glm::min(lo, v), hi = glm::max(hi, v);
    }
    return accessor(view(flat), kFloat, p.size(), "VEC3",
                    {{"min", {lo.x, lo.y, lo.z}}, {"max", {hi.x, hi.y, hi.z}}});
  }

  int vec3s(const std::vector<glm::vec3>& p) {
    std::vector<float> flat;
    for (const glm::vec3& v : p) flat.insert(flat.end(), {v.x, v.y, v.z});
    return accessor(view(flat), kFloat, p.size(), "VEC3");
  }

  template <class T>
  int indices(const std::vector<T>& idx) {
    int type = sizeof(T) == 1 ? kByte : sizeof(T) == 2 ? kUShort : kUInt;
    return accessor(view(idx), type, idx.size(), "SCALAR");
  }

  int push(const char* key, const json& value) {
    if (!j_.contains(key)) j_[key] = json::array();
    j_[key].push_back(value);
    return int(j_[key].size() - 1);
  }

  int node(const json& n, bool root = true) {
    int index = push("nodes", n);
    if (root) j_["scenes"][0]["nodes"].push_back(index);
    return index;
  }

  /// A mesh with the given primitives, on a root node.
  int meshNode(const std::string& name, const json& primitives, json nodeExtra = json::object(),
               bool root = true) {
    int mesh = push("meshes", json{{"name", name}, {"primitives", primitives}});
    json n = {{"name", name}, {"mesh", mesh}};
    n.update(nodeExtra);
    return node(n, root);
  }

  void writeGltf(const fs::path& path) {
    json j = j_;
    if (!bin_.empty())
      j["buffers"] =
          json::array({json{{"byteLength", bin_.size()},
                            {"uri", "data:application/octet-stream;base64," + base64(bin_)}}});
    std::ofstream(path) << j.dump(1) << "\n";
  }

  std::vector<std::uint8_t> glbBytes() {
    json j = j_;
    while (bin_.size() % 4) bin_.push_back(0);
    j["buffers"] = json::array({json{{"byteLength", bin_.size()}}});
    std::string text = j.dump();
    while (text.size() % 4) text += ' ';
    std::vector<std::uint8_t> out;
    auto u32 = [&](std::uint32_t v) {
      for (int i = 0; i < 4; ++i) out.push_back(std::uint8_t(v >> (8 * i)));
    };
    u32(0x46546C67u);  // "glTF"
    u32(2);
    u32(std::uint32_t(12 + 8 + text.size() + 8 + bin_.size()));
    u32(std::uint32_t(text.size()));
    u32(0x4E4F534Au);  // "JSON"
    out.insert(out.end(), text.begin(), text.end());
    u32(std::uint32_t(bin_.size()));
    u32(0x004E4942u);  // "BIN\0"
    out.insert(out.end(), bin_.begin(), bin_.end());
    return out;
  }

 private:
  json j_;
  std::vector<std::uint8_t> bin_;
};

void writeBytes(const fs::path& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

/// A unit quad on y = 0 over [x0, x0 + 1] x [-1, 0], counter-clockwise seen from +y.
std::vector<glm::vec3> quadAt(float x0) {
  return {{x0, 0, 0}, {x0 + 1, 0, 0}, {x0 + 1, 0, -1}, {x0, 0, -1}};
}
const std::vector<std::uint32_t> kQuadIndices = {0, 1, 2, 0, 2, 3};

json triangles(int position, int indicesAccessor = -1, json attributes = json::object()) {
  attributes["POSITION"] = position;
  json p = {{"attributes", attributes}};
  if (indicesAccessor >= 0) p["indices"] = indicesAccessor;
  return p;
}

// ---- good files ------------------------------------------------------------------------

/// A mirrored (negative-determinant) matrix node over a TRS child and a TRS grandchild, and
/// an unmirrored sibling: winding must flip exactly under the mirror.
void hierarchyNegativeScale(const fs::path& dir) {
  Fixture f;
  std::vector<glm::vec3> up(4, glm::vec3(0, 1, 0));
  int pos = f.positions(quadAt(0.0f));
  int nrm = f.vec3s(up);
  int idx = f.indices(std::vector<std::uint16_t>(kQuadIndices.begin(), kQuadIndices.end()));
  int mesh =
      f.push("meshes", json{{"name", "quad"},
                            {"primitives", json::array({triangles(pos, idx, {{"NORMAL", nrm}})})}});
  const double s45 = std::sqrt(0.5);
  int grandchild =
      f.node({{"name", "grandchild"}, {"mesh", mesh}, {"translation", {0, 3, 0}}}, false);
  int child = f.node({{"name", "child"},
                      {"mesh", mesh},
                      {"translation", {2, 0, 0}},
                      {"rotation", {0, s45, 0, s45}},  // +90 degrees about y
                      {"scale", {1, 2, 1}},
                      {"children", {grandchild}}},
                     false);
  // Mirror in x, as a column-major matrix.
  f.node({{"name", "mirror"},
          {"matrix", {-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}},
          {"children", {child}}});
  f.node({{"name", "plain"}, {"mesh", mesh}, {"translation", {0, 0, 5}}});
  f.writeGltf(dir / "hierarchy-negative-scale.gltf");
}

/// The same quad four times: u8, u16 (positions interleaved with normals, byteStride 24),
/// u32 indices, and non-indexed.
void indexTypes(const fs::path& dir) {
  Fixture f;
  json prims = json::array();
  prims.push_back(
      triangles(f.positions(quadAt(0.0f)),
                f.indices(std::vector<std::uint8_t>(kQuadIndices.begin(), kQuadIndices.end()))));
  {
    std::vector<float> interleaved;
    for (const glm::vec3& p : quadAt(2.0f))
      interleaved.insert(interleaved.end(), {p.x, p.y, p.z, 0, 1, 0});
    int v = f.view(interleaved, 24);
    int pos = f.accessor(v, kFloat, 4, "VEC3", {{"min", {2, 0, -1}}, {"max", {3, 0, 0}}});
    int nrm = f.accessor(v, kFloat, 4, "VEC3", {{"byteOffset", 12}});
    prims.push_back(triangles(
        pos, f.indices(std::vector<std::uint16_t>(kQuadIndices.begin(), kQuadIndices.end())),
        {{"NORMAL", nrm}}));
  }
  prims.push_back(triangles(f.positions(quadAt(4.0f)), f.indices(kQuadIndices)));
  {
    std::vector<glm::vec3> q = quadAt(6.0f), flat;
    for (std::uint32_t i : kQuadIndices) flat.push_back(q[i]);
    prims.push_back(triangles(f.positions(flat)));
  }
  f.meshNode("quads", prims);
  f.writeGltf(dir / "index-types.gltf");
}

/// Sparse accessors: one overriding vertex 2 of a bufferView-backed quad (to y = 5), one
/// with no bufferView at all (a triangle defined only by its sparse values).
void sparse(const fs::path& dir) {
  Fixture f;
  json prims = json::array();
  {
    std::vector<float> base;
    for (const glm::vec3& p : quadAt(0.0f)) base.insert(base.end(), {p.x, p.y, p.z});
    int baseView = f.view(base);
    int idxView = f.view(std::vector<std::uint8_t>{2});
    int valView = f.view(std::vector<float>{1, 5, -1});
    json sparseJson = {{"count", 1},
                       {"indices", {{"bufferView", idxView}, {"componentType", kByte}}},
                       {"values", {{"bufferView", valView}}}};
    int pos = f.accessor(baseView, kFloat, 4, "VEC3",
                         {{"min", {0, 0, -1}}, {"max", {1, 5, 0}}, {"sparse", sparseJson}});
    prims.push_back(triangles(
        pos, f.indices(std::vector<std::uint16_t>(kQuadIndices.begin(), kQuadIndices.end()))));
  }
  {
    int idxView = f.view(std::vector<std::uint16_t>{0, 1, 2});
    int valView = f.view(std::vector<float>{3, 0, 0, 4, 0, 0, 3, 0, -1});
    json sparseJson = {{"count", 3},
                       {"indices", {{"bufferView", idxView}, {"componentType", kUShort}}},
                       {"values", {{"bufferView", valView}}}};
    int pos = f.accessor(-1, kFloat, 3, "VEC3",
                         {{"min", {3, 0, -1}}, {"max", {4, 0, 0}}, {"sparse", sparseJson}});
    prims.push_back(triangles(pos));
  }
  f.meshNode("sparse", prims);
  f.writeGltf(dir / "sparse.gltf");
}

/// A cube with shared corners and no normals: the loader computes flat ones.
void noNormals(const fs::path& dir) {
  Fixture f;
  std::vector<glm::vec3> corners;
  for (int i = 0; i < 8; ++i) corners.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  // Counter-clockwise seen from outside.
  std::vector<std::uint16_t> idx = {0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5, 0, 1, 5, 0, 5, 4,
                                    2, 6, 7, 2, 7, 3, 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6};
  f.meshNode("cube", json::array({triangles(f.positions(corners), f.indices(idx))}));
  f.writeGltf(dir / "no-normals.gltf");
}

/// A MASK material (cutoff 0.3, double-sided, tinted, 2x2 RGBA texture) on a quad whose
/// TEXCOORD_0 are normalized unsigned shorts interleaved with positions and normals
/// (byteStride 28),
/// and a second quad whose material adds a KHR_texture_transform (required, accepted).
void maskMaterial(const fs::path& dir) {
  Fixture f;
  tinygltf::Image img;
  img.name = "checker";
  img.width = img.height = 2;
  img.component = 4;
  img.bits = 8;
  img.pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
  img.image = {255, 0, 0, 255, 0, 255, 0, 0, 0, 0, 255, 128, 255, 255, 255, 255};
  std::string uri, base = dir.string(), name = "checker.png";
  tinygltf::WriteImageData(&base, &name, &img, true, &uri, nullptr);
  f.push("images", json{{"name", "checker"}, {"uri", uri}});
  f.push("samplers", json{{"magFilter", 9728}, {"minFilter", 9728}});
  f.push("textures", json{{"source", 0}, {"sampler", 0}});
  f.push(
      "materials",
      json{{"name", "cutout"},
           {"alphaMode", "MASK"},
           {"alphaCutoff", 0.3},
           {"doubleSided", true},
           {"pbrMetallicRoughness",
            {{"baseColorFactor", {1.0, 0.5, 0.25, 1.0}}, {"baseColorTexture", {{"index", 0}}}}}});
  f.push(
      "materials",
      json{{"name", "transformed"},
           {"alphaMode", "BLEND"},
           {"pbrMetallicRoughness",
            {{"baseColorTexture",
              {{"index", 0},
               {"extensions",
                {{"KHR_texture_transform", {{"offset", {0.5, 0.0}}, {"scale", {2.0, 2.0}}}}}}}}}}});
  f.root()["extensionsUsed"] = {"KHR_texture_transform"};
  f.root()["extensionsRequired"] = {"KHR_texture_transform"};

  struct Vertex {
    float x, y, z, nx, ny, nz;
    std::uint16_t u, v;
  };
  static_assert(sizeof(Vertex) == 28);
  const std::uint16_t full = 65535, half = 32768;
  std::vector<Vertex> verts = {{0, 0, 0, 0, 1, 0, 0, full},
                               {1, 0, 0, 0, 1, 0, full, full},
                               {1, 0, -1, 0, 1, 0, full, 0},
                               {0, 0, -1, 0, 1, 0, half, 0}};
  int v = f.view(verts, 28);
  int pos = f.accessor(v, kFloat, 4, "VEC3", {{"min", {0, 0, -1}}, {"max", {1, 0, 0}}});
  int nrm = f.accessor(v, kFloat, 4, "VEC3", {{"byteOffset", 12}});
  int uv = f.accessor(v, kUShort, 4, "VEC2", {{"byteOffset", 24}, {"normalized", true}});
  int idx = f.indices(std::vector<std::uint16_t>(kQuadIndices.begin(), kQuadIndices.end()));
  json p0 = triangles(pos, idx, {{"NORMAL", nrm}, {"TEXCOORD_0", uv}});
  p0["material"] = 0;
  json p1 = p0;
  p1["material"] = 1;
  f.meshNode("cutout", json::array({p0}));
  f.meshNode("transformed", json::array({p1}), {{"translation", {0, 0, 2}}});
  f.writeGltf(dir / "mask-material.gltf");
}

/// A triangle strip and a triangle fan (both facing +y, no normals), plus lines and points
/// that are skipped with warnings.
void stripFanLines(const fs::path& dir) {
  Fixture f;
  json strip = triangles(f.positions({{0, 0, -1}, {0, 0, 0}, {1, 0, -1}, {1, 0, 0}, {2, 0, -1}}));
  strip["mode"] = 5;
  json fan = triangles(f.positions({{5, 0, 0}, {6, 0, 0}, {5, 0, -1}, {4, 0, 0}, {5, 0, 1}}));
  fan["mode"] = 6;
  json lines = triangles(f.positions({{0, 1, 0}, {1, 1, 0}}));
  lines["mode"] = 1;
  json points = triangles(f.positions({{0, 2, 0}}));
  points["mode"] = 0;
  f.meshNode("mixed", json::array({strip, fan, lines, points}));
  f.writeGltf(dir / "strip-fan-lines.gltf");
}

/// A 10 x 10 m ground quad and KHR_lights_punctual in extensionsUsed.
void groundAndLightsExtension(Fixture& f) {
  f.meshNode("ground",
             json::array({triangles(f.positions({{-5, 0, 5}, {5, 0, 5}, {5, 0, -5}, {-5, 0, -5}}),
                                    f.indices(std::vector<std::uint16_t>(kQuadIndices.begin(),
                                                                         kQuadIndices.end())))}));
  f.root()["extensionsUsed"] = {"KHR_lights_punctual"};
}

/// Punctual lights without a sun: a spot under a translated parent node (its child turned
/// -90 degrees about x, so it shines straight down), a point light with a range, a spot with
/// a cone wider than a hemisphere (ignored) and a light of unknown type (ignored). The
/// first valid one in node order, the spot, lights the scene.
void punctualLights(const fs::path& dir) {
  Fixture f;
  groundAndLightsExtension(f);
  f.root()["extensions"] = {
      {"KHR_lights_punctual",
       {{"lights", json::array({json{{"name", "lamp"},
                                     {"type", "spot"},
                                     {"range", 12.0},
                                     {"spot", {{"innerConeAngle", 0.3}, {"outerConeAngle", 0.6}}}},
                                json{{"name", "bulb"}, {"type", "point"}, {"range", 8.0}},
                                json{{"name", "too-wide"},
                                     {"type", "spot"},
                                     {"spot", {{"innerConeAngle", 0.1}, {"outerConeAngle", 2.0}}}},
                                json{{"name", "odd"}, {"type", "area"}}})}}}};
  glm::quat down = glm::angleAxis(glm::radians(-90.0f), glm::vec3(1, 0, 0));
  int child = f.node({{"name", "lamp"},
                      {"rotation", {down.x, down.y, down.z, down.w}},
                      {"translation", {0, 1, 0}},
                      {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}},
                     false);
  f.node({{"name", "lamp-mount"}, {"translation", {1, 3, -2}}, {"children", {child}}});
  f.node({{"name", "bulb"},
          {"translation", {-1, 2.5, 0.5}},
          {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
  f.node({{"name", "too-wide"}, {"extensions", {{"KHR_lights_punctual", {{"light", 2}}}}}});
  f.node({{"name", "odd"}, {"extensions", {{"KHR_lights_punctual", {{"light", 3}}}}}});
  f.writeGltf(dir / "punctual-lights.gltf");
}

/// Only a point light (with no range: infinite).
void pointLightOnly(const fs::path& dir) {
  Fixture f;
  groundAndLightsExtension(f);
  f.root()["extensions"] = {
      {"KHR_lights_punctual",
       {{"lights", json::array({json{{"name", "bulb"}, {"type", "point"}}})}}}};
  f.node({{"name", "bulb"},
          {"translation", {0.5, 4, -0.25}},
          {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  f.writeGltf(dir / "point-light.gltf");
}

/// A sun (directional light on a rotated node), a point light, a perspective camera with
/// no zfar animated by LINEAR translation and STEP rotation keys, and an orthographic camera.
void cameraPath(const fs::path& dir) {
  Fixture f;
  f.meshNode(
      "ground",
      json::array({triangles(
          f.positions({{-10, 0, 10}, {10, 0, 10}, {10, 0, -10}, {-10, 0, -10}}),
          f.indices(std::vector<std::uint16_t>(kQuadIndices.begin(), kQuadIndices.end())))}));
  f.root()["extensionsUsed"] = {"KHR_lights_punctual"};
  f.root()["extensionsRequired"] = {"KHR_lights_punctual"};  // supported: accepted
  f.root()["extensions"] = {
      {"KHR_lights_punctual",
       {{"lights",
         json::array({json{{"name", "lamp"}, {"type", "point"}},
                      json{{"name", "sun"}, {"type", "directional"}, {"intensity", 2.0}}})}}}};
  // -60 degrees about x: the node's +z turns to (0, sin 60, cos 60).
  glm::quat q = glm::angleAxis(glm::radians(-60.0f), glm::vec3(1, 0, 0));
  f.node({{"name", "lamp"},
          {"translation", {0, 3, 0}},
          {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  f.node({{"name", "sun"},
          {"rotation", {q.x, q.y, q.z, q.w}},
          {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
  f.push("cameras", json{{"name", "tracker"},
                         {"type", "perspective"},
                         {"perspective", {{"yfov", 0.8}, {"znear", 0.05}}}});
  f.push("cameras",
         json{{"name", "plan"},
              {"type", "orthographic"},
              {"orthographic", {{"xmag", 5}, {"ymag", 5}, {"znear", 0.1}, {"zfar", 50}}}});
  int cam = f.node({{"name", "tracker-node"}, {"camera", 0}, {"translation", {0, 1, 10}}});
  f.node({{"name", "plan-node"}, {"camera", 1}, {"translation", {0, 20, 0}}});
  int tIn = f.accessor(f.view(std::vector<float>{0, 2, 4}), kFloat, 3, "SCALAR",
                       {{"min", {0}}, {"max", {4}}});
  int tOut = f.vec3s({{0, 1, 10}, {0, 1, 6}, {0, 1, 2}});
  glm::quat r = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 1, 0));
  int rIn = f.accessor(f.view(std::vector<float>{0, 3}), kFloat, 2, "SCALAR",
                       {{"min", {0}}, {"max", {3}}});
  int rOut =
      f.accessor(f.view(std::vector<float>{0, 0, 0, 1, r.x, r.y, r.z, r.w}), kFloat, 2, "VEC4");
  f.push("animations",
         json{{"name", "dolly"},
              {"samplers",
               json::array({json{{"input", tIn}, {"output", tOut}, {"interpolation", "LINEAR"}},
                            json{{"input", rIn}, {"output", rOut}, {"interpolation", "STEP"}}})},
              {"channels",
               json::array(
                   {json{{"sampler", 0}, {"target", {{"node", cam}, {"path", "translation"}}}},
                    json{{"sampler", 1}, {"target", {{"node", cam}, {"path", "rotation"}}}}})}});
  f.writeGltf(dir / "camera-path.gltf");
}

/// A skinned triangle whose node is also animated: drawn in its rest pose, with warnings.
void skinnedAnimated(const fs::path& dir) {
  Fixture f;
  int joint = f.node({{"name", "joint"}, {"translation", {0, 0, 0}}}, false);
  f.push("skins", json{{"joints", {joint}}});
  int mesh = f.meshNode("skinned",
                        json::array({triangles(f.positions({{0, 0, 0}, {1, 0, 0}, {0, 0, -1}}))}),
                        {{"skin", 0}, {"translation", {0, 1, 0}}, {"children", {joint}}});
  int in = f.accessor(f.view(std::vector<float>{0, 1}), kFloat, 2, "SCALAR",
                      {{"min", {0}}, {"max", {1}}});
  int out = f.vec3s({{0, 1, 0}, {0, 5, 0}});
  f.push("animations",
         json{{"name", "bounce"},
              {"samplers", json::array({json{{"input", in}, {"output", out}}})},
              {"channels",
               json::array({json{{"sampler", 0},
                                 {"target", {{"node", mesh}, {"path", "translation"}}}}})}});
  f.writeGltf(dir / "skinned-animated.gltf");
}

/// A cube with normals as a binary .glb (and the first 100 bytes of it as a truncated one).
void glb(const fs::path& dir) {
  Fixture f;
  std::vector<glm::vec3> pos, nrm;
  std::vector<std::uint16_t> idx;
  const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const glm::vec3& n : axes) {
    glm::vec3 u = std::abs(n.y) > 0.5f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    glm::vec3 v = glm::cross(n, u);  // cross(u, v) = n
    auto base = std::uint16_t(pos.size());
    for (glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
      pos.push_back(0.5f * (n + c.x * u + c.y * v));
      nrm.push_back(n);
    }
    idx.insert(idx.end(), {base, std::uint16_t(base + 1), std::uint16_t(base + 2), base,
                           std::uint16_t(base + 2), std::uint16_t(base + 3)});
  }
  f.meshNode("cube",
             json::array({triangles(f.positions(pos), f.indices(idx), {{"NORMAL", f.vec3s(nrm)}})}),
             {{"translation", {0, 0.5, 0}}});
  std::vector<std::uint8_t> bytes = f.glbBytes();
  writeBytes(dir / "cube.glb", bytes);
  bytes.resize(100);
  writeBytes(dir / "truncated.glb", bytes);
}

// ---- bad files -------------------------------------------------------------------------

/// A single triangle, optionally with a tweak applied to the JSON before writing.
Fixture triangleFixture(const std::vector<glm::vec3>& corners,
                        const std::vector<std::uint16_t>& idx) {
  Fixture f;
  f.meshNode("triangle", json::array({triangles(f.positions(corners), f.indices(idx))}));
  return f;
}

void badFiles(const fs::path& dir) {
  const std::vector<glm::vec3> tri = {{0, 0, 0}, {1, 0, 0}, {0, 0, -1}};
  std::ofstream(dir / "malformed.gltf")
      << "{\n \"asset\": {\"version\": \"2.0\"},\n \"meshes\": [\n  {\"primitives\": [\n";

  {
    Fixture f;
    json lines = triangles(f.positions({{0, 0, 0}, {1, 0, 0}}));
    lines["mode"] = 1;
    f.meshNode("only-lines", json::array({lines}));
    f.writeGltf(dir / "no-triangles.gltf");
  }
  {
    Fixture f;
    std::vector<float> p = {0, 0, 0, std::numeric_limits<float>::quiet_NaN(), 0, 0, 0, 0, -1};
    int pos = f.accessor(f.view(p), kFloat, 3, "VEC3");  // no min/max: JSON has no NaN
    f.meshNode("nan", json::array({triangles(pos)}));
    f.writeGltf(dir / "nan-position.gltf");
  }
  {
    Fixture f = triangleFixture(tri, {0, 1, 2});
    f.root()["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    f.root()["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    f.writeGltf(dir / "draco-required.gltf");
  }
  triangleFixture(tri, {0, 1, 7}).writeGltf(dir / "bad-index.gltf");
  {
    Fixture f;
    std::vector<float> p = {0, 0, 0, 1, 0, 0, 0, 0, -1};
    int pos = f.accessor(f.view(p), kFloat, 10, "VEC3", {{"min", {0, 0, -1}}, {"max", {1, 0, 0}}});
    f.meshNode("short", json::array({triangles(pos)}));
    f.writeGltf(dir / "buffer-out-of-range.gltf");
  }
}

}  // namespace

int writeFixtures(const std::filesystem::path& dir) {
  hierarchyNegativeScale(dir);
  indexTypes(dir);
  sparse(dir);
  noNormals(dir);
  maskMaterial(dir);
  stripFanLines(dir);
  cameraPath(dir);
  punctualLights(dir);
  pointLightOnly(dir);
  skinnedAnimated(dir);
  glb(dir);
  badFiles(dir);
  std::printf("fixtures written to %s\n", dir.string().c_str());
  return 0;
}

}  // namespace sl::gen
