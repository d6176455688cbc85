// Scene generator building blocks: procedural meshes and the tinygltf model writer.
#include "SceneBuilder.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>

namespace sl::gen {

namespace {
constexpr float kPi = 3.14159265358979f;

glm::vec3 rotateY(const glm::vec3& v, float yawRad) {
  float c = std::cos(yawRad), s = std::sin(yawRad);
  return glm::vec3(c * v.x + s * v.z, v.y, -s * v.x + c * v.z);
}
}  // namespace

void MeshData::addQuad(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2,
                       const glm::vec3& p3, glm::vec2 uvScale) {
  glm::vec3 n = glm::normalize(glm::cross(p1 - p0, p2 - p0));
  auto base = std::uint32_t(positions.size());
  positions.insert(positions.end(), {p0, p1, p2, p3});
  normals.insert(normals.end(), {n, n, n, n});
  uvs.insert(uvs.end(), {glm::vec2(0.0f, uvScale.y), glm::vec2(uvScale.x, uvScale.y),
                         glm::vec2(uvScale.x, 0.0f), glm::vec2(0.0f)});
  indices.insert(indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

void MeshData::addBox(const glm::vec3& center, const glm::vec3& halfSize, float yawDeg) {
  // Each face: outward axis n and in-face axes u, v with cross(u, v) = n.
  struct Face {
    glm::vec3 n, u, v;
  };
  const Face faces[6] = {
      {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
      {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
      {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
  };
  float yaw = glm::radians(yawDeg);
  for (const Face& f : faces) {
    glm::vec3 n = f.n * glm::abs(glm::dot(halfSize, f.n));
    glm::vec3 u = f.u * glm::abs(glm::dot(halfSize, f.u));
    glm::vec3 v = f.v * glm::abs(glm::dot(halfSize, f.v));
    auto corner = [&](float su, float sv) { return center + rotateY(n + su * u + sv * v, yaw); };
    addQuad(corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1));
  }
}

void MeshData::addCylinder(const glm::vec3& base, float radiusM, float heightM, int segments) {
  // Angle a runs from +x towards -z, so that increasing a is counter-clockwise seen from +y.
  auto ring = [&](float a) { return glm::vec3(std::cos(a), 0.0f, -std::sin(a)); };
  glm::vec3 up(0.0f, heightM, 0.0f);
  for (int i = 0; i < segments; ++i) {
    float a0 = 2.0f * kPi * float(i) / float(segments);
    float a1 = 2.0f * kPi * float(i + 1) / float(segments);
    glm::vec3 d0 = ring(a0), d1 = ring(a1);
    auto s = std::uint32_t(positions.size());
    positions.insert(positions.end(), {base + radiusM * d0, base + radiusM * d1,
                                       base + radiusM * d1 + up, base + radiusM * d0 + up});
    normals.insert(normals.end(), {d0, d1, d1, d0});
    float u0 = float(i) / float(segments), u1 = float(i + 1) / float(segments);
    uvs.insert(uvs.end(), {{u0, 1.0f}, {u1, 1.0f}, {u1, 0.0f}, {u0, 0.0f}});
    indices.insert(indices.end(), {s, s + 1, s + 2, s, s + 2, s + 3});
    // Caps as fans from the centre.
    auto t = std::uint32_t(positions.size());
    positions.insert(positions.end(),
                     {base + up, base + up + radiusM * d0, base + up + radiusM * d1, base,
                      base + radiusM * d1, base + radiusM * d0});
    glm::vec3 n(0.0f, 1.0f, 0.0f);
    normals.insert(normals.end(), {n, n, n, -n, -n, -n});
    uvs.insert(uvs.end(), 6, glm::vec2(0.5f));
    indices.insert(indices.end(), {t, t + 1, t + 2, t + 3, t + 4, t + 5});
  }
}

void MeshData::addSphere(const glm::vec3& center, float radiusM, int slices, int stacks) {
  auto base = std::uint32_t(positions.size());
  for (int i = 0; i <= stacks; ++i) {
    float theta = kPi * float(i) / float(stacks);  // 0 at the top
    for (int j = 0; j <= slices; ++j) {
      float phi = 2.0f * kPi * float(j) / float(slices);
      glm::vec3 d(std::sin(theta) * std::cos(phi), std::cos(theta),
                  -std::sin(theta) * std::sin(phi));
      positions.push_back(center + radiusM * d);
      normals.push_back(d);
      uvs.emplace_back(float(j) / float(slices), float(i) / float(stacks));
    }
  }
  auto at = [&](int i, int j) { return base + std::uint32_t(i * (slices + 1) + j); };
  for (int i = 0; i < stacks; ++i) {
    for (int j = 0; j < slices; ++j) {
      // Lower row (i + 1) then upper row (i): counter-clockwise seen from outside.
      std::uint32_t p0 = at(i + 1, j), p1 = at(i + 1, j + 1), p2 = at(i, j + 1), p3 = at(i, j);
      if (i + 1 < stacks) indices.insert(indices.end(), {p0, p1, p2});  // not at the south pole
      if (i > 0) indices.insert(indices.end(), {p0, p2, p3});           // not at the north pole
    }
  }
}

void MeshData::append(const MeshData& other) {
  auto base = std::uint32_t(positions.size());
  positions.insert(positions.end(), other.positions.begin(), other.positions.end());
  normals.insert(normals.end(), other.normals.begin(), other.normals.end());
  uvs.insert(uvs.end(), other.uvs.begin(), other.uvs.end());
  for (std::uint32_t i : other.indices) indices.push_back(base + i);
}

void addSurface(MeshData& m, int nu, int nv, const std::function<glm::vec3(float, float)>& p,
                const glm::vec3* flatNormal) {
  const auto base = std::uint32_t(m.positions.size());
  const float h = 1e-3f;
  for (int j = 0; j <= nv; ++j) {
    for (int i = 0; i <= nu; ++i) {
      const float u = float(i) / float(nu), v = float(j) / float(nv);
      glm::vec3 du = p(std::min(u + h, 1.0f), v) - p(std::max(u - h, 0.0f), v);
      glm::vec3 dv = p(u, std::min(v + h, 1.0f)) - p(u, std::max(v - h, 0.0f));
      glm::vec3 n = glm::cross(du, dv);
      const float len = glm::length(n);
      m.positions.push_back(p(u, v));
      m.normals.push_back(flatNormal   ? *flatNormal
                          : len > 0.0f ? n / len
                                       : glm::vec3(0.0f, 1.0f, 0.0f));
      m.uvs.emplace_back(u, v);
    }
  }
  auto at = [&](int i, int j) { return base + std::uint32_t(j * (nu + 1) + i); };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i)
      m.indices.insert(m.indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j),
                                         at(i + 1, j + 1), at(i, j + 1)});
}

glm::quat rotationWithZAxis(const glm::vec3& zIn) {
  glm::vec3 z = glm::normalize(zIn);
  glm::vec3 up =
      std::abs(z.y) > 0.999f ? glm::vec3(0.0f, 0.0f, -1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
  glm::vec3 x = glm::normalize(glm::cross(up, z));
  glm::vec3 y = glm::cross(z, x);
  return glm::normalize(glm::quat_cast(glm::mat3(x, y, z)));
}

glm::vec3 towardsLightFromAngles(float azimuthDeg, float elevationDeg) {
  float az = glm::radians(azimuthDeg), el = glm::radians(elevationDeg);
  return glm::vec3(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
}

SceneBuilder::SceneBuilder(const std::string& sceneName) {
  model_.asset.version = "2.0";
  model_.asset.generator = "shadowlab-make-scenes (scenes/tools)";
  model_.buffers.emplace_back();
  model_.buffers[0].name = sceneName;
  tinygltf::Scene scene;
  scene.name = sceneName;
  model_.scenes.push_back(scene);
  model_.defaultScene = 0;
}

int SceneBuilder::addAccessor(const void* data, std::size_t bytes, int componentType, int type,
                              std::size_t count, int target, std::vector<double> minValues,
                              std::vector<double> maxValues) {
  std::vector<unsigned char>& buf = model_.buffers[0].data;
  while (buf.size() % 4) buf.push_back(0);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = buf.size();
  view.byteLength = bytes;
  view.target = target;
  buf.resize(buf.size() + bytes);
  std::memcpy(buf.data() + view.byteOffset, data, bytes);
  model_.bufferViews.push_back(view);
  tinygltf::Accessor acc;
  acc.bufferView = int(model_.bufferViews.size() - 1);
  acc.componentType = componentType;
  acc.type = type;
  acc.count = count;
  acc.minValues = std::move(minValues);
  acc.maxValues = std::move(maxValues);
  model_.accessors.push_back(acc);
  return int(model_.accessors.size() - 1);
}

int SceneBuilder::addMaterial(const std::string& name, const glm::vec4& baseColor,
                              const std::string& alphaMode, float alphaCutoff, bool doubleSided,
                              int texture) {
  tinygltf::Material m;
  m.name = name;
  m.pbrMetallicRoughness.baseColorFactor = {baseColor.r, baseColor.g, baseColor.b, baseColor.a};
  m.pbrMetallicRoughness.metallicFactor = 0.0;
  m.pbrMetallicRoughness.roughnessFactor = 0.8;
  m.pbrMetallicRoughness.baseColorTexture.index = texture;
  m.alphaMode = alphaMode;
  m.alphaCutoff = alphaCutoff;
  m.doubleSided = doubleSided;
  model_.materials.push_back(m);
  return int(model_.materials.size() - 1);
}

int SceneBuilder::addTexture(const std::string& name, int width, int height,
                             const std::vector<std::uint8_t>& rgba) {
  tinygltf::Image img;
  img.name = name;
  img.width = width;
  img.height = height;
  img.component = 4;
  img.bits = 8;
  img.pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
  img.mimeType = "image/png";
  img.image = rgba;
  model_.images.push_back(img);
  tinygltf::Sampler sampler;
  sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
  sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
  model_.samplers.push_back(sampler);
  tinygltf::Texture tex;
  tex.name = name;
  tex.source = int(model_.images.size() - 1);
  tex.sampler = int(model_.samplers.size() - 1);
  model_.textures.push_back(tex);
  return int(model_.textures.size() - 1);
}

int SceneBuilder::addMesh(const std::string& name, const MeshData& mesh, int material) {
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const glm::vec3& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const std::size_t n = mesh.positions.size();
  tinygltf::Primitive prim;
  prim.mode = TINYGLTF_MODE_TRIANGLES;
  prim.material = material;
  prim.attributes["POSITION"] =
      addAccessor(mesh.positions.data(), n * 12, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3,
                  n, TINYGLTF_TARGET_ARRAY_BUFFER, {lo.x, lo.y, lo.z}, {hi.x, hi.y, hi.z});
  prim.attributes["NORMAL"] =
      addAccessor(mesh.normals.data(), n * 12, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n,
                  TINYGLTF_TARGET_ARRAY_BUFFER);
  if (mesh.uvs.size() == n)
    prim.attributes["TEXCOORD_0"] =
        addAccessor(mesh.uvs.data(), n * 8, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, n,
                    TINYGLTF_TARGET_ARRAY_BUFFER);
  if (n < 65536) {
    std::vector<std::uint16_t> idx(mesh.indices.begin(), mesh.indices.end());
    prim.indices =
        addAccessor(idx.data(), idx.size() * 2, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                    TINYGLTF_TYPE_SCALAR, idx.size(), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  } else {
    prim.indices = addAccessor(mesh.indices.data(), mesh.indices.size() * 4,
                               TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                               mesh.indices.size(), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  }
  tinygltf::Mesh m;
  m.name = name;
  m.primitives.push_back(prim);
  model_.meshes.push_back(m);
  triangles_ += mesh.triangleCount();
  return int(model_.meshes.size() - 1);
}

int SceneBuilder::addNode(const std::string& name, int mesh, const glm::vec3& translation) {
  tinygltf::Node node;
  node.name = name;
  node.mesh = mesh;
  if (translation != glm::vec3(0.0f))
    node.translation = {translation.x, translation.y, translation.z};
  model_.nodes.push_back(node);
  int index = int(model_.nodes.size() - 1);
  model_.scenes[0].nodes.push_back(index);
  return index;
}

namespace {
/// A light of glTF `type` in the warm white of every built-in scene; `rangeM` 0: infinite.
tinygltf::Light warmLight(const std::string& name, const std::string& type, float intensity,
                          float rangeM = 0.0f) {
  tinygltf::Light light;
  light.name = name;
  light.type = type;
  light.color = {1.0, 0.96, 0.9};
  light.intensity = intensity;
  light.range = rangeM;
  return light;
}
}  // namespace

int SceneBuilder::addLightNode(const tinygltf::Light& light, tinygltf::Node node) {
  model_.lights.push_back(light);
  node.name = light.name;
  tinygltf::Value::Object ref;
  ref["light"] = tinygltf::Value(int(model_.lights.size() - 1));
  node.extensions["KHR_lights_punctual"] = tinygltf::Value(ref);
  model_.nodes.push_back(node);
  int index = int(model_.nodes.size() - 1);
  model_.scenes[0].nodes.push_back(index);
  return index;
}

int SceneBuilder::addSun(float azimuthDeg, float elevationDeg, float intensityLux) {
  tinygltf::Light light = warmLight("sun", "directional", intensityLux);
  tinygltf::Node node;
  glm::quat q = rotationWithZAxis(towardsLightFromAngles(azimuthDeg, elevationDeg));
  node.rotation = {q.x, q.y, q.z, q.w};
  return addLightNode(light, node);
}

int SceneBuilder::addPointLight(const std::string& name, const glm::vec3& positionM, float rangeM,
                                float intensityCd) {
  tinygltf::Light light = warmLight(name, "point", intensityCd, rangeM);
  tinygltf::Node node;
  node.translation = {positionM.x, positionM.y, positionM.z};
  return addLightNode(light, node);
}

int SceneBuilder::addSpotLight(const std::string& name, const glm::vec3& positionM,
                               const glm::vec3& direction, float outerConeDeg, float innerConeDeg,
                               float rangeM, float intensityCd) {
  tinygltf::Light light = warmLight(name, "spot", intensityCd, rangeM);
  light.spot.outerConeAngle = glm::radians(double(outerConeDeg));
  light.spot.innerConeAngle = glm::radians(double(innerConeDeg));
  tinygltf::Node node;
  node.translation = {positionM.x, positionM.y, positionM.z};
  glm::quat q = rotationWithZAxis(-glm::normalize(direction));  // shines along -z
  node.rotation = {q.x, q.y, q.z, q.w};
  return addLightNode(light, node);
}

int SceneBuilder::addCamera(const std::string& name, const glm::vec3& eye, const glm::vec3& target,
                            float yfovDeg, float znearM, float zfarM) {
  tinygltf::Camera cam;
  cam.name = name;
  cam.type = "perspective";
  cam.perspective.yfov = glm::radians(double(yfovDeg));
  cam.perspective.znear = znearM;
  cam.perspective.zfar = zfarM;
  cam.perspective.aspectRatio = 16.0 / 9.0;
  model_.cameras.push_back(cam);
  tinygltf::Node node;
  node.name = name;
  node.camera = int(model_.cameras.size() - 1);
  glm::quat q = rotationWithZAxis(eye - target);
  node.translation = {eye.x, eye.y, eye.z};
  node.rotation = {q.x, q.y, q.z, q.w};
  model_.nodes.push_back(node);
  int index = int(model_.nodes.size() - 1);
  model_.scenes[0].nodes.push_back(index);
  return index;
}

void SceneBuilder::addCameraPath(const std::string& name, int cameraNode,
                                 const std::vector<CameraKeyframe>& keys) {
  std::vector<float> times, translations, rotations;
  glm::quat previous(1.0f, 0.0f, 0.0f, 0.0f);
  for (std::size_t k = 0; k < keys.size(); ++k) {
    times.push_back(keys[k].timeS);
    translations.insert(translations.end(), {keys[k].eye.x, keys[k].eye.y, keys[k].eye.z});
    glm::quat q = rotationWithZAxis(keys[k].eye - keys[k].target);
    if (k > 0 && glm::dot(q, previous) < 0.0f) q = -q;  // keep neighbours in one hemisphere
    previous = q;
    rotations.insert(rotations.end(), {q.x, q.y, q.z, q.w});
  }
  const std::size_t n = keys.size();
  int input = addAccessor(times.data(), n * 4, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_SCALAR,
                          n, 0, {times.front()}, {times.back()});
  int outT = addAccessor(translations.data(), n * 12, TINYGLTF_COMPONENT_TYPE_FLOAT,
                         TINYGLTF_TYPE_VEC3, n, 0);
  int outR = addAccessor(rotations.data(), n * 16, TINYGLTF_COMPONENT_TYPE_FLOAT,
                         TINYGLTF_TYPE_VEC4, n, 0);
  tinygltf::Animation anim;
  anim.name = name;
  for (int out : {outT, outR}) {
    tinygltf::AnimationSampler sampler;
    sampler.input = input;
    sampler.output = out;
    sampler.interpolation = "LINEAR";
    anim.samplers.push_back(sampler);
    tinygltf::AnimationChannel channel;
    channel.sampler = int(anim.samplers.size() - 1);
    channel.target_node = cameraNode;
    channel.target_path = out == outT ? "translation" : "rotation";
    anim.channels.push_back(channel);
  }
  model_.animations.push_back(anim);
}

std::string SceneBuilder::write(const std::string& path) {
  tinygltf::TinyGLTF writer;
  // FILE.glb: binary glTF, the buffer in its BIN chunk; else JSON with base64 buffers.
  const bool binary = path.size() >= 4 && path.compare(path.size() - 4, 4, ".glb") == 0;
  if (!writer.WriteGltfSceneToFile(&model_, path, /*embedImages=*/true, /*embedBuffers=*/true,
                                   /*prettyPrint=*/!binary, /*writeBinary=*/binary))
    return "could not write " + path;
  return "";
}

}  // namespace sl::gen
