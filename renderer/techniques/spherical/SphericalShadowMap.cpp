// Spherical (lat-long) shadow map (SphericalShadowMap.h): frame and depth range, the depth
// pass per half of the map, the lookup's uniforms.
#include "SphericalShadowMap.h"

#include <algorithm>
#include <stdexcept>

#include "common/shared_constants.h"
#include "core/Publish.h"
#include "core/SceneGpu.h"

namespace sl {

namespace {

gl::ProgramDesc depthDesc() {
  return {"spherical/depth",
          {{GL_VERTEX_SHADER, "spherical/depth.vert"},
           {GL_GEOMETRY_SHADER, "spherical/depth.geom"},
           {GL_FRAGMENT_SHADER, "spherical/depth.frag"}},
          {},
          {}};
}

const glm::dvec3 kAxes[3] = {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}};

}  // namespace

TechniqueInfo SphericalShadowMap::info() {
  std::vector<ParamDecl> p = shadowMapParamDecls(2048);
  for (ParamDecl& d : p)
    if (d.key == "resolution")
      d.help =
          "Height of the latitude-longitude map in texels (latitude, 180°); its width is "
          "twice that (longitude, 360°), so texels are square in angle on the equator and "
          "the map holds 2 x resolution^2 texels, as the dual paraboloid at the same "
          "resolution.";
  p.push_back({.key = "sph.axis",
               .label = "Pole axis",
               .group = "Spherical",
               .type = ParamType::Enum,
               .defaultValue = 0,
               .minValue = 0,
               .maxValue = 2,
               .step = 1,
               .enumNames = {"y", "x", "z"},
               .help = "The poles (latitude ±90°) lie along +axis and -axis: every texel of the "
                       "map's top or bottom row meets there, so texels near a pole are about "
                       "2 x resolution / pi times smaller than on the equator (oversampled); "
                       "the seam (longitude ±180°) is a half-plane through the axis."});
  p.push_back({.key = "sph.exactCoverage",
               .label = "Exact coverage",
               .group = "Spherical",
               .type = ParamType::Bool,
               .defaultValue = 1,
               .minValue = 0,
               .maxValue = 1,
               .help = "The tool's change to the lecture's environment-map recipe (map each "
                       "vertex, let the rasteriser join them): draw each triangle over its "
                       "image's longitude-latitude bounds (copied across the seam, every "
                       "longitude where it holds a pole) and keep a texel where the texel's "
                       "own ray hits the triangle, so edges follow their true curves. Off: the "
                       "recipe as given, the three vertices mapped and joined by straight lines "
                       "in the map (copied across the seam): long triangles' shadows take the "
                       "wrong shape and a triangle around a pole is lost (depth stays exact per "
                       "texel)."});
  TechniqueInfo info{"spherical", "Spherical (lat-long) shadow map",
                     "Omni-directional shadows in one latitude-longitude map, the spherical "
                     "parameterisation the omni-light lecture slides list beside the cube and "
                     "the dual paraboloid (Romanick, after Brabec, Annen, Seidel 2002): "
                     "longitude and latitude about a pole axis are u and v; each texel stores "
                     "the exact distance along its own ray.",
                     std::move(p)};
  info.passes = {{"lat-long halves", "Latitude-longitude halves",
                  "Render the scene's distance from the light into the two halves of the "
                  "lat-long map (longitudes -180°..0° and 0°..180°): not a projection, so "
                  "straight edges become curves; each triangle is drawn over its image's bounds "
                  "(across the seam twice, around a pole over every longitude) and each texel "
                  "keeps it where its own ray hits it, at that ray's distance.",
                  "spherical"}};
  info.publications = {
      {"sph.half.*.map", PublicationKind::ImageSet,
       "Each half of the lat-long map (window depth = distance / far), i = 0 (longitudes "
       "-180°..0°), 1 (0°..180°).",
       "4 B x min(resolution, 2048)^2 x 2 halves",
       [](const ParamSet& ps) {
         const int r = ps.getInt("resolution");
         return publishedImageBytes(r, r) * 2;
       }},
      {"sph.far_m", PublicationKind::Number, "The depth range's far end (m).", "", {}},
  };
  info.lights = {LightType::Point, LightType::Spot};
  info.checkParams = [](const ParamSet& ps) {
    return DepthMapArray::sizeError(int(ps.getInt("resolution")), omni::kLatLongHalves,
                                    "spherical: 2 halves", "resolution");
  };
  return info;
}

SphericalShadowMap::SphericalShadowMap(const gl::ShaderLibrary& lib)
    : depthProgram_(lib, depthDesc()) {}

void SphericalShadowMap::setMapping(const gl::Program& program) const {
  program.set("u_sphLight", lightPosM_);
  program.set("u_sphX", glm::vec3(frame_.x));
  program.set("u_sphY", glm::vec3(frame_.y));
  program.set("u_sphPole", glm::vec3(frame_.pole));
  program.set("u_sphNearM", nearM_);
  program.set("u_sphFarM", farM_);
}

void SphericalShadowMap::renderShadows(FrameContext& ctx) {
  const int res = ctx.params.getInt("resolution");
  const bool exact = ctx.params.getBool("sph.exactCoverage");
  if (auto err = ctx.light.validate()) throw std::runtime_error(*err);
  if (!ctx.scene.bounds.valid()) throw std::runtime_error("scene: empty bounds (no geometry)");
  lightPosM_ = ctx.light.positionM;
  frame_ = omni::latLongFrame(kAxes[std::clamp(ctx.params.getInt("sph.axis"), 0, 2)]);
  float far = 0.0f;
  for (const glm::vec3& c : ctx.scene.bounds.corners())
    far = std::max(far, glm::length(c - lightPosM_));
  if (ctx.light.rangeM > 0.0f) far = std::min(far, ctx.light.rangeM);
  nearM_ = 0.0f;
  farM_ = 1.01f * std::max(far, 1e-3f);

  auto pass = ctx.timer.scope("lat-long halves");
  maps_.ensure(res, omni::kLatLongHalves, "spherical: 2 halves", "resolution");
  for (int i = 0; i < omni::kLatLongHalves; ++i) {
    beginDepthPass(maps_.layerFramebuffer(i), res, res);
    depthProgram_.use();
    setMapping(depthProgram_);
    depthProgram_.set("u_sphHalfIndex", i);
    depthProgram_.set("u_sphExact", exact ? 1 : 0);
    depthProgram_.set("u_mapTexels", float(res));
    ctx.sceneGpu.draw(depthProgram_, SL_UNIT_MATERIAL);
  }
  publishNumber(ctx, "sph.far_m", farM_);
  for (int i = 0; i < omni::kLatLongHalves; ++i)
    publishDepthLayer(ctx, "sph.half." + std::to_string(i) + ".map", maps_.texture(), i);
}

void SphericalShadowMap::bindLookup(const gl::Program& resolve, int firstUnit) const {
  glBindTextureUnit(GLuint(firstUnit), maps_.texture().id());
  resolve.set("u_sphMaps", firstUnit);
  setMapping(resolve);
}

MemoryStats SphericalShadowMap::memory() const {
  MemoryStats m;
  maps_.addMemory(m, "lat-long map (two halves, array)");
  return m;
}

std::optional<std::string> SphericalShadowMap::reloadShaders(const gl::ShaderLibrary& lib) {
  return depthProgram_.rebuild(lib);
}

}  // namespace sl
