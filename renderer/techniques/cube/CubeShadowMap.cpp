// Cube shadow map (CubeShadowMap.h): fit the faces, render their distances from the light
// (layered or six passes), bind the six per-face views of the shared lookup.
#include "CubeShadowMap.h"

#include <stdexcept>

#include "common/shared_constants.h"
#include "core/Publish.h"
#include "core/SceneGpu.h"
#include "core/omni/OmniDeclarations.h"

namespace sl {

namespace {

gl::ProgramDesc facePassProgramDesc() {
  return {"cube/distance",
          {{GL_VERTEX_SHADER, "cube/distance.vert"}, {GL_FRAGMENT_SHADER, "cube/distance.frag"}},
          {},
          {}};
}

gl::ProgramDesc layeredProgramDesc() {
  return {"cube/depth_layered",
          {{GL_VERTEX_SHADER, "cube/depth_layered.vert"},
           {GL_GEOMETRY_SHADER, "cube/depth_layered.geom"},
           {GL_FRAGMENT_SHADER, "cube/distance.frag"}},
          {},
          {}};
}

}  // namespace

TechniqueInfo CubeShadowMap::info() {
  std::vector<ParamDecl> p = shadowMapParamDecls(
      1024, "Width and height of EACH cube face in texels (a point light has six faces).");
  p.push_back(switchParam("cube.layered", "One layered pass", "Cube", true)
                  .withHelp("Render every face in one pass (a geometry shader sends each triangle "
                            "to the layers whose frustum it touches) instead of six passes over "
                            "the scene. The maps are identical; only the time differs."));
  TechniqueInfo info{"cube", "Cube shadow map",
                     "Omni-directional shadows: six 90° perspective depth maps "
                     "around a point light, one per cube face; a spot renders only the faces "
                     "its cone reaches. The lookup picks the face by the major axis of the "
                     "direction from the light.",
                     std::move(p)};
  info.passes = {{"cube faces", "Cube faces",
                  "Render the scene's distance from the light six times, once per 90° face "
                  "(+x, -x, +y, -y, +z, -z), in one layered pass or six: one frustum cannot "
                  "hold a light that shines every way. Texels are densest at the face "
                  "corners (3√3 times the centre's per steradian).",
                  "omni"}};
  info.publications = {
      omniMapsPublicationDecl(
          "face.*.map",
          "Every rendered face's map: the distance from the light along each texel centre's "
          "ray, (d - cube.near_m) / (cube.far_m - cube.near_m), 1 = nothing; i = face 0..5 (+x, "
          "-x, +y, -y, +z, -z).",
          "4 B x min(resolution, 2048)^2 x faces (6 for a point light)", omni::kCubeFaces),
      {"cube.faces",
       PublicationKind::Number,
       "How many faces were rendered (6, fewer for a spot).",
       "",
       {}},
      {"cube.near_m", PublicationKind::Number, "The faces' near plane (m).", "", {}},
      {"cube.far_m", PublicationKind::Number, "The faces' far plane (m).", "", {}},
  };
  info.lights = {LightType::Point, LightType::Spot};
  // Up to six faces (a point light's), before the first frame.
  info.checkParams =
      omniMapsCheck(omni::kCubeFaces, "cube: up to " + std::to_string(omni::kCubeFaces) + " faces");
  return info;
}

CubeShadowMap::CubeShadowMap(const gl::ShaderLibrary& lib)
    : depthProgram_(lib, facePassProgramDesc()), layeredProgram_(lib, layeredProgramDesc()) {}

void CubeShadowMap::setDistance(const gl::Program& program) const {
  program.set("u_cubeLightPos", fit_.lightPosM);
  program.set("u_cubeNearM", fit_.nearM);
  program.set("u_cubeFarM", fit_.farM);
}

void CubeShadowMap::renderShadows(FrameContext& ctx) {
  const int res = ctx.params.getInt("resolution");
  {
    auto pass = ctx.timer.scope("cube faces");
    omni::CubeFit fit;
    if (auto err = omni::fitCube(ctx.light, ctx.scene.bounds, fit)) throw std::runtime_error(*err);
    fit_ = fit;
    faces_.ensure(res, fit_.layers, "cube: " + std::to_string(fit_.layers) + " faces",
                  "resolution");
    views_.clear();
    for (int f = 0; f < omni::kCubeFaces; ++f) {
      DepthMapView v;
      v.lightViewProj = fit_.viewProj[size_t(f)];
      v.extentM = glm::vec2(2.0f);  // 2 tan(45°): metres per uv at 1 m along the face axis
      v.perspective = true;
      v.nearM = fit_.nearM;
      v.farM = fit_.farM;
      views_.push_back(v);
    }
    setDistance(depthProgram_);
    setDistance(layeredProgram_);
    if (ctx.params.getBool("cube.layered")) {
      beginDepthPass(faces_.layeredFramebuffer(), res, res);
      layeredProgram_.use();
      layeredProgram_.set("u_layerCount", fit_.layers);
      for (int f = 0; f < omni::kCubeFaces; ++f)
        if (int l = fit_.layer[size_t(f)]; l >= 0)
          layeredProgram_.set(("u_layerViewProj[" + std::to_string(l) + "]").c_str(),
                              fit_.viewProj[size_t(f)]);
      ctx.sceneGpu.draw(layeredProgram_, SL_UNIT_MATERIAL);
    } else {
      for (int f = 0; f < omni::kCubeFaces; ++f)
        if (int l = fit_.layer[size_t(f)]; l >= 0)
          renderDepth(ctx, depthProgram_, faces_.layerFramebuffer(l), res, res,
                      fit_.viewProj[size_t(f)]);
    }
  }
  publishNumber(ctx, "cube.faces", fit_.layers);
  publishNumber(ctx, "cube.near_m", fit_.nearM);
  publishNumber(ctx, "cube.far_m", fit_.farM);
  for (int f = 0; f < omni::kCubeFaces; ++f)
    if (int l = fit_.layer[size_t(f)]; l >= 0)
      publishDepthLayer(ctx, "face." + std::to_string(f) + ".map", faces_.texture(), l);
}

void CubeShadowMap::bindLookup(const gl::Program& resolve, int firstUnit) const {
  bindDepthLookup(resolve, views_);
  glBindTextureUnit(GLuint(firstUnit), faces_.texture().id());
  resolve.set("u_cubeFaces", firstUnit);
  setDistance(resolve);
  for (int f = 0; f < omni::kCubeFaces; ++f) {
    const std::string i = "[" + std::to_string(f) + "]";
    resolve.set(("u_cubeFaceLayer" + i).c_str(), fit_.layer[size_t(f)]);
    const omni::CubeFaceBasis b = omni::cubeFaceBasis(f);
    resolve.set(("u_cubeFaceBasis" + i).c_str(),
                glm::mat3(glm::vec3(b.right), glm::vec3(b.up), glm::vec3(b.forward)));
  }
}

MemoryStats CubeShadowMap::memory() const {
  MemoryStats m;
  faces_.addMemory(m, "cube faces (array)");
  return m;
}

std::optional<std::string> CubeShadowMap::reloadShaders(const gl::ShaderLibrary& lib) {
  if (auto e = depthProgram_.rebuild(lib)) return e;
  return layeredProgram_.rebuild(lib);
}

}  // namespace sl
