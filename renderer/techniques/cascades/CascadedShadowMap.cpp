// Cascaded shadow maps (CascadedShadowMap.h): fit the k slices, render each into its layer,
// reduce the G-buffer's view-depth range for the next frame, select by view depth.
#include "CascadedShadowMap.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "algo/partition/Splits.h"
#include "common/shared_constants.h"
#include "core/PartitionMStats.h"
#include "core/Publish.h"
#include "core/SceneGpu.h"
#include "core/Warp.h"

namespace sl {

static_assert(SL_MAX_CASCADES <= SL_MAX_DEPTH_MAPS);  // one lookup map per partition

namespace {

constexpr std::uint32_t kFloatMaxBits = 0x7f7fffffu;

gl::ProgramDesc rangeProgramDesc() {
  return {"cascades/depth_range", {{GL_COMPUTE_SHADER, "cascades/depth_range.comp"}}, {}, {}};
}

}  // namespace

TechniqueInfo CascadedShadowMap::info() {
  std::vector<ParamDecl> p = shadowMapParamDecls(
      1024,
      "Width and height of EVERY partition's map in texels (the total is k times its "
      "square).");
  auto add = [&](ParamDecl d) { p.push_back(std::move(d)); };
  add(intParam("partitions", "Partitions", "Cascades", 4, {1, SL_MAX_CASCADES, 1})
          .withHelp("k: the view frustum is cut into k slices along the view depth, one "
                    "orthographic map each (z-partitioning)."));
  add(choiceParam("split", "Split scheme", "Cascades", {"uniform", "log", "practical"},
                  double(int(partition::SplitScheme::Log)))
          .withHelp("Where the slices end: uniform in depth, logarithmic z_i = n (f/n)^(i/k) "
                    "(equal error per slice, Lloyd et al. 2006), or practical: split.lambda * log "
                    "+ (1 - split.lambda) * uniform (Zhang et al. 2006)."));
  add(floatParam("split.lambda", "Practical lambda", "Cascades", partition::kDefaultSplitLambda,
                 {0.0, 1.0, 0.05})
          .withHelp("Blend of the practical split: 1 = logarithmic, 0 = uniform."));
  add(switchParam("stabilize", "Stabilise", "Cascades", true)
          .withHelp("Each slice's map covers its bounding sphere (extent quantised, so it does not "
                    "change as the camera turns) and moves by whole texels (so edges do not crawl "
                    "as the camera moves); the split range is quantised to 1/8 octave. Off: fitted "
                    "tightly to slice ∩ scene bounds (more texels on the scene, shimmering edges). "
                    "Unwarped partitions only: with partition.warp a warped map is fitted tightly "
                    "(its texels change size along the warp, so no whole-texel step holds them "
                    "still); a partition whose warp falls back to uniform is stabilised."));
  add(switchParam("stabilize.scene", "Stabilised: clamp to scene", "Cascades", true)
          .withHelp(
              "With stabilize: a slice whose bounding sphere is wider than the whole scene seen "
              "from the light covers the scene's light-space square instead (it does not move with "
              "the camera, so it is as stable). The tool's addition to the bounding-sphere fit, "
              "which alone spends a deep slice's texels outside a small scene seen whole (a room, "
              "one model): docs/results/real-content.md. Off: the sphere always."));
  add(switchParam("partition.warp", "Warp partitions", "Cascades", false)
          .withHelp("Warp every partition with a perspective along light-space z (LiSPSM at "
                    "warp.eta = 0) fitted around its slice ∩ scene bounds: warping combined with "
                    "z-partitioning, the least error for k maps (Lloyd et al. 2006 §5). Where the "
                    "frustum looks square from the light a partition falls back to uniform "
                    "(partition.<i>.warped = 0 and its cause)."));
  add(warpEtaDecl(0.0));
  add(switchParam("depth.fit", "Fit depth range", "Cascades", true)
          .withHelp("Cut the splits over the view depths the G-buffer actually holds (a min/max "
                    "reduction of this frame's G-buffer, read back before the fit) instead of the "
                    "whole view frustum ∩ scene bounds."));

  TechniqueInfo info{"cascades", "Cascaded shadow maps",
                     "z-partitioning (Lloyd et al. 2006 §5.2; parallel-split maps, Zhang et al. "
                     "2006): k orthographic maps, each fitted to one depth slice of the view "
                     "frustum, selected per pixel by view depth. Directional light only.",
                     std::move(p)};
  info.temporalState = true;  // depth.fit's held range (stabilize: hysteresis)
  info.aliasingPattern =
      "Steps across the view: each cascade has its own texel size, so m jumps at every split "
      "distance (the partition overlay colours the cascades).";
  info.passes = {
      {"depth range", "Depth range reduction",
       "Min and max view depth over this frame's G-buffer's covered pixels (a compute "
       "reduction), read back before the split range is fitted to what the camera really sees "
       "(depth.fit).",
       "partitions"},
      {"partition maps", "Partition maps",
       "Cut the visible depth range into k slices (the split scheme), fit one orthographic light "
       "frustum to each slice (stabilised: its bounding sphere, snapped to whole texels) and "
       "render the scene's depth into that slice's layer. Near slices are small: their texels "
       "are small where the camera is close.",
       "partitions"},
      PartitionMStats::passDecl(),
  };
  info.publications = {
      {"partition.*.map", PublicationKind::ImageSet,
       "Every partition's depth map as rendered (depth 0..1), i = 0..k-1.",
       "4 B x min(resolution, 2048)^2 x partitions",
       [](const ParamSet& ps) {
         const int r = ps.getInt("resolution");
         return publishedImageBytes(r, r) * std::uint64_t(ps.getInt("partitions"));
       }},
      PartitionMStats::publicationDecl([](const ParamSet& ps) { return ps.getInt("partitions"); }),
      {"partition.count", PublicationKind::Number, "k, the number of partitions.", "", {}},
      {"partition.*.near",
       PublicationKind::Number,
       "Partition i's near split (view depth, m).",
       "",
       {}},
      {"partition.*.far",
       PublicationKind::Number,
       "Partition i's far split (view depth, m).",
       "",
       {}},
      {"partition.*.texels_per_m",
       PublicationKind::Number,
       "Partition i's shadow-map texels per metre (resolution / light-frustum width).",
       "",
       {}},
      {"partition.*.extent_m",
       PublicationKind::Number,
       "Partition i's light-frustum width (m).",
       "",
       {}},
      {"partition.*.texels", PublicationKind::Number, "Partition i's texel count.", "", {}},
      {"partition.*.scene_clamped",
       PublicationKind::Number,
       "1 when stabilised partition i covers the scene's light-space square because its "
       "slice's bounding sphere is wider (stabilize.scene), else 0.",
       "",
       {}},
      {"partition.*.warped",
       PublicationKind::Number,
       "1 when partition i's map is warped (partition.warp on and no fallback), else 0.",
       "",
       {}},
      {"partition.*.warp.fallback_cause",
       PublicationKind::Number,
       "Why partition i asked for a warp and got the uniform map: 0 none (or not asked), 1 "
       "light behind the viewer, 2 in front, 4 degenerate (the warp's fallback cause).",
       "",
       {}},
      {"partition.*.warp.n_prime",
       PublicationKind::Number,
       "Partition i's n' (m): its warp's projection centre to its body; 0 = unwarped (no inf: the "
       "suites count non-finite numbers).",
       "",
       {}},
      {"partition.*.warp.eta",
       PublicationKind::Number,
       "The eta of partition i's warp (Lloyd et al.'s eq. 11: 0 LiSPSM, 1 PSM, towards -1 "
       "uniform); -1 when unwarped.",
       "",
       {}},
      {"partition.*.slice_uv",
       PublicationKind::Curve,
       "Partition i's slice of the view frustum in its map's uv (0..1 = the map): the 12 edges "
       "clipped to the map's front and to [-1, 2]^2, 4 values (u0, v0, u1, v1) per segment.",
       "",
       {}},
      {"depth.near",
       PublicationKind::Number,
       "Near end of the split range (view depth, m).",
       "",
       {}},
      {"depth.far", PublicationKind::Number, "Far end of the split range (view depth, m).", "", {}},
      {"depth.fitted",
       PublicationKind::Number,
       "1 when the split range used the G-buffer's depth range (depth.fit on, a pixel covered).",
       "",
       {}},
      {"depth.measured.near",
       PublicationKind::Number,
       "The smallest view depth (m) of this frame's covered G-buffer pixels, as the "
       "depth-range reduction read it back (depth.fit on; 0 when none).",
       "",
       {}},
      {"depth.measured.far",
       PublicationKind::Number,
       "The largest view depth (m) of this frame's covered G-buffer pixels (as "
       "depth.measured.near).",
       "",
       {}},
  };
  // Every partition's map, before the first frame (a 16384^2 array is refused here, not by it).
  info.checkParams = [](const ParamSet& ps) {
    const int k = int(ps.getInt("partitions"));
    return DepthMapArray::sizeError(int(ps.getInt("resolution")), k,
                                    "cascades: " + std::to_string(k) + " partitions",
                                    "resolution or partitions");
  };
  return info;
}

CascadedShadowMap::CascadedShadowMap(const gl::ShaderLibrary& lib)
    : depthProgram_(lib), rangeProgram_(lib, rangeProgramDesc()), mStats_(lib) {}

void CascadedShadowMap::resetTemporalState() {
  rangeFence_.reset();
  range_.reset();
}

std::optional<glm::dvec2> CascadedShadowMap::readDepthRange() {
  if (rangeFence_ && rangeFence_.wait()) {
    rangeFence_.reset();
    std::uint32_t bits[2] = {0, 0};
    glGetNamedBufferSubData(rangeBuffer_.id(), 0, sizeof bits, bits);
    float lo = 0.0f, hi = 0.0f;
    std::memcpy(&lo, &bits[0], 4);
    std::memcpy(&hi, &bits[1], 4);
    // Nothing covered: no range (the whole visible range is cut).
    if (bits[1] != 0u && bits[0] != kFloatMaxBits && hi >= lo)
      range_->last = glm::dvec2(lo, hi);
    else
      range_->last.reset();
  }
  return range_->last;
}

void CascadedShadowMap::reduceDepthRange(const FrameContext& ctx) {
  auto pass = ctx.timer.scope("depth range");
  if (!rangeBuffer_) rangeBuffer_ = gl::Buffer::create(8, nullptr);
  const std::uint32_t init[2] = {kFloatMaxBits, 0u};
  glNamedBufferSubData(rangeBuffer_.id(), 0, sizeof init, init);
  rangeProgram_.use();
  rangeProgram_.set("u_eye", ctx.camera.position);
  rangeProgram_.set("u_forward", ctx.camera.forward());
  rangeProgram_.set("u_size", glm::ivec2(ctx.width, ctx.height));
  glBindTextureUnit(SL_UNIT_G_POSITION, ctx.gbuffer.position.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SL_CASCADE_BUFFER_DEPTH_RANGE, rangeBuffer_.id());
  glDispatchCompute(GLuint((ctx.width + SL_CASCADE_GROUP - 1) / SL_CASCADE_GROUP),
                    GLuint((ctx.height + SL_CASCADE_GROUP - 1) / SL_CASCADE_GROUP), 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  rangeFence_.place();
}

void CascadedShadowMap::renderShadows(FrameContext& ctx) {
  const int res = ctx.params.getInt("resolution");
  const int k = ctx.params.getInt("partitions");
  const bool fitDepth = ctx.params.getBool("depth.fit");
  partition::CascadeSettings s;
  s.partitions = k;
  s.split = partition::SplitScheme(ctx.params.getInt("split"));
  s.lambda = ctx.params.get("split.lambda");
  s.resolution = res;
  s.stabilize = ctx.params.getBool("stabilize");
  s.clampToScene = ctx.params.getBool("stabilize.scene");
  s.warp = ctx.params.getBool("partition.warp");
  s.eta = ctx.params.get("warp.eta");
  if (fitDepth) {
    // This frame's range: the reduction runs over this frame's G-buffer (drawn before the
    // technique) and is read back at once (a frame late, a moving camera or the sparse
    // frames of a bench path were fitted to the previous view: ~20 % of the pixels wrong).
    // Widened by 5 % each way; stabilised, held while it still fits (hysteresis), so the
    // splits do not move with every frame.
    reduceDepthRange(ctx);
    if (auto r = readDepthRange()) {
      const glm::dvec2 measured(r->x / 1.05, r->y * 1.05);
      if (s.stabilize) {
        range_->held = partition::holdDepthRange(range_->held, measured);
        s.visibleDepthM = range_->held;
      } else {
        s.visibleDepthM = measured;
      }
    }
  } else {
    rangeFence_.reset();
    *range_ = {};       // this frame's (committed with it)
    rangeBuffer_ = {};  // held only while used (memory())
  }

  {
    auto pass = ctx.timer.scope("partition maps");
    partition::CascadeFit fit;
    if (auto err = partition::fitCascades(ctx.camera, ctx.aspect, ctx.scene.bounds,
                                          ctx.light.directionalTowards(), s, fit))
      throw std::runtime_error(*err);
    fit_ = std::move(fit);
    eye_ = ctx.camera.position;
    forward_ = ctx.camera.forward();

    maps_.ensure(res, k, "cascades: " + std::to_string(k) + " partitions",
                 "resolution or partitions");
    views_.clear();
    for (int i = 0; i < k; ++i) {
      const partition::CascadePart& p = fit_.parts[size_t(i)];
      // Warped: as `lispsm`, the warp's perspective (w = z'), per map.
      const DepthMapView v = p.warped()
                                 ? depthMapView(p.warpFit->mapFrame())
                                 : DepthMapView{p.viewProj, glm::vec2(p.extentM),
                                                p.depthRangeM > 0.0 ? float(p.depthRangeM) : 1.0f};
      views_.push_back(v);
      renderDepth(ctx, depthProgram_, maps_.layerFramebuffer(i), res, res, p.viewProj);
      ctx.addOutline(p.viewProj, OutlineRole::LightMap, i);
      if (ctx.outlines && i + 1 < k) ctx.outlines->splitDepthsM.push_back(float(p.farM));
    }
  }
  mStats_.update(ctx, k);

  // Publications: the maps (only when asked), the splits and texel densities (numbers).
  publishNumber(ctx, "partition.count", k);
  publishNumber(ctx, "depth.near", fit_.nearM);
  publishNumber(ctx, "depth.far", fit_.farM);
  publishNumber(ctx, "depth.fitted", s.visibleDepthM ? 1.0 : 0.0);
  publishNumber(ctx, "depth.measured.near", fitDepth && range_->last ? range_->last->x : 0.0);
  publishNumber(ctx, "depth.measured.far", fitDepth && range_->last ? range_->last->y : 0.0);
  for (int i = 0; i < k; ++i) {
    const partition::CascadePart& p = fit_.parts[size_t(i)];
    const std::string key = "partition." + std::to_string(i);
    publishDepthLayer(ctx, key + ".map", maps_.texture(), i);
    publishNumber(ctx, key + ".near", p.nearM);
    publishNumber(ctx, key + ".far", p.farM);
    publishNumber(ctx, key + ".extent_m", std::max(p.extentM.x, p.extentM.y));
    publishNumber(ctx, key + ".texels_per_m", p.texelM > 0.0 ? 1.0 / p.texelM : 0.0);
    publishNumber(ctx, key + ".texels", double(res) * double(res));
    publishNumber(ctx, key + ".warped", p.warped() ? 1.0 : 0.0);
    publishNumber(ctx, key + ".scene_clamped", p.sceneClamped ? 1.0 : 0.0);
    publishNumber(ctx, key + ".warp.fallback_cause",
                  p.warpFit ? double(int(p.warpFit->fallbackCause)) : 0.0);
    publishNumber(ctx, key + ".warp.n_prime", p.warped() ? p.warpFit->nPrime : 0.0);
    publishNumber(ctx, key + ".warp.eta", p.warped() ? p.warpFit->eta : -1.0);
    publishValues(ctx, key + ".slice_uv", p.sliceUv);
  }
}

void CascadedShadowMap::bindLookup(const gl::Program& resolve, int firstUnit) const {
  bindDepthLookup(resolve, views_);
  glBindTextureUnit(GLuint(firstUnit), maps_.texture().id());
  resolve.set("u_cascadeMaps", firstUnit);
  resolve.set("u_cascadeCount", int(fit_.parts.size()));
  resolve.set("u_cascadeEye", eye_);
  resolve.set("u_cascadeForward", forward_);
  for (size_t i = 0; i < fit_.parts.size(); ++i)
    resolve.set(("u_cascadeFar[" + std::to_string(i) + "]").c_str(), float(fit_.parts[i].farM));
}

MemoryStats CascadedShadowMap::memory() const {
  MemoryStats m;
  maps_.addMemory(m, "partition maps (array)");
  if (rangeBuffer_) m.add("depth range (min, max)", "R32UI", 2, 1, 1, 4);
  mStats_.addMemory(m);
  return m;
}

std::optional<std::string> CascadedShadowMap::reloadShaders(const gl::ShaderLibrary& lib) {
  if (auto e = depthProgram_.rebuild(lib)) return e;
  if (auto e = rangeProgram_.rebuild(lib)) return e;
  return mStats_.reloadShaders(lib);
}

}  // namespace sl
