// Measuring configurations frame by frame (techniques.md, "Measuring"), shared by `bench`
// and `stability`: a configuration is a technique with parameter values; each gets its
// own Renderer (so switching between configurations, interleaved frame by frame, never
// reallocates maps or mixes temporal state), and one exact Embree reference per frame
// serves every configuration (the G-buffer does not depend on the technique).
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "algo/metrics/BenchStats.h"
#include "core/Renderer.h"
#include "metrics/ShadowReference.h"

namespace sl::cli {

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
  /// Forgets the previous frame (no mask change or flicker against it); the renderer's
  /// temporal state (DA-RTW's rotation) stays, so warm-up frames settle it.
  void forgetPreviousFrame();

 private:
  ConfigSpec spec_;
  std::unique_ptr<Renderer> renderer_;
  bool publishingWanted_ = true;  ///< off once a frame showed there is nothing to read
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

/// One camera per frame: `frames` along a camera path (`path`, or the scene's first when
/// neither is given and it has one), else a fixed bookmark (`camera`). `cameraText` names
/// it ("path walk", "camera (first bookmark)"). UsageError when both are given or the name
/// is not the scene's.
std::vector<Camera> measureCameras(const Scene& scene, const std::string& path,
                                   const std::string& camera, int frames, std::string& cameraText);

/// Every configuration renders every camera, interleaved frame by frame (the starting
/// configuration rotates so none always runs right after the reference), after `warmup`
/// unmeasured frames of each at the first camera (shaders compile, maps are allocated,
/// DA-RTW's rotation settles). `onSample(config, frame, sample)` sees each sample before it
/// is stored. Returns the samples per configuration, in frame order.
std::vector<std::vector<FrameSample>> runInterleaved(
    const std::vector<std::unique_ptr<ConfigRunner>>& runners, const std::vector<Camera>& cameras,
    const MeasureOptions& options, ReferenceCache* reference, int warmup,
    const std::function<void(std::size_t, int, const FrameSample&)>& onSample);

}  // namespace sl::cli
