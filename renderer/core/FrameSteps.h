// The steps of one frame, declared once as a list (kFrameSteps) that Renderer::renderFrame
// walks: G-buffer -> the technique's shadow passes -> resolve -> mask change -> aliasing
// statistics -> composite -> outside view -> present (docs/ARCHITECTURE.md). The resolve
// and the statistics are in FrameResolve.cpp, the other steps in FrameSteps.cpp.
#pragma once

#include <exception>
#include <optional>
#include <string>

#include "core/RendererState.h"

namespace sl::frame {

/// One camera's way through the G-buffer, resolve and composite steps: the main camera's
/// (timed, measured) or the outside view's (view.outside: untimed, read by no metric).
struct CameraPass {
  Targets& targets;
  glm::mat4 view{1.0f}, proj{1.0f};
  glm::vec3 eye{0.0f};
  bool mainCamera = true;
};

/// What renderFrame was asked for and what follows from it before the first step.
struct FrameSetup {
  int width = 0, height = 0;                ///< internal size: targets, readback, metrics
  int presentWidth = 0, presentHeight = 0;  ///< what the host's framebuffer shows it at
  unsigned hostFramebuffer = 0;             ///< 0: the default (none on surfaceless EGL)
  float aspect = 1.0f;
  bool publishing = false;       ///< publications requested this frame
  bool countMaskChange = false;  ///< the changed overlay or a "mask.*" key is on
  bool hadMask = false;          ///< a complete frame's mask at this size is kept (prevHard)
  bool showOutsideView = false;  ///< view.outside
};

/// What the steps hand on to later steps and to FrameStats.
struct FrameResults {
  FrameOutlines outlines;  ///< what the outside view draws (the technique adds its frusta)
  std::optional<FrameStats::MaskChangeCount> maskChange;
  std::optional<Camera> outsideCamera;
};

/// One frame while its steps run: the setup, the camera the per-camera steps draw (the main
/// one, or the outside view's while its step runs), and the results so far.
struct Frame {
  const FrameSetup setup;
  CameraPass mainCamera;
  CameraPass* camera = nullptr;
  FrameResults results;
};

// --- The steps. Each reads the frame's setup and results and the renderer's state.

/// G-buffer of the frame's camera: world position (w = covered), normal, albedo, depth.
void gbufferStep(RendererState& s, Frame& f);
/// The technique's shadow passes (its own timer scopes), its parameters bound to its programs
/// from their declarations first.
void shadowsStep(RendererState& s, Frame& f);
/// Resolve of the frame's camera's G-buffer with the technique's maps as this frame built
/// them (lookup pass or deferred): hard mask, filtered visibility, aliasing m, selected map
/// and its uv per pixel.
void resolveStep(RendererState& s, Frame& f);
/// The mask change (changed overlay, "mask.*"): the pixels whose hard test flipped since the
/// last complete frame; nothing on the first frame of a size.
void maskChangeStep(RendererState& s, Frame& f);
/// The measured aliasing statistics ("aliasing.*"), timed with the resolve.
void aliasingStatsStep(RendererState& s, Frame&);
/// Shading of the frame's camera with the view.overlay: the error overlay only for the main
/// camera of a whole frame whose exact view has a reference; the aliasing and changed
/// overlays only for the main camera (the outside view's own derivatives would show m for a
/// camera that is not measured).
void compositeStep(RendererState& s, Frame& f);
/// The outside view (view.outside) into s.outsideTargets: the G-buffer, resolve and composite
/// steps again with a third camera placed around the frusta the technique outlined (the
/// warp-grid and partition overlays, not the error and aliasing ones), then the outlines.
/// The main camera's targets stay what every metric reads.
void outsideViewStep(RendererState& s, Frame& f);
/// To the host's framebuffer (a surfaceless EGL context has none: the frame then stays in the
/// renderer's colour target, which readback() returns): the outside view's image while on. A
/// smaller internal size (the GUI's adaptive resolution) is stretched over the present size.
void presentStep(RendererState& s, Frame& f);

/// Whether the aliasing statistics step runs for publication `pub` (an "aliasing.*" key).
bool wantsAliasingStats(const Publication& pub);
/// Whether the mask change is counted this frame (the changed overlay or a "mask.*" key).
bool wantsMaskChange(RendererState& s, bool publishing);

// --- The frame, declared once.

/// What an error a step throws is reported as (renderFrame then renders a neutral frame).
enum class StepFailure {
  Propagates,        ///< not caught (the renderer's own passes)
  NamesTechnique,    ///< "technique '<id>': ..."
  NamesOutsideView,  ///< "outside view: ..."
};

/// One step of renderFrame.
struct FrameStep {
  const char* name;  ///< FrameStats::stoppedBefore names it
  /// The timer scope it runs in (consecutive steps of one pass share one scope); null: not
  /// timed by the renderer (the technique times its own passes; the outside view is not timed).
  const char* timedPass;
  StepFailure failure;
  /// The host's stop flag is read before the step. Not before the first (a frame stopped at
  /// once still has its G-buffer) nor before the main resolve (the maps of this frame go with
  /// their resolve; a deferred resolve stops between its units itself). Wherever a frame stops,
  /// endFrame discards what it changed (the frame is transactional).
  bool stopsBefore;
  /// When it runs (null: every frame).
  bool (*when)(const RendererState&, const Frame&);
  void (*run)(RendererState&, Frame&);
};

/// Every step of a frame, in order. renderFrame walks it once, reading the host's stop flag
/// before the steps that say so (and a deferred resolve between its units).
inline constexpr FrameStep kFrameSteps[] = {
    {.name = "gbuffer",
     .timedPass = "gbuffer",
     .failure = StepFailure::Propagates,
     .stopsBefore = false,
     .when = nullptr,
     .run = gbufferStep},
    {.name = "shadows",
     .timedPass = nullptr,
     .failure = StepFailure::NamesTechnique,
     .stopsBefore = true,
     .when = nullptr,
     .run = shadowsStep},
    {.name = "resolve",
     .timedPass = "resolve",
     .failure = StepFailure::NamesTechnique,
     .stopsBefore = false,
     .when = nullptr,
     .run = resolveStep},
    {.name = "mask change",
     .timedPass = "resolve",
     .failure = StepFailure::NamesTechnique,
     .stopsBefore = true,
     .when = [](const RendererState&,
                const Frame& f) { return f.setup.countMaskChange && f.setup.hadMask; },
     .run = maskChangeStep},
    {.name = "aliasing statistics",
     .timedPass = "resolve",
     .failure = StepFailure::NamesTechnique,
     .stopsBefore = true,
     .when = [](const RendererState& s,
                const Frame& f) { return f.setup.publishing && wantsAliasingStats(s.publication); },
     .run = aliasingStatsStep},
    {.name = "composite",
     .timedPass = "composite",
     .failure = StepFailure::Propagates,
     .stopsBefore = true,
     .when = nullptr,
     .run = compositeStep},
    {.name = "outside view",
     .timedPass = nullptr,
     .failure = StepFailure::NamesOutsideView,
     .stopsBefore = true,
     .when = [](const RendererState&, const Frame& f) { return f.setup.showOutsideView; },
     .run = outsideViewStep},
    {.name = "present",
     .timedPass = nullptr,
     .failure = StepFailure::Propagates,
     .stopsBefore = true,
     .when = nullptr,
     .run = presentStep},
};

/// The renderer's own numbers (rendererPublicationDecls): camera, light, parameter values.
void publishFrameNumbers(RendererState& s, int height, float aspect);
/// The message of a step's error, or nothing when it propagates.
std::optional<std::string> stepFailureMessage(const RendererState& s, StepFailure failure,
                                              const std::exception& e);
/// What this frame shows (scene, technique, parameters, size, camera, light); the error
/// overlay is only drawn for a matching reference.
std::string frameSignatureOf(const RendererState& s, const ParamSet& params, int width, int height);
/// The end of a frame's transaction: a complete frame (FrameStats::complete) keeps its resolve
/// targets as the previous frame's and commits the technique's state across frames; any other
/// call (stopped, failed, a progressive call short of its last unit) discards that state, and
/// the next frame starts from the last complete one (Technique::commitFrame).
void endFrame(RendererState& s, bool complete);
/// FrameStats of the frame the steps rendered, or of the part a frame the host's flag stopped
/// before `stoppedBefore` did.
void fillStats(RendererState& s, Frame& f, const FrameStep* stoppedBefore);

}  // namespace sl::frame
