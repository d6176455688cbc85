// Fitted virtual shadow maps (FittedVirtualShadowMap.h).
#include "FittedVirtualShadowMap.h"

#include <cmath>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "algo/Focus.h"
#include "common/shared_constants.h"
#include "core/LightBinding.h"
#include "core/Publish.h"
#include "core/SceneGpu.h"
#include "core/tiled/TiledVirtualMap.h"

namespace sl {

namespace {

constexpr int kMinTextureLog2 = 4;  ///< the smallest tile side: 16 texels
/// The FVSM panel's thumbnails (fvsm.camera, fvsm.light.depth): this many texels per axis.
constexpr int kThumbnail = SL_FVSM_THUMBNAIL;

int log2Of(int v) {
  int l = 0;
  while ((1 << l) < v) ++l;
  return l;
}

fvsm::TextureMode textureMode(const ParamSet& p) {
  return fvsm::TextureMode(p.getInt("fvsm.texture.mode"));
}

fvsm::EntryFormat entryFormat(const ParamSet& p) {
  return fvsm::EntryFormat(p.getInt("fvsm.smtmm.entry"));
}

/// What renderShadows needs of the values together (TechniqueInfo::checkParams).
std::optional<std::string> checkFvsmParams(const ParamSet& p) {
  if (auto e = checkPowerOfTwo(p, "fvsm.grid")) return e;
  if (auto e = checkPowerOfTwo(p, "fvsm.max_texture")) return e;
  const int eta0 = p.getInt("fvsm.eta0"), eta1 = p.getInt("fvsm.eta1");
  if (eta0 >= eta1)
    return "fvsm.eta0 = " + std::to_string(eta0) +
           " must be below fvsm.eta1 = " + std::to_string(eta1) +
           " (the histogram's lower and upper end buckets)";
  return std::nullopt;
}

}  // namespace

TechniqueInfo FittedVirtualShadowMap::info() {
  std::vector<ParamDecl> params = {
      intParam("fvsm.xi", "Quality ξ", "FVSM", -3, {fvsm::kMinXi, 12, 1})
          .withHelp(
              "ξ: subtracted from every log2 resolution need before the traversal (Giegl & Wimmer "
              "§4.9): each step halves the texels per axis everywhere. Large ξ: one ordinary "
              "shadow map. The paper uses 0 … 5 (0: the sub-pixel need, 5 about one ordinary map "
              "in its scene); the default −3 is the tool's: 8 times the texels per axis of the "
              "paper's 0 (with the 32 x 32 grid, about the 16 x 16 x 4096² brute force's wrong "
              "pixels on diagonal and fewer on corridor: docs/techniques/fvsm.md)."),
      choiceParam("fvsm.texture.mode", "Tile textures", "FVSM",
                  {"sub-rectangle", "power-of-two", "exact"}, 1)
          .withHelp("Where a tile is rendered (§4.10): a sub-rectangle of one max-size texture "
                    "(t_max²), of the smallest square of a power-of-two series (< 4/3 t_max², the "
                    "paper's recommendation and the default), or a texture of exactly its size "
                    "(the paper sums 2 · 4/3 t_max² for these, counting per level the square and "
                    "the two half-size rectangles only; the tool allocates each w x h the frame "
                    "uses, up to (2 t_max − 16)²)."),
      intParam("fvsm.overlap", "Tile overlap", "FVSM", 1, {0, 4, 1})
          .withHelp(
              "A border of this many texels around each tile (§5): its texture covers the kd cell "
              "grown by that many of its own texels on every side, so receivers near a tile edge "
              "find the neighbour's depth (0 shows the seams). The border adds texels (2^t + 2 x "
              "overlap per side); the cell keeps its 2^t, on the same lattice."),
      intParam("fvsm.grid", "Tile grid n", "FVSM", 32, {1, 64, 1})
          .withHelp(
              "n x n tile grid the SMTMM is accumulated into (a power of two; the paper: 16 or "
              "32): the finest kd-tree level. A cell at the finest level holds at most the max "
              "texture: 32 x 4096 (default) lets the neediest cells go finer than the 16 x 16 x "
              "4096² brute force, and fits coarser cells more tightly (docs/techniques/fvsm.md)."),
      intParam("fvsm.max_texture", "Max tile texture", "FVSM", 4096, {16, 8192, 16})
          .withHelp("t_max (a power of two): a kd node needing more texels along an axis is split "
                    "along it."),
      intParam("fvsm.smtmm.divisor", "SMTMM divisor", "FVSM", 4, {1, 16, 1})
          .withHelp("The SMTMM has frame / divisor entries per axis (the paper: 256² for a 1024² "
                    "frame), each sampling the pixel at the centre of its block."),
      choiceParam("fvsm.smtmm.entry", "SMTMM entry", "FVSM", {"16-byte", "4-byte"},
                  SL_FVSM_ENTRY_16_BYTE)
          .withHelp("How an SMTMM entry is stored and read back: four floats (16-byte, the tool's "
                    "default), or the paper's 4 bytes (4-byte): the SM position as the column and "
                    "row of 256 holding it, and the two needs. It loses where inside its 1/256 "
                    "column a pixel looks, which changes no grid cell (n ≤ 256) and so no tile; "
                    "the SMTMM and its read-back are a quarter of the bytes."),
      intParam("fvsm.eta0", "Histogram η0", "FVSM", 17, {0, SL_FVSM_MAX_NEED_LOG2 - 1, 1})
          .withHelp("Lower end bucket of each tile's need histogram (log2): needs up to η0 are "
                    "never discarded as outliers (the paper: 17)."),
      intParam("fvsm.eta1", "Histogram η1", "FVSM", 22, {1, SL_FVSM_MAX_NEED_LOG2, 1})
          .withHelp(
              "Upper end bucket (log2): needs from η1 up are counted together (the paper: 22)."),
      intParam("fvsm.outliers", "Outlier entries", "FVSM", 0, {0, 4096, 1})
          .withHelp("Per tile, at most this many SMTMM entries needing more than η0 are discarded "
                    "(highest needs first, whole buckets); 0 (the default) keeps the plain "
                    "maximum. The paper discards \"a very few\" outlier pixels per cell with this "
                    "histogram (§4.4) without saying how many; the default turns that off."),
      switchParam("fvsm.screen_rect", "Apply in screen rectangles", "FVSM", true)
          .withHelp("Apply each tile only inside the screen rectangle of its SMTMM entries (one "
                    "entry block of margin); off: over the whole screen."),
      choiceParam("fvsm.need.footprint", "Need from footprint", "FVSM", {"box", "chord"},
                  SL_FVSM_FOOTPRINT_CHORD)
          .withUniform("u_footprint")
          .withHelp("How a pixel's footprint in the light's map becomes a need per SM axis: the "
                    "half sides of its axis-aligned bounding box (box: the paper's, §4.3), or the "
                    "half length of its chord through the pixel along each axis (chord, the tool's "
                    "default; equal for footprints along an axis, much shorter for thin footprints "
                    "along a diagonal of the map, which the box undersamples). Both keep the sign "
                    "of the depth step the footprint is built from."),
      choiceParam("fvsm.warp", "Virtual map warp", "FVSM", {"none", "lispsm"})
          .withHelp("The virtual map the tiles cut: the focused light frustum, unwarped (none, the "
                    "tool's default), or warped by LiSPSM (Wimmer et al. 2004; n' = n + sqrt(f n), "
                    "fitted around view frustum ∩ scene as `lispsm` fits it), which every result "
                    "of Giegl & Wimmer uses. Each tile is the warped frustum cropped to its uv "
                    "rectangle; the SMTMM's positions and needs are in the warped map. When LiSPSM "
                    "falls back (the light nearly along the view), the map is the unwarped one."),
      choiceParam("fvsm.apply", "Apply tiles by", "FVSM", {"deferred", "multi-pass"})
          .withHelp("How each kd leaf shadows the scene (Giegl & Wimmer §3): deferred shadowing, a "
                    "compute pass rebuilding each pixel's position from the eye-space depth buffer "
                    "(deferred, the default and what the paper's results use), or multi-pass "
                    "shadowing (§3.1): the scene rasterised again per leaf inside its screen "
                    "rectangle, depth test EQUAL, only the leaf's own fragments written. The "
                    "tool's first pass is a depth-only pre-pass, where the paper's also shades."),
      intParam("fvsm.fallback.resolution", "Fallback map", "FVSM", 1024, {16, 8192, 16})
          .withHelp(
              "Pixels no tile reached (the SMTMM samples one pixel per block) are shadowed with "
              "one map of this size over the whole fit (the tool's; the paper has none)."),
  };
  appendTileBiasParams(params);
  TechniqueInfo info{
      "fvsm", "Fitted virtual shadow maps",
      "Giegl & Wimmer 2007: a low-resolution SMTMM says where in the light's map each pixel "
      "looks and how many texels it needs per axis; on the CPU, a tile grid with outlier "
      "rejection, its max pyramid and a kd-tree traversal choose tiles that each fit the "
      "max texture size; each is rendered at its need and applied only inside its screen "
      "rectangle. The virtual map is the focused light frustum, unwarped by default or warped "
      "by LiSPSM (fvsm.warp), as in all the paper's results.",
      std::move(params)};
  info.passes = {
      EyeDepthBuffer::passDecl(),
      {"smtmm", "SMTMM",
       "Step 2 (§4.3). One entry per block of pixels: where the pixel looks in the light's "
       "map, and the log2 resolution the whole map needs there along each axis (from its "
       "footprint built from neighbour depths in the eye-space depth buffer, eq. 1); read "
       "back to the CPU.",
       "fvsm"},
      {"fvsm grid", "Tile grid (CPU)",
       "Step 3 (§4.4). The read-back SMTMM accumulated into an n x n grid over the light's "
       "map: per cell the max need per axis, the screen rectangle of its entries, and a "
       "histogram of needs with end buckets η0, η1 (a few outlier entries may be dropped).",
       "fvsm"},
      {"fvsm pyramid", "Max pyramid (CPU)",
       "Step 4 (§4.5). A max pyramid over the grid: each coarser cell holds the largest need "
       "(per axis) and the union of the screen rectangles of the four below it.",
       "fvsm"},
      {"fvsm kd-tree", "kd-tree traversal (CPU)",
       "Step 5 (§4.6). Top-down over the pyramid: a node is split along an axis while its "
       "need (less ξ) exceeds the max texture size; each leaf gets the texture its need asks "
       "for (allocated here when new).",
       "fvsm"},
      {"tile depth", "Tile depth (all tiles)",
       "Each kd leaf's part of the light frustum rendered at the resolution it needs (with the "
       "overlap) into its texture. The time is the sum over the tiles (per tile: "
       "fvsm.tile_ms).",
       "", true},
      {"tile apply", "Deferred shadowing (all tiles)",
       "Each leaf applied to the pixels of its screen rectangle whose light uv falls in it, "
       "their world positions rebuilt from the eye-space depth buffer (eq. 1), or with "
       "fvsm.apply = multi-pass the scene rasterised again (§3.1). The time is "
       "the sum over the tiles (per tile: fvsm.tile_ms).",
       "", true},
      {"fallback", "Fallback map", "Pixels no leaf reached: one map over the whole fit.", "", true},
  };
  const auto number = [](const char* key, const char* what) {
    return PublicationDecl{key, PublicationKind::Number, what, "", nullptr};
  };
  info.publications = {
      {"fvsm.smtmm", PublicationKind::Image,
       "the SMTMM, 4 channels per entry: SM u, SM v, log2 need along u, along v (−1: no "
       "surface); row 0 at the bottom (with the 4-byte entry, u and v are the centres of "
       "their 1/256 columns)",
       "0 B (read back for the grid anyway)", [](const ParamSet&) { return std::uint64_t(0); }},
      number("fvsm.tiles", "kd-tree leaves rendered this frame"),
      number("fvsm.warped",
             "1 when the virtual map is LiSPSM-warped this frame (fvsm.warp = "
             "lispsm and no fallback), else 0"),
      number("fvsm.tiles.unmet", "leaves whose need exceeded the max texture at the finest level"),
      number("fvsm.need_log2.u", "log2 texels the whole map needs along u (after ξ, outliers)"),
      number("fvsm.need_log2.v", "log2 texels the whole map needs along v (after ξ, outliers)"),
      number("fvsm.texels", "texels of all tiles rendered this frame (their borders included)"),
      number("fvsm.histogram.eta0", "the histograms' lower end bucket η0 (log2)"),
      number("fvsm.histogram.eta1", "the histograms' upper end bucket η1 (log2)"),
      {"fvsm.grid", PublicationKind::Image,
       "the tile grid, n x n cells of 5 channels: need u, v after outlier rejection (−1 "
       "empty), SMTMM entries, plain max need u, v (algo/fvsm gridChannels); row 0 at v = 0",
       "0 B (the CPU's grid)", [](const ParamSet&) { return std::uint64_t(0); }},
      {"fvsm.grid.histogram", PublicationKind::Image,
       "each grid cell's need histogram, 2 (η1 − η0 + 1) channels: the buckets along u, then "
       "along v (algo/fvsm gridHistogramChannels)",
       "0 B (the CPU's grid)", [](const ParamSet&) { return std::uint64_t(0); }},
      {"fvsm.camera", PublicationKind::Image,
       "the camera's image for the panel's screen rectangles: the frame scaled into " +
           std::to_string(kThumbnail) +
           "² with its aspect kept, from the bottom-left (−2 "
           "beyond the frame); unshadowed N.L grey, −1 without a surface",
       "4 B x " + std::to_string(kThumbnail) + "²",
       [](const ParamSet&) { return std::uint64_t(4) * kThumbnail * kThumbnail; }},
      {"fvsm.light.depth", PublicationKind::Image,
       "the light's view for the panel's kd leaves: the whole fit's depth (0..1) at " +
           std::to_string(kThumbnail) + "²; row 0 at v = 0",
       "4 B x " + std::to_string(kThumbnail) + "²",
       [](const ParamSet&) { return std::uint64_t(4) * kThumbnail * kThumbnail; }},
      {"fvsm.tiles.list", PublicationKind::Curve,
       "the kd leaves, 17 floats each (algo/fvsm packTileRecords): level, index, need, texture "
       "log2, texture and viewport size, screen rectangle in SMTMM entries, unmet",
       "0 B (the CPU's kd-tree)", [](const ParamSet&) { return std::uint64_t(0); }},
      {"fvsm.tile_ms", PublicationKind::Curve,
       "per kd leaf, in the order of fvsm.tiles.list: its depth ms and its apply ms, 2 floats "
       "(the scopes the passes tile depth / tile apply sum; the fallback map not included)",
       "0 B (the timer's own)", [](const ParamSet&) { return std::uint64_t(0); }},
  };
  info.tileTiming = TechniqueInfo::TileTiming{"fvsm.tile_ms", "tile depth", "tile apply"};
  info.lights = {LightType::Directional};
  info.checkParams = checkFvsmParams;
  return info;
}

FittedVirtualShadowMap::FittedVirtualShadowMap(const gl::ShaderLibrary& lib)
    : depth_(lib),
      apply_(lib, applyTileProgramDesc()),
      smtmm_(lib, {"fvsm/smtmm", {{GL_COMPUTE_SHADER, "fvsm/smtmm.comp"}}, {}, {}}),
      smtmmPacked_(lib, {"fvsm/smtmm (4-byte entry)",
                         {{GL_COMPUTE_SHADER, "fvsm/smtmm.comp"}},
                         {},
                         {"SL_FVSM_PACKED_ENTRY"}}),
      cameraThumb_(
          lib,
          {"fvsm/camera_thumbnail", {{GL_COMPUTE_SHADER, "fvsm/camera_thumbnail.comp"}}, {}, {}}),
      multiPass_(lib, {"fvsm/multipass",
                       {{GL_VERTEX_SHADER, "common/gbuffer.vert"},
                        {GL_FRAGMENT_SHADER, "fvsm/multipass.frag"}},
                       {},
                       {}}),
      eyeDepth_(lib) {}

void FittedVirtualShadowMap::renderShadows(FrameContext& ctx) {
  const ParamSet& p = ctx.params;
  const int n = p.getInt("fvsm.grid"), tmax = p.getInt("fvsm.max_texture");
  if (auto e = checkFvsmParams(p)) throw std::runtime_error(*e);  // renderFrame checked it
  fvsm::HistogramSettings histogram{p.getInt("fvsm.eta0"), p.getInt("fvsm.eta1"),
                                    p.getInt("fvsm.outliers")};
  fvsm::TraversalSettings traversal{log2Of(tmax), std::min(kMinTextureLog2, log2Of(tmax)),
                                    p.getInt("fvsm.xi")};
  try {
    histogram.validate();
    traversal.validate();
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(e.what());
  }

  {  // 1. The eye-space depth buffer.
    auto pass = ctx.timer.scope("eye depth");
    eyeDepth_.update(ctx.gbuffer.position, ctx.width, ctx.height, ctx.cameraView, ctx.cameraProj);
  }
  const fvsm::EntryFormat format = entryFormat(p);
  const bool packed = format == fvsm::EntryFormat::Packed4Byte;
  std::vector<glm::vec4> raw;            // 16-byte entries
  std::vector<std::uint32_t> rawPacked;  // 4-byte entries
  {                                      // 2. The SMTMM, read back.
    auto pass = ctx.timer.scope("smtmm");
    LightFit fit;
    if (auto err = fitDirectionalLight(ctx.camera, ctx.aspect, ctx.scene.bounds,
                                       ctx.light.directionalTowards(), FocusSettings{}, fit)) {
      throw std::runtime_error(*err);
    }
    full_ = focusedMapView(ctx, fit, p.getInt("fvsm.warp") == 1);
    publishNumber(ctx, "fvsm.warped", full_.perspective ? 1.0 : 0.0);
    ctx.addOutline(full_.lightViewProj, OutlineRole::LightMap);
    const int divisor = p.getInt("fvsm.smtmm.divisor");
    frameSize_ = {ctx.width, ctx.height};
    smtmmSize_ = (frameSize_ + divisor - 1) / divisor;
    const GLenum texFormat = packed ? GL_R32UI : GL_RGBA32F;
    if (!smtmmTexture_ || smtmmTexture_.width() != smtmmSize_.x ||
        smtmmTexture_.height() != smtmmSize_.y || smtmmTexture_.format() != texFormat) {
      smtmmTexture_ = gl::Texture::create2D(texFormat, smtmmSize_.x, smtmmSize_.y);
    }
    glm::mat4 uvFromClip(1.0f);
    uvFromClip[0][0] = uvFromClip[1][1] = 0.5f;
    uvFromClip[3][0] = uvFromClip[3][1] = 0.5f;
    gl::Program& program = packed ? smtmmPacked_ : smtmm_;
    program.use();
    program.set("u_frameSize", frameSize_);
    program.set("u_smtmmSize", smtmmSize_);
    program.set("u_eyeToSmUv", uvFromClip * full_.lightViewProj * glm::inverse(ctx.cameraView));
    eyeDepth_.bind(program);
    glBindImageTexture(SL_IMAGE_FVSM_SMTMM, smtmmTexture_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                       texFormat);
    glDispatchCompute(GLuint((smtmmSize_.x + 7) / 8), GLuint((smtmmSize_.y + 7) / 8), 1);
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    const std::size_t count = std::size_t(smtmmSize_.x) * std::size_t(smtmmSize_.y);
    if (packed) {
      rawPacked.resize(count);
      glGetTextureImage(smtmmTexture_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT,
                        GLsizei(count * sizeof(std::uint32_t)), rawPacked.data());
    } else {
      raw.resize(count);
      glGetTextureImage(smtmmTexture_.id(), 0, GL_RGBA, GL_FLOAT,
                        GLsizei(count * sizeof(glm::vec4)), raw.data());
    }
  }
  if (ctx.wants("fvsm.camera")) {  // the panel's camera image
    if (!cameraTexture_) cameraTexture_ = gl::Texture::create2D(GL_R32F, kThumbnail, kThumbnail);
    const glm::ivec2 used = fvsm::thumbnailUsedSize(frameSize_, kThumbnail);
    cameraThumb_.use();
    cameraThumb_.set("u_frameSize", frameSize_);
    cameraThumb_.set("u_used", used);
    cameraThumb_.set("u_towardsLight", ctx.light.directionalTowards());
    glBindTextureUnit(SL_UNIT_G_POSITION, ctx.gbuffer.position.id());
    glBindTextureUnit(SL_UNIT_G_NORMAL, ctx.gbuffer.normal.id());
    glBindImageTexture(SL_IMAGE_FVSM_CAMERA, cameraTexture_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                       GL_R32F);
    glDispatchCompute(GLuint((kThumbnail + 7) / 8), GLuint((kThumbnail + 7) / 8), 1);
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
    publishRed(ctx, "fvsm.camera", cameraTexture_);
  }
  if (ctx.wants("fvsm.light.depth")) {  // the panel's light view: the whole fit, small
    lightThumb_.ensure(glm::ivec2(kThumbnail), "fvsm light-view thumbnail");
    renderDepth(ctx, depth_, lightThumb_.fbo.id(), kThumbnail, kThumbnail, full_.lightViewProj);
    publishDepth(ctx, "fvsm.light.depth", lightThumb_.texture);
  }
  fvsm::TileGrid grid;
  std::vector<fvsm::SmtmmEntry> entries(std::max(raw.size(), rawPacked.size()));
  {  // 3. The tile grid with its histograms (CPU).
    auto pass = ctx.timer.scope("fvsm grid");
    for (std::size_t i = 0; i < raw.size(); ++i) {
      if (raw[i].z < 0.0f) continue;
      entries[i] = {true, glm::dvec2(raw[i].x, raw[i].y), glm::ivec2(raw[i].z, raw[i].w)};
    }
    for (std::size_t i = 0; i < rawPacked.size(); ++i)
      entries[i] = fvsm::unpackSmtmmEntry(rawPacked[i]);
    grid = fvsm::accumulateGrid(entries, smtmmSize_, n, histogram);
    const auto publishCells = [&](const char* key, int channels, std::vector<float> values) {
      if (ctx.wants(key))
        ctx.publication->images[key] = FloatImage{n, n, channels, std::move(values)};
    };
    if (ctx.wants("fvsm.grid"))
      publishCells("fvsm.grid", fvsm::kGridChannels, fvsm::gridChannels(grid));
    if (ctx.wants("fvsm.grid.histogram"))
      publishCells("fvsm.grid.histogram", 2 * histogram.bucketCount(),
                   fvsm::gridHistogramChannels(grid, histogram));
    publishNumber(ctx, "fvsm.histogram.eta0", double(histogram.eta0));
    publishNumber(ctx, "fvsm.histogram.eta1", double(histogram.eta1));
  }
  if (ctx.wants("fvsm.smtmm")) {  // read back anyway: publishing it costs no readback
    FloatImage img{smtmmSize_.x, smtmmSize_.y, 4, {}};
    img.values.reserve(entries.size() * 4);
    for (const fvsm::SmtmmEntry& e : entries) {
      if (!e.covered) {
        img.values.insert(img.values.end(), {0.0f, 0.0f, -1.0f, -1.0f});
        continue;
      }
      img.values.insert(img.values.end(), {float(e.smUv.x), float(e.smUv.y), float(e.needLog2.x),
                                           float(e.needLog2.y)});
    }
    ctx.publication->images["fvsm.smtmm"] = std::move(img);
  }
  fvsm::Pyramid pyramid;
  {  // 4. The max pyramid (CPU).
    auto pass = ctx.timer.scope("fvsm pyramid");
    pyramid = fvsm::buildPyramid(grid);
  }
  {  // 5. The kd-tree traversal (CPU), and the textures its leaves need.
    auto pass = ctx.timer.scope("fvsm kd-tree");
    tiles_ = fvsm::traverse(pyramid, traversal);
    if (ctx.wants("fvsm.tiles.list"))
      publishValues(ctx, "fvsm.tiles.list",
                    fvsm::packTileRecords(tiles_, textureMode(p), traversal.maxTextureLog2,
                                          p.getInt("fvsm.overlap")));
    fallbackResolution_ = p.getInt("fvsm.fallback.resolution");
    // Allocate every texture this frame's tiles use now, so memory() holds them all.
    const fvsm::TextureMode mode = textureMode(p);
    std::uint64_t texels = 0;
    int unmet = 0;
    for (const fvsm::Tile& t : tiles_) {
      const fvsm::TileTexture tex = fvsm::tileTexture(mode, t.textureLog2, traversal.maxTextureLog2,
                                                      p.getInt("fvsm.overlap"));
      depthTarget(tex.size);
      texels += std::uint64_t(tex.viewport.x) * std::uint64_t(tex.viewport.y);
      unmet += t.unmet ? 1 : 0;
    }
    depthTarget(glm::ivec2(fallbackResolution_));
    const glm::ivec2 root = pyramid.at(0, 0, 0).needLog2;
    publishNumber(ctx, "fvsm.tiles", double(tiles_.size()));
    publishNumber(ctx, "fvsm.tiles.unmet", double(unmet));
    publishNumber(ctx, "fvsm.need_log2.u", double(std::max(root.x - traversal.xi, -1)));
    publishNumber(ctx, "fvsm.need_log2.v", double(std::max(root.y - traversal.xi, -1)));
    publishNumber(ctx, "fvsm.texels", double(texels));
  }
}

TileDepthTarget& FittedVirtualShadowMap::depthTarget(glm::ivec2 size) {
  TileDepthTarget& d = targets_[{size.x, size.y}];
  d.ensure(size, "fvsm tile " + std::to_string(size.x) + "x" + std::to_string(size.y));
  return d;
}

void FittedVirtualShadowMap::resolveDeferred(const ResolveTargets& t, const ParamSet& params) {
  if (!t.sceneGpu) throw std::logic_error("fvsm: the resolve has no scene");
  eyeDepth_.updateForResolve(t);
  const fvsm::TextureMode mode = textureMode(params);
  const int maxLog2 = log2Of(params.getInt("fvsm.max_texture"));
  const int overlap = params.getInt("fvsm.overlap");
  const bool rects = params.getBool("fvsm.screen_rect") && t.mainCamera &&
                     frameSize_ == glm::ivec2(t.width, t.height);
  clearResolveTargets(t);
  const bool multiPass = params.getInt("fvsm.apply") == 1;
  gl::Framebuffer passes;  // multi-pass: the resolve targets and the pre-pass's depth
  const glm::mat4 viewProj = t.cameraProj * t.cameraView;
  const glm::vec3 eye = glm::vec3(glm::inverse(t.cameraView)[3]);
  if (multiPass) {
    if (t.timer) t.timer->begin("tile apply");
    if (!passDepth_ || passDepth_.width() != t.width || passDepth_.height() != t.height)
      passDepth_ = gl::Texture::create2D(GL_DEPTH_COMPONENT32F, t.width, t.height);
    passes = gl::Framebuffer::create();
    const gl::Texture* targets[5] = {&t.outputs.hard, &t.outputs.filtered, &t.outputs.aliasing,
                                     &t.outputs.texel, &t.outputs.mapIndex};
    for (int i = 0; i < 5; ++i) passes.attach(GLenum(GL_COLOR_ATTACHMENT0 + i), *targets[i]);
    passes.attach(GL_DEPTH_ATTACHMENT, passDepth_);
    passes.setDrawBuffers(5);
    passes.checkComplete("fvsm multi-pass");
    // The first pass: the scene's depth only, with the very program of the tile passes (the
    // same positions, so that EQUAL holds).
    glBindFramebuffer(GL_FRAMEBUFFER, passes.id());
    glViewport(0, 0, t.width, t.height);
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    const float one = 1.0f;
    glClearNamedFramebufferfv(passes.id(), GL_DEPTH, 0, &one);
    multiPass_.use();
    multiPass_.set("u_viewProj", viewProj);
    multiPass_.set("u_cameraPos", eye);
    multiPass_.set("u_depthOnly", 1);
    t.sceneGpu->draw(multiPass_, SL_UNIT_MATERIAL);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  }
  bool stopped = false;  // the host stopped the frame (Renderer::setCancelFlag)
  for (std::size_t k = 0; k < tiles_.size(); ++k) {
    if (k > 0 && t.cancelRequested()) {
      stopped = true;
      break;
    }
    const fvsm::Tile& tile = tiles_[k];
    const fvsm::TileTexture tex = fvsm::tileTexture(mode, tile.textureLog2, maxLog2, overlap);
    TileDepthTarget& target = depthTarget(tex.size);
    glm::dvec2 lo, hi;
    fvsm::tileUvRectWithOverlap(tile, overlap, lo, hi);
    const DepthMapView view = subRectView(full_, lo, hi);
    if (t.timer) t.timer->begin("tile depth");
    glEnable(GL_SCISSOR_TEST);  // only the tile's sub-rectangle is cleared and drawn
    glScissor(0, 0, tex.viewport.x, tex.viewport.y);
    renderDepth(*t.sceneGpu, depth_, target.fbo.id(), tex.viewport.x, tex.viewport.y,
                view.lightViewProj);
    glDisable(GL_SCISSOR_TEST);
    if (t.timer) t.timer->begin("tile apply");
    glm::dvec2 applyLo, applyHi;  // the kd cell itself (the overlap only feeds the lookup)
    tileApplyRange(tile.uvMin(), tile.uvMax(), applyLo, applyHi);
    glm::ivec2 rectMin(0), rectMax(t.width, t.height);
    if (rects) fvsm::tileScreenRectPixels(tile.screen, smtmmSize_, frameSize_, 1, rectMin, rectMax);
    if (multiPass) {
      applyTileMultiPass(t, passes, view, target.texture, tex.viewport, applyLo, applyHi,
                         glm::vec2(glm::dvec2(tex.viewport) / (hi - lo)), rectMin, rectMax,
                         unsigned(k) & 255u, viewProj, eye);
      continue;
    }
    applyTile(
        apply_, t, eyeDepth_,
        {full_, view, target.texture, tex.viewport, applyLo, applyHi,
         glm::vec2(glm::dvec2(tex.viewport) / (hi - lo)), rectMin, rectMax, unsigned(k) & 255u,
         /*onlyEmpty=*/false, /*clampToTile=*/false});
  }
  if (!stopped) {  // Pixels no leaf reached: one map over the whole fit.
    if (t.timer) t.timer->begin("fallback");
    TileDepthTarget& target = depthTarget(glm::ivec2(fallbackResolution_));
    renderDepth(*t.sceneGpu, depth_, target.fbo.id(), fallbackResolution_, fallbackResolution_,
                full_.lightViewProj);
    glm::dvec2 everywhereLo, everywhereHi;  // the whole map is a border tile
    tileApplyRange(glm::dvec2(0.0), glm::dvec2(1.0), everywhereLo, everywhereHi);
    applyTile(apply_, t, eyeDepth_,
              {full_, full_, target.texture, glm::ivec2(fallbackResolution_), everywhereLo,
               everywhereHi, glm::vec2(float(fallbackResolution_)), glm::ivec2(0),
               glm::ivec2(t.width, t.height), 255u, /*onlyEmpty=*/true});
  }
  endTiles(t);
}

void FittedVirtualShadowMap::applyTileMultiPass(
    const ResolveTargets& t, const gl::Framebuffer& passes, const DepthMapView& tile,
    const gl::Texture& texture, glm::ivec2 texels, glm::dvec2 uvMin, glm::dvec2 uvMax,
    glm::vec2 texelsPerFullUv, glm::ivec2 rectMin, glm::ivec2 rectMax, unsigned mapIndex,
    const glm::mat4& viewProj, glm::vec3 eye) {
  const glm::ivec2 size = glm::max(rectMax - rectMin, glm::ivec2(0));
  if (size.x == 0 || size.y == 0) return;
  glBindFramebuffer(GL_FRAMEBUFFER, passes.id());
  glViewport(0, 0, t.width, t.height);
  glEnable(GL_SCISSOR_TEST);  // the leaf's screen rectangle
  glScissor(rectMin.x, rectMin.y, size.x, size.y);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_EQUAL);
  glDepthMask(GL_FALSE);
  multiPass_.use();
  bindLight(multiPass_, t.light);
  multiPass_.set("u_viewProj", viewProj);
  multiPass_.set("u_cameraPos", eye);
  multiPass_.set("u_depthOnly", 0);
  multiPass_.set("u_fullViewProj", full_.lightViewProj);
  multiPass_.set("u_tileUvMin", glm::vec2(uvMin));
  multiPass_.set("u_tileUvMax", glm::vec2(uvMax));
  multiPass_.set("u_texelsPerFullUv", texelsPerFullUv);
  multiPass_.set("u_mapIndex", mapIndex);
  multiPass_.set("u_clampToTile", 0);
  multiPass_.set("u_tileTexels", texels);
  bindDepthLookup(multiPass_, std::span(&tile, 1));
  glBindTextureUnit(SL_UNIT_LOOKUP_FIRST, texture.id());
  multiPass_.set("u_shadowMap", SL_UNIT_LOOKUP_FIRST);
  t.sceneGpu->draw(multiPass_, SL_UNIT_MATERIAL);
  glDisable(GL_SCISSOR_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                  GL_FRAMEBUFFER_BARRIER_BIT);
}

MemoryStats FittedVirtualShadowMap::memory() const {
  MemoryStats m;
  if (smtmmTexture_)
    m.add("SMTMM", gl::formatName(smtmmTexture_.format()), smtmmTexture_.width(),
          smtmmTexture_.height(), 1, gl::bytesPerTexel(smtmmTexture_.format()));
  for (const auto& [size, target] : targets_) target.addMemory(m, "tile texture");
  eyeDepth_.addMemory(m);
  if (passDepth_)
    m.add("multi-pass depth", gl::formatName(passDepth_.format()), passDepth_.width(),
          passDepth_.height(), 1, gl::bytesPerTexel(passDepth_.format()));
  if (cameraTexture_)
    m.add("camera thumbnail (panel)", gl::formatName(cameraTexture_.format()),
          cameraTexture_.width(), cameraTexture_.height(), 1,
          gl::bytesPerTexel(cameraTexture_.format()));
  lightThumb_.addMemory(m, "light-view thumbnail (panel)");
  return m;
}

std::optional<std::string> FittedVirtualShadowMap::reloadShaders(const gl::ShaderLibrary& lib) {
  if (auto e = depth_.rebuild(lib)) return e;
  if (auto e = apply_.rebuild(lib)) return e;
  if (auto e = cameraThumb_.rebuild(lib)) return e;
  if (auto e = eyeDepth_.reloadShaders(lib)) return e;
  if (auto e = smtmmPacked_.rebuild(lib)) return e;
  if (auto e = multiPass_.rebuild(lib)) return e;
  return smtmm_.rebuild(lib);
}

}  // namespace sl
