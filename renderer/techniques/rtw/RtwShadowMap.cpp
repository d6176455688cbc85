// RTW / DA-RTW (RtwShadowMap.h): analysis, 1D warp maps, the exact warped depth pass.
#include "RtwShadowMap.h"

#include <bit>
#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "algo/Focus.h"
#include "algo/rtw/Moments.h"
#include "algo/rtw/Warp.h"
#include "common/shared_constants.h"
#include "core/LightBinding.h"
#include "core/ParamBinding.h"
#include "core/Publish.h"
#include "core/SceneGpu.h"
#include "core/ShadowPass.h"

namespace sl {

namespace {

/// Largest tessellation level the warped pass asks for (why 16: shared_constants.h).
constexpr int kMaxTessellationLevel = SL_MAX_TESSELLATION_LEVEL;

/// Work groups of `n` invocations for a group size of `group`.
GLuint groups(int n, int group) {
  return GLuint((n + group - 1) / group);
}

gl::ProgramDesc compute(const std::string& file) {
  return {file, {{GL_COMPUTE_SHADER, file}}, {}, {}};
}

std::vector<float> readFloats(const gl::Buffer& b, size_t offset, size_t count) {
  std::vector<float> v(count);
  glGetNamedBufferSubData(b.id(), GLintptr(offset * sizeof(float)),
                          GLsizeiptr(count * sizeof(float)), v.data());
  return v;
}

}  // namespace

TechniqueInfo RtwShadowMap::info(const std::string& id) {
  std::vector<ParamDecl> p = shadowMapParamDecls(1024);
  auto add = [&](ParamDecl d) { p.push_back(std::move(d)); };
  add(intParam("im.resolution", "IM resolution", "Importance", 512, {32, SL_IM_MAX_RESOLUTION, 32})
          .withHelp(
              "Importance map width and height (light space); also the length of the 1D maps."));
  add(switchParam("importance.eye", "Eye distance term", "Importance", true)
          .withUniform("u_eyeOn")
          .withHelp("Perspective aliasing: importance near/eye depth (Rosen 2012's only term)."));
  add(floatParam("importance.eye.weight", "Eye weight", "Importance", 1, {0, 1, 0.05})
          .withUniform("u_eyeWeight")
          .withHelp("0 = neutral, 1 = the full near/depth falloff."));
  add(switchParam("importance.orientation", "Orientation term", "Importance", true)
          .withUniform("u_orientationOn")
          .withHelp("Projection aliasing: cos(theta_eye) / cos(theta_light) of the surface."));
  add(floatParam("importance.orientation.weight", "Orientation weight", "Importance", 0.5,
                 {0, 1, 0.05})
          .withUniform("u_orientationWeight")
          .withHelp("0 = neutral, 1 = the full cosine ratio."));
  add(switchParam("importance.edge", "Shadow-edge term", "Importance", false)
          .withUniform("u_edgeOn")
          .withHelp("Extra importance within 2 px of a shadow edge of the previous frame."));
  add(intParam("importance.stride", "Pixel stride", "Importance", 2, {1, 4, 1})
          .withUniform("u_stride")
          .withHelp(
              "Backward analysis: every k-th camera pixel in x and y scatters its importance (k^2 "
              "fewer atomics). The IM keeps the maximum per texel, and neighbouring pixels land in "
              "the same or adjacent texels, which the blur spreads over anyway."));
  add(floatParam("importance.edge.weight", "Edge weight", "Importance", 4, {0, 16, 0.5})
          .withUniform("u_edgeWeight")
          .withHelp("A texel on a shadow edge gets (1 + weight) times the importance."));
  add(intParam("blur.radius", "Blur radius", "Warp", 4, {0, rtw::kMaxBlurRadius, 1})
          .withHelp("Gaussian blur radius of the 1D importance maps, in texels."));
  add(floatParam("blur.sigma", "Blur sigma", "Warp", 2, {0.1, 16, 0.1})
          .withHelp("Gaussian blur standard deviation, in texels."));
  add(floatParam("importance.floor", "Importance floor", "Warp", 0.01, {0, 1, 0.01})
          .withUniform("u_floor")
          .withHelp("Minimum importance as a share of the maximum, so no region collapses to zero "
                    "texels."));
  add(switchParam("tessellation", "Tessellation", "Warp", true)
          .withUniform("u_tessOn")
          .withHelp(
              "Tessellate while rendering the warped map so long triangles bend with the warp."));
  add(floatParam("tessellation.tolerance", "Bend tolerance", "Warp", 1.0, {0.01, 16, 0.05})
          .withUniform("u_toleranceTexels")
          .withHelp("Tessellation level from the warped edge: how far the warp bends it from a "
                    "straight line, in texels; level = ceil(sqrt(bend / tolerance)), at most " +
                    std::to_string(kMaxTessellationLevel) +
                    ". With warp.depth = exact, depth is exact whatever the level: this only "
                    "shapes silhouettes."));
  add(choiceParam("warp.depth", "Warped depth", "Warp", {"exact", "interpolated"})
          .withUniform("u_interpolatedDepth")
          .withHelp("exact: each texel holds its triangle's depth plane at the texel's unwarped "
                    "centre. interpolated: depth interpolated linearly between the warped "
                    "vertices, as Rosen (2012) renders RTW; wrong inside long triangles (acne, "
                    "leaks). With tessellation off, the vertex shader warps the vertices and no "
                    "tessellation stage runs: the seed's pass."));
  add(switchParam("warp.split", "Split long triangles", "Warp", true)
          .withHelp("Render the warped map from the scene's triangles split to edges of at most "
                    "1/32 of its diagonal, so tessellation can bend every edge; off: the triangles "
                    "as loaded, as Rosen (2012) renders them."));
  add(choiceParam("light.fit", "Frustum fit", "Light frustum", {"tight", "rotation-invariant"})
          .withHelp(
              "tight: the smallest box around what the camera sees, in the (rotated) light frame, "
              "so its area and texels per m^2 change with a rotation. rotation-invariant: the "
              "square around that region's bounding circle; a rotation turns it without resizing "
              "it (the area is published as light.area)."));
  const bool da = id == "da-rtw";
  if (da) {
    add(choiceParam("pca.source", "PCA source", "Rotation", {"block-max", "im"})
            .withHelp(
                "What the moments are taken of. block-max: a copy of the IM reduced to at most " +
                std::to_string(SL_MOMENT_IM_MAX) +
                "^2 blocks, each weighted by its most important texel. im: the importance map "
                "itself, every texel (the poster)."));
    add(choiceParam("pca.metric", "PCA metric", "Rotation", {"metres", "im-units"})
            .withHelp("Units of x and y in the covariance. metres: scaled by the light frustum's "
                      "half extents, the axis as it lies in the world. im-units: centred IM texel "
                      "coordinates in [-1, 1] (the poster); with light.fit = tight the frustum's "
                      "aspect changes with the angle, and measured on diagonal and corridor the "
                      "rotation then never settles."));
    add(choiceParam("rotation.mode", "Turn by", "Rotation", {"pca", "predicted", "fixed"}, 1)
            .withHelp("How the light's image plane is turned. pca: along the importance's "
                      "principal axis every frame (Tokuyoshi et al. 2014), held by the vibration "
                      "threshold and the two gates. predicted: to the angle whose warp, predicted "
                      "from the last frame's importance map, leaves the fewest expected wrong "
                      "pixels, when it beats the current frame by more than rotation.margin. "
                      "fixed: rotation.fixed_deg, for sweeping the true error against the angle."));
    add(floatParam("rotation.fixed_deg", "Fixed turn", "Rotation", 0, {-90, 90, 1})
            .withHelp("rotation.mode = fixed: the turn of the shadow map's x axis about the light "
                      "direction, degrees counter-clockwise from the frame rtw-backward uses."));
    add(floatParam("rotation.margin", "Turn margin", "Rotation", rtw::kDefaultTurnMargin,
                   {0, 1, 0.01})
            .withHelp("rotation.mode = predicted: turn only when the best angle's predicted score "
                      "is lower than the current frame's by more than this share (the role the "
                      "vibration threshold plays for pca). " +
                      std::string(rtw::kTurnMarginWhy)));
    add(choiceParam("prediction.weight", "Predict over", "Rotation", {"edges", "pixels"})
            .withHelp("What the predicted score counts. edges: the last frame's shadow-edge "
                      "pixels, each with its edge's direction in the light plane (a hard shadow is "
                      "wrong only near an edge, by the texel's width across it). pixels: every "
                      "pixel the camera sees, edges of every direction alike."));
    add(floatParam(rtw::kHoldThresholdKey, "Vibration threshold", "Rotation",
                   rtw::kDefaultHoldThreshold,
                   {rtw::kMinHoldThreshold, rtw::kMaxHoldThreshold, 0.0001})
            .withHelp("Keep the rotation while e_x > threshold (Tokuyoshi et al. 2014 use 0.9999); "
                      "1.0 never holds. rotation.mode = predicted holds a turn smaller than "
                      "acos(threshold) (0.81 degrees at 0.9999)."));
    add(floatParam("pca.min_anisotropy", "Min anisotropy", "Rotation", 0, {0, 1, 0.01})
            .withHelp("rotation.mode = pca: turn only while the importance is thin: (l1 - l2) / "
                      "(l1 + l2) of its covariance at least this; below it R stays as it is. 0 = "
                      "always, as the poster. For the ablation: docs/techniques/rtw.md."));
    add(floatParam("pca.min_spread", "Min spread", "Rotation", 0, {0, 1, 0.01})
            .withHelp("rotation.mode = pca: turn only while the importance is spread over the map: "
                      "the wider of the half-mass widths of last frame's 1D importance maps (share "
                      "of the map) at least this; below it R stays as it is. 0 = always, as the "
                      "poster. For the ablation: docs/techniques/rtw.md."));
  }
  std::string name, desc;
  if (id == "rtw-forward") {
    name = "RTW (forward analysis)";
    desc =
        "Rectilinear texture warping (Rosen 2012): importance from the light's "
        "view projected into the camera, 1D warp maps, warped shadow map.";
  } else if (id == "rtw-backward") {
    name = "RTW (backward analysis)";
    desc =
        "Rectilinear texture warping with backward analysis: camera pixels scatter "
        "importance into light space (atomicMax).";
  } else if (id == "rtw-hybrid") {
    name = "RTW (hybrid analysis)";
    desc =
        "Forward analysis plus an eye-depth visibility test, so hidden surfaces get no "
        "importance.";
  } else {
    name = "Directionality-aware RTW";
    desc =
        "Backward RTW with the light frustum rotated by PCA of the importance map "
        "(Tokuyoshi et al. 2014), with a vibration threshold.";
  }
  // Directional only: the warp is built over one orthographic light image; a spot's
  // perspective map (or a point light's cube) would need the importance and warp defined in
  // its projective space, which is not implemented.
  TechniqueInfo info{id, name, desc + " Directional light only.", p};
  info.passes = passDecls(id);
  info.publications = publicationDecls(id);
  info.lights = {LightType::Directional};
  info.temporalRotation = da;
  info.firstScreen = da;
  info.unanalysedWarp = true;
  info.temporalState = info.temporalRotation;  // the rotation and the moments it is read from
  info.aliasingPattern =
      "Straight bands along the light's axes: the warp is separable, so a whole row and column "
      "of the map get the density of their most important point (a steep face, something near "
      "the camera) and the ground along them is oversampled (blue).";
  if (info.temporalRotation) {
    info.settleKeys = {"pca.valid",     "rotation.held",     "rotation.step_deg",
                       "rotation.mode", "prediction.reason", "rotation.frames"};
    info.settled = &rotationSettled;
  }
  return info;
}

std::optional<bool> RtwShadowMap::rotationSettled(const Publication& pub) {
  const double valid = pub.number("pca.valid", -1.0);
  if (valid < 0.0) return std::nullopt;  // no estimate this frame (no last frame's moments)
  const bool unchanged = pub.number("rotation.step_deg", 1.0) == 0.0;
  if (pub.number("rotation.mode", 0.0) == 1.0) {  // predicted
    // The first estimate has no shadow edges to weigh (the mask before the first frame is
    // empty): a prediction needs one frame more; a view without edges stays unpredicted.
    const bool predicted =
        pub.number("prediction.reason", 0.0) != double(int(rtw::TurnReason::NoPrediction));
    if (!predicted && pub.number("rotation.frames", 0.0) < 2.0) return std::nullopt;
    return unchanged;
  }
  return valid == 0.0 || pub.number("rotation.held", 0.0) != 0.0 || unchanged;
}

int RtwShadowMap::momentResolution(const ParamSet& params, int imRes) {
  return params.has("pca.source") && params.getInt("pca.source") == 1
             ? imRes
             : std::min(imRes, kMomentImMax);
}

RtwShadowMap::RtwShadowMap(const gl::ShaderLibrary& lib, Config config)
    : config_(config),
      backward_(lib, {"rtw/importance_backward",
                      {{GL_VERTEX_SHADER, "common/fullscreen.vert"},
                       {GL_FRAGMENT_SHADER, "rtw/importance_backward.frag"}},
                      {},
                      {}}),
      forward_(lib, {"rtw/importance_forward",
                     {{GL_VERTEX_SHADER, "rtw/importance_forward.vert"},
                      {GL_FRAGMENT_SHADER, "rtw/importance_forward.frag"}},
                     {},
                     {}}),
      collapse_(lib, compute("rtw/collapse.comp")),
      blur_(lib, compute("rtw/blur.comp")),
      scanWarp_(lib, compute("rtw/scan_warp.comp")),
      inverseWarp_(lib, compute("rtw/inverse_warp.comp")),
      warped_(lib, {"rtw/warped",
                    {{GL_VERTEX_SHADER, "rtw/warped_tess.vert"},
                     {GL_TESS_CONTROL_SHADER, "rtw/warped_tess.tesc"},
                     {GL_TESS_EVALUATION_SHADER, "rtw/warped_tess.tese"},
                     {GL_FRAGMENT_SHADER, "rtw/warped_exact.frag"}},
                    {},
                    {}}),
      warpedVertex_(lib, {"rtw/warped_vertex",
                          {{GL_VERTEX_SHADER, "rtw/warped_vertex.vert"},
                           {GL_FRAGMENT_SHADER, "rtw/warped_vertex.frag"}},
                          {},
                          {}}),
      moments_(lib, compute("rtw/moments.comp")),
      momentsLevel1_(lib, compute("rtw/moments_level1.comp")),
      momentsReduce_(lib, compute("rtw/moments_reduce.comp")),
      scatterFbo_(gl::Framebuffer::create()),
      emptyVao_(gl::createVertexArray()) {}

void RtwShadowMap::resetTemporalState() {
  carried_.reset();
  lastUpdate_ = {};
  momentFence_.reset();
  spareSpread_ = {};
  spareFence_.reset();
  snapshot_.reset();
  swappedThisFrame_ = false;
}

void RtwShadowMap::commitFrame() {
  carried_.commit();
  snapshot_.reset();  // the next frame reads this frame's moments
  swappedThisFrame_ = false;
}

void RtwShadowMap::discardFrame() {
  carried_.discard();
  if (swappedThisFrame_) swapMoments();  // the last complete frame's again
  swappedThisFrame_ = false;
}

void RtwShadowMap::swapMoments() {
  if (!spareSpread_)
    spareSpread_ = gl::Buffer::create(GLsizeiptr(spread_.size()), nullptr,
                                      GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT);
  std::swap(spread_, spareSpread_);
  std::swap(momentFence_, spareFence_);
}

void RtwShadowMap::ensureResources(int smRes, int imRes, const FrameContext& ctx) {
  const GLbitfield rw = GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT;
  if (smRes != smRes_) {
    shadowMap_ = gl::Texture::create2D(GL_DEPTH_COMPONENT32F, smRes, smRes);
    smFbo_ = gl::Framebuffer::create();
    smFbo_.attach(GL_DEPTH_ATTACHMENT, shadowMap_);
    smFbo_.setDrawBuffers(0);
    smFbo_.checkComplete("RTW warped shadow map");
    inverse_ = gl::Buffer::create(GLsizeiptr(2 * smRes * sizeof(float)), nullptr, rw);
    inverseView_ = gl::Texture::createBufferView(GL_R32F, inverse_);
    uniformMap_ = {};
    smRes_ = smRes;
  }
  if (imRes != imRes_) {
    importance_ = {};
    forwardDepth_ = {};
    momentIm_ = {};
    collapsed_ = gl::Buffer::create(GLsizeiptr(2 * imRes * sizeof(float)), nullptr, rw);
    spread_ = config_.rotation
                  ? gl::Buffer::create(GLsizeiptr((2 * imRes + 6) * sizeof(float)), nullptr, rw)
                  : gl::Buffer{};
    blurred_ = gl::Buffer::create(GLsizeiptr(2 * imRes * sizeof(float)), nullptr, rw);
    warp_ = gl::Buffer::create(GLsizeiptr(2 * (imRes + 1) * sizeof(float)), nullptr, rw);
    warpView_ = gl::Texture::createBufferView(GL_R32F, warp_);
    imRes_ = imRes;
    momentFence_.reset();
    spareSpread_ = {};
    spareFence_.reset();
    snapshot_.reset();
  }
  // The 2D IM: always for forward analysis (its render target), else only while asked for.
  const bool wantIm = !backward() || ctx.wants("importance");
  if (wantIm && !importance_) {
    importance_ = gl::Texture::create2D(GL_R32UI, imRes, imRes);
    if (!backward()) {
      forwardDepth_ = gl::Texture::create2D(GL_DEPTH_COMPONENT32F, imRes, imRes);
      forwardFbo_ = gl::Framebuffer::create();
      forwardFbo_.attach(GL_COLOR_ATTACHMENT0, importance_);
      forwardFbo_.attach(GL_DEPTH_ATTACHMENT, forwardDepth_);
      forwardFbo_.setDrawBuffers(1);
      forwardFbo_.checkComplete("RTW forward importance");
    }
  } else if (!wantIm && importance_) {
    importance_ = {};
  }
  if (!ctx.wants("shadow map.uniform")) uniformMap_ = {};
  // DA-RTW: the PCA's IM: the IM itself (pca.source = im) or its block maxima down to
  // kMomentImMax^2. The scatter writes it at its own resolution, so at imRes it is the IM.
  const int momentRes = momentResolution(ctx.params, imRes);
  if (config_.rotation && (momentRes != momentRes_ || !momentIm_)) {
    momentIm_ = gl::Texture::create2D(GL_R32UI, momentRes, momentRes);
    momentOffsets_.clear();
    momentSizes_.clear();
    int offset = 0;
    for (glm::ivec2 s(momentRes);; s = (s + 1) / 2) {
      momentOffsets_.push_back(offset);
      momentSizes_.push_back(s);
      offset += 6 * s.x * s.y;
      if (s.x == 1 && s.y == 1) break;
    }
    momentBuffer_ = gl::Buffer::create(GLsizeiptr(offset * sizeof(float)), nullptr, rw);
    momentCounts_ = gl::Buffer::create(
        GLsizeiptr(SL_RTW_COUNT_PLANES * size_t(momentRes) * size_t(momentRes) * sizeof(GLuint)),
        nullptr, rw);
    momentRes_ = momentRes;
    momentFence_.reset();
    spareSpread_ = {};
    spareFence_.reset();
    snapshot_.reset();
  }
}

// The rotation of this frame from the moments of the last frame's IM, read back behind
// a fence placed a frame ago: no stall (seed 000 also uses the previous frame's IM). By
// rotation.mode: PCA's axis with the poster's hold (pca), the turn whose predicted warp is
// best (predicted), or a fixed angle (fixed, whatever the moments say).
void RtwShadowMap::rotationFromLastMoments(FrameContext& ctx) {
  auto pass = ctx.timer.scope("rotation estimate");
  const ParamSet& p = ctx.params;
  const bool fixed = enumIs(p, "rotation.mode", "fixed"), pca = enumIs(p, "rotation.mode", "pca"),
             predicted = enumIs(p, "rotation.mode", "predicted");
  lastUpdate_ = {};
  predicted_ = false;
  if (fixed) {
    const glm::mat2 r = rtw::rotationOfAngle(p.get("rotation.fixed_deg"));
    ++carried_->rotation.frames;
    if (r != carried_->rotation.R) {
      lastUpdate_.stepDeg =
          float(rtw::foldQuarterTurn(p.get("rotation.fixed_deg") - carried_->rotation.angleDeg()));
      lastUpdate_.rotated = true;
      carried_->rotation.R = r;
      ++carried_->rotation.changes;
    }
  }
  // Read, not consumed: a discarded frame (discardFrame) leaves them to the next one.
  if (!momentFence_ || !momentFence_.wait()) return;
  // The chain's top, copied behind that frame's 1D maps (renderShadows).
  std::vector<float> top = readFloats(spread_, 2 * size_t(imRes_), 6);
  rtw::MomentTexel t;
  for (int c = 0; c < 6; ++c) t[c] = top[c], lastTop_[c] = top[c];
  // pca.metric: in metres (the IM's axes span the light frustum's extents) or IM units.
  const bool metres = p.getInt("pca.metric") == 0;
  const glm::vec2 scale = metres ? 0.5f * carried_->momentExtentM : glm::vec2(1.0f);
  rtw::MomentStats stats = rtw::momentsFromTop(t, scale);
  publishNumber(ctx, "pca.scale.x", scale.x);
  publishNumber(ctx, "pca.scale.y", scale.y);
  // The spread gate: the half-mass widths of the 1D maps that frame's warp was built from.
  const std::vector<float> last = readFloats(spread_, 0, 2 * size_t(imRes_));
  const float spreadX = rtw::halfMassWidth({last.begin(), last.begin() + imRes_});
  const float spreadY = rtw::halfMassWidth({last.begin() + imRes_, last.end()});
  const float spread = std::max(spreadX, spreadY);
  publishNumber(ctx, "pca.spread", spread);
  if (pca) {
    lastUpdate_ = rtw::updateRotation(
        carried_->rotation, stats, float(p.get(rtw::kHoldThresholdKey)),
        float(p.get("pca.min_anisotropy")), spread, float(p.get("pca.min_spread")));
  } else {  // the axis shown, not turned along
    if (predicted) ++carried_->rotation.frames;
    lastUpdate_.valid = stats.valid;
    lastUpdate_.e_x = stats.ex;
    lastUpdate_.e_y = stats.ey;
  }
  // PCA's axis as an absolute angle: its angle in the frame the moments were taken in, plus
  // that frame's turn.
  std::optional<double> axis;
  if (stats.valid) axis = carried_->momentAngleDeg + double(stats.angleDeg);
  pcaAxisDeg_ = axis.value_or(0.0);
  if (axis) publishNumber(ctx, "pca.axis_deg", rtw::foldQuarterTurn(*axis));
  if (predicted || ctx.wants("prediction.valid") || ctx.wants("prediction.curve"))
    predictTurn(ctx, axis, predicted);
  publishNumber(ctx, "pca.anisotropy", stats.anisotropy);
  publishNumber(ctx, "mean.x", stats.meanX);
  publishNumber(ctx, "mean.y", stats.meanY);
  publishNumber(ctx, "cov.xx", stats.covXX);
  publishNumber(ctx, "cov.xy", stats.covXY);
  publishNumber(ctx, "cov.yy", stats.covYY);
  publishNumber(ctx, "eigen.1", stats.lambda1);
  publishNumber(ctx, "eigen.2", stats.lambda2);
  publishNumber(ctx, "pca.valid", stats.valid ? 1 : 0);
  const char* names[6] = {"moment.I",   "moment.xI",  "moment.yI",
                          "moment.xxI", "moment.yyI", "moment.xyI"};
  for (int c = 0; c < 6; ++c) publishNumber(ctx, names[c], top[c]);
}

LightFit RtwShadowMap::fitAt(const FrameContext& ctx, const glm::mat2& rotation) const {
  FocusSettings fs;
  fs.rotation = glm::transpose(rotation);  // rtw::lightViewRotation: the view needs R^T
  if (ctx.params.getInt("light.fit") == 1) fs.extent = FocusExtent::RotationInvariant;
  LightFit fit;
  if (auto err = fitDirectionalLight(ctx.camera, ctx.aspect, ctx.scene.bounds,
                                     ctx.light.directionalTowards(), fs, fit))
    throw std::runtime_error(*err);
  return fit;
}

rtw::ImportanceSnapshot RtwShadowMap::readSnapshot() const {
  rtw::ImportanceSnapshot s;
  const size_t m = size_t(momentRes_), plane = m * m;
  std::vector<GLuint> bits(plane);
  glGetTextureImage(momentIm_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT,
                    GLsizei(plane * sizeof(GLuint)), bits.data());
  std::vector<GLuint> counts(SL_RTW_COUNT_PLANES * plane);
  glGetNamedBufferSubData(momentCounts_.id(), 0, GLsizeiptr(counts.size() * sizeof(GLuint)),
                          counts.data());
  s.size = int(m);
  s.importance.resize(plane);
  s.meanImportance.resize(plane);
  for (size_t i = 0; i < plane; ++i) {
    s.importance[i] = std::bit_cast<float>(bits[i]);
    const double sum = (double(counts[2 * plane + i]) * 4294967296.0 + double(counts[plane + i])) /
                       SL_RTW_IMPORTANCE_ONE;
    s.meanImportance[i] = counts[i] > 0 ? float(sum / double(counts[i])) : 0.0f;
  }
  s.pixels.assign(counts.begin(), counts.begin() + std::ptrdiff_t(plane));
  s.edgeBins.assign(counts.begin() + std::ptrdiff_t(3 * plane), counts.end());
  // The 1D maps that frame's warp was built from (copied beside the moments).
  const std::vector<float> collapsed = readFloats(spread_, 0, 2 * size_t(imRes_));
  s.collapsedX.assign(collapsed.begin(), collapsed.begin() + imRes_);
  s.collapsedY.assign(collapsed.begin() + imRes_, collapsed.end());
  // pca.source = im reads the whole IM: the prediction reads it at the block-max size.
  return rtw::reduceSnapshot(s, kMomentImMax);
}

// The turn predicted from the last frame's importance (algo/rtw/TurnPrediction.h): every
// candidate angle's frame fitted as this frame would fit it, the snapshot resampled into it.
void RtwShadowMap::predictTurn(FrameContext& ctx, std::optional<double> pcaAxisDeg, bool apply) {
  const auto start = std::chrono::steady_clock::now();
  const ParamSet& p = ctx.params;
  // Read once per committed frame: a discarded frame has overwritten the IM and its counts,
  // but its reading of the last complete frame's stays (commitFrame forgets it).
  if (!snapshot_) snapshot_ = readSnapshot();
  const rtw::ImportanceSnapshot& snapshot = *snapshot_;
  rtw::PredictionSettings settings;
  settings.warp = {p.getInt("blur.radius"), float(p.get("blur.sigma")),
                   float(p.get("importance.floor"))};
  settings.warpResolution = imRes_;
  settings.mapResolution = smRes_;
  // k: texels per metre a sample of importance 1 asks for (one texel per pixel at the near
  // plane: H / (2 tan(fovY / 2) near); TurnPrediction.h).
  settings.densityPerImportance =
      double(ctx.height) /
      (2.0 * std::tan(0.5 * double(ctx.camera.fovYDeg) * std::numbers::pi / 180.0) *
       double(ctx.camera.nearM));
  settings.weight = p.getInt("prediction.weight") == 0 ? rtw::PredictionWeight::EdgePixels
                                                       : rtw::PredictionWeight::Pixels;
  auto frameAt = [&](double angleDeg) {
    const LightFit fit = fitAt(ctx, rtw::rotationOfAngle(angleDeg));
    rtw::CandidateFrame c;
    c.angleDeg = angleDeg;
    c.turnDeg = angleDeg - carried_->momentAngleDeg;
    c.fromSnapshot = rtw::uvAffineBetween(carried_->momentViewProj, fit.viewProj);
    c.extentM = fit.extentM;
    return c;
  };
  const rtw::TurnPredictor predictor(snapshot, settings);
  auto predict = [&](double angleDeg) { return predictor.predict(frameAt(angleDeg)); };
  // Refined only when a turn is in sight: the coarse best predicted better by half the margin.
  lastSearch_ = rtw::searchTurn(carried_->rotation.angleDeg(), pcaAxisDeg, predict,
                                0.5 * p.get("rotation.margin"));
  const double threshold =
      std::clamp(p.get(rtw::kHoldThresholdKey), rtw::kMinHoldThreshold, rtw::kMaxHoldThreshold);
  const double holdDeg = std::acos(threshold) * 180.0 / std::numbers::pi;
  lastDecision_ = rtw::decideTurn(lastSearch_, p.get("rotation.margin"), holdDeg);
  predicted_ = true;
  if (apply && lastDecision_.reason == rtw::TurnReason::Turned) {
    const double step = rtw::foldQuarterTurn(lastDecision_.toDeg - carried_->rotation.angleDeg());
    carried_->rotation.R = rtw::rotationOfAngle(lastDecision_.toDeg);
    ++carried_->rotation.changes;
    carried_->rotation.accumulatedDeg += std::abs(step);
    lastUpdate_.rotated = true;
    lastUpdate_.stepDeg = float(step);
  }
  const rtw::WarpPrediction& cur = lastSearch_.scored[size_t(lastSearch_.current)];
  const rtw::WarpPrediction& best = lastSearch_.scored[size_t(lastSearch_.best)];
  publishNumber(ctx, "prediction.valid", cur.valid && best.valid ? 1 : 0);
  publishNumber(ctx, "prediction.reason", double(int(lastDecision_.reason)));
  publishNumber(ctx, "prediction.current_deg", cur.angleDeg);
  publishNumber(ctx, "prediction.best_deg", best.angleDeg);
  publishNumber(ctx, "prediction.gain", lastDecision_.gain);
  publishNumber(ctx, "prediction.margin", p.get("rotation.margin"));
  publishNumber(ctx, "prediction.score.current", cur.score);
  publishNumber(ctx, "prediction.score.best", best.score);
  publishNumber(ctx, "prediction.undersampled.current", cur.undersampled);
  publishNumber(ctx, "prediction.undersampled.best", best.undersampled);
  publishNumber(ctx, "prediction.weight", cur.weight);
  if (ctx.wants("prediction.pixels") || ctx.wants("prediction.edge_pixels")) {
    double pixels = 0.0, edges = 0.0;
    for (std::size_t i = 0; i < snapshot.importance.size(); ++i) {
      pixels += snapshot.pixels.empty() ? 0.0 : double(snapshot.pixels[i]);
      edges += snapshot.edgePixels(i);
    }
    publishNumber(ctx, "prediction.pixels", pixels);
    publishNumber(ctx, "prediction.edge_pixels", edges);
  }
  publishNumber(ctx, "prediction.candidates", double(lastSearch_.scored.size()));
  if (ctx.wants("prediction.searched")) {
    std::vector<float> pairs;
    for (const rtw::WarpPrediction& w : lastSearch_.scored) {
      pairs.push_back(float(w.angleDeg));
      pairs.push_back(w.valid ? float(w.score) : 0.0f);
    }
    publishValues(ctx, "prediction.searched", std::move(pairs));
  }
  if (ctx.wants("prediction.curve")) {  // the panel's plot: -90..90 every kTurnCurveStepDeg
    std::vector<float> curve;
    for (double a = -90.0; a <= 90.0 + 1e-9; a += rtw::kTurnCurveStepDeg) {
      const double f = rtw::foldQuarterTurn(a);
      const auto same = std::find_if(
          lastSearch_.scored.begin(), lastSearch_.scored.end(),
          [&](const rtw::WarpPrediction& w) { return std::abs(w.angleDeg - f) < 1e-9; });
      const rtw::WarpPrediction w = same != lastSearch_.scored.end() ? *same : predict(f);
      curve.push_back(w.valid ? float(w.score) : 0.0f);
    }
    publishValues(ctx, "prediction.curve", std::move(curve));
  }
  if (ctx.wants("prediction.m.p50") || ctx.wants("prediction.m.p95")) {
    // The frame this one is rendered in: what the renderer's aliasing.p50 / p95 will measure.
    const std::vector<double> q = {0.5, 0.95};
    const std::vector<double> m =
        predictor.aliasingQuantiles(frameAt(carried_->rotation.angleDeg()), q);
    if (m.size() == 2) {
      publishNumber(ctx, "prediction.m.p50", m[0]);
      publishNumber(ctx, "prediction.m.p95", m[1]);
    }
  }
  publishNumber(
      ctx, "prediction.ms",
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
}

// DA-RTW's moment chain of this frame's moment IM (level 1 straight from it, then one
// dispatch per level), fenced so the next frame reads its 24-byte top without a stall.
void RtwShadowMap::buildMoments(FrameContext& ctx) {
  auto pass = ctx.timer.scope("moments");
  const glm::ivec2 size(momentRes_);
  const glm::vec2 invSize(1.0f / float(size.x), 1.0f / float(size.y));
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  glBindImageTexture(SL_RTW_IMAGE_MOMENT_IM, momentIm_.id(), 0, GL_FALSE, 0, GL_READ_ONLY,
                     GL_R32UI);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SL_RTW_BUFFER_MOMENTS, momentBuffer_.id());
  const char* ch[6] = {"I", "xI", "yI", "xxI", "yyI", "xyI"};
  auto levelKey = [&ch](int c, size_t level) {
    return "moment." + std::string(ch[c]) + "." + std::to_string(level);
  };
  auto wantsLevel = [&](size_t level) {
    for (int c = 0; c < 6; ++c)
      if (ctx.wants(levelKey(c, level))) return true;
    return false;
  };
  if (wantsLevel(0)) {  // level 0 only for the panels; the estimate never needs it
    moments_.use();
    moments_.set("u_size", size);
    moments_.set("u_invSize", invSize);
    glDispatchCompute(groups(size.x, SL_RTW_MOMENT_GROUP), groups(size.y, SL_RTW_MOMENT_GROUP), 1);
  }
  const bool chain = momentSizes_.size() > 1;
  if (chain) {
    momentsLevel1_.use();
    momentsLevel1_.set("u_size", size);
    momentsLevel1_.set("u_invSize", invSize);
    momentsLevel1_.set("u_dstOffset", momentOffsets_[1]);
    glDispatchCompute(groups(momentSizes_[1].x, SL_RTW_MOMENT_GROUP),
                      groups(momentSizes_[1].y, SL_RTW_MOMENT_GROUP), 1);
  }
  momentsReduce_.use();
  for (size_t l = chain ? 1 : 0; l + 1 < momentSizes_.size(); ++l) {
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    glm::ivec2 dst = (momentSizes_[l] + 1) / 2;
    momentsReduce_.set("u_srcSize", momentSizes_[l]);
    momentsReduce_.set("u_srcOffset", momentOffsets_[l]);
    momentsReduce_.set("u_dstOffset", momentOffsets_[l + 1]);
    glDispatchCompute(groups(dst.x, SL_RTW_MOMENT_GROUP), groups(dst.y, SL_RTW_MOMENT_GROUP), 1);
  }
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  carried_->momentExtentM = lastExtentM_;
  carried_->momentViewProj = lastViewProj_;
  carried_->momentAngleDeg = carried_->rotation.angleDeg();
  // The chain itself (level images) and its IM, for the moment panel (debug: blocking),
  // only what is asked for.
  publishFloatBits(ctx, "importance.moments", momentIm_);
  for (size_t l = 0; l < momentSizes_.size(); ++l) {
    if (!wantsLevel(l)) continue;
    glm::ivec2 s = momentSizes_[l];
    std::vector<float> all =
        readPublishedFloats(ctx, momentBuffer_, size_t(momentOffsets_[l]), size_t(6 * s.x * s.y));
    for (int c = 0; c < 6; ++c) {
      if (!ctx.wants(levelKey(c, l))) continue;
      FloatImage img{s.x, s.y, 1, std::vector<float>(size_t(s.x * s.y))};
      for (size_t i = 0; i < img.values.size(); ++i) img.values[i] = all[6 * i + size_t(c)];
      ctx.publication->images[levelKey(c, l)] = std::move(img);
    }
  }
}

void RtwShadowMap::buildImportance(FrameContext& ctx, const glm::mat4& lightViewProj,
                                   float lightTexelM) {
  auto pass = ctx.timer.scope("importance");
  const ParamSet& p = ctx.params;
  auto setTerms = [&](const gl::Program& prog) {
    // The importance.* terms are bound from their declarations (bindParams).
    prog.set("u_minCosL", 0.1f);
    prog.set("u_nearM", ctx.camera.nearM);
    prog.set("u_lightViewProj", lightViewProj);
    prog.set("u_cameraPos", ctx.camera.position);
    prog.set("u_cameraForward", ctx.camera.forward());
    bindLight(prog, ctx.light);
    prog.set("u_gPosition", SL_UNIT_G_POSITION);
    prog.set("u_prevHard", SL_UNIT_HARD);
  };
  glBindTextureUnit(SL_UNIT_G_POSITION, ctx.gbuffer.position.id());
  glBindTextureUnit(SL_UNIT_G_NORMAL, ctx.gbuffer.normal.id());
  glBindTextureUnit(SL_UNIT_HARD, ctx.previous.hard.id());
  const GLuint zero = 0;
  if (importance_) glClearTexImage(importance_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  if (momentIm_) {
    glClearTexImage(momentIm_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    glClearNamedBufferData(momentCounts_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  }
  if (backward()) {
    // Straight into the two 1D maps (the collapse's max over rows and columns is the max
    // of the scatter), plus the 2D IM for the panels and DA-RTW's moment IM when present.
    glClearNamedBufferData(collapsed_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    backward_.use();
    setTerms(backward_);
    backward_.set("u_gNormal", SL_UNIT_G_NORMAL);
    backward_.set("u_n", imRes_);
    backward_.set("u_writeIm", importance_ ? 1 : 0);
    backward_.set("u_writeMomentIm", momentIm_ ? 1 : 0);
    backward_.set("u_lightExtentM", lastExtentM_);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                    GL_BUFFER_UPDATE_BARRIER_BIT);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SL_RTW_BUFFER_COLLAPSED, collapsed_.id());
    if (importance_)
      glBindImageTexture(SL_RTW_IMAGE_IM, importance_.id(), 0, GL_FALSE, 0, GL_READ_WRITE,
                         GL_R32UI);
    if (momentIm_) {
      glBindImageTexture(SL_RTW_IMAGE_MOMENT_IM, momentIm_.id(), 0, GL_FALSE, 0, GL_READ_WRITE,
                         GL_R32UI);
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SL_RTW_BUFFER_MOMENT_COUNTS, momentCounts_.id());
    }
    // One full-screen triangle into a framebuffer with no attachments, one fragment per
    // scattering pixel (every importance.stride-th in x and y).
    const int stride = p.getInt("importance.stride");  // u_stride: bound from its declaration
    const int sw = (ctx.width + stride - 1) / stride, sh = (ctx.height + stride - 1) / stride;
    glBindFramebuffer(GL_FRAMEBUFFER, scatterFbo_.id());
    glNamedFramebufferParameteri(scatterFbo_.id(), GL_FRAMEBUFFER_DEFAULT_WIDTH, sw);
    glNamedFramebufferParameteri(scatterFbo_.id(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, sh);
    glViewport(0, 0, sw, sh);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glBindVertexArray(emptyVao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
  } else {
    beginDepthPass(forwardFbo_.id(), imRes_, imRes_);
    forward_.use();
    setTerms(forward_);
    forward_.set("u_cameraViewProj", ctx.cameraProj * ctx.cameraView);
    forward_.set("u_hybrid", config_.analysis == Analysis::Hybrid ? 1 : 0);
    forward_.set("u_visibilityToleranceM", 3.0f * lightTexelM);
    ctx.sceneGpu.draw(forward_, SL_UNIT_MATERIAL);
  }
}

void RtwShadowMap::buildWarpMaps(FrameContext& ctx) {
  const ParamSet& p = ctx.params;
  const int n = imRes_;
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT |
                  GL_SHADER_STORAGE_BARRIER_BIT);
  if (!backward()) {  // backward analysis scattered straight into the 1D maps
    auto pass = ctx.timer.scope("collapse");
    collapse_.use();
    glBindImageTexture(SL_RTW_IMAGE_IM, importance_.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SL_RTW_BUFFER_COLLAPSED, collapsed_.id());
    collapse_.set("u_n", n);
    glDispatchCompute(groups(2 * n, SL_RTW_LINEAR_GROUP), 1, 1);
  }
  {
    auto pass = ctx.timer.scope("blur");
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    std::vector<float> w =
        rtw::gaussianWeights(p.getInt("blur.radius"), float(p.get("blur.sigma")));
    int radius = int(w.size() / 2);
    blur_.use();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SL_RTW_BUFFER_COLLAPSED, collapsed_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SL_RTW_BUFFER_BLURRED, blurred_.id());
    blur_.set("u_n", n);
    blur_.set("u_radius", radius);
    glProgramUniform1fv(blur_.id(), blur_.location("u_weights"), GLsizei(w.size()), w.data());
    glDispatchCompute(groups(2 * n, SL_RTW_LINEAR_GROUP), 1, 1);
  }
  {
    auto pass = ctx.timer.scope("scan + warp");
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    scanWarp_.use();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SL_RTW_BUFFER_BLURRED, blurred_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SL_RTW_BUFFER_WARP, warp_.id());
    scanWarp_.set("u_n", n);
    scanWarp_.set("u_m", int(std::bit_ceil(unsigned(n))));
    glDispatchCompute(2, 1, 1);
    // The inverse tables: the unwarped light uv of every warped texel centre.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    inverseWarp_.use();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SL_RTW_BUFFER_INVERSE, inverse_.id());
    inverseWarp_.set("u_n", n);
    inverseWarp_.set("u_size", smRes_);
    glDispatchCompute(groups(2 * smRes_, SL_RTW_LINEAR_GROUP), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  }
}

void RtwShadowMap::renderWarped(FrameContext& ctx, const glm::mat4& lightViewProj, bool warp) {
  const ParamSet& p = ctx.params;
  gl::Framebuffer& fbo = warp ? smFbo_ : uniformFbo_;
  beginDepthPass(fbo.id(), smRes_, smRes_);
  const SceneGpu::Geometry geometry = p.getInt("warp.split") != 0
                                          ? SceneGpu::Geometry::SplitLongTriangles
                                          : SceneGpu::Geometry::AsLoaded;
  if (p.getInt("warp.depth") == 1 && (p.getInt("tessellation") == 0 || !warp)) {
    // Seed 002's pass: warped in the vertex shader, depth interpolated by the rasteriser.
    warpedVertex_.use();
    bindWarpTextures(warpedVertex_, SL_UNIT_MATERIAL + 1);
    warpedVertex_.set("u_lightViewProj", lightViewProj);
    warpedVertex_.set("u_warpN", imRes_);
    warpedVertex_.set("u_warpOn", warp ? 1 : 0);
    ctx.sceneGpu.draw(warpedVertex_, SL_UNIT_MATERIAL, false, geometry);
    return;
  }
  warped_.use();
  bindWarpTextures(warped_, SL_UNIT_MATERIAL + 1);
  warped_.set("u_lightViewProj", lightViewProj);
  warped_.set("u_warpN", imRes_);
  warped_.set("u_warpOn", warp ? 1 : 0);
  warped_.set("u_smRes", smRes_);
  bindParams(warped_, p);                 // tessellation, tessellation.tolerance, warp.depth
  if (!warp) warped_.set("u_tessOn", 0);  // the unwarped contrast map: no bending
  warped_.set("u_smSize", glm::vec2(float(smRes_)));
  ctx.sceneGpu.draw(warped_, SL_UNIT_MATERIAL, true, geometry);
}

void RtwShadowMap::renderShadows(FrameContext& ctx) {
  const ParamSet& p = ctx.params;
  ensureResources(p.getInt("resolution"), p.getInt("im.resolution"), ctx);
  if (config_.rotation) {
    rotationFromLastMoments(ctx);
    publishRotation(ctx);
    // This frame's moments go into the other set: the last complete frame's stay readable
    // until the frame is committed.
    swapMoments();
    swappedThisFrame_ = true;
  }

  LightFit fit;
  {
    auto pass = ctx.timer.scope("focus");
    fit = fitAt(ctx, config_.rotation ? carried_->rotation.R : glm::mat2(1.0f));
  }
  view_ = depthMapView(fit);
  lastExtentM_ = fit.extentM;
  lastViewProj_ = fit.viewProj;
  ctx.addOutline(fit.viewProj, OutlineRole::LightMap);  // the unwarped light frustum

  buildImportance(ctx, fit.viewProj, std::max(fit.extentM.x, fit.extentM.y) / float(imRes_));
  if (config_.rotation) buildMoments(ctx);
  buildWarpMaps(ctx);
  if (config_.rotation) {
    // The 1D maps of this frame for the next frame's spread gate, and the fence the next
    // frame waits on before it reads them, the moment chain's top, the moment IM and its
    // counts (the turn prediction).
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT |
                    GL_TEXTURE_UPDATE_BARRIER_BIT);
    glCopyNamedBufferSubData(collapsed_.id(), spread_.id(), 0, 0,
                             GLsizeiptr(2 * imRes_ * sizeof(float)));
    glCopyNamedBufferSubData(momentBuffer_.id(), spread_.id(),
                             GLintptr(momentOffsets_.back() * sizeof(float)),
                             GLintptr(2 * imRes_ * sizeof(float)), GLsizeiptr(6 * sizeof(float)));
    momentFence_.place();
  }
  {
    auto pass = ctx.timer.scope("warped shadow map");
    renderWarped(ctx, fit.viewProj, true);
  }
  if (ctx.publication) publish(ctx, fit.viewProj);
}

void RtwShadowMap::publishRotation(FrameContext& ctx) {
  const ParamSet& p = ctx.params;
  publishNumber(ctx, "rotation.mode", p.getInt("rotation.mode"));
  publishNumber(ctx, "e_x", lastUpdate_.e_x);
  publishNumber(ctx, "e_y", lastUpdate_.e_y);
  publishNumber(ctx, "rotation.held", lastUpdate_.held ? 1 : 0);
  publishNumber(ctx, "rotation.too_round", lastUpdate_.tooRound ? 1 : 0);
  publishNumber(ctx, "rotation.too_concentrated", lastUpdate_.tooConcentrated ? 1 : 0);
  publishNumber(ctx, "rotation.deg", carried_->rotation.angleDeg());
  publishNumber(ctx, "rotation.step_deg", lastUpdate_.stepDeg);
  publishNumber(ctx, "rotation.changes", carried_->rotation.changes);
  publishNumber(ctx, "rotation.frames", carried_->rotation.frames);
  publishNumber(ctx, rtw::kHoldThresholdKey, p.get(rtw::kHoldThresholdKey));
  publishNumber(ctx, "pca.min_anisotropy", p.get("pca.min_anisotropy"));
  publishNumber(ctx, "pca.min_spread", p.get("pca.min_spread"));
}

void RtwShadowMap::publish(FrameContext& ctx, const glm::mat4& lightViewProj) {
  const size_t n = size_t(imRes_), sm = size_t(smRes_);
  publishNumber(ctx, "light.extent.x", lastExtentM_.x);
  publishNumber(ctx, "light.extent.y", lastExtentM_.y);
  publishNumber(ctx, "light.area", double(lastExtentM_.x) * double(lastExtentM_.y));
  for (int axis = 0; axis < 2; ++axis) {  // reads only the 1D map of an axis asked for
    const std::string key = axis == 0 ? "importance.halfmass.x" : "importance.halfmass.y";
    if (ctx.wants(key))
      publishNumber(ctx, key,
                    rtw::halfMassWidth(readPublishedFloats(ctx, collapsed_, size_t(axis) * n, n)));
  }
  if (importance_) publishFloatBits(ctx, "importance", importance_);
  publishCurve(ctx, "inverse.x", inverse_, 0, sm);
  publishCurve(ctx, "inverse.y", inverse_, sm, sm);
  publishCurve(ctx, "importance.x", collapsed_, 0, n);
  publishCurve(ctx, "importance.y", collapsed_, n, n);
  publishCurve(ctx, "importance.x.blurred", blurred_, 0, n);
  publishCurve(ctx, "importance.y.blurred", blurred_, n, n);
  publishCurve(ctx, "warp.x", warp_, 0, n + 1);
  publishCurve(ctx, "warp.y", warp_, n + 1, n + 1);
  publishDepth(ctx, "shadow map", shadowMap_);
  // The unwarped map of the same size, for contrast: rendered only while asked for (and
  // then listed in memory()).
  if (!ctx.wants("shadow map.uniform")) return;
  if (!uniformMap_ || uniformMap_.width() != smRes_) {
    uniformMap_ = gl::Texture::create2D(GL_DEPTH_COMPONENT32F, smRes_, smRes_);
    uniformFbo_ = gl::Framebuffer::create();
    uniformFbo_.attach(GL_DEPTH_ATTACHMENT, uniformMap_);
    uniformFbo_.setDrawBuffers(0);
    uniformFbo_.checkComplete("RTW contrast map");
  }
  renderWarped(ctx, lightViewProj, false);
  publishDepth(ctx, "shadow map.uniform", uniformMap_);
}

void RtwShadowMap::bindLookup(const gl::Program& resolve, int firstUnit) const {
  bindDepthLookup(resolve, std::span(&view_, 1));
  glBindTextureUnit(GLuint(firstUnit), shadowMap_.id());
  resolve.set("u_shadowMap", firstUnit);
  bindWarpTextures(resolve, firstUnit + 1);
  resolve.set("u_warpN", imRes_);
  resolve.set("u_warpOn", 1);
  resolve.set("u_smRes", smRes_);
}

void RtwShadowMap::bindWarpTextures(const gl::Program& prog, int unit) const {
  glBindTextureUnit(GLuint(unit), warpView_.id());
  glBindTextureUnit(GLuint(unit + 1), inverseView_.id());
  prog.set("u_warpEdges", unit);
  prog.set("u_inverseWarp", unit + 1);
}

std::vector<const gl::Program*> RtwShadowMap::programs() const {
  return {&backward_, &forward_,      &collapse_, &blur_,          &scanWarp_,     &inverseWarp_,
          &warped_,   &warpedVertex_, &moments_,  &momentsLevel1_, &momentsReduce_};
}

MemoryStats RtwShadowMap::memory() const {
  MemoryStats m;
  if (!shadowMap_) return m;
  m.add("warped shadow map", "DEPTH_COMPONENT32F", smRes_, smRes_, 1, 4);
  m.add("inverse warp tables (x, y)", "R32F", smRes_, 1, 2, 4);
  m.add("1D importance (x, y)", "R32UI", imRes_, 1, 2, 4);
  m.add("1D importance blurred (x, y)", "R32F", imRes_, 1, 2, 4);
  m.add("warp maps (x, y; n+1 edges)", "R32F", imRes_ + 1, 1, 2, 4);
  if (importance_ && backward())  // backward analysis scatters into the 1D maps: a debug view
    m.addDebugView("importance map (while a panel shows it)", "R32UI", imRes_, imRes_, 1, 4);
  else if (importance_)
    m.add("importance map", "R32UI", imRes_, imRes_, 1, 4);
  if (forwardDepth_) m.add("forward depth", "DEPTH_COMPONENT32F", imRes_, imRes_, 1, 4);
  if (momentIm_) {
    m.add(momentRes_ == imRes_ ? "moment IM (the IM itself)" : "moment IM (block maxima)", "R32UI",
          momentRes_, momentRes_, 1, 4);
    int texels = 0;
    for (glm::ivec2 s : momentSizes_) texels += s.x * s.y;
    m.add("moment chain (6 channels, all levels)", "R32F x6", texels, 1, 6, 4);
    m.add("turn prediction counts (pixels, importance sum, edge bins)", "R32UI", momentRes_,
          momentRes_, SL_RTW_COUNT_PLANES, 4);
  }
  if (spread_)
    m.add("last frame's 1D importance (x, y; the spread gate) and moment top", "R32F",
          2 * imRes_ + 6, 1, 1, 4);
  if (spareSpread_)  // the last complete frame's, while a frame writes its own (swapMoments)
    m.add("1D importance and moment top of the last complete frame", "R32F", 2 * imRes_ + 6, 1, 1,
          4);
  if (uniformMap_)
    m.addDebugView("unwarped contrast map (while a panel shows it)", "DEPTH_COMPONENT32F", smRes_,
                   smRes_, 1, 4);
  return m;
}

std::optional<std::string> RtwShadowMap::reloadShaders(const gl::ShaderLibrary& lib) {
  std::string errors;
  for (gl::Program* prog : {&backward_, &forward_, &collapse_, &blur_, &scanWarp_, &inverseWarp_,
                            &warped_, &warpedVertex_, &moments_, &momentsLevel1_, &momentsReduce_})
    if (auto e = prog->rebuild(lib)) errors += (errors.empty() ? "" : "\n") + *e;
  if (errors.empty()) return std::nullopt;
  return errors;
}

}  // namespace sl
