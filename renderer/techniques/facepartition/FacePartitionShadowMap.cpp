// Face-partitioned shadow maps (FacePartitionShadowMap.h): fit the face partitions, render
// each into its layer through its warp, bind the selection planes for the lookup.
#include "FacePartitionShadowMap.h"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "algo/partition/StorageFactor.h"
#include "core/PartitionMStats.h"
#include "core/Publish.h"
#include "core/SceneGpu.h"
#include "techniques/perspective/PerspectiveShadowMap.h"

namespace sl {

namespace {

constexpr int kSlots = partition::kFaceSlots;
static_assert(kSlots <= SL_MAX_DEPTH_MAPS);

/// The lookup's view of one partition's map: its warp's perspective frame, or the
/// orthographic fit when the warp fell back to uniform.
DepthMapView partView(const warp::WarpFit& fit) {
  if (!fit.uniform) return depthMapView(fit.mapFrame());
  DepthMapView v;
  v.lightViewProj = fit.lightProj * fit.lightView;
  v.extentM =
      glm::vec2(float(std::max(fit.hi.x - fit.lo.x, 1e-9)), float(std::max(fit.depthM, 1e-9)));
  v.depthRangeM = float(std::max(fit.hi.y - fit.lo.y, 1e-9));
  return v;
}

}  // namespace

TechniqueInfo FacePartitionShadowMap::info() {
  std::vector<ParamDecl> p = shadowMapParamDecls(1024);
  for (ParamDecl& d : p)
    if (d.key == "resolution")
      d.help =
          "Width and height of EVERY face partition's map in texels. There are 5 (the near face "
          "and the four sides, one slot each, unused ones empty): the total is 5 times its "
          "square.";
  p.insert(p.begin(), warpEtaDecl(0.0));
  TechniqueInfo info{
      "face-partition", "Face-partitioned shadow maps",
      "Lloyd et al. 2006 §5.1: the view frustum split along its faces as seen from the light "
      "(front faces when v . y < 0, back faces otherwise), each part warped with LiSPSM along "
      "the bisector of its projected side edges, one map each; warping works even where the "
      "frustum looks square from the light (dueling frusta). Directional light only.",
      std::move(p)};
  info.passes = {
      {"face fit", "Fit the face partitions",
       "Clip the view frustum to the scene, take its faces towards the light (light behind the "
       "viewer) or away from it (light in front), and fit one warp per face: light-space z "
       "along the bisector of the face's two side edges projected perpendicular to the light, "
       "n' from warp.eta (0 = LiSPSM). The near face has no side edges: it warps along the view "
       "vector, or stays uniform where the frustum looks square.",
       "partitions"},
      {"face maps", "Face partition maps",
       "Render the scene's depth into each face partition's layer through its warp: texels "
       "dense where the face is close to the camera.",
       "partitions"},
      PartitionMStats::passDecl(),
  };
  auto number = [](std::string key, std::string what) {
    return PublicationDecl{std::move(key), PublicationKind::Number, std::move(what), "", {}};
  };
  info.publications = {
      {"partition.*.map", PublicationKind::ImageSet,
       "Every face slot's depth map as rendered (depth 0..1, warped; 1 everywhere when the slot "
       "is unused), i = 0 near, 1 -x, 2 +x, 3 -y (bottom), 4 +y (top).",
       "4 B x resolution^2 x 5",
       [](const ParamSet& ps) {
         const std::uint64_t r = std::uint64_t(ps.getInt("resolution"));
         return 4 * r * r * kSlots;
       }},
      PartitionMStats::publicationDecl([](const ParamSet&) { return kSlots; }),
      number("partition.count", "Number of face slots (5)."),
      number("partition.active",
             "Number of faces used this frame (1 to 5: those towards the light, or away)."),
      number("partition.*.active", "1 when slot i's face is used this frame."),
      number("partition.*.face",
             "The frustum face of slot i (StorageFactor's order: 0 near, 2 -x, 3 +x, 4 -y, 5 +y; "
             "0 when unused)."),
      number("partition.*.near", "Nearest view depth of slot i's region (m; 0 when unused)."),
      number("partition.*.far", "Farthest view depth of slot i's region (m; 0 when unused)."),
      number("partition.*.extent_m",
             "Slot i's light-space width: the larger of its x and z extents (m)."),
      number("partition.*.texels", "Slot i's texel count."),
      number("partition.*.texels_per_m",
             "Slot i's mean texels per metre across its map: resolution / extent_m (a warp puts "
             "more of them near the camera, fewer far away; 0 when unused)."),
      number("partition.*.warp.eta", "eta of slot i's warp (-1: uniform)."),
      number("partition.*.warp.fallback",
             "1 when slot i asked for a warp but used the uniform map."),
      number("partition.*.warp.fallback_cause",
             "why: 0 none, 1 light behind, 2 light in front, 4 degenerate (the warp's fallback "
             "cause)."),
      number("partition.*.warped",
             "1 when slot i's map is warped (active, no fallback), else 0 (the Partitions "
             "panel's warp column, as cascades)."),
      number("partition.*.warp.n_prime",
             "Slot i's n' (m): its warp's projection centre to its body; 0 = unwarped or unused."),
      number("faces.front",
             "1 when the front faces (towards the light, v . y < 0) are used, 0 for the back."),
      number("depth.near", "Near plane of the frustum clipped to the scene (m)."),
      number("depth.far", "Far plane of the frustum clipped to the scene (m)."),
  };
  info.lights = {LightType::Directional};
  return info;
}

FacePartitionShadowMap::FacePartitionShadowMap(const gl::ShaderLibrary& lib)
    : depthProgram_(lib, depthProgramDesc()), mStats_(lib) {}

void FacePartitionShadowMap::renderShadows(FrameContext& ctx) {
  const int res = ctx.params.getInt("resolution");
  {
    auto pass = ctx.timer.scope("face fit");
    partition::FacePartitionFit fit;
    if (auto err = partition::fitFacePartitions(ctx.camera, ctx.aspect, ctx.scene.bounds,
                                                glm::dvec3(ctx.light.directionalTowards()),
                                                ctx.params.get("warp.eta"), fit))
      throw std::runtime_error(*err);
    fit_ = std::move(fit);
    views_.assign(kSlots, DepthMapView{});
    for (const partition::FacePart& p : fit_.parts) {
      views_[std::size_t(p.slot)] = partView(p.fit);
      // The outside view: a warped face's light box and warping frustum, a uniform one's
      // orthographic light frustum; coloured by slot like the partition overlay.
      if (p.fit.warped() && ctx.outlines)
        addWarpOutlines(p.fit, *ctx.outlines, p.slot);
      else if (!p.fit.warped())
        ctx.addOutline(views_[std::size_t(p.slot)].lightViewProj, OutlineRole::LightMap, p.slot);
    }
  }
  {
    auto pass = ctx.timer.scope("face maps");
    maps_.ensure(res, kSlots, "face-partition: 5 maps", "resolution");
    std::array<bool, kSlots> used{};
    for (const partition::FacePart& p : fit_.parts) {
      used[std::size_t(p.slot)] = true;
      renderDepth(ctx, depthProgram_, maps_.layerFramebuffer(p.slot), res, res,
                  views_[std::size_t(p.slot)].lightViewProj);
    }
    for (int i = 0; i < kSlots; ++i)
      if (!used[std::size_t(i)]) {
        beginDepthPass(maps_.layerFramebuffer(i), res, res);  // cleared to 1: empty
      }
  }

  mStats_.update(ctx, kSlots);  // the previous frame's m per selected slot, when requested

  publishNumber(ctx, "partition.count", kSlots);
  publishNumber(ctx, "partition.active", double(fit_.parts.size()));
  publishNumber(ctx, "faces.front", fit_.selection.frontFaces ? 1.0 : 0.0);
  publishNumber(ctx, "depth.near", fit_.view.nearM);
  publishNumber(ctx, "depth.far", fit_.view.farM);
  for (int i = 0; i < kSlots; ++i) {
    const std::string key = "partition." + std::to_string(i);
    publishDepthLayer(ctx, key + ".map", maps_.texture(), i);
    publishNumber(ctx, key + ".texels", double(res) * double(res));
    const auto part = std::find_if(fit_.parts.begin(), fit_.parts.end(),
                                   [&](const partition::FacePart& p) { return p.slot == i; });
    const bool active = part != fit_.parts.end();
    publishNumber(ctx, key + ".active", active ? 1.0 : 0.0);
    if (!active) {
      for (const char* k : {".face", ".near", ".far", ".extent_m", ".texels_per_m", ".warp.eta",
                            ".warp.fallback", ".warp.fallback_cause", ".warped", ".warp.n_prime"})
        publishNumber(ctx, key + k, 0.0);
      continue;
    }
    const partition::FacePart& p = *part;
    publishNumber(ctx, key + ".face", p.face);
    publishNumber(ctx, key + ".near", p.nearM);
    publishNumber(ctx, key + ".far", p.farM);
    const double extent = std::max(p.fit.hi.x - p.fit.lo.x, p.fit.hi.z - p.fit.lo.z);
    publishNumber(ctx, key + ".extent_m", extent);
    publishNumber(ctx, key + ".texels_per_m", extent > 0.0 ? double(res) / extent : 0.0);
    publishNumber(ctx, key + ".warp.eta", p.fit.eta);
    publishNumber(ctx, key + ".warp.fallback", p.fit.fallback ? 1.0 : 0.0);
    publishNumber(ctx, key + ".warp.fallback_cause", double(int(p.fit.fallbackCause)));
    publishNumber(ctx, key + ".warped", p.fit.warped() ? 1.0 : 0.0);
    publishNumber(ctx, key + ".warp.n_prime", p.fit.warped() ? p.fit.nPrime : 0.0);
  }
}

void FacePartitionShadowMap::bindLookup(const gl::Program& resolve, int firstUnit) const {
  bindDepthLookup(resolve, views_);
  glBindTextureUnit(GLuint(firstUnit), maps_.texture().id());
  resolve.set("u_faceMaps", firstUnit);
  resolve.set("u_faceRayDir", glm::vec3(fit_.selection.rayDir));
  for (std::size_t f = 0; f < 6; ++f) {
    const std::string i = "[" + std::to_string(f) + "]";
    resolve.set(("u_facePlanes" + i).c_str(), glm::vec4(fit_.selection.planes[f]));
    resolve.set(("u_facePartition" + i).c_str(), fit_.selection.partitionOfFace[f]);
  }
}

MemoryStats FacePartitionShadowMap::memory() const {
  MemoryStats m;
  maps_.addMemory(m, "face partition maps (array)");
  mStats_.addMemory(m);
  return m;
}

std::optional<std::string> FacePartitionShadowMap::reloadShaders(const gl::ShaderLibrary& lib) {
  if (auto e = depthProgram_.rebuild(lib)) return e;
  return mStats_.reloadShaders(lib);
}

}  // namespace sl
