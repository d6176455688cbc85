// Face-partitioned shadow maps (Lloyd, Tuft, Yoon, Manocha, EGSR 2006 §5.1): the view frustum
// split along its faces as seen from the light, one LiSPSM map per face (its own layer of a
// texture array) warped along the bisector of the face's projected side edges; the lookup
// picks a pixel's face by where its light ray leaves the frustum (algo/partition/FacePartitionFit).
// face.zsplits = k > 1: the frustum is first cut into k depth slices (log split) and every
// slice face-partitioned, 5 slots per slice (their combined scheme).
#pragma once

#include <vector>

#include "algo/partition/FacePartitionFit.h"
#include "core/PartitionMStats.h"
#include "core/ShadowPass.h"
#include "core/Technique.h"

namespace sl {

class FacePartitionShadowMap : public Technique {
 public:
  static TechniqueInfo info();
  explicit FacePartitionShadowMap(const gl::ShaderLibrary& lib);

  void renderShadows(FrameContext& ctx) override;
  std::string lookupShader() const override { return "facepartition/lookup.glsl"; }
  void bindLookup(const gl::Program& resolve, int firstUnit) const override;
  std::vector<const gl::Program*> programs() const override {
    std::vector<const gl::Program*> p = depthProgram_.programs();
    p.push_back(&mStats_.program());
    return p;
  }
  MemoryStats memory() const override;
  std::optional<std::string> reloadShaders(const gl::ShaderLibrary& lib) override;

  /// The last frame's partitions (their faces, bodies, warps and the selection rule).
  const partition::FacePartitionFit& lastFit() const { return fit_; }

 private:
  DepthProgram depthProgram_;
  PartitionMStats mStats_;  ///< partition.<i>.m.* per slot (only while requested)
  DepthMapArray maps_;      ///< one layer per (slice, face) slot
  partition::FacePartitionFit fit_;
  std::vector<DepthMapView> views_;
};

}  // namespace sl
