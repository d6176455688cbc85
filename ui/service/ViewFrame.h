// One frame of the view as it travels between the two threads: the ORDER the UI thread
// builds (everything the render thread needs, copied: scene pointer, camera, light, both
// sides' techniques and parameters, sizes, a probe, a reference mask to upload) and the
// OUTCOME the render thread sends back (the images, each side's stats and publication, its
// problem, snapshots for the live reference). Plus the other jobs of the view that need
// GL: the error of the last frame, the figure export, the equal-memory match. No GL header.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <QImage>
#include <QPoint>

#include "figures/FigureTypes.h"
#include "core/Renderer.h"
#include "core/ViewSide.h"
#include "metrics/AsyncReference.h"

namespace sl::ui {

class RenderContext;

struct FrameOrder {
  std::uint64_t id = 0;
  std::uint64_t viewRevision = 0;
  std::shared_ptr<const sl::Scene> scene;
  sl::Camera camera;
  sl::Light light;
  sl::ParamSet shared;  ///< view and shading parameters (both halves)
  sl::SideRequest main;
  std::optional<sl::SideRequest> split;  ///< the right half, when drawn
  bool clearOnly = false;                ///< a view too small to draw: nothing rendered
  int divisor = 1;                       ///< adaptive resolution's (1: full size)
  bool fullSize = false;                 ///< a settle or export frame (not adaptive's sample)
  int frameWidth = 0, frameHeight = 0;   ///< the main half's internal size
  int splitWidth = 0;                    ///< the right half's internal width
  double progressiveBudgetMs = 0.0;
  std::optional<QPoint> probe;  ///< internal pixel of the main half to probe after the frame
  bool snapshotMain = false, snapshotSplit = false;  ///< live reference: snapshots wanted
  /// A finished trace's mask for the main renderer's error overlay.
  std::optional<sl::FinishedReference> referenceMask;
};

struct FrameOutcome {
  std::uint64_t id = 0;
  std::uint64_t viewRevision = 0;
  int divisor = 1;
  bool fullSize = false;
  bool hasSplit = false;
  bool stopped = false;  ///< a newer order stopped it: nothing here is shown or measured
  QImage mainImage, splitImage;
  sl::FrameStats mainStats, splitStats;
  sl::Publication mainPublication, splitPublication;
  std::string mainProblem;   ///< renderFrame's problem (the frame is the neutral one)
  std::string splitProblem;  ///< "split view: …"
  std::vector<std::string> glErrors;
  double wallMs = 0.0;  ///< both halves, the render thread's wall clock
  bool probed = false;
  std::optional<sl::PixelProbe> probe;
  std::shared_ptr<sl::Renderer::ReferenceSnapshot> mainSnapshot, splitSnapshot;
};

/// On the render thread: brings the renderers "main" (and "split") to the order, renders
/// the right half first, then the main one, reads both images, probes, snapshots. Stops
/// between the halves and inside a frame when the service's stop flag is set.
void renderOrder(RenderContext& c, const FrameOrder& order, FrameOutcome& out);

/// Brings the renderer `r` to a side of `order` (scene, technique, parameters, camera, light,
/// publications); the problem, or nothing.
std::optional<std::string> applySide(sl::Renderer& r, const FrameOrder& order,
                                     const sl::SideRequest& side);

/// The split view's equal-memory match on the render thread: the largest value of `knob`
/// whose memory() is at most `mainBytes`, each candidate measured by rendering the split
/// renderer at `width` x `height` with `order`'s camera, light and parameters.
struct MemoryMatchRun {
  long long value = 0;
  std::uint64_t bytes = 0;
  bool belowMinimum = false;
  int evaluations = 0;
  std::string problem;  ///< empty: ok
};
MemoryMatchRun matchSplitMemoryOn(RenderContext& c, const FrameOrder& order,
                                  const sl::ParamDecl& knob, std::uint64_t mainBytes, int width,
                                  int height);

/// The error of the last frame of the renderer `name` (render thread): a number, or why
/// it is not one.
struct SideError {
  std::optional<double> pct;
  std::string unmeasured;
  std::string problem;  ///< the metric failed (an exception): not evaluated
};
SideError computeSideError(RenderContext& c, const std::string& name);

/// A trace of a snapshot for an AsyncReference worker (null snapshot: nothing to trace).
std::optional<sl::ReferenceJob> referenceJob(
    std::shared_ptr<sl::Renderer::ReferenceSnapshot> snapshot, std::uint64_t viewRevision,
    std::uint64_t frameNumber);

/// File > Export figure's cell of the renderer `name` (render thread): its last frame with
/// the error image; `label` names the technique and its non-default parameters.
FigureCell figureCellOf(RenderContext& c, const std::string& name, const std::string& label,
                        int dilatePx);

}  // namespace sl::ui
