// The GL side of a tiled virtual shadow map, shared by `virtual-tiled` (the brute force) and
// `fvsm` (Giegl & Wimmer, GI 2007): a tile's depth target, the tiles' bias parameters, the uv
// range a tile serves, and the deferred application of one tile over the screen
// (shaders/common/tiled/apply_tile.comp), each pixel's position rebuilt from the eye-space
// depth buffer (core/tiled/EyeDepthBuffer.h). The tile views themselves are core/ShadowPass's
// focusedMapView and subRectView.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/tiled/EyeDepthBuffer.h"
#include "core/ShadowPass.h"
#include "core/Technique.h"

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

/// The deferred application of one tile (shaders/common/tiled/apply_tile.comp): writes the resolve
/// targets of the pixels in screen rectangle [rectMin, rectMax) whose light uv in `full` lies in
/// [uvMin, uvMax), with the tile as map 0 of the shared bias model (its texture on
/// SL_UNIT_LOOKUP_FIRST); each pixel's position rebuilt from the eye-space depth buffer
/// (applyTile's `eyeDepth`).
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
