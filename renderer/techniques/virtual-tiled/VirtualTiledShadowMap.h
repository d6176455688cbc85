// Brute-force virtual tiled shadow map (Giegl & Wimmer, GI 2007, §3.2; docs/techniques.md §6):
// the light's focused frustum (orthographic, or LiSPSM-warped with tile.warp as the paper's)
// cut into n x n tiles, each rendered at
// tile.resolution (16 x 16 x 4096² = a 65536² virtual map) into ONE reused depth texture and
// applied at once by deferred shadowing: a compute pass over the screen rebuilds each pixel's
// world position from the eye-space depth buffer (eq. 1, EyeDepthBuffer.h) and shadows the
// pixels whose light uv falls in that tile. The baseline fitted virtual shadow maps are
// measured against.
#pragma once

#include "core/ShadowPass.h"
#include "core/Technique.h"
#include "techniques/virtual-tiled/EyeDepthBuffer.h"

namespace sl {

/// A tile's depth texture and its framebuffer (DEPTH_COMPONENT32F).
struct TileDepthTarget {
  gl::Texture texture;
  gl::Framebuffer fbo;
  /// (Re)allocates when the size differs; `label` names it in framebuffer errors.
  void ensure(glm::ivec2 size, const std::string& label);
  /// Its line of Technique::memory() (nothing when not allocated).
  void addMemory(MemoryStats& m, const std::string& name) const;
};

/// The shared bias and PCF parameters of the tiled maps: shadowMapParamDecls without its one
/// `resolution` (the tiles have their own), appended to `params`.
void appendTileBiasParams(std::vector<ParamDecl>& params);

/// The light uv range a tile applies to: its rectangle [uvMin, uvMax), with the sides on the
/// full map's border (0 or 1) pushed out to infinity — the border tiles also serve what lies
/// beyond the fit (their texture clamps there).
void tileApplyRange(glm::dvec2 uvMin, glm::dvec2 uvMax, glm::dvec2& applyMin, glm::dvec2& applyMax);

/// After the tiles of a deferred resolve: reopens the renderer's "resolve" scope (closed by the
/// tiles' own) and restores the resolve's framebuffer, viewport and depth state.
void endTiles(const ResolveTargets& targets);

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

/// The deferred application of one tile (shaders/virtual-tiled/apply_tile.comp), shared by
/// the virtual tiled map and fvsm: writes the resolve targets of the pixels in screen
/// rectangle [rectMin, rectMax) whose light uv in `full` lies in [uvMin, uvMax), with the
/// tile as map 0 of the shared bias model (its texture on SL_UNIT_LOOKUP_FIRST); each
/// pixel's position rebuilt from the eye-space depth buffer (applyTile's `eyeDepth`).
struct TileApply {
  const DepthMapView& full;
  const DepthMapView& tile;
  const gl::Texture& texture;
  glm::ivec2 texels;            ///< the tile's texels: a sub-rectangle of `texture` at its origin
  glm::dvec2 uvMin, uvMax;      ///< the part of `full` this tile serves
  glm::vec2 texelsPerFullUv;    ///< the tile's texels per unit of full-map uv (aliasing m)
  glm::ivec2 rectMin, rectMax;  ///< screen pixels the pass covers
  unsigned mapIndex = 0;        ///< written to the map-index target
  bool onlyEmpty = false;       ///< only pixels no tile has written yet (hard still empty)
  /// A receiver whose normal offset leaves the tile compares with its edge texel; false: it
  /// is lit (tile_lookup.glsl), the seams an overlap removes.
  bool clampToTile = true;
};
void applyTile(const gl::Program& apply, const ResolveTargets& targets,
               const EyeDepthBuffer& eyeDepth, const TileApply& tile);
/// Before the tiles: every pixel empty (hard SL_MASK_EMPTY, visibility 1, m 0, uv 0).
void clearResolveTargets(const ResolveTargets& targets);
/// The apply program (shared by the tiled techniques).
gl::ProgramDesc applyTileProgramDesc();

}  // namespace sl
