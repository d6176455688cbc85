// Building blocks of the scene generator: CPU meshes (boxes, cylinders, spheres, quads) and a
// thin builder over tinygltf::Model that writes them, with a sun, cameras and camera paths,
// as a self-contained .gltf (buffers and images embedded as base64 data URIs).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <tiny_gltf.h>

namespace sl::gen {

/// One triangle list, counter-clockwise front faces, in the node's local space (metres).
struct MeshData {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<glm::vec2> uvs;
  std::vector<std::uint32_t> indices;

  std::size_t triangleCount() const { return indices.size() / 3; }
  /// A planar quad p0 p1 p2 p3 (counter-clockwise seen from its front) with uvs at its
  /// corners (0,1) (1,1) (1,0) (0,0) scaled by `uvScale` (row 0 of an image is v = 0, the top).
  void addQuad(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, const glm::vec3& p3,
               glm::vec2 uvScale = glm::vec2(1.0f));
  /// An axis-aligned box, rotated by `yawDeg` about +y around its centre.
  void addBox(const glm::vec3& center, const glm::vec3& halfSize, float yawDeg = 0.0f);
  /// A capped cylinder standing on `base`.
  void addCylinder(const glm::vec3& base, float radiusM, float heightM, int segments);
  /// A UV sphere.
  void addSphere(const glm::vec3& center, float radiusM, int slices, int stacks);
  void append(const MeshData& other);
};

/// A (nu x nv)-quad parametric surface p(u, v), u, v in [0, 1], sharing vertices;
/// counter-clockwise faces on the side of cross(dp/du, dp/dv), the normals' side: by central
/// differences, or `flatNormal` for a planar surface (with corners where it degenerates).
void addSurface(MeshData& m, int nu, int nv, const std::function<glm::vec3(float, float)>& p,
                const glm::vec3* flatNormal = nullptr);

/// Rotation whose local +z axis points along `z` (local +y stays as close to world +y as it
/// can): the node rotation of a light shining along -z, or of a camera looking along -z.
glm::quat rotationWithZAxis(const glm::vec3& z);
/// Unit vector towards a light at azimuth (from +z towards +x) and elevation, in degrees;
/// the same convention as sl::Light::directionalTowards.
glm::vec3 towardsLightFromAngles(float azimuthDeg, float elevationDeg);

struct CameraKeyframe {
  float timeS;
  glm::vec3 eye;
  glm::vec3 target;
};

class SceneBuilder {
 public:
  explicit SceneBuilder(const std::string& sceneName);

  int addMaterial(const std::string& name, const glm::vec4& baseColor,
                  const std::string& alphaMode = "OPAQUE", float alphaCutoff = 0.5f,
                  bool doubleSided = false, int texture = -1);
  /// An RGBA8 texture (row 0 = top = v 0), repeat-wrapped and mipmapped.
  int addTexture(const std::string& name, int width, int height,
                 const std::vector<std::uint8_t>& rgba);
  int addMesh(const std::string& name, const MeshData& mesh, int material);
  int addNode(const std::string& name, int mesh, const glm::vec3& translation = glm::vec3(0.0f));
  /// A KHR_lights_punctual directional light; its node's +z points towards the light.
  int addSun(float azimuthDeg, float elevationDeg, float intensityLux = 3.0f);
  /// A KHR_lights_punctual point light at `positionM` (range 0: none written = infinite).
  int addPointLight(const std::string& name, const glm::vec3& positionM, float rangeM = 0.0f,
                    float intensityCd = 100.0f);
  /// A KHR_lights_punctual spot light at `positionM` shining along `direction` (its node's
  /// -z), cone half-angles in degrees.
  int addSpotLight(const std::string& name, const glm::vec3& positionM, const glm::vec3& direction,
                   float outerConeDeg, float innerConeDeg, float rangeM = 0.0f,
                   float intensityCd = 200.0f);
  /// A perspective camera node looking from `eye` at `target`.
  int addCamera(const std::string& name, const glm::vec3& eye, const glm::vec3& target,
                float yfovDeg, float znearM, float zfarM);
  /// A LINEAR translation + rotation animation of `cameraNode` through the keyframes.
  void addCameraPath(const std::string& name, int cameraNode,
                     const std::vector<CameraKeyframe>& keys);

  std::size_t triangleCount() const { return triangles_; }
  /// Writes the .gltf (a path ending in .glb: binary glTF); returns an error message or "".
  std::string write(const std::string& path);

 private:
  /// Appends `light` and `node` (named after the light, referring to it) as a root node.
  int addLightNode(const tinygltf::Light& light, tinygltf::Node node);
  int addAccessor(const void* data, std::size_t bytes, int componentType, int type,
                  std::size_t count, int target, std::vector<double> minValues = {},
                  std::vector<double> maxValues = {});

  tinygltf::Model model_;
  std::size_t triangles_ = 0;
};

}  // namespace sl::gen
