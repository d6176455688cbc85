// Brute-force virtual tiled shadow map (Giegl & Wimmer, GI 2007, §3.2; docs/techniques.md §6):
// the light's focused orthographic frustum cut into n x n tiles, each rendered at
// tile.resolution (16 x 16 x 4096² = a 65536² virtual map) into ONE reused depth texture and
// applied at once by deferred shadowing: a compute pass over the screen shadows the pixels
// whose light uv falls in that tile. The baseline fitted virtual shadow maps are measured
// against.
#pragma once

#include "core/ShadowPass.h"
#include "core/Technique.h"

namespace sl {

class VirtualTiledShadowMap : public Technique {
 public:
  static TechniqueInfo info();
  explicit VirtualTiledShadowMap(const gl::ShaderLibrary& lib);

  void renderShadows(FrameContext& ctx) override;
  ResolveMode resolveMode() const override { return ResolveMode::Deferred; }
  void resolveDeferred(const ResolveTargets& targets, const ParamSet& params) override;
  std::vector<const gl::Program*> programs() const override { return {&depth_, &apply_}; }
  MemoryStats memory() const override;
  std::optional<std::string> reloadShaders(const gl::ShaderLibrary& lib) override;

 private:
  void ensureTile(int resolution);

  gl::Program depth_;
  gl::Program apply_;
  gl::Texture tile_;  ///< the one tile texture every tile is rendered into in turn
  gl::Framebuffer fbo_;
  DepthMapView full_;  ///< the whole virtual map (this frame's fit)
};

/// The deferred application of one tile (shaders/virtual-tiled/apply_tile.comp), shared by
/// the virtual tiled map and fvsm: writes the resolve targets of the pixels in screen
/// rectangle [rectMin, rectMax) whose light uv in `full` lies in [uvMin, uvMax), with the
/// tile as map 0 of the shared bias model (its texture on SL_UNIT_LOOKUP_FIRST).
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
};
void applyTile(const gl::Program& apply, const ResolveTargets& targets, const TileApply& tile);
/// Before the tiles: every pixel empty (hard SL_MASK_EMPTY, visibility 1, m 0, uv 0).
void clearResolveTargets(const ResolveTargets& targets);
/// The apply program (shared by the tiled techniques).
gl::ProgramDesc applyTileProgramDesc();

}  // namespace sl
