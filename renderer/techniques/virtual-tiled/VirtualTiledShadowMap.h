// Brute-force virtual tiled shadow map (Giegl & Wimmer, GI 2007, §3.2; docs/techniques.md §6):
// the light's focused frustum (orthographic, or LiSPSM-warped with tile.warp as the paper's)
// cut into n x n tiles, each rendered at
// tile.resolution (16 x 16 x 4096² = a 65536² virtual map) into ONE reused depth texture and
// applied at once by deferred shadowing: a compute pass over the screen rebuilds each pixel's
// world position from the eye-space depth buffer (eq. 1, core/tiled/EyeDepthBuffer.h) and shadows
// the pixels whose light uv falls in that tile. The baseline fitted virtual shadow maps are
// measured against.
#pragma once

#include "core/tiled/EyeDepthBuffer.h"
#include "core/ShadowPass.h"
#include "core/Technique.h"
#include "core/tiled/TiledVirtualMap.h"

namespace sl {

class VirtualTiledShadowMap : public Technique {
 public:
  /// A progressive resolve (ResolveProgress) renders a tile's depth in bands of this many rows
  /// (scissored: the same texels as one pass), one unit each, so that a unit of a 4096² tile
  /// is an eighth of its depth pass; the tile is applied after its last band.
  static constexpr int kProgressiveBandRows = 512;
  static TechniqueInfo info();
  explicit VirtualTiledShadowMap(const gl::ShaderLibrary& lib);

  void renderShadows(FrameContext& ctx) override;
  ResolveMode resolveMode() const override { return ResolveMode::Deferred; }
  void resolveDeferred(const ResolveTargets& targets, const ParamSet& params) override;
  std::vector<const gl::Program*> programs() const override {
    std::vector<const gl::Program*> p = depth_.programs();
    p.insert(p.end(), {&apply_, &eyeDepth_.program()});
    return p;
  }
  MemoryStats memory() const override;
  std::optional<std::string> reloadShaders(const gl::ShaderLibrary& lib) override;

 private:
  DepthProgram depth_;
  gl::Program apply_;
  EyeDepthBuffer eyeDepth_;  ///< this frame's (the outside view's during its resolve)
  TileDepthTarget tile_;     ///< the one tile texture every tile is rendered into in turn
  DepthMapView full_;        ///< the whole virtual map (this frame's fit)
  /// The tile whose first `bandsDone_` bands tile_ holds (progressive); -1: none (a one-call
  /// resolve, e.g. the outside view's, reuses tile_).
  int bandTile_ = -1, bandsDone_ = 0;
};

}  // namespace sl
