// Spherical (lat-long) shadow map (SphericalShadowMap.h): the pole's frame, the depth pass per
// half of the map, the lookup's uniforms (the frame, depth range and halves' array:
// core/omni/OmniRayMap).
#include "SphericalShadowMap.h"

#include "algo/omni/LatLongMapping.h"
#include "common/shared_constants.h"
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

}  // namespace

TechniqueInfo SphericalShadowMap::info() {
  std::vector<ParamDecl> p = shadowMapParamDecls(
      2048,
      "Height of the latitude-longitude map in texels (latitude, 180°); its width is "
      "twice that (longitude, 360°), so texels are square in angle on the equator and "
      "the map holds 2 x resolution^2 texels, as the dual paraboloid at the same "
      "resolution.");
  p.push_back(omniAxisParamDecl(
      "sph.axis", "Pole axis", "Spherical",
      "The poles (latitude ±90°) lie along +axis and -axis: every texel of the map's top or "
      "bottom row meets there, so texels near a pole are about 2 x resolution / pi times "
      "smaller than on the equator (oversampled); the seam (longitude ±180°) is a half-plane "
      "through the axis."));
  p.push_back(
      switchParam("sph.exactCoverage", "Exact coverage", "Spherical", true)
          .withHelp(
              "The tool's change to the lecture's environment-map recipe (map each vertex, let the "
              "rasteriser join them): draw each triangle over its image's longitude-latitude "
              "bounds (copied across the seam, every longitude where it holds a pole) and keep a "
              "texel where the texel's own ray hits the triangle, so edges follow their true "
              "curves. Off: the recipe as given, the three vertices mapped and joined by straight "
              "lines in the map (copied across the seam): long triangles' shadows take the wrong "
              "shape and a triangle around a pole is lost (depth stays exact per texel)."));
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
      omniMapsPublicationDecl("sph.half.*.map",
                              "Each half of the lat-long map (window depth = distance / far), "
                              "i = 0 (longitudes -180°..0°), 1 (0°..180°).",
                              "4 B x min(resolution, 2048)^2 x 2 halves", 2),
      {"sph.far_m", PublicationKind::Number, "The depth range's far end (m).", "", {}},
  };
  info.lights = {LightType::Point, LightType::Spot};
  info.checkParams = omniMapsCheck(omni::kLatLongHalves, "spherical: 2 halves");
  return info;
}

SphericalShadowMap::SphericalShadowMap(const gl::ShaderLibrary& lib)
    : OmniRayMap(lib, depthDesc(), "lat-long map (two halves, array)") {}

void SphericalShadowMap::renderShadows(FrameContext& ctx) {
  const int res = ctx.params.getInt("resolution");
  const bool exact = ctx.params.getBool("sph.exactCoverage");
  const omni::LatLongFrame frame = omni::latLongFrame(omniAxisOf(ctx.params, "sph.axis"));
  fitFrame(ctx, frame.x, frame.y, frame.pole);

  auto pass = ctx.timer.scope("lat-long halves");
  ensureHalves(res, omni::kLatLongHalves, "spherical: 2 halves");
  for (int i = 0; i < omni::kLatLongHalves; ++i) {
    beginHalf(i, res);
    depthProgram_.set("u_sphHalfIndex", i);
    depthProgram_.set("u_sphExact", exact ? 1 : 0);
    depthProgram_.set("u_mapTexels", float(res));
    ctx.sceneGpu.draw(depthProgram_, SL_UNIT_MATERIAL);
  }
  publishHalves(ctx, "sph.far_m", "sph.half.", omni::kLatLongHalves);
}

void SphericalShadowMap::bindLookup(const gl::Program& resolve, int firstUnit) const {
  bindHalves(resolve, firstUnit, "u_sphMaps");
}

}  // namespace sl
