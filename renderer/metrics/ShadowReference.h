// The exact hard-shadow reference (techniques.md, "Measuring"): for each visible surface
// point an occlusion ray towards the light (directional: to infinity; spot, point: to its
// position) is traced against the scene's triangles with Embree 3. Every shadow-map technique's
// pixel error is measured against it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "algo/Light.h"
#include "scene/Scene.h"

namespace sl {

/// Ray-traced hard shadows for one scene. Built once per scene (the BVH build takes ~15 ms
/// for 10k triangles on 2 cores); queries are const and thread-safe. A moved-from object
/// may only be destroyed or assigned to.
///
/// What casts shadows (the same rules as shaders/common/material.glsl, materialAlphaRejects):
/// - Every triangle, from both sides (no back-face culling, whatever doubleSided says).
/// - AlphaMode::Mask: alpha-tested as in glTF. At the hit, the primitive's uvs
///   (MeshPrimitive::uvs) are interpolated with the hit's barycentrics; alpha =
///   baseColorFactor.a * texture alpha (bilinear between texel centres as GL_LINEAR on
///   mip level 0, REPEAT wrap, v = 0 on image row 0); hits with alpha < alphaCutoff are
///   ignored. No texture: factor alpha alone; a primitive without uvs samples uv (0, 0).
/// - AlphaMode::Blend: an opaque caster (a hard shadow has no partial coverage; the GPU
///   passes only discard for Mask as well).
/// - Opaque: opaque, texture alpha ignored.
///
/// Self-shadowing: the ray starts at p + normalize(n) * normalOffsetM() and ignores hits
/// closer than rayTNearM() (= normalOffsetM()) along the ray; far end: infinity for a
/// directional light, the light's position minus rayTNearM() for spot and point lights.
/// Outside a spot's cone or a light's range (Light::illuminates): not lit. The offset
/// is normalOffsetFraction times the scene's bounding-box diagonal, at least 1 um, or four
/// float spacings of the point's largest coordinate where that is more (a scene far from
/// the origin: 1.6 cm at 5e4 m; scaling the offset by the distance instead moved every
/// shadow border there by 0.7 m): the default 1e-5 gives 0.28 mm for a 20 x 20 m scene, which moves
/// a shadow border by 0.28 mm / tan(elevation) (0.5 mm at 30 degrees).
class ShadowReference {
 public:
  /// Copies what it needs from `scene` (the scene may be destroyed afterwards). Throws
  /// std::runtime_error when Embree fails (device, scene, geometry or BVH build) or a
  /// primitive's index points past its vertices. An empty scene is allowed.
  explicit ShadowReference(const Scene& scene, float normalOffsetFraction = 1e-5f);
  /// False in a build without Embree (SHADOWLAB_REFERENCE=OFF, the headless folder that
  /// travels): constructing one then throws std::runtime_error with unavailableReason().
  static bool available();
  /// Why there is no reference in this build ("" where available()).
  static const char* unavailableReason();
  ~ShadowReference();
  ShadowReference(const ShadowReference&) = delete;
  ShadowReference& operator=(const ShadowReference&) = delete;
  ShadowReference(ShadowReference&&) noexcept;
  ShadowReference& operator=(ShadowReference&&) noexcept;

  /// The exact hard-shadow answer at surface point `p` (world, metres) with normal `n`
  /// (world, need not be unit): false when dot(n, towardsLight) <= 0 (facing away),
  /// otherwise true when nothing blocks the ray towards the light.
  /// `towardsLight` need not be unit; it must not be zero.
  bool isLit(const glm::vec3& p, const glm::vec3& n, const glm::vec3& towardsLight) const;
  /// The same for any light (Light::towardsLight(p), illuminates(p), rays ending at the
  /// light's position for spot and point). Not lit when the light does not validate().
  bool isLit(const glm::vec3& p, const glm::vec3& n, const Light& light) const;

  /// A whole frame: positions[i].xyz world position, positions[i].w > 0 where pixel i is
  /// covered; normals[i].xyz its normal. out[i] = 1 lit, 0 shadowed, 255 not covered
  /// (the encoding of ErrorMetrics.h). Same answers as isLit(). Uses every hardware
  /// thread, in chunks of contiguous pixels (rows of a row-major frame), with Embree ray
  /// streams. Throws std::invalid_argument when positions and normals differ in size.
  void evaluate(std::span<const glm::vec4> positions, std::span<const glm::vec4> normals,
                const glm::vec3& towardsLight, std::vector<std::uint8_t>& out) const;
  /// The same for any light (see isLit(p, n, light)).
  void evaluate(std::span<const glm::vec4> positions, std::span<const glm::vec4> normals,
                const Light& light, std::vector<std::uint8_t>& out) const;

  std::size_t triangleCount() const;         ///< triangles in the BVH
  std::size_t alphaTestedTriangles() const;  ///< of which alpha-tested (Mask materials)
  float normalOffsetM() const;               ///< origin offset along the normal, metres
  float rayTNearM() const;                   ///< hits closer than this along the ray are ignored

 private:
  /// isLit / evaluate with the directional case's exact unit vector `dirTowards` (so the
  /// vector overloads trace exactly the direction they were given).
  bool isLitTowards(const glm::vec3& p, const glm::vec3& n, const Light& light,
                    const glm::vec3& dirTowards) const;
  /// dir: null when nothing can be lit (zero or invalid light).
  void evaluateTowards(std::span<const glm::vec4> positions, std::span<const glm::vec4> normals,
                       const Light& light, const glm::vec3* dir,
                       std::vector<std::uint8_t>& out) const;

  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sl
