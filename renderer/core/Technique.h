// The interface every shadow technique implements. A technique is one self-contained
// unit (its C++ under renderer/techniques/<name>/, its shaders under shaders/<name>/):
// it builds its shadow map(s) each frame and then EITHER provides the GLSL lookup (over
// any number of maps) the resolve pass includes as "@lookup", OR resolves the pixels
// itself in a deferred pass. Adding a technique touches its folder and TechniqueRegistry.cpp.
#pragma once

#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "algo/Camera.h"
#include "algo/Params.h"
#include "core/FrameCarried.h"
#include "core/FrameStats.h"
#include "core/Renderer.h"
#include "gl/GpuTimer.h"
#include "gl/ShaderLibrary.h"

namespace sl {

class SceneGpu;

/// A camera's G-buffer (the main camera's, or the outside view's): world position (w =
/// covered) and world normal facing the camera, RGBA32F, the frame's size.
struct GBufferTextures {
  const gl::Texture& position;
  const gl::Texture& normal;
};

/// The resolve targets before this frame's resolve: what the previous frame's resolve wrote
/// (camera space). Shadow-edge importance reads its hard mask (R8UI), per-map statistics a
/// frame late its aliasing m (R32F) and selected map index (R8UI).
struct PreviousResolve {
  const gl::Texture& hard;
  const gl::Texture& aliasing;
  const gl::Texture& mapIndex;
};

/// Everything a technique may read while building its shadows for one frame. Built with
/// designated initialisers (its textures are grouped in named structs, so no two of them
/// can be swapped by position).
struct FrameContext {
  const Scene& scene;
  const SceneGpu& sceneGpu;
  const Camera& camera;
  float aspect = 1.0f;
  glm::mat4 cameraView{1.0f}, cameraProj{1.0f};
  const Light& light;         ///< validated, of a kind the technique supports
  int width = 0, height = 0;  ///< camera image size in pixels
  /// Camera G-buffer of this frame (for backward analysis), width x height.
  GBufferTextures gbuffer;
  PreviousResolve previous;
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
  /// What the outside view draws (algo/OutsideView.h): every technique adds each map's
  /// world -> clip matrix (and a warp's, and its split depths) every frame; cheap, no GL.
  FrameOutlines* outlines = nullptr;
  void addOutline(const glm::mat4& worldToClip, OutlineRole role, int map = 0) const {
    if (outlines) outlines->frusta.push_back(FrustumOutline::fromClip(worldToClip, role, map));
  }
};

/// How a technique turns its maps into the resolve targets.
enum class ResolveMode {
  /// The renderer's resolve pass (shaders/common/resolve.frag) includes lookupShader() as
  /// "@lookup": a selection of one of any number of maps + a test in it. Aliasing m comes
  /// from the screen derivatives of the selected map's texel coordinate.
  Lookup,
  /// The technique writes the targets itself in resolveDeferred (tile by tile, a
  /// screen-space result...), with the same meaning as the resolve pass's outputs.
  Deferred,
};

/// A deferred resolve spread over several calls (Renderer::setProgressiveBudget: the GUI's
/// continuous rendering; the CLI, tests and grabs never set it and resolve in one call). A
/// technique that resolves in independent units (virtual-tiled: a 512-row band of a tile's
/// depth pass each, the tile applied after its last band; every pixel written by exactly one
/// tile) does units [next, ...) until `budgetMs` of wall time has gone
/// (at least one), then sets `next` and `total`; the result once every unit is done is the
/// one-call resolve's, pixel for pixel. A technique that ignores it leaves `total` 0 (done).
struct ResolveProgress {
  /// In: the targets already hold this same frame's earlier units (or a complete result): do
  /// not clear them.
  bool resume = false;
  int next = 0;   ///< in: the first unit to do; out: the next one (total: complete)
  int total = 0;  ///< out: the number of units (0: not progressive, done in one call)
  /// out: units per tile (virtual-tiled: a tile's depth pass in bands of rows), for the note
  int unitsPerTile = 1;
  double budgetMs = 0;  ///< in: wall time to spend on units in this call
  double spentMs = 0;   ///< out: wall time spent on units in this call
};

/// The resolve's five targets (shaders/common/resolve.frag's outputs; meanings below).
struct ResolveOutputs {
  const gl::Texture& hard;      ///< R8UI, SL_MASK_*
  const gl::Texture& filtered;  ///< R8, 1 = lit
  const gl::Texture& aliasing;  ///< R32F, m
  const gl::Texture& texel;     ///< RG32F, the selected map's uv
  const gl::Texture& mapIndex;  ///< R8UI, the selected map
};

/// What a deferred resolve reads and writes (Technique::resolveDeferred). The targets
/// follow shaders/common/resolve.frag: hard mask R8UI (SL_MASK_*), filtered visibility
/// R8 (1 = lit), aliasing m R32F (texel footprint of the SELECTED map / pixel footprint,
/// 0 where uncovered), texel RG32F (the selected map's uv, for the grid overlay), map index
/// R8UI (the selected map, for the partition overlay; cleared to 0 before the call).
struct ResolveTargets {
  int width = 0, height = 0;
  GBufferTextures gbuffer;  ///< what the resolve reads
  ResolveOutputs outputs;   ///< what it writes
  GLuint framebuffer = 0;   ///< the five as colour attachments 0..4, for a fragment pass
  const Light& light;       ///< the frame's light (sl::bindLight: common/light.glsl)
  /// The scene on the GPU, for a technique that renders its maps during the resolve (tile
  /// by tile: virtual-tiled, fvsm).
  const SceneGpu* sceneGpu = nullptr;
  /// Times the passes of a deferred resolve (per tile); null where the resolve is not timed
  /// (the outside view). A scope opened here closes the renderer's "resolve" scope (scopes do
  /// not nest): a technique that opens one reopens "resolve" before it returns.
  gl::GpuTimer* timer = nullptr;
  /// False for the outside view's resolve: its pixels are not the main camera's, which a
  /// screen-space analysis (fvsm's tile rectangles) was made for.
  bool mainCamera = true;
  /// Non-null: the host spreads the resolve over calls (ResolveProgress); null: one call.
  ResolveProgress* progress = nullptr;
  /// The host's stop flag (Renderer::setCancelFlag; null: never stopped). A technique that
  /// resolves unit by unit checks cancelRequested() after each unit and, once it is set, stops
  /// there (reporting `progress->next` when progressive); the renderer then drops the frame.
  const std::atomic<bool>* cancel = nullptr;
  bool cancelRequested() const { return cancel && cancel->load(std::memory_order_relaxed); }
  /// The camera the G-buffer was drawn with (the main one, or the outside view's): its view
  /// and perspective projection (the tiled techniques rebuild positions from eye depth).
  glm::mat4 cameraView{1.0f}, cameraProj{1.0f};
  /// Binds the G-buffer to texture units SL_UNIT_G_POSITION / SL_UNIT_G_NORMAL and the five
  /// targets to image units SL_IMAGE_RESOLVE_* (write-only), for a compute pass.
  void bindForCompute() const;
};

class Technique {
 public:
  virtual ~Technique() = default;
  /// Builds this frame's shadow map(s). Throws std::runtime_error on unrecoverable GL
  /// problems; parameter values are already validated.
  virtual void renderShadows(FrameContext& ctx) = 0;
  virtual ResolveMode resolveMode() const { return ResolveMode::Lookup; }
  /// Lookup mode: GLSL file (relative to shaders/) defining the lookup functions listed in
  /// shaders/common/resolve.frag (shadowLookupCoord, shadowMapSize, shadowHardAt,
  /// shadowFilteredAt), included by the resolve pass as "@lookup". Depth maps get them from
  /// shaders/common/depth_map_test.glsl.
  virtual std::string lookupShader() const { return {}; }
  /// Lookup mode: binds what the lookup needs (textures from `firstUnit` on, per-map
  /// uniforms) to `resolve`. Declared parameters are already bound (bindParams).
  virtual void bindLookup(const gl::Program& /*resolve*/, int /*firstUnit*/) const {}
  /// Deferred mode: writes the resolve targets for this frame (the map index optionally). Throws
  /// like renderShadows. Declared parameters are already bound to programs().
  virtual void resolveDeferred(const ResolveTargets& /*targets*/, const ParamSet& /*params*/) {}
  /// Every program of the technique (not the renderer's resolve pass). The renderer binds
  /// the declared parameters (ParamDecl::uniform) to each before renderShadows, and refuses
  /// the technique when a declared uniform is in none of them nor in the resolve pass.
  virtual std::vector<const gl::Program*> programs() const = 0;
  /// Shadow-related GPU resources of the last frame.
  virtual MemoryStats memory() const = 0;
  virtual std::optional<std::string> reloadShaders(const gl::ShaderLibrary& lib) = 0;
  /// State carried across frames (TechniqueInfo::temporalState declares that a technique has
  /// any) is transactional: a frame reads what the last COMPLETE frame left and works on a
  /// pending copy (FrameCarried); the renderer calls commitFrame() once the frame is complete
  /// (FrameStats::complete) and discardFrame() for any other call: stopped by the host's flag
  /// (before or after the shadow passes, within a resolve), failed, or a progressive call
  /// that has not finished its units. A discarded frame leaves no trace: the next frame is
  /// byte for byte what a renderer that never saw it renders. GPU-resident state counts too
  /// (a pending copy, or what the frame overwrote restored on discard). Called with the GL
  /// context current, only for techniques that declare temporalState.
  virtual void commitFrame() {}
  virtual void discardFrame() {}
  /// Forgets the carried state, committed and pending (a new scene, the user's reset).
  virtual void resetTemporalState() {}
  /// Pages per side of each map the lookup selects (a paged map: rmsm and asm, one map per
  /// quadtree level), for the page-border overlay (SL_OVERLAY_PAGES: a pixel's page is its map
  /// and floor(uv * pages per side)); empty when the technique has no pages.
  virtual std::vector<int> pageGrid() const { return {}; }
};

/// The built-in technique list (TechniqueEntry: core/Renderer.h).
const std::vector<TechniqueEntry>& techniqueRegistry();

/// Parameters most shadow-map techniques share (resolution, bias, PCF), declared once;
/// `resolutionHelp`, when given, says in the technique's words what the resolution is of
/// (each cube face, every partition's map...).
std::vector<ParamDecl> shadowMapParamDecls(int defaultResolution, std::string resolutionHelp = {});
/// Replaces the help text of `key` in `decls` (a technique's own words for a shared
/// declaration); throws std::logic_error when it is absent.
void setParamHelp(std::vector<ParamDecl>& decls, const std::string& key, std::string help);
/// The "shadow map" publication of a technique with one `resolution`^2 depth map.
PublicationDecl shadowMapPublicationDecl();

}  // namespace sl
