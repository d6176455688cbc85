// The interface every shadow technique implements. A technique is one self-contained
// unit (its C++ under renderer/techniques/<name>/, its shaders under shaders/<name>/):
// it builds its shadow map(s) each frame and provides the GLSL lookup the resolve pass
// includes as "@lookup". Adding a technique touches its folder and TechniqueRegistry.cpp.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "algo/Camera.h"
#include "algo/Params.h"
#include "core/FrameStats.h"
#include "core/Renderer.h"
#include "gl/GpuTimer.h"
#include "gl/ShaderLibrary.h"

namespace sl {

class SceneGpu;

/// Everything a technique may read while building its shadows for one frame.
struct FrameContext {
  const Scene& scene;
  const SceneGpu& sceneGpu;
  const Camera& camera;
  float aspect = 1.0f;
  glm::mat4 cameraView{1.0f}, cameraProj{1.0f};
  glm::vec3 towardsLight{0.0f, 1.0f, 0.0f};
  int width = 0, height = 0;  ///< camera image size in pixels
  /// Camera G-buffer of this frame (for backward analysis): world position (w = covered)
  /// and world normal, RGBA32F, width x height.
  const gl::Texture& gPosition;
  const gl::Texture& gNormal;
  /// The previous frame's hard shadow mask (R8UI, camera space): shadow-edge importance.
  const gl::Texture& prevHardMask;
  const ParamSet& params;  ///< the technique's own parameters
  gl::GpuTimer& timer;
  const gl::ShaderLibrary& shaders;
  std::uint64_t frameIndex = 0;
  /// Non-null when publications are requested; publish only what wants() accepts, through
  /// the readback helpers of core/Publish.h (they count the bytes).
  Publication* publication = nullptr;
  /// True when `key` is requested this frame: read it back, or do the work that exists
  /// only to show it.
  bool wants(std::string_view key) const { return publication && publication->wants(key); }
};

class Technique {
 public:
  virtual ~Technique() = default;
  /// Builds this frame's shadow map(s). Throws std::runtime_error on unrecoverable GL
  /// problems; parameter values are already validated.
  virtual void renderShadows(FrameContext& ctx) = 0;
  /// GLSL file (relative to shaders/) defining the lookup functions listed in
  /// shaders/common/resolve.frag (shadowLookupCoord, shadowMapSize, shadowHardAt,
  /// shadowFilteredAt), included by the resolve pass as "@lookup".
  virtual std::string lookupShader() const = 0;
  /// Binds what the lookup needs (textures from `firstUnit` on, uniforms) to `resolve`.
  virtual void bindLookup(const gl::Program& resolve, int firstUnit) const = 0;
  /// Shadow-related GPU resources of the last frame.
  virtual MemoryStats memory() const = 0;
  virtual std::optional<std::string> reloadShaders(const gl::ShaderLibrary& lib) = 0;
  virtual void resetTemporalState() {}
};

/// One entry of the technique list: what it is, and how to make one (GL current).
struct TechniqueEntry {
  TechniqueInfo info;
  std::unique_ptr<Technique> (*create)(const gl::ShaderLibrary& lib);
};
const std::vector<TechniqueEntry>& techniqueRegistry();

/// Parameters most shadow-map techniques share (resolution, bias, PCF), declared once.
std::vector<ParamDecl> shadowMapParamDecls(int defaultResolution);
/// The "shadow map" publication of a technique with one `resolution`^2 depth map.
PublicationDecl shadowMapPublicationDecl();

}  // namespace sl
