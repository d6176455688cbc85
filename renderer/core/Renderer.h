// The renderer: the only part of ShadowLab that calls OpenGL. Hosts (the Qt widget,
// the EGL command line, tests) make a GL 4.5 core context current and call renderFrame;
// panels read what the renderer publishes (FrameStats, Publication) and never touch GL.
// This header is GL-free on purpose so that UI headers can include it.
#pragma once

#include <atomic>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "algo/Camera.h"
#include "algo/Light.h"
#include "algo/Params.h"
#include "core/FrameStats.h"
#include "metrics/ErrorMetrics.h"
#include "metrics/Image.h"
#include "scene/Scene.h"

namespace sl::gl {
class ShaderLibrary;
}

namespace sl {

class ShadowReference;
class Technique;
struct RendererState;

/// One GPU pass of a frame, declared where it is implemented (GL-free): pass stepping, the
/// Timing panel and the lessons read these; no pass is named in ui/.
struct PassDecl {
  std::string id;           ///< as timed (gl::GpuTimer scope, FrameStats::passes): "blur"
  std::string title;        ///< "Blur and floor"
  std::string explanation;  ///< what the pass does and what to look at (pass-stepping banner)
  /// The panel showing its output: a panel id of the UI's registry ("importance", "warp",
  /// "shadowmap", ...); empty = the view itself.
  std::string panel;
  /// Timed inside the renderer's resolve (a deferred technique's per-tile passes:
  /// Technique::resolveDeferred): listed after "resolve" in framePassDecls.
  bool duringResolve = false;
  /// Runs only while the technique's Int/Enum parameter `onlyWhenParam` equals
  /// `onlyWhenValue` (rmsm.render: superpages or pages); empty = every frame.
  std::string onlyWhenParam;
  int onlyWhenValue = 0;
};

/// What a publication is: a float image, a set of images under one pattern, a curve
/// (std::vector<float>) or a number.
enum class PublicationKind { Image, ImageSet, Curve, Number };
const char* publicationKindName(PublicationKind kind);  ///< "image", "image set", ...

/// One key (or key pattern, '*' = any run of characters: "moment.*.*") a technique publishes
/// when asked (Renderer::requestPublications), and what reading it back costs.
struct PublicationDecl {
  std::string key;
  PublicationKind kind = PublicationKind::Number;
  std::string what;  ///< one line
  /// The cost as a formula the UI can show ("4 B x im.resolution^2"); empty for numbers.
  std::string cost;
  /// Bytes read back from the GPU per frame for `params` (the technique's); numbers: 0
  /// unless computing them reads something back (the renderer's "aliasing.*").
  std::function<std::uint64_t(const ParamSet& params)> bytes;
};

/// True when `key` matches `pattern` ('*' matches any run of characters, dots included).
bool publicationKeyMatches(std::string_view pattern, std::string_view key);

struct Publication;

/// What a technique is, without creating it (no GL needed): for `list`, menus, presets.
struct TechniqueInfo {
  std::string id;           ///< "uniform", "rtw-backward", ...
  std::string name;         ///< "Uniform shadow map"
  std::string description;  ///< one or two sentences, with the source paper
  std::vector<ParamDecl> params;
  std::vector<PassDecl> passes;  ///< the technique's own passes, in frame order
  std::vector<PublicationDecl> publications;
  /// The light kinds it renders; renderFrame refuses any other (an error, a neutral frame).
  std::vector<LightType> lights{LightType::Directional};
  /// Keeps a rotation across frames (DA-RTW: R_k from the previous frame's moments), so one
  /// frame is not what a user sees: measuring commands render unmeasured frames until it
  /// settles (`settled`).
  bool temporalRotation = false;
  /// The plain shadow map the others are measured against (uniform): what a renderer starts
  /// on, the CLI's render default, the split view's and the Charts dock's partner, a scheme the
  /// storage analysis reads as is (Renderer::baselineTechniqueId).
  bool baseline = false;
  /// The technique a window opens on when neither the command line, a lesson nor the last
  /// session names one (da-rtw: the one every RTW panel draws, so that the first screen shows
  /// what the tool is about; Renderer::firstScreenTechniqueId).
  bool firstScreen = false;
  /// Warps its map by an analysis of its own (RTW's importance maps) that the storage analysis
  /// (measure/StorageScheme) does not model: it reports the map as a uniform one and says so.
  bool unanalysedWarp = false;
  /// Keeps state from one frame to the next that changes what later frames show (DA-RTW's
  /// rotation and moments, ASM's page cache, the cascades' held depth range, rmsm's budget
  /// pool): the renderer then commits it only when a frame completes and discards it
  /// otherwise (Technique::commitFrame). Declared here once; the cancellation tests cover
  /// every technique that declares it.
  bool temporalState = false;
  /// With temporalRotation: the numbers `settled` reads, and the rule itself, declared once
  /// for the command line, the lessons and the tests: after a frame whose publication holds
  /// settleKeys, whether the state stopped changing; nothing when the frame could not tell
  /// yet (no estimate from a last frame).
  std::set<std::string> settleKeys;
  std::function<std::optional<bool>(const Publication&)> settled;
  /// What a pattern of the technique's own in the aliasing overlay (view.overlay = aliasing)
  /// comes from, one or two sentences the overlay's legend shows under its colour bar; empty
  /// when the technique draws none (m then only follows distance and slope).
  std::string aliasingPattern;
  /// A deferred technique that times its tiles as repeated passes (virtual-tiled, fvsm): when
  /// `key` (a Curve it declares) is requested, the renderer publishes per tile, in the order
  /// the tiles were applied, two values: the ms of the `depthPass` scopes since the previous
  /// tile's `applyPass` scope (the tile's depth; its bands in a progressive call) and of its
  /// `applyPass` scope — from the timer results FrameStats::passes sums (tileTimingCurve).
  struct TileTiming {
    std::string key, depthPass, applyPass;
  };
  std::optional<TileTiming> tileTiming;
  /// The declaration matching `key` (exactly or by pattern); null when not published.
  const PublicationDecl* findPublication(std::string_view key) const;
  /// Combinations of parameter values the technique cannot render though each value is in
  /// its declared range (fvsm.grid must be a power of two, a page pool must hold the top of
  /// the quadtree): an error naming the parameters, their values and what they need; null
  /// (or unset) when every in-range combination renders. Checked wherever values are set up
  /// front (the CLI's --set, presets and suites) and by renderFrame.
  std::function<std::optional<std::string>(const ParamSet&)> checkParams;
};
/// `info.checkParams(params)` when the technique declares one, else nothing.
std::optional<std::string> checkTechniqueParams(const TechniqueInfo& info, const ParamSet& params);
/// An error like "technique 'uniform' supports: directional, spot; the light is a point
/// light" when `info` does not support `type`, else nothing.
std::optional<std::string> checkLightSupport(const TechniqueInfo& info, LightType type);

/// Passes of the renderer itself, declared once: "gbuffer" (before the technique's),
/// "resolve" and "composite" (after).
std::vector<PassDecl> rendererPassDecls();
/// Every pass of a frame with `technique`, in frame order: gbuffer, the technique's
/// passes, resolve, composite.
std::vector<PassDecl> framePassDecls(const TechniqueInfo& technique);
/// The passes of a frame with `technique` under `params` (its ParamSet): framePassDecls less
/// those whose onlyWhenParam does not hold (the timed passes of that frame).
std::vector<PassDecl> framePassDecls(const TechniqueInfo& technique, const ParamSet& params);
/// Publications of the renderer itself, whatever the technique, declared once (next to
/// rendererPassDecls): the measured aliasing statistics "aliasing.*" (a GPU reduction of the
/// resolve pass's m, run only while requested), the frame's camera "camera.*" and light
/// "light.type" (and, directional only, "light.azimuth_deg" / "light.elevation_deg"), and the
/// technique's parameter values "param.<key>" (enums as their index), so that panels read what the
/// frame used.
const std::vector<PublicationDecl>& rendererPublicationDecls();
/// The declaration matching `key` among the renderer's and then `technique`'s publications.
const PublicationDecl* findFramePublication(const TechniqueInfo& technique, std::string_view key);
/// Bytes a frame with `technique` reads back with `params` when `requested` (patterns) is
/// asked for: the sum of the declared costs of every publication (the renderer's and the
/// technique's) a pattern matches.
std::uint64_t declaredPublicationBytes(const TechniqueInfo& technique, const ParamSet& params,
                                       const std::set<std::string>& requested);

/// Parameters shared by every technique (shading, view) — declared once here.
std::vector<ParamDecl> rendererParamDecls();

/// A float image published for the panels (e.g. an importance map), row 0 = bottom.
struct FloatImage {
  int width = 0, height = 0, channels = 1;
  std::vector<float> values;
  /// The texture's size when the image is a downsampled view of it (a map larger than
  /// kMaxPublishedImageSide per side); 0 when the image is the texture.
  int sourceWidth = 0, sourceHeight = 0;
};

/// The largest side of an image a technique publishes from a texture: a larger map is read
/// back nearest-sampled (every n-th texel, n the smallest integer that brings both sides within
/// this), so a panel of a 16384² map reads 16 MiB, not 1 GiB.
inline constexpr int kMaxPublishedImageSide = 2048;
/// {width, height} of the image published from a width x height texture.
std::pair<int, int> publishedImageSize(int width, int height);
/// The bytes of one float per texel of that image (what publishing it reads back).
std::uint64_t publishedImageBytes(int width, int height);

/// Debug data a technique publishes each frame, only the keys requested
/// (Renderer::requestPublications): images, curves and numbers. Each technique declares its
/// keys and their cost in TechniqueInfo::publications. Keys (absent when a technique has no
/// such thing):
///  the renderer, any technique (rendererPublicationDecls):
///           "aliasing.p50", "aliasing.p95", "aliasing.max", "aliasing.pixels",
///           "aliasing.bin_octaves" (m over the covered pixels: the exact maximum, the
///           percentiles from a GPU histogram of log2 m, within half a bin of the exact ones),
///           "camera.near_m", "camera.far_m", "camera.fov_deg" (full vertical angle),
///           "camera.aspect", "camera.height_px", "camera.forward.{x,y,z}", "camera.up.{x,y,z}"
///           (unit, orthogonal), "light.type", "light.azimuth_deg", "light.elevation_deg"
///           (directional lights only), "param.<key>" (the
///           technique's values)
///  every shadow-map technique:  "shadow map" (image: the map as rendered, depth 0..1)
///  RTW keys (listed between the markers; tests/source/ui_names_no_rtw_key.sh checks that no
///  file in ui/ outside ui/panels/rtw/ names one):
///  BEGIN RTW KEYS
///  images:  "shadow map.uniform" (an unwarped map of the same size, for contrast),
///           "importance" (IM before collapse, im.resolution^2),
///           "importance.moments" (DA-RTW: the block-maxima IM the PCA reads),
///           "moment.<c>.<level>" (DA-RTW: c in I,xI,yI,xxI,yyI,xyI; level 0 = full size;
///           mip chain of SUMS, see algo/rtw/Moments.h)
///  curves:  "importance.x", "importance.y" (collapsed, before blur),
///           "importance.x.blurred", "importance.y.blurred" (after blur and floor),
///           "warp.x", "warp.y" (n+1 edge offsets; u' = u + warp, algo/rtw/Warp.h),
///           "inverse.x", "inverse.y" (unwarped light coordinate of every warped texel)
///  numbers: "moment.I", "moment.xI", "moment.yI", "moment.xxI", "moment.yyI", "moment.xyI"
///           (top-level sums), "mean.x", "mean.y", "cov.xx", "cov.xy", "cov.yy",
///           "eigen.1", "eigen.2", "e_x", "e_y", "pca.valid" (0/1), "pca.threshold",
///           "rotation.held" (0/1), "rotation.deg" (accumulated angle of R),
///           "rotation.step_deg", "rotation.changes", "light.extent.x", "light.extent.y".
///  END RTW KEYS
struct Publication {
  std::uint64_t frameIndex = 0;
  std::string techniqueId;
  /// The patterns requested for this frame; a technique publishes only keys they match.
  std::set<std::string> requested;
  std::map<std::string, FloatImage> images;
  std::map<std::string, std::vector<float>> curves;
  std::map<std::string, double> numbers;
  /// Bytes read back from the GPU for this publication, counted by the readback helpers
  /// (core/Publish.h) as they read.
  std::uint64_t readbackBytes = 0;
  bool wants(std::string_view key) const;
  /// The published number `key`, or `fallback` when this frame did not publish it.
  double number(const std::string& key, double fallback) const;
};

/// Per-pixel data of the last frame, read back from the GPU (slow: metrics and tests).
/// Every array is row-major with row 0 = the TOP row of the image.
struct FrameReadback {
  int width = 0, height = 0;
  std::vector<glm::vec4> positions;    ///< world xyz, w = 1 covered / 0 background
  std::vector<glm::vec4> normals;      ///< world, unit, facing the camera
  std::vector<std::uint8_t> hardMask;  ///< technique's hard test: 1 lit, 0 shadow, 255 empty
  /// Perspective aliasing m per pixel: shadow-map texel footprint over pixel footprint,
  /// 1/sqrt(|dX x dY|) with dX, dY the screen derivatives of the final (warped) shadow-map
  /// texel coordinate. m > 1: undersampled. 0 where uncovered.
  std::vector<float> aliasing;
  /// The final shadow-map uv the resolve pass looked up per pixel (through any warp, with
  /// the technique's normal offset applied); (0, 0) where uncovered.
  std::vector<glm::vec2> texel;
  /// The index of the map the resolve selected per pixel (a cascade, face, layer; 0 for
  /// single-map techniques and where uncovered).
  std::vector<std::uint8_t> mapIndex;
  ImageRGBA8 color;  ///< final shaded image of the main camera, row 0 = top
  /// The outside view's image (view.outside on: the third camera with the frusta drawn, what
  /// the host was shown); empty otherwise. Every other array is the main camera's.
  ImageRGBA8 outside;
  /// The last frame was stopped (Renderer::setCancelFlag): nothing was read (size 0).
  bool cancelled = false;
};

/// What the last frame's main camera saw at one pixel (Renderer::probePixel): the view's
/// hover readout, e.g. the Omni map panel's marker of the map texel a pixel looks up.
struct PixelProbe {
  int x = 0, y = 0;         ///< the pixel, row 0 = top
  bool covered = false;     ///< a surface is there (else the rest is zero)
  glm::vec3 worldM{0.0f};   ///< its world position (metres)
  std::uint8_t hard = 255;  ///< the technique's hard test (SL_MASK_*)
  float aliasing = 0.0f;    ///< m there
  int map = 0;              ///< the map the lookup selected (face, hemisphere, cascade...)
  glm::vec2 mapUv{0.0f};    ///< the uv it looked up in that map
};

/// One entry of a technique list: what it is, and how to make one (GL current; throws
/// std::runtime_error or gl::ShaderError when it cannot).
struct TechniqueEntry {
  TechniqueInfo info;
  std::unique_ptr<Technique> (*create)(const gl::ShaderLibrary& lib) = nullptr;
};

struct RendererOptions {
  std::string shaderDir;  ///< empty: SHADOWLAB_SHADER_DIR env var, else compiled-in path
  bool debugOutput = true;
  /// How passes are timed (FrameStats::timingMethod). Empty: the SHADOWLAB_TIMING env var
  /// (finish|query), else from GL_RENDERER (glFinish + wall clock on software rasterisers,
  /// timer queries elsewhere). Tests force a method here rather than in the environment.
  std::optional<TimingMethod> timing;
  /// Techniques this renderer offers besides the built-in list (Renderer::techniques()):
  /// tests add techniques that live only in tests. Found by setTechnique and paramsOf.
  std::vector<TechniqueEntry> extraTechniques;
};

class Renderer {
 public:
  /// Needs a current OpenGL 4.5 core context. Throws std::runtime_error naming what is
  /// missing (GL version, extension) or the shader that failed to compile.
  explicit Renderer(const RendererOptions& options = {});
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  static const std::vector<TechniqueInfo>& techniques();
  static const TechniqueInfo* findTechnique(std::string_view id);
  /// The id of the technique declared TechniqueInfo::baseline, else of the first one.
  static const std::string& baselineTechniqueId();
  /// The id of the technique declared TechniqueInfo::firstScreen, else of the first one.
  static const std::string& firstScreenTechniqueId();

  /// "GL_RENDERER | GL_VERSION" of the context.
  std::string glDescription() const;
  /// GL_VENDOR, GL_RENDERER and GL_VERSION of the context ("?" for one GL does not give).
  struct GlStrings {
    std::string vendor, renderer, version;
  };
  GlStrings glStrings() const;

  /// The largest frame the current context renders: per side the smallest of
  /// GL_MAX_TEXTURE_SIZE, GL_MAX_RENDERBUFFER_SIZE and GL_MAX_FRAMEBUFFER_WIDTH/HEIGHT.
  struct FrameSizeLimit {
    int width = 0, height = 0;  ///< pixels
    /// The GL constant behind each, e.g. "GL_MAX_TEXTURE_SIZE".
    std::string widthLimit, heightLimit;
  };
  static FrameSizeLimit maxFrameSize();
  /// An error naming the limit when a width x height frame exceeds maxFrameSize() or the
  /// implementation cannot allocate the G-buffer's widest target (RGBA32F) at that size
  /// (asked with a GL_PROXY_TEXTURE_2D, before anything is allocated). Needs a current context.
  static std::optional<std::string> checkFrameSize(int width, int height);

  void setScene(std::shared_ptr<const Scene> scene);
  const std::shared_ptr<const Scene>& scene() const;

  /// Switches technique (each technique keeps its own parameter values). Unknown id:
  /// an error naming the known ids, nothing changes.
  std::optional<std::string> setTechnique(std::string_view id);
  const std::string& techniqueId() const;
  ParamSet& params();  ///< the current technique's parameters (live)
  ParamSet& paramsOf(std::string_view techniqueId);
  ParamSet& rendererParams();  ///< shared view/shading parameters

  void setCamera(const Camera& camera);
  const Camera& camera() const;
  void setLight(const Light& light);
  const Light& light() const;

  /// Renders one frame of width x height into `targetFramebuffer` (0 = default).
  /// Returns an error (and renders a neutral frame) when the camera, light or size is
  /// degenerate, or the technique does not support the light's kind (checkLightSupport);
  /// the renderer keeps working.
  std::optional<std::string> renderFrame(int width, int height, unsigned targetFramebuffer);
  /// The same, the frame then stretched (linear) over presentWidth x presentHeight of the
  /// target (the GUI's adaptive resolution); every target and readback stays width x height.
  std::optional<std::string> renderFrame(int width, int height, unsigned targetFramebuffer,
                                         int presentWidth, int presentHeight);
  /// The host's stop flag (any thread may set it; null: never stopped). renderFrame reads it
  /// between its steps and between a progressive resolve's units; once it is set the frame stops
  /// there: renderFrame returns nothing, stats().cancelled is true and stats().complete() false.
  /// A stopped frame is no measurement: readback() returns an empty frame, computeError()
  /// throws, traceReference() returns nothing and publication() stays the last complete
  /// frame's. A flag already set when renderFrame starts stops it after its first step (the
  /// G-buffer). The shadow passes and the main resolve they feed go together (the flag is not
  /// read between them; a deferred resolve reads it between its units, one-call or progressive).
  /// Frames are transactional: a stopped frame leaves no trace, the next frame is byte for
  /// byte what a renderer that never saw it renders. A technique's state across frames
  /// (TechniqueInfo::temporalState: DA-RTW's rotation, ASM's page cache...) and the previous
  /// frame's resolve targets the next frame reads (the shadow-edge term's mask, the mask change,
  /// per-map statistics) are the last COMPLETE frame's. Only a progressive resolve's units go
  /// on: the next call of the same view resumes from the units done (pixels, not state).
  void setCancelFlag(const std::atomic<bool>* flag);
  /// Fills the target with the neutral background and renders nothing: no pass runs, no
  /// temporal state changes (a view too small to show anything).
  static void clearFrame(int width, int height, unsigned targetFramebuffer);
  const FrameStats& stats() const;

  /// The publication keys (or patterns, '*' = any run of characters; "*" = everything)
  /// the next frames publish; empty (the default) = none, and nothing is read back. A
  /// technique reads back only what is requested, and work that exists only for a panel
  /// (e.g. RTW's 2D IM in backward analysis) happens only while requested.
  void requestPublications(std::set<std::string> patterns);
  const std::set<std::string>& requestedPublications() const;
  /// The last frame's publication when something was requested (else an older one:
  /// compare frameIndex with stats().frameIndex).
  const Publication& publication() const;

  /// Reads the last frame back (positions, normals, hard mask, colour); an empty frame with
  /// `cancelled` set when the last frame was stopped (setCancelFlag).
  FrameReadback readback() const;
  /// Reads only the last frame's shown colour image (the main camera's, or the outside
  /// view's while on), row 0 = top: the GUI's zoom inset.
  ImageRGBA8 readColor() const;
  /// Reads one pixel of the last frame (x right, y down from the top row; GL current):
  /// nothing before a frame or outside it. A few bytes: cheap enough for every mouse move.
  std::optional<PixelProbe> probePixel(int x, int y) const;
  /// Exact reference for the last frame (Embree, cached per scene) and the error. Throws
  /// std::runtime_error when the last frame was stopped (setCancelFlag): it is not a frame.
  struct ErrorResult {
    ShadowErrorStats stats;
    std::vector<std::uint8_t> referenceMask;
    FrameReadback frame;
  };
  ErrorResult computeError() const;
  /// computeError() in three steps, so that the trace runs on another thread (the GUI's
  /// continuous rendering, metrics/AsyncReference): `snapshotForReference` reads the last
  /// frame back (GL current) with the light, the scene's Embree scene (shared: it outlives
  /// a scene change) and what the frame showed; `traceReference` traces and compares it
  /// without GL on any thread, returning nothing once `cancelled` became true (checked
  /// between bands of rows) or when the snapshot's frame was stopped (setCancelFlag);
  /// `setReferenceMask` (GL current) keeps the mask for the error overlay, which draws it only
  /// while frames show the same `frameSignature` — false when the frame size changed since.
  struct ReferenceSnapshot {
    FrameReadback frame;
    Light light;
    std::shared_ptr<const ShadowReference> reference;  ///< null: no scene or no frame
    std::string frameSignature;
  };
  ReferenceSnapshot snapshotForReference() const;
  static std::optional<ErrorResult> traceReference(ReferenceSnapshot snapshot,
                                                   const std::atomic<bool>* cancelled = nullptr);
  bool setReferenceMask(const std::string& frameSignature, std::span<const std::uint8_t> mask,
                        int width, int height);
  /// What the last frame showed (scene, technique, parameters, size, camera, light): the
  /// error overlay's reference must have been traced for the same.
  const std::string& frameSignature() const;

  /// Shader hot reload: on failure the last good programs stay in use, error returned.
  std::optional<std::string> reloadShaders();
  /// GL debug-output errors seen since the last call (empty when all is well).
  std::vector<std::string> takeGlErrors();
  /// Progressive resolve (the GUI's continuous rendering, so that no call blocks its event
  /// loop for long): > 0 lets a technique that resolves unit by unit (virtual-tiled's tiles,
  /// ResolveProgress) spend about `ms` of wall time on units per renderFrame, keeping its
  /// screen-space result between calls while the frame signature stays the same (restarting
  /// when camera, light, parameters, scene or size change); FrameStats::progress says how far
  /// it is. Once every unit is done the targets equal a one-call frame's, pixel for pixel.
  /// 0 (the default: CLI, tests, grabs) = every frame complete in one call.
  void setProgressiveBudget(double ms);
  double progressiveBudget() const;
  /// Resets state that accumulates over frames (e.g. DA-RTW's rotation).
  void resetTemporalState();

 private:
  std::unique_ptr<RendererState> s_;
};

}  // namespace sl
