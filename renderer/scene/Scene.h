// A loaded scene, flattened to world space: what the renderer uploads and what the
// Embree reference traces. No GL, no Qt.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "algo/Camera.h"
#include "algo/Light.h"

namespace sl {

struct SceneImage {
  std::string name;
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  ///< width*height*4 bytes, row 0 = glTF's first row (v = 0)
};

enum class AlphaMode { Opaque, Mask, Blend };

struct Material {
  std::string name;
  glm::vec4 baseColorFactor{1.0f};
  int baseColorTexture = -1;  ///< index into Scene::images, or -1
  AlphaMode alphaMode = AlphaMode::Opaque;
  float alphaCutoff = 0.5f;
  bool doubleSided = false;
};

/// One triangle list in world space. Front faces are counter-clockwise (winding already
/// flipped for nodes with a negative-determinant transform).
struct MeshPrimitive {
  std::string name;
  std::vector<glm::vec3> positions;  ///< metres, world space
  std::vector<glm::vec3> normals;    ///< unit, world space (computed when the file has none)
  std::vector<glm::vec2> uvs;  ///< base colour texture coordinates (TEXCOORD_0 unless the material
                               ///< names another set; KHR_texture_transform baked in), or empty
  std::vector<std::uint32_t> indices;
  int material = -1;  ///< index into Scene::materials, -1 = default material
};

struct CameraBookmark {
  std::string name;
  Camera camera;
};

/// A camera path (for benchmarks): keyframes of a glTF animation of a camera node.
struct CameraKey {
  float timeS = 0.0f;
  glm::vec3 position{0.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  ///< glTF camera looks along -z
};

struct CameraPath {
  std::string name;
  std::vector<CameraKey> keys;  ///< sorted by time
  float fovYDeg = 50.0f;
  float nearM = 0.1f;
  float farM = 200.0f;
  float durationS() const { return keys.empty() ? 0.0f : keys.back().timeS; }  ///< last key
  float startS() const { return keys.empty() ? 0.0f : keys.front().timeS; }    ///< first key
  /// Camera at time t (clamped), linear position and slerped rotation. Its target lies
  /// 1 m ahead (a path fixes the view, not an orbit centre).
  Camera sample(float timeS) const;
  /// The camera a fraction `f` (0..1) of the way from the first key to the last (keys at
  /// 5-10 s: f = 0.5 samples 7.5 s).
  Camera sampleFraction(float f) const { return sample(startS() + f * (durationS() - startS())); }
  /// Frame `frame` of `frames` spread evenly from the first key to the last (one frame: the
  /// first key).
  Camera sampleFrame(int frame, int frames) const {
    return sampleFraction(frames > 1 ? float(frame) / float(frames - 1) : 0.0f);
  }
};

/// A ShadowLab camera for a glTF camera pose (the camera looks along its local -z).
/// `up` is world +y, or the pose's own +y when the view is within ~2.5 degrees of vertical
/// (so the camera stays valid); a glTF roll about the view axis is dropped.
Camera cameraFromPose(const glm::vec3& positionM, const glm::quat& rotation, float fovYDeg,
                      float nearM, float farM, float targetDistanceM = 1.0f);

struct Scene {
  std::string name;        ///< built-in name or file stem
  std::string sourcePath;  ///< file it was loaded from
  /// Every file loading read: the scene file, then its external buffers and images (outputs
  /// must not overwrite any of them).
  std::vector<std::string> inputFiles;
  std::vector<MeshPrimitive> primitives;
  std::vector<Material> materials;
  std::vector<SceneImage> images;
  std::optional<Light> light;           ///< from KHR_lights_punctual (GltfLoader::addLights)
  std::vector<CameraBookmark> cameras;  ///< from glTF cameras
  std::vector<CameraPath> paths;        ///< from animations of camera nodes
  std::vector<std::string> warnings;    ///< non-fatal notes from loading
  Aabb bounds;

  std::size_t triangleCount() const;
  const Material& materialOf(const MeshPrimitive& prim) const;
  /// A camera that frames the whole scene (used when the file has none).
  Camera defaultCamera() const;
};

}  // namespace sl
