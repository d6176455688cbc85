// Cascaded shadow maps (z-partitioning; Lloyd, Tuft, Yoon, Manocha, EGSR 2006 §5.2; the
// practical split of Zhang et al. 2006): k orthographic depth maps in one texture array,
// each fitted to one slice of the view frustum (algo/partition/CascadeFit), stabilised by
// default, the lookup selecting the map by view depth (shaders/cascades/lookup.glsl).
#pragma once

#include <optional>
#include <vector>

#include "algo/partition/CascadeFit.h"
#include "core/PartitionMStats.h"
#include "core/ShadowPass.h"
#include "core/Technique.h"

namespace sl {

class CascadedShadowMap : public Technique {
 public:
  static TechniqueInfo info();
  explicit CascadedShadowMap(const gl::ShaderLibrary& lib);

  void renderShadows(FrameContext& ctx) override;
  std::string lookupShader() const override { return "cascades/lookup.glsl"; }
  void bindLookup(const gl::Program& resolve, int firstUnit) const override;
  std::vector<const gl::Program*> programs() const override {
    std::vector<const gl::Program*> p = depthProgram_.programs();
    p.insert(p.end(), {&rangeProgram_, &mStats_.program()});
    return p;
  }
  MemoryStats memory() const override;
  std::optional<std::string> reloadShaders(const gl::ShaderLibrary& lib) override;
  void resetTemporalState() override;
  void commitFrame() override { range_.commit(); }
  void discardFrame() override { range_.discard(); }

 private:
  /// Last frame's min/max view depth of the G-buffer, read behind its fence (no stall).
  std::optional<glm::dvec2> readDepthRange();
  void reduceDepthRange(const FrameContext& ctx);

  DepthProgram depthProgram_;
  gl::Program rangeProgram_;
  PartitionMStats mStats_;  ///< partition.<i>.m.* (only while requested)
  DepthMapArray maps_;      ///< one layer per partition
  gl::Buffer rangeBuffer_;  ///< 2 uints: min and max view depth bits
  gl::Fence rangeFence_;
  /// What depth.fit carries across frames (TechniqueInfo::temporalState).
  struct DepthRanges {
    std::optional<glm::dvec2> last;  ///< the last range read back (kept while unchanged)
    std::optional<glm::dvec2> held;  ///< stabilised: the range the splits cut (hysteresis)
  };
  FrameCarried<DepthRanges> range_;
  partition::CascadeFit fit_;
  std::vector<DepthMapView> views_;
  glm::vec3 eye_{0.0f}, forward_{0.0f, 0.0f, -1.0f};
};

}  // namespace sl
