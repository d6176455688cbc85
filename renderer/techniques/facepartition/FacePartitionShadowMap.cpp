// Face-partitioned shadow maps (FacePartitionShadowMap.h): fit the face partitions, render
// each into its layer through its warp, bind the selection planes for the lookup.
#include "FacePartitionShadowMap.h"

#include <algorithm>
#include <stdexcept>

#include "algo/partition/StorageFactor.h"
#include "core/Publish.h"
#include "core/SceneGpu.h"
#include "techniques/perspective/PerspectiveShadowMap.h"

namespace sl {

namespace {

/// The most partitions a frustum has towards one side of the light: the near face and the
/// four side faces.
constexpr int kMaxFaceParts = 5;
static_assert(kMaxFaceParts <= SL_MAX_DEPTH_MAPS);

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
          "Width and height of EVERY face partition's map in texels (the total is the number of "
          "partitions, 1 to 5, times its square: partition.count).";
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
  };
  info.publications = {
      {"partition.*.map", PublicationKind::ImageSet,
       "Every face partition's depth map as rendered (depth 0..1, warped), i = 0..count-1.",
       "4 B x resolution^2 x partitions (at most 5)",
       [](const ParamSet& ps) {
         const std::uint64_t r = std::uint64_t(ps.getInt("resolution"));
         return 4 * r * r * kMaxFaceParts;
       }},
      {"partition.count", PublicationKind::Number, "Number of face partitions (1 to 5).", "", {}},
      {"partition.*.face",
       PublicationKind::Number,
       "The frustum face of partition i: 0 near, 2 -x, 3 +x, 4 -y (bottom), 5 +y (top).",
       "",
       {}},
      {"partition.*.near",
       PublicationKind::Number,
       "Nearest view depth of partition i's region (m).",
       "",
       {}},
      {"partition.*.far",
       PublicationKind::Number,
       "Farthest view depth of partition i's region (m).",
       "",
       {}},
      {"partition.*.extent_m",
       PublicationKind::Number,
       "Partition i's light-space width: the larger of its x and z extents (m).",
       "",
       {}},
      {"partition.*.texels", PublicationKind::Number, "Partition i's texel count.", "", {}},
      {"partition.*.warp.eta",
       PublicationKind::Number,
       "eta of partition i's warp (-1: uniform).",
       "",
       {}},
      {"partition.*.warp.fallback",
       PublicationKind::Number,
       "1 when partition i asked for a warp but used the uniform map (warp::FallbackCause in "
       "partition.*.warp.fallback_cause).",
       "",
       {}},
      {"partition.*.warp.fallback_cause",
       PublicationKind::Number,
       "why: 0 none, 1 light behind, 2 light in front, 4 degenerate (warp::FallbackCause).",
       "",
       {}},
      {"faces.front",
       PublicationKind::Number,
       "1 when the front faces (towards the light, v . y < 0) are used, 0 for the back faces.",
       "",
       {}},
      {"depth.near", PublicationKind::Number, "Near plane of the clipped frustum (m).", "", {}},
      {"depth.far", PublicationKind::Number, "Far plane of the clipped frustum (m).", "", {}},
  };
  info.lights = {LightType::Directional};
  return info;
}

FacePartitionShadowMap::FacePartitionShadowMap(const gl::ShaderLibrary& lib)
    : depthProgram_(lib, depthProgramDesc()) {}

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
    views_.clear();
    for (const partition::FacePart& p : fit_.parts) views_.push_back(partView(p.fit));
  }
  const int k = int(fit_.parts.size());
  {
    auto pass = ctx.timer.scope("face maps");
    if (!maps_ || maps_.width() != res || maps_.layers() != k) {
      maps_ = gl::Texture::create2DArray(GL_DEPTH_COMPONENT32F, res, res, k);
      fbos_.clear();
      for (int i = 0; i < k; ++i) {
        gl::Framebuffer f = gl::Framebuffer::create();
        f.attachLayer(GL_DEPTH_ATTACHMENT, maps_, i);
        f.setDrawBuffers(0);
        f.checkComplete("face partition " + std::to_string(i));
        fbos_.push_back(std::move(f));
      }
    }
    for (int i = 0; i < k; ++i)
      renderDepth(ctx, depthProgram_, fbos_[std::size_t(i)].id(), res, res,
                  views_[std::size_t(i)].lightViewProj);
  }

  publishNumber(ctx, "partition.count", k);
  publishNumber(ctx, "faces.front", fit_.selection.frontFaces ? 1.0 : 0.0);
  publishNumber(ctx, "depth.near", fit_.view.nearM);
  publishNumber(ctx, "depth.far", fit_.view.farM);
  for (int i = 0; i < k; ++i) {
    const partition::FacePart& p = fit_.parts[std::size_t(i)];
    const std::string key = "partition." + std::to_string(i);
    publishDepthLayer(ctx, key + ".map", maps_, i);
    publishNumber(ctx, key + ".face", p.face);
    publishNumber(ctx, key + ".near", p.nearM);
    publishNumber(ctx, key + ".far", p.farM);
    publishNumber(ctx, key + ".extent_m",
                  std::max(p.fit.hi.x - p.fit.lo.x, p.fit.hi.z - p.fit.lo.z));
    publishNumber(ctx, key + ".texels", double(res) * double(res));
    publishNumber(ctx, key + ".warp.eta", p.fit.eta);
    publishNumber(ctx, key + ".warp.fallback", p.fit.fallback ? 1.0 : 0.0);
    publishNumber(ctx, key + ".warp.fallback_cause", double(int(p.fit.fallbackCause)));
  }
}

void FacePartitionShadowMap::bindLookup(const gl::Program& resolve, int firstUnit) const {
  bindDepthLookup(resolve, views_);
  glBindTextureUnit(GLuint(firstUnit), maps_.id());
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
  if (maps_)
    m.add("face partition maps (array)", gl::formatName(maps_.format()), maps_.width(),
          maps_.height(), maps_.layers(), gl::bytesPerTexel(maps_.format()));
  return m;
}

std::optional<std::string> FacePartitionShadowMap::reloadShaders(const gl::ShaderLibrary& lib) {
  return depthProgram_.rebuild(lib);
}

}  // namespace sl
