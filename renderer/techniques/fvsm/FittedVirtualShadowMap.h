// Fitted virtual shadow maps (Giegl & Wimmer, GI 2007; docs/techniques.md §6): the eye-space
// depth buffer (core/tiled/EyeDepthBuffer) and the SMTMM pass on the GPU
// (shaders/fvsm/smtmm.comp), read back; the tile grid, its max pyramid and the
// kd-tree traversal on the CPU with the reference itself (algo/fvsm); then every kd leaf is
// rendered at the resolution it needs and applied by deferred shadowing inside its screen
// rectangle (core/tiled/TiledVirtualMap applyTile, shared with `virtual-tiled`), or by
// multi-pass shadowing (§3.1, fvsm.apply; shaders/fvsm/multipass.frag). Pixels no leaf
// reached (the SMTMM samples one pixel per block) get a fallback map over the whole fit. The
// virtual map is the focused orthographic fit or its LiSPSM warp (fvsm.warp), the leaves its
// crops (core/ShadowPass focusedMapView, subRectView).
#pragma once

#include <map>
#include <utility>

#include "algo/fvsm/Fvsm.h"
#include "core/ShadowPass.h"
#include "core/Technique.h"
#include "core/tiled/TiledVirtualMap.h"

namespace sl {

class FittedVirtualShadowMap : public Technique {
 public:
  static TechniqueInfo info();
  explicit FittedVirtualShadowMap(const gl::ShaderLibrary& lib);

  void renderShadows(FrameContext& ctx) override;
  ResolveMode resolveMode() const override { return ResolveMode::Deferred; }
  void resolveDeferred(const ResolveTargets& targets, const ParamSet& params) override;
  std::vector<const gl::Program*> programs() const override {
    std::vector<const gl::Program*> p = depth_.programs();
    p.insert(p.end(),
             {&apply_, &smtmm_, &smtmmPacked_, &cameraThumb_, &multiPass_, &eyeDepth_.program()});
    return p;
  }
  MemoryStats memory() const override;
  std::optional<std::string> reloadShaders(const gl::ShaderLibrary& lib) override;

  /// This frame's kd-tree leaves (for tests: the CPU reference's output on the read-back
  /// SMTMM).
  const std::vector<fvsm::Tile>& tiles() const { return tiles_; }

 private:
  TileDepthTarget& depthTarget(glm::ivec2 size);
  /// §3.1: one leaf applied by rasterising the scene again inside its screen rectangle
  /// (fvsm.apply = multi-pass; shaders/fvsm/multipass.frag), depth test EQUAL against the
  /// pre-pass in `passes`, into the resolve targets (its colour attachments 0..4).
  void applyTileMultiPass(const ResolveTargets& t, const gl::Framebuffer& passes,
                          const DepthMapView& tile, const gl::Texture& texture, glm::ivec2 texels,
                          glm::dvec2 uvMin, glm::dvec2 uvMax, glm::vec2 texelsPerFullUv,
                          glm::ivec2 rectMin, glm::ivec2 rectMax, unsigned mapIndex,
                          const glm::mat4& viewProj, glm::vec3 eye);

  DepthProgram depth_;
  gl::Program apply_;
  gl::Program smtmm_;
  gl::Program smtmmPacked_;  ///< the same pass writing the paper's 4-byte entry
  gl::Program cameraThumb_;
  gl::Program multiPass_;    ///< §3.1: the scene per leaf (fvsm.apply = multi-pass)
  gl::Texture passDepth_;    ///< multi-pass: the pre-pass's depth (allocated once used)
  EyeDepthBuffer eyeDepth_;  ///< this frame's (the outside view's during its resolve)
  gl::Texture smtmmTexture_;
  // The FVSM panel's views, allocated only once it asks for them (fvsm.camera,
  // fvsm.light.depth): the camera's image at one pixel per SMTMM entry, and the whole fit's
  // depth at kLightThumbnail² texels.
  gl::Texture cameraTexture_;
  TileDepthTarget lightThumb_;
  std::map<std::pair<int, int>, TileDepthTarget> targets_;  ///< tile textures by (width, height)
  DepthMapView full_;
  glm::ivec2 smtmmSize_{0}, frameSize_{0};
  std::vector<fvsm::Tile> tiles_;
  int fallbackResolution_ = 0;
};

}  // namespace sl
