// What a frame costs: per-pass time (with the timing method used) and the memory of
// every shadow-related resource. Published by the renderer; read by CLI, UI and tests.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "algo/Camera.h"
#include "algo/OutsideView.h"

namespace sl {

/// How pass times are measured (gl::GpuTimer): glFinish + a wall clock around each pass (this
/// frame's times; software rasterisers, where GL_TIME_ELAPSED is meaningless), or
/// GL_TIME_ELAPSED timer queries read a frame late (real GPUs).
enum class TimingMethod { FinishWallClock, TimerQuery };

struct PassTiming {
  std::string name;  ///< e.g. "gbuffer", "shadow map", "resolve"
  double ms = 0.0;
};

struct ResourceInfo {
  std::string name;    ///< e.g. "shadow map"
  std::string format;  ///< e.g. "DEPTH_COMPONENT32F"
  int width = 0, height = 1, layers = 1;
  std::uint64_t texels = 0;
  std::uint64_t bytes = 0;
  /// Held only while a panel shows it (a debug view): not the technique's memory.
  bool debugView = false;
};

struct MemoryStats {
  std::vector<ResourceInfo> resources;  ///< shadow-related resources of the technique
  /// The technique's memory: every resource but the debug views (the same with or without
  /// a panel open, so the GUI and the CLI report the same figure).
  std::uint64_t texels() const;
  std::uint64_t bytes() const;
  /// What is held only for the panels (debug views), reported apart.
  std::uint64_t debugViewBytes() const;
  /// Everything allocated: bytes() + debugViewBytes().
  std::uint64_t allocatedBytes() const { return bytes() + debugViewBytes(); }
  void add(std::string name, std::string format, int width, int height, int layers,
           int bytesPerTexel);
  /// A resource held only while a panel shows it.
  void addDebugView(std::string name, std::string format, int width, int height, int layers,
                    int bytesPerTexel);
};

struct FrameStats {
  std::uint64_t frameIndex = 0;
  int width = 0, height = 0;
  /// Per declared pass, the sum of its scopes (a pass repeated per tile or cascade is one
  /// entry), in the order each was first timed.
  std::vector<PassTiming> passes;
  /// The same timer results, one entry per scope in the order they ran (unsummed): e.g. a
  /// "tile depth" / "tile apply" pair per tile (tileTimingCurve).
  std::vector<PassTiming> passSequence;
  /// The passes this frame opened, one name per declared pass in the order each was first
  /// opened: the names `passes` holds once this frame's times arrive. Known when each scope
  /// opens, so it is this frame's whatever the timing method (`passes` may be
  /// `timingFramesLate` frames old).
  std::vector<std::string> passOrder;
  double totalMs = 0.0;
  /// "glFinish+wallclock" (software rasterisers, where GL_TIME_ELAPSED is meaningless)
  /// or "GL_TIME_ELAPSED" (timer queries on real GPUs).
  std::string timingMethod;
  /// How many frames old `passes` are: 0 for glFinish+wallclock; timer queries are read a
  /// frame late so the CPU never waits on the GPU (1; more while the GPU lags; the first
  /// frame has no passes).
  int timingFramesLate = 0;
  MemoryStats memory;
  /// Bytes read back from the GPU this frame for the requested publications (0 when
  /// nothing is requested), counted by the readback helpers themselves.
  std::uint64_t publicationBytes = 0;
  /// What the technique published for the outside view (its maps' frusta, split depths);
  /// filled every frame, drawn only while view.outside is on.
  FrameOutlines outlines;
  /// The third camera of this frame when view.outside is on (algo/OutsideView).
  std::optional<Camera> outsideCamera;
  /// Pixels of the hard mask that changed since the previous frame (common/mask_change.comp,
  /// CPU mirror sl::compareConsecutiveMasks): counted while view.overlay is "changed" or a
  /// "mask.*" key is requested, else absent (and absent on the first frame of a size).
  struct MaskChangeCount {
    std::uint64_t compared = 0;  ///< pixels covered in both frames
    std::uint64_t changed = 0;   ///< of which lit in one and shadowed in the other
  };
  std::optional<MaskChangeCount> maskChange;
  /// A progressive resolve (Renderer::setProgressiveBudget, a technique that resolves unit by
  /// unit): the units done of this view and their number. Absent for a one-call resolve (the
  /// frame is complete). `shownComplete`: the targets hold every unit of this view (a whole
  /// pass has finished since the view last changed; later calls refresh it in place).
  struct Progress {
    int done = 0, total = 0;
    bool shownComplete = false;
    bool completedNow = false;  ///< this call finished the pass (done == total)
    double spentMs = 0.0;       ///< wall time this call spent on units (within the budget)
    int unitsPerTile = 1;       ///< units (bands) per tile: tiles done = done / unitsPerTile
  };
  std::optional<Progress> progress;
  /// The host's stop flag stopped this frame between its steps (Renderer::setCancelFlag): the
  /// stats hold what ran (no measurement), and nothing was presented. Reset every frame.
  bool cancelled = false;
  /// The step it stopped before ("shadows", "composite", ...: kFrameSteps in
  /// core/Renderer.cpp); empty when not cancelled.
  std::string stoppedBefore;
  /// False while the view shows a partial progressive result or the frame was cancelled
  /// (metrics and error wait).
  bool complete() const { return !cancelled && (!progress || progress->shownComplete); }
  double passMs(const std::string& name) const;
};

/// Per tile of a technique that times its tiles as repeated scopes (TechniqueInfo::tileTiming),
/// from the unsummed `sequence` (FrameStats::passSequence): for each `applyPass` scope, in
/// order, two values — the ms of the `depthPass` scopes since the previous `applyPass` scope
/// (or the start), and of that `applyPass` scope. Other scopes are skipped; depth scopes
/// after the last apply (a tile not applied yet) are not listed.
std::vector<float> tileTimingCurve(const std::vector<PassTiming>& sequence,
                                   const std::string& depthPass, const std::string& applyPass);

}  // namespace sl
