// Face-partitioned shadow maps (FacePartitionShadowMap.h): fit the face partitions, render
// each into its layer through its warp, bind the selection planes for the lookup.
#include "FacePartitionShadowMap.h"

#include <algorithm>
#include <stdexcept>

#include "algo/partition/StorageFactor.h"
#include "core/PartitionMStats.h"
#include "core/Publish.h"
#include "core/SceneGpu.h"
#include "core/Warp.h"

namespace sl {

namespace {

constexpr int kSlots = partition::kFaceSlots;  // per depth slice

/// Maps of the array for the parameters: kSlots per depth slice.
int mapsFor(const ParamSet& ps) {
  return kSlots * int(ps.getInt("face.zsplits"));
}

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
  std::vector<ParamDecl> p = shadowMapParamDecls(
      1024,
      "Width and height of EVERY face partition's map in texels. There are 5 per depth "
      "slice (the near face and the four sides, one slot each, unused ones empty): the "
      "total is 5 x face.zsplits times its square.");
  p.insert(p.begin(), warpEtaDecl(0.0));
  p.push_back(intParam("face.zsplits", "Depth slices", "Face partitions", 1,
                       {1, partition::kMaxFaceZSplits, 1})
                  .withHelp("k: face partitions combined with z-partitioning at the log split z_i "
                            "= n (f/n)^(i/k) of the view frustum clipped to the scene (Lloyd et "
                            "al. 2006's combined scheme), nested as face.nesting says: one warped "
                            "map per (slice, face), 5 k maps. 1: face partitioning alone."));
  p.push_back(
      choiceParam("face.nesting", "Nesting", "Face partitions", {"faces-first", "zsplits-first"})
          .withHelp(
              "faces-first (the paper: the view frustum's face partitions, each then cut along its "
              "length at the split depths; every slice selects by the whole frustum's faces) or "
              "zsplits-first (slices first: the frustum cut into slices first, each slice "
              "face-partitioned along its own faces, so every slice has its own near-face map). "
              "Only matters for face.zsplits > 1. Measured at 3 slices of 1024^2 (error "
              "faces-first / zsplits-first): corridor 0.172 / 0.168 %, diagonal 0.079 / 0.062 %, "
              "default 0.435 / 0.281 %: slices first is the better one there."));
  TechniqueInfo info{
      "face-partition", "Face-partitioned shadow maps",
      "Lloyd et al. 2006 §5.1: the view frustum split along its faces as seen from the light "
      "(front faces when v . y < 0, back faces otherwise), each part warped with LiSPSM along "
      "the bisector of its projected side edges, one map each; warping works even where the "
      "frustum looks square from the light (dueling frusta). With face.zsplits > 1 every face "
      "partition is also cut along its length at the log split (their combined scheme; "
      "face.nesting zsplits-first slices the frustum first). Directional light only.",
      std::move(p)};
  info.passes = {
      {"face fit", "Fit the face partitions",
       "Clip the view frustum to the scene, take its faces towards the light (light behind "
       "the viewer) or away from it (light in front), cut each face partition (faces-first) "
       "or the frustum (zsplits-first) into face.zsplits slices at the log split, and fit one "
       "warp per (slice, face): light-space z along the bisector of the "
       "face's two side edges projected perpendicular to the light, n' from warp.eta (0 = "
       "LiSPSM). The near face has no side edges: it warps along the view vector, or stays "
       "uniform where the frustum looks square.",
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
       "is unused), i = 5 s + f for depth slice s and f = 0 near, 1 -x, 2 +x, 3 -y (bottom), "
       "4 +y (top).",
       "4 B x min(resolution, 2048)^2 x 5 x face.zsplits",
       [](const ParamSet& ps) {
         const int r = ps.getInt("resolution");
         return publishedImageBytes(r, r) * std::uint64_t(mapsFor(ps));
       }},
      PartitionMStats::publicationDecl(mapsFor),
      number("partition.count", "Number of face slots (5 x face.zsplits)."),
      number("partition.active",
             "Number of (slice, face) maps used this frame (1 to 5 per slice: the faces towards "
             "the light, or away)."),
      number("partition.*.slice", "The depth slice of slot i (0 nearest)."),
      number("face.split.*",
             "View depth of split i of the clipped frustum (m): i = 0 its near plane .. "
             "face.zsplits its far plane (the log split)."),
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
  // Every slot's map, before the first frame (a 16384^2 array is refused here, not by it).
  info.checkParams = [](const ParamSet& ps) {
    return DepthMapArray::sizeError(int(ps.getInt("resolution")), mapsFor(ps),
                                    "face-partition: " + std::to_string(mapsFor(ps)) + " maps",
                                    "resolution or face.zsplits");
  };
  return info;
}

FacePartitionShadowMap::FacePartitionShadowMap(const gl::ShaderLibrary& lib)
    : depthProgram_(lib), mStats_(lib) {}

void FacePartitionShadowMap::renderShadows(FrameContext& ctx) {
  const int res = ctx.params.getInt("resolution");
  {
    auto pass = ctx.timer.scope("face fit");
    partition::FacePartitionFit fit;
    if (auto err = partition::fitFacePartitions(
            ctx.camera, ctx.aspect, ctx.scene.bounds, glm::dvec3(ctx.light.directionalTowards()),
            ctx.params.get("warp.eta"), fit, ctx.params.getInt("face.zsplits"),
            ctx.params.getInt("face.nesting") == 0 ? partition::FaceNesting::FacesFirst
                                                   : partition::FaceNesting::ZSplitsFirst))
      throw std::runtime_error(*err);
    fit_ = std::move(fit);
    views_.assign(std::size_t(fit_.slots()), DepthMapView{});
    for (const partition::FacePart& p : fit_.parts) {
      views_[std::size_t(p.slot)] = partView(p.fit);
      // The outside view: a warped face's light box and warping frustum, a uniform one's
      // orthographic light frustum; coloured by slot like the partition overlay.
      if (p.fit.warped() && ctx.outlines)
        addWarpOutlines(p.fit, *ctx.outlines, p.slot);
      else if (!p.fit.warped())
        ctx.addOutline(views_[std::size_t(p.slot)].lightViewProj, OutlineRole::LightMap, p.slot);
    }
    // The slices' split planes (the outside view's rectangles), as cascades draw theirs.
    if (ctx.outlines)
      for (std::size_t i = 1; i + 1 < fit_.splits.size(); ++i)
        ctx.outlines->splitDepthsM.push_back(float(fit_.splits[i]));
  }
  const int slots = fit_.slots();
  {
    auto pass = ctx.timer.scope("face maps");
    maps_.ensure(res, slots, "face-partition: " + std::to_string(slots) + " maps",
                 slots > kSlots ? "resolution or face.zsplits" : "resolution");
    std::vector<bool> used(std::size_t(slots), false);
    for (const partition::FacePart& p : fit_.parts) {
      used[std::size_t(p.slot)] = true;
      renderDepth(ctx, depthProgram_, maps_.layerFramebuffer(p.slot), res, res,
                  views_[std::size_t(p.slot)].lightViewProj);
    }
    for (int i = 0; i < slots; ++i)
      if (!used[std::size_t(i)]) {
        beginDepthPass(maps_.layerFramebuffer(i), res, res);  // cleared to 1: empty
      }
  }

  mStats_.update(ctx, slots);  // the previous frame's m per selected slot, when requested

  publishNumber(ctx, "partition.count", slots);
  publishNumber(ctx, "partition.active", double(fit_.parts.size()));
  publishNumber(ctx, "faces.front", fit_.selection.frontFaces ? 1.0 : 0.0);
  publishNumber(ctx, "depth.near", fit_.view.nearM);
  publishNumber(ctx, "depth.far", fit_.view.farM);
  for (std::size_t i = 0; i < fit_.splits.size(); ++i)
    publishNumber(ctx, "face.split." + std::to_string(i), fit_.splits[i]);
  for (int i = 0; i < slots; ++i) {
    const std::string key = "partition." + std::to_string(i);
    publishDepthLayer(ctx, key + ".map", maps_.texture(), i);
    publishNumber(ctx, key + ".texels", double(res) * double(res));
    publishNumber(ctx, key + ".slice", double(i / kSlots));
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
  resolve.set("u_faceSlices", fit_.selection.slices());
  resolve.set("u_faceEye", glm::vec3(fit_.selection.eye));
  resolve.set("u_faceForward", glm::vec3(fit_.selection.forward));
  for (std::size_t s = 0; s < fit_.selection.splitFarM.size(); ++s)
    resolve.set(("u_faceSplitFar[" + std::to_string(s) + "]").c_str(),
                float(fit_.selection.splitFarM[s]));
  for (std::size_t f = 0; f < fit_.selection.planes.size(); ++f) {
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
