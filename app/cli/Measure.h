// Measuring configurations frame by frame (techniques.md, "Measuring"), shared by `bench`
// and `stability`: a configuration is a technique with parameter values; each gets its
// own Renderer (so switching between configurations, interleaved frame by frame, never
// reallocates maps or mixes temporal state), and one exact Embree reference per frame
// serves every configuration (the G-buffer does not depend on the technique).
#pragma once

#include <cstdint>
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

}  // namespace sl::cli
