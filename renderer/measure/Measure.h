// Measuring configurations frame by frame (techniques.md, "Measuring"), shared by
// shadowlab-cli's `bench`, `stability`, suites and `reproduce` and by the GUI's Charts panel: a
// configuration is a technique with parameter values; each gets its own Renderer (so switching
// between configurations, interleaved frame by frame, never reallocates maps or mixes temporal
// state), and one exact Embree reference per frame serves every configuration (the G-buffer does
// not depend on the technique).
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "algo/metrics/BenchStats.h"
#include "core/Renderer.h"
#include "measure/UsageError.h"
#include "metrics/ShadowReference.h"

namespace sl::measure {

/// One technique with parameter values (technique or shared renderer parameters).
struct ConfigSpec {
  std::string techniqueId;
  std::vector<std::pair<std::string, std::string>> sets;  ///< key, value text; in order
  std::string label;  ///< unique name, e.g. "uniform resolution=512"

  /// "resolution=512 pcf=1" (all sets), or "" when none.
  std::string paramsText() const;
};

/// Techniques offered besides the built-in list (Renderer::techniques()), to every
/// configuration measured after the call: a program that links the measuring code adds its
/// own (RendererOptions::extraTechniques). Call before any ConfigRunner exists.
void addExtraTechnique(TechniqueEntry entry);
/// A technique of the built-in list or an added one; null when none has that id.
const TechniqueInfo* findTechniqueInfo(const std::string& id);

/// Checks that the technique exists, every key is a parameter of it (or a shared one),
/// every value is in range and the values together are ones the technique renders
/// (TechniqueInfo::checkParams); the error names the problem.
std::optional<std::string> validateConfig(const ConfigSpec& spec);

/// Parses "ID[:KEY=V1,V2,...]..." (e.g. "uniform:resolution=512,1024:pcf=0,1") into the
/// cartesian product of the listed values, in the order listed (last key fastest).
/// Throws UsageError (naming `opt`) for bad syntax, unknown technique, key or value.
std::vector<ConfigSpec> expandTechniqueSweep(const std::string& text,
                                             const std::string& opt = "--technique");

/// The exact reference of the last evaluated frame, reused while positions, normals and
/// light are unchanged (a static camera costs one evaluation, every configuration shares
/// each frame's).
class ReferenceCache {
 public:
  explicit ReferenceCache(const Scene& scene) : reference_(scene) {}
  const std::vector<std::uint8_t>& evaluate(const FrameReadback& frame, const Light& light);
  int evaluations() const { return evaluations_; }

 private:
  ShadowReference reference_;
  std::vector<glm::vec4> positions_, normals_;
  Light light_;
  std::vector<std::uint8_t> mask_;
  bool valid_ = false;
  int evaluations_ = 0;
};

/// What one frame of one configuration measured.
struct FrameSample {
  /// renderFrame's error: the frame failed and measured nothing (every number below stays
  /// at its default and is never counted; see failed()).
  std::string renderError;
  std::vector<std::string> glErrors;
  double totalMs = 0.0;
  std::vector<PassTiming> passes;
  std::string timingMethod;
  std::uint64_t texels = 0, bytes = 0;
  bool hasReference = false;
  ShadowErrorStats error;                ///< against the reference (when hasReference)
  DistanceSplitError errorByDistance;    ///< the same, nearer and farther than the median
  AliasingStats aliasing;                ///< m over covered pixels
  std::optional<MaskChange> maskChange;  ///< against this configuration's previous frame
  std::optional<FlickerStats> flicker;   ///< needs the reference of both frames
  bool hasRotation = false;              ///< the technique published "rotation.deg"
  double rotationDeg = 0.0;              ///< the rotation R_k in degrees (0 without one)
  double ex = 1.0;                       ///< principal axis x component (1 without one)
  bool held = true;                      ///< the threshold held the rotation (true without one)
  std::vector<std::string> nonFiniteNumbers;  ///< published numbers that are NaN/inf
  /// RTW's light frustum area (m^2) and the half-mass widths of its collapsed importance
  /// (share of the map side); NaN when not published.
  double lightAreaM2 = std::numeric_limits<double>::quiet_NaN();
  double halfMassX = std::numeric_limits<double>::quiet_NaN();
  double halfMassY = std::numeric_limits<double>::quiet_NaN();
  double anisotropy = std::numeric_limits<double>::quiet_NaN();  ///< DA-RTW's (λ1−λ2)/(λ1+λ2)
  /// Every number the technique published this frame (MeasureOptions::publishing).
  std::map<std::string, double> numbers;
  /// The shaded image and its error image (magenta false lit, cyan false shadowed) when
  /// MeasureOptions::keepImages and the frame had a reference; empty otherwise.
  ImageRGBA8 color, errorImage;

  bool failed() const { return !renderError.empty(); }
};

/// The first failed frame of a run, "frame 3: camera: position, target or up is not finite"
/// (cut to the 300-character rule), or "" when every frame rendered. `frames` in the order
/// they ran, numbered from 0.
std::string firstFailureText(const std::vector<const FrameSample*>& frames);

struct MeasureOptions {
  int width = 640, height = 360;
  bool reference = true;    ///< Embree reference: error, flicker
  bool publishing = false;  ///< ask for the published numbers (rotation): no readback
  bool keepImages = false;  ///< keep the frame's image and error image (FrameSample::color)
};

/// One configuration with its own renderer (needs the current GL context).
class ConfigRunner {
 public:
  ConfigRunner(ConfigSpec spec, std::shared_ptr<const Scene> scene,
               const std::optional<Light>& light);
  ~ConfigRunner();
  ConfigRunner(const ConfigRunner&) = delete;
  ConfigRunner& operator=(const ConfigRunner&) = delete;
  const ConfigSpec& spec() const { return spec_; }
  Renderer& renderer() { return *renderer_; }

  /// Renders one frame from `camera` and measures it. `reference` may be null (no error or
  /// flicker). The mask change and flicker compare with this runner's previous frame. A
  /// frame renderFrame refuses is returned failed (renderError set, nothing read back or
  /// compared), and the next frame compares with none.
  FrameSample renderAndMeasure(const Camera& camera, const MeasureOptions& options,
                               ReferenceCache* reference);
  /// Renders one frame from `camera` that is not measured (an in-between frame along a
  /// path): the renderer's temporal state advances as in any frame, with the same
  /// publications asked for, but nothing is read back or compared, and the previous frame
  /// the next measurement compares with stays the last measured one. GL errors count
  /// against the next measured frame. renderFrame's error, or nothing.
  std::optional<std::string> renderUnmeasured(const Camera& camera, const MeasureOptions& options);
  /// Frames this runner rendered, measured or not (warm-up included).
  std::size_t framesRendered() const { return framesRendered_; }
  /// Forgets the previous frame (no mask change or flicker against it); the renderer's
  /// temporal state (DA-RTW's rotation) stays, so warm-up frames settle it.
  void forgetPreviousFrame();

 private:
  /// The published numbers a frame asks for (MeasureOptions::publishing).
  std::set<std::string> numberKeys(const MeasureOptions& options) const;

  ConfigSpec spec_;
  std::unique_ptr<Renderer> renderer_;
  bool publishingWanted_ = true;  ///< off once a frame showed there is nothing to read
  std::size_t framesRendered_ = 0;
  std::vector<std::uint8_t> previousMask_, previousReference_;
};

/// Medians over the frames of one configuration that rendered; a failed frame is counted
/// and named, never measured.
struct ConfigSummary {
  double totalMs = 0;
  std::vector<double> frameMs;  ///< every frame's total, in the order the frames ran (NaN: failed)
  std::map<std::string, double> passMs;
  std::string timingMethod;
  double texels = 0, bytes = 0;
  /// Over the frames with a covered pixel; NaN (not measured) when none had one. `covered`
  /// is the median over the same frames: 0 exactly when the error was measured on none.
  double errorPct = 0, falseLitPct = 0, falseShadowPct = 0, covered = 0;
  /// The error of the covered pixels at or nearer than each frame's median distance from the
  /// camera, and beyond it (DistanceSplitError); NaN when not measured.
  double errorNearPct = 0, errorFarPct = 0;
  /// m over the frames with a covered pixel that has a shadow-map coordinate; NaN when none.
  double aliasingMean = 0, aliasingP95 = 0, aliasingMax = 0;
  /// Over the consecutive frames that compared a covered pixel; NaN when none (one frame).
  double flickerPct = 0;
  double lightAreaM2 = 0, halfMassX = 0, halfMassY = 0;  ///< NaN when not published
  double rotationDeg = 0;  ///< DA-RTW's image-plane angle R (NaN without a rotation)
  double anisotropy = 0;   ///< DA-RTW's (λ1−λ2)/(λ1+λ2) (NaN without one)
  std::size_t renderErrors = 0, glErrors = 0;  ///< failed frames; GL errors in all frames
  std::string failure;  ///< the first failed frame and why ("" when every frame rendered)
  /// No frame rendered: a failed row, every number empty.
  bool failed() const { return !failure.empty() && frameMs.size() == renderErrors; }
};

ConfigSummary summarise(const std::vector<FrameSample>& all);

/// Path time between the frames a configuration renders along a camera path (`--path-hz`,
/// a suite case's "path_hz"): between two measured frames it renders one every 1/HZ s, so
/// its temporal state (DA-RTW's rotation, a page cache, hysteresis) is what a real-time user
/// at HZ frames a second would see. 0: the measured frames only (the spacing before there
/// were in-between frames: a 10 s path in 12 frames is 0.9 s a frame).
inline constexpr double kDefaultPathHz = 30.0;
inline constexpr double kMaxPathHz = 240.0;
/// The most in-between frames one configuration renders in a run (a glTF path may last
/// hours): more is refused naming --path-hz.
inline constexpr std::size_t kMaxInBetweenFrames = 100000;

/// The cameras of a run: one per measured frame and, before each, the unmeasured frames
/// each configuration renders right before it (in path order).
struct MeasureCameras {
  std::vector<Camera> measured;
  /// Per measured frame (same size as `measured`): empty for the first frame, a fixed
  /// camera, path time too short for one, or path_hz 0.
  std::vector<std::vector<Camera>> between;
  double pathHz = 0.0;  ///< the spacing used; 0 with a fixed camera (no path)
  bool alongPath = false;
  std::size_t betweenCount() const;  ///< in-between frames of one configuration, in all
};

/// `frames` measured cameras spread evenly along `path` (CameraPath::sampleFrame: frame f
/// at path time t_f = start + f / (frames - 1) of its duration) and, with `hz` > 0, before
/// frame f > 0 the cameras at t_f - k / hz for k = ..., 2, 1 while later than t_{f-1}: the
/// last comes 1/hz before t_f, as a real-time frame would. UsageError naming `opt` when
/// there would be more than kMaxInBetweenFrames.
MeasureCameras pathCameras(const CameraPath& path, int frames, double hz,
                           const std::string& opt = "--path-hz");

/// One camera per measured frame: `frames` along a camera path (`path`, or the scene's first
/// when neither is given and it has one; in-between frames every 1/`pathHz` s, see
/// pathCameras), else a fixed bookmark (`camera`, no in-between frames). `cameraText` names
/// it ("path walk", "camera (first bookmark)"). UsageError when both are given or the name
/// is not the scene's.
MeasureCameras measureCameras(const Scene& scene, const std::string& path,
                              const std::string& camera, int frames, double pathHz,
                              std::string& cameraText);

/// Every configuration renders every measured camera, interleaved frame by frame (the
/// starting configuration rotates so none always runs right after the reference), after
/// `warmup` unmeasured frames of each at the first camera (shaders compile, maps are
/// allocated, DA-RTW's rotation settles). Right before each of its measured frames a
/// configuration renders that frame's in-between cameras (ConfigRunner::renderUnmeasured: no
/// reference, nothing read back). `onSample(config, frame, sample)` sees each sample before
/// it is stored. Returns the samples per configuration, in frame order.
std::vector<std::vector<FrameSample>> runInterleaved(
    const std::vector<std::unique_ptr<ConfigRunner>>& runners, const MeasureCameras& cameras,
    const MeasureOptions& options, ReferenceCache* reference, int warmup,
    const std::function<void(std::size_t, int, const FrameSample&)>& onSample);

/// Renders `between` (a measured frame's in-between cameras) with `runner`, then measures
/// `camera`. A failed in-between frame fails the measured frame (its temporal state is not
/// the one measured): the sample says so and nothing is rendered after it.
FrameSample renderBetweenAndMeasure(ConfigRunner& runner, const std::vector<Camera>& between,
                                    const Camera& camera, const MeasureOptions& options,
                                    ReferenceCache* reference);

}  // namespace sl::measure
