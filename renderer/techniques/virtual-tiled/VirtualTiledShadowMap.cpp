// Brute-force virtual tiled shadow map (VirtualTiledShadowMap.h): n x n tiles of one
// focused frustum (orthographic or LiSPSM-warped), each rendered into one reused texture and
// applied by a deferred compute pass before the next.
#include "VirtualTiledShadowMap.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <stdexcept>

#include "algo/Focus.h"
#include "common/shared_constants.h"
#include "core/LightBinding.h"

namespace sl {

TechniqueInfo VirtualTiledShadowMap::info() {
  std::vector<ParamDecl> params = {
      intParam("tiles", "Tiles per axis", "Virtual map", 16, {1, 64, 1})
          .withHelp("n: the light's focused frustum is cut into n x n tiles, each rendered and "
                    "applied in turn (16 x 16 of 4096² = a 65536² virtual map)."),
      intParam("tile.resolution", "Tile resolution", "Virtual map", 4096, {16, 8192, 16})
          .withHelp("Width and height of every tile's depth texture in texels (one texture, reused "
                    "by every tile).")
          .asMemoryKnob(),
      choiceParam("tile.warp", "Virtual map warp", "Virtual map", {"none", "lispsm"})
          .withHelp("The virtual map the n x n tiles cut: the focused light frustum, unwarped "
                    "(none, the tool's default), or warped by LiSPSM (Wimmer et al. 2004, fitted "
                    "as `lispsm` fits it), which Giegl & Wimmer's brute force uses; each tile is "
                    "the warped frustum cropped to its uv square. LiSPSM's fallback (the light "
                    "nearly along the view) keeps the unwarped map."),
  };
  appendTileBiasParams(params);
  TechniqueInfo info{"virtual-tiled", "Virtual tiled shadow map (brute force)",
                     "The brute-force baseline of fitted virtual shadow maps (Giegl & Wimmer "
                     "2007): n x n tiles of the focused light frustum (LiSPSM-warped with "
                     "tile.warp, as the paper's), every tile rendered at "
                     "the full tile resolution and applied by deferred shadowing over the "
                     "whole screen. Quality of an (n x resolution)² map, at n² times the cost.",
                     std::move(params)};
  info.passes = {
      EyeDepthBuffer::passDecl(),
      {"tile depth", "Tile depth (all tiles)",
       "For each of the n x n tiles in turn: render the scene's depth over that tile's part of "
       "the light frustum into the one tile texture. The time is the sum over the tiles "
       "(per tile: virtual_tiled.tile_ms).",
       "", true},
      {"tile apply", "Deferred shadowing (all tiles)",
       "After each tile's depth: a compute pass over the screen rebuilds each pixel's world "
       "position from the eye-space depth buffer (eq. 1), shadows the pixels whose light uv "
       "falls in that tile and writes the hard mask, visibility, aliasing m, the tile's uv and "
       "its index. The time is the sum over the tiles (per tile: virtual_tiled.tile_ms).",
       "", true},
  };
  info.tileTiming = TechniqueInfo::TileTiming{"virtual_tiled.tile_ms", "tile depth", "tile apply"};
  info.publications = {
      {"virtual_tiled.tile_ms", PublicationKind::Curve,
       "per tile applied this frame, in order (row by row of the tile grid): its depth ms and "
       "its apply ms, 2 floats (the scopes the passes tile depth / tile apply sum; in a "
       "progressive call only that call's tiles and bands)",
       "0 B (the timer's own)", [](const ParamSet&) { return std::uint64_t(0); }},
  };
  info.lights = {LightType::Directional};
  return info;
}

VirtualTiledShadowMap::VirtualTiledShadowMap(const gl::ShaderLibrary& lib)
    : depth_(lib), apply_(lib, applyTileProgramDesc()), eyeDepth_(lib) {}

void VirtualTiledShadowMap::renderShadows(FrameContext& ctx) {
  {
    auto pass = ctx.timer.scope("eye depth");
    eyeDepth_.update(ctx.gbuffer.position, ctx.width, ctx.height, ctx.cameraView, ctx.cameraProj);
  }
  LightFit fit;
  if (auto err = fitDirectionalLight(ctx.camera, ctx.aspect, ctx.scene.bounds,
                                     ctx.light.directionalTowards(), FocusSettings{}, fit)) {
    throw std::runtime_error(*err);
  }
  full_ = focusedMapView(ctx, fit, ctx.params.getInt("tile.warp") == 1);
  ctx.addOutline(full_.lightViewProj, OutlineRole::LightMap);
}

void VirtualTiledShadowMap::resolveDeferred(const ResolveTargets& t, const ParamSet& params) {
  if (!t.sceneGpu) throw std::logic_error("virtual-tiled: the resolve has no scene");
  eyeDepth_.updateForResolve(t);
  const int n = params.getInt("tiles");
  const int res = params.getInt("tile.resolution");
  tile_.ensure(glm::ivec2(res), "virtual-tiled tile");
  ResolveProgress* progress = t.progress;
  // Progressive (the GUI's continuous rendering): units from `next` on, at least one, then as
  // long as the next unit (estimated as long as the last) fits in the budget. A unit is one band
  // of a tile's depth rows; after its last band the tile is applied. Every pixel is written by
  // exactly one tile and a band writes only its own texels, so the result once all are done
  // does not depend on how the units were spread over calls. One call: a band per tile.
  const int bands = progress ? std::max(1, res / kProgressiveBandRows) : 1;
  const int total = n * n * bands;
  int first = 0;
  if (progress && progress->resume) first = std::clamp(progress->next, 0, total);
  if (first >= total) first = 0;
  // Mid-tile, the earlier bands must still be in tile_ (a one-call resolve in between, the
  // outside view's, rendered other tiles into it): else that tile starts again at band 0, and
  // this call finishes it whatever the budget (so that it cannot restart forever).
  int mustReach = first + 1;
  if (first % bands != 0 && (bandTile_ != first / bands || bandsDone_ != first % bands)) {
    first -= first % bands;
    mustReach = first + bands;
  }
  if (!progress || !progress->resume) clearResolveTargets(t);
  const auto start = std::chrono::steady_clock::now();
  const glm::vec2 texelsPerUv(float(n) * float(res));
  int u = first;
  double doneMs = 0.0;  // wall time when the previous unit was done
  while (u < total) {
    const int k = u / bands, band = u % bands;
    const int i = k % n, j = k / n;
    const glm::dvec2 lo(double(i) / n, double(j) / n);
    const glm::dvec2 hi(double(i + 1) / n, double(j + 1) / n);
    const DepthMapView view = subRectView(full_, lo, hi);
    if (t.timer) t.timer->begin("tile depth");
    if (bands > 1) {
      const int y0 = res * band / bands, y1 = res * (band + 1) / bands;
      glEnable(GL_SCISSOR_TEST);  // the clear and the draw: rows [y0, y1) only
      glScissor(0, y0, res, y1 - y0);
    }
    renderDepth(*t.sceneGpu, depth_, tile_.fbo.id(), res, res, view.lightViewProj);
    if (bands > 1) glDisable(GL_SCISSOR_TEST);
    bandTile_ = progress ? k : -1;
    bandsDone_ = band + 1;
    if (band == bands - 1) {
      if (t.timer) t.timer->begin("tile apply");
      glm::dvec2 applyLo, applyHi;
      tileApplyRange(lo, hi, applyLo, applyHi);
      applyTile(apply_, t, eyeDepth_,
                {full_, view, tile_.texture, glm::ivec2(res), applyLo, applyHi, texelsPerUv,
                 glm::ivec2(0), glm::ivec2(t.width, t.height), unsigned(k) & 255u});
    }
    ++u;
    // The host stopped the frame (Renderer::setCancelFlag): `next` says where to go on.
    if (u < total && t.cancelRequested()) break;
    if (progress) {
      glFinish();  // the unit's real cost, so that the budget bounds the call's wall time
      const double ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
              .count();
      const double unitMs = ms - doneMs;
      doneMs = ms;
      // Stop before a unit that would pass the budget (estimated as long as this one).
      if (u >= mustReach && ms + unitMs > progress->budgetMs) break;
    }
  }
  if (progress) {
    progress->next = u;
    progress->total = total;
    progress->unitsPerTile = bands;
    progress->spentMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }
  endTiles(t);
}

MemoryStats VirtualTiledShadowMap::memory() const {
  MemoryStats m;
  tile_.addMemory(m, "tile");
  eyeDepth_.addMemory(m);
  return m;
}

std::optional<std::string> VirtualTiledShadowMap::reloadShaders(const gl::ShaderLibrary& lib) {
  if (auto e = depth_.rebuild(lib)) return e;
  if (auto e = eyeDepth_.reloadShaders(lib)) return e;
  return apply_.rebuild(lib);
}

}  // namespace sl
