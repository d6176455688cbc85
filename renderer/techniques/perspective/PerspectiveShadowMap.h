// PSM, LiSPSM and TSM: one depth map rendered through a perspective warp along light-space z
// (Lloyd et al., EGSR 2006, §4 and eq. 11; Wimmer et al. 2004; Stamminger and Drettakis 2002;
// Martin and Tan 2004), fitted each frame around view frustum ∩ scene (algo/warp).
#pragma once

#include <string>

#include "algo/warp/PerspectiveWarp.h"
#include "algo/warp/PostPerspective.h"
#include "core/ShadowPass.h"
#include "core/Technique.h"
#include "core/Warp.h"

namespace sl {

class PerspectiveShadowMap : public SingleDepthMapTechnique {
 public:
  enum class Kind { Psm, Lispsm, Tsm };
  /// "psm", "lispsm" or "tsm"; throws std::invalid_argument for anything else.
  static TechniqueInfo info(const std::string& id);
  PerspectiveShadowMap(const gl::ShaderLibrary& lib, Kind kind);

  void renderShadows(FrameContext& ctx) override;
  std::string lookupShader() const override { return "perspective/lookup.glsl"; }

  /// The last frame's warp (n', eta, the fallback and its reason, the PSM clamp note).
  const warp::WarpFit& lastFit() const { return fit_; }
  /// psm with psm.method = post-perspective: the last frame's Stamminger-Drettakis fit.
  const warp::PsmFit& lastPsmFit() const { return psmFit_; }
  /// The post-perspective fit psm renders for this scene, camera and light with `params`
  /// (psm's psm.near, psm.slide): receivers, casters, the pushed near plane.
  static std::optional<std::string> fitPostPerspectiveFor(const Scene& scene, const Camera& camera,
                                                          float aspect, glm::vec3 towards,
                                                          const ParamSet& params,
                                                          warp::PsmFit& out);

 private:
  void renderPostPerspective(FrameContext& ctx);

  Kind kind_;
  warp::WarpFit fit_;
  warp::PsmFit psmFit_;
};

}  // namespace sl
