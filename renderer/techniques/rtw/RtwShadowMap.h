// Rectilinear Texture Warping (Rosen, I3D 2012; seed 002) with forward, backward or hybrid
// importance analysis, and its directionality-aware variant (seed 000): PCA of the
// importance map through a moment mip chain rotates the light's image plane so that
// diagonal importance lines up with a shadow-map axis. techniques.md §2-3.
// Every GPU pass mirrors a function of algo/rtw/ (the CPU reference; parity-tested).
#pragma once

#include <optional>
#include <vector>

#include "algo/Focus.h"
#include "algo/rtw/Rotation.h"
#include "algo/rtw/TurnPrediction.h"
#include "common/shared_constants.h"
#include "core/ShadowPass.h"
#include "core/Technique.h"

namespace sl {

class RtwShadowMap : public Technique {
 public:
  enum class Analysis { Forward, Backward, Hybrid };
  struct Config {
    Analysis analysis = Analysis::Backward;
    bool rotation = false;  ///< DA-RTW
  };
  static TechniqueInfo info(const std::string& id);
  /// DA-RTW's TechniqueInfo::settled: the frame made an estimate and left R as it was (no axis,
  /// held, or no step); in predicted mode once a prediction could weigh shadow edges.
  static std::optional<bool> rotationSettled(const Publication& pub);
  /// DA-RTW's PCA reads the IM reduced to at most this size (block maxima): seed 000's
  /// moments need the distribution's shape, not 512^2 texels.
  static constexpr int kMomentImMax = SL_MOMENT_IM_MAX;  ///< common/shared_constants.h
  /// Side of the IM the PCA reads: im.resolution (pca.source = im, the poster) or
  /// min(im.resolution, kMomentImMax) (block-max).
  static int momentResolution(const ParamSet& params, int imRes);
  /// The passes of technique `id` in frame order, as timed (RtwDeclarations.cpp).
  static std::vector<PassDecl> passDecls(const std::string& id);
  /// What technique `id` publishes when asked, with the readback cost of each key.
  static std::vector<PublicationDecl> publicationDecls(const std::string& id);
  RtwShadowMap(const gl::ShaderLibrary& lib, Config config);

  void renderShadows(FrameContext& ctx) override;
  std::string lookupShader() const override { return "rtw/lookup.glsl"; }
  void bindLookup(const gl::Program& resolve, int firstUnit) const override;
  std::vector<const gl::Program*> programs() const override;
  MemoryStats memory() const override;
  std::optional<std::string> reloadShaders(const gl::ShaderLibrary& lib) override;
  void resetTemporalState() override;
  /// DA-RTW: the rotation and the moments the next frame reads are the last complete frame's.
  void commitFrame() override;
  void discardFrame() override;

  const rtw::RotationState& rotation() const { return carried_->rotation; }

 private:
  void ensureResources(int smRes, int imRes, const FrameContext& ctx);
  /// Exchanges what the next frame reads of this frame's moments (spread_: the 1D maps and the
  /// moment chain's top, and its fence) with the spare set (created on first use).
  void swapMoments();
  void rotationFromLastMoments(FrameContext& ctx);
  /// rotation.mode = predicted (or the prediction's keys asked for): the last frame's moment IM
  /// and counts read back (behind the moment fence), the candidate turns scored and, in
  /// predicted mode, R turned to the decision's angle.
  void predictTurn(FrameContext& ctx, std::optional<double> pcaAxisDeg, bool apply);
  /// The light frustum this frame would get turned to angleDeg (the fit renderShadows makes).
  LightFit fitAt(const FrameContext& ctx, const glm::mat2& rotation) const;
  rtw::ImportanceSnapshot readSnapshot() const;
  void publishRotation(FrameContext& ctx);
  void buildMoments(FrameContext& ctx);
  void buildImportance(FrameContext& ctx, const glm::mat4& lightViewProj, float lightTexelM);
  void buildWarpMaps(FrameContext& ctx);
  void renderWarped(FrameContext& ctx, const glm::mat4& lightViewProj, bool warp);
  void publish(FrameContext& ctx, const glm::mat4& lightViewProj);
  bool backward() const { return config_.analysis == Analysis::Backward; }
  /// Binds the warp maps and inverse tables (shaders/rtw/warp.glsl) to `unit`, `unit + 1`.
  void bindWarpTextures(const gl::Program& prog, int unit) const;

  Config config_;
  gl::Program backward_, forward_, collapse_, blur_, scanWarp_, inverseWarp_, warped_,
      warpedVertex_,  ///< warp.depth = interpolated without tessellation: seed 002's pass
      moments_, momentsLevel1_, momentsReduce_;
  gl::Texture shadowMap_;
  /// The 2D importance map: the forward/hybrid render target; for backward analysis (which
  /// scatters straight into the 1D maps) made only while a panel shows it.
  gl::Texture importance_, forwardDepth_;
  gl::Texture momentIm_;    ///< DA-RTW: the IM the PCA reads, at most kMomentImMax^2
  gl::Texture uniformMap_;  ///< unwarped contrast map, only while a panel shows it
  gl::Framebuffer smFbo_, forwardFbo_, uniformFbo_;
  gl::Buffer collapsed_, blurred_, warp_, inverse_, momentBuffer_;
  gl::Buffer spread_;  ///< DA-RTW: a copy of the last frame's 1D maps (the spread gate)
  /// DA-RTW: per moment IM texel, the scattering pixels and the edge-normal bins
  /// (SL_RTW_COUNT_PLANES planes of momentRes^2 uints: pixels, importance sum, edge bins).
  gl::Buffer momentCounts_;
  gl::Texture warpView_, inverseView_;  ///< buffer textures over warp_ and inverse_
  gl::Framebuffer scatterFbo_;          ///< no attachments: the backward scatter's pass
  gl::VertexArray emptyVao_;
  gl::Fence momentFence_;  ///< after the last frame's moment chain and 1D maps (read a frame late)
  std::vector<int> momentOffsets_;  ///< float offset of each level
  std::vector<glm::ivec2> momentSizes_;
  int smRes_ = 0, imRes_ = 0, momentRes_ = 0;
  DepthMapView view_;
  glm::vec2 lastExtentM_{1.0f};
  glm::mat4 lastViewProj_{1.0f};
  /// What DA-RTW carries across frames (TechniqueInfo::temporalState): R, and what the moments
  /// the next frame reads were taken in.
  struct Carried {
    rtw::RotationState rotation;
    glm::vec2 momentExtentM{1.0f};   ///< the light frustum extent the pending moments were taken in
    glm::mat4 momentViewProj{1.0f};  ///< ... and its view-projection (the prediction's snapshot)
    double momentAngleDeg = 0.0;     ///< ... and the angle of R it was turned by
  };
  FrameCarried<Carried> carried_;
  /// The other set of spread_ and momentFence_: a frame reads the last complete frame's, swaps,
  /// and writes its own into the other; a discarded frame swaps back (discardFrame).
  gl::Buffer spareSpread_;
  gl::Fence spareFence_;
  bool swappedThisFrame_ = false;
  /// The turn prediction's reading of the last complete frame's moment IM and counts (which a
  /// frame overwrites): kept when a frame is discarded, forgotten when one commits.
  std::optional<rtw::ImportanceSnapshot> snapshot_;
  rtw::RotationUpdate lastUpdate_;
  std::array<float, 6> lastTop_{};
  /// The last prediction: every candidate scored and the decision (valid when searched).
  rtw::TurnSearch lastSearch_;
  rtw::TurnDecision lastDecision_;
  bool predicted_ = false;   ///< this frame made a prediction
  double pcaAxisDeg_ = 0.0;  ///< PCA's axis as an absolute angle (when valid)
};

}  // namespace sl
