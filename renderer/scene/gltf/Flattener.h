// The flattening of a parsed glTF model into a Scene: images and materials, the node
// hierarchy walked into world-space instances, their mesh primitives as triangle lists
// (Flatten.cpp), and the light, camera bookmarks and camera paths (CamerasLights.cpp).
#pragma once

#include <algorithm>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <tiny_gltf.h>

#include "algo/TriangleBvh.h"
#include "scene/Scene.h"
#include "scene/gltf/Hardening.h"

namespace sl::gltf {

/// A node's local transform: its matrix, else translation * rotation * scale.
glm::dmat4 localMatrix(const tinygltf::Node& node);
/// Every component finite (no NaN or inf).
bool finite(const glm::vec3& v);
/// Position and rotation (scale removed) of a world matrix.
void decomposePose(const glm::dmat4& world, glm::vec3& position, glm::quat& rotation);

/// A node as the walk from the scene's roots reaches it, with its world transform.
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

/// Flattens `model` into `scene`; a refusal throws LoadFailure, what it leaves out becomes
/// a warning in Scene::warnings.
class Flattener {
 public:
  Flattener(const tinygltf::Model& model, Scene& scene) : model_(model), scene_(scene) {}

  /// Images, materials, the hierarchy, its primitives, the light, cameras and paths.
  void run();

 private:
  void warn(const std::string& text) { scene_.warnings.push_back(text); }

  /// Refuses geometry reaching farther from the origin than kMaxSceneExtentM.
  void checkExtent() const;

  void warnOnce(const std::string& key, const std::string& text) {
    if (warnedKeys_.insert(key).second) warn(text);
  }

  std::string nodeName(int index) const {
    const tinygltf::Node& n = model_.nodes[std::size_t(index)];
    return n.name.empty() ? "node " + std::to_string(index) : inQuotes(n.name);
  }

  void convertImages();

  void convertMaterials();

  static void readTextureTransform(const tinygltf::Value& ext, UvRule& rule);

  void collectInstances();

  /// "node 7" or "node 7 'name'": the index always, since names need not be unique.
  std::string nodeLabel(int index) const {
    const tinygltf::Node& n = model_.nodes[std::size_t(index)];
    return "node " + std::to_string(index) + (n.name.empty() ? "" : " " + quoteInput(n.name));
  }

  /// glTF's rules for a node's transform, which the flattening relies on: a matrix
  /// decomposes into translation, rotation and scale (affine: last row 0, 0, 0, 1), a
  /// rotation is a unit quaternion, every value is finite. A zero or non-finite quaternion and
  /// a projective matrix are refused; a rotation of another length is normalised with a warning.
  void checkNodeTransform(int index);

  /// Depth-first, parents before children (the order a recursive walk gives), with an
  /// explicit stack so that a chain of a million nodes cannot overflow the call stack. glTF
  /// requires the hierarchy to be a set of disjoint trees: a node reached a second time (a
  /// DAG, whose instances would double with each level, or a cycle) is refused.
  void visitTree(const std::vector<int>& roots);

  /// Refuses, before anything is read or allocated, a scene whose instances would flatten to
  /// more than kMaxTriangles triangles (a mesh instanced by many nodes). The estimate comes
  /// from the accessors' counts; addPrimitive() checks the exact total as it goes.
  void checkTriangleEstimate() const;

  void addMeshInstance(const NodeInstance& inst);

  void addPrimitive(const tinygltf::Primitive& src, const std::string& label,
                    const std::string& name, const glm::dmat4& world);

  /// The spec's rule for primitives without normals: flat shading. Each triangle gets its
  /// own three vertices whose normal is the (counter-clockwise) face normal.
  static void computeFlatNormals(MeshPrimitive& prim);

  /// KHR_lights_punctual: the scene's light is its first directional light (the sun), or,
  /// when it has none, its first spot or point light (in node order). Position and axis
  /// come from the node's world transform (lights shine along the node's -z); cone angles
  /// and range from the light (range is not scaled by the node, as the extension says).
  void addLights();

  /// Distance along a ray to the first triangle (either side), or +inf. The hierarchy is
  /// built on the first call: a ray per camera through every triangle was O(cameras x
  /// triangles), 111 s for 10^5 cameras each on a node with a mesh.
  float firstHit(const glm::vec3& origin, const glm::vec3& dir);

  /// A far plane that reaches every corner of the scene bounds from `position`.
  float farFromBounds(const glm::vec3& position, float nearM) const;

  struct CameraLens {
    float fovYDeg = 50.0f, nearM = 0.1f, farM = 0.0f;  ///< farM 0 = from the scene bounds
  };

  /// The lens of a perspective camera, or nothing (with a warning) for other cameras.
  std::optional<CameraLens> lensOf(int cameraIndex, const std::string& where);

  std::string cameraName(const NodeInstance& inst) const;

  /// `nearM`, raised (with a warning) to far / Camera::kMaxFarOverNear where the depth buffer
  /// could not tell the far half of the view apart (a 1e-6 m znear with a 200 m zfar).
  float nearWithinDepthPrecision(float nearM, float farM, const std::string& where);

  void addCameras();

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
                  const std::string& label);

  void addPaths();

  /// Keys at every keyframe time of either track. A STEP track also gets a key just before
  /// each jump, so that CameraPath's linear interpolation reproduces the step.
  std::vector<CameraKey> sampleKeys(const NodeInstance& inst, const Track* tTrack,
                                    const Track* rTrack) const;

  const tinygltf::Model& model_;
  Scene& scene_;
  std::vector<NodeInstance> instances_;
  std::size_t triangles_ = 0;  ///< in scene_.primitives so far
  std::vector<UvRule> uvRules_;
  std::set<std::string> warnedKeys_;
  std::optional<TriangleBvh> bvh_;  ///< for firstHit(), built when first needed
};

}  // namespace sl::gltf
