// Dual-paraboloid shadow map (DualParaboloidShadowMap.h): the hemispheres' frame, the two
// tessellated depth passes, the lookup's uniforms (the frame, depth range and halves' array:
// core/omni/OmniRayMap).
#include "DualParaboloidShadowMap.h"

#include "algo/omni/OmniMapping.h"
#include "common/shared_constants.h"
#include "core/SceneGpu.h"

namespace sl {

namespace {

gl::ProgramDesc depthDesc() {
  return {"dual-paraboloid/depth",
          {{GL_VERTEX_SHADER, "dual-paraboloid/depth.vert"},
           {GL_TESS_CONTROL_SHADER, "dual-paraboloid/depth.tesc"},
           {GL_TESS_EVALUATION_SHADER, "dual-paraboloid/depth.tese"},
           {GL_FRAGMENT_SHADER, "dual-paraboloid/depth.frag"}},
          {},
          {}};
}

/// Chord tolerance of the tessellation, in texels of the map.
constexpr float kToleranceTexels = 0.25f;

}  // namespace

TechniqueInfo DualParaboloidShadowMap::info() {
  std::vector<ParamDecl> p = shadowMapParamDecls(
      2048, "Width and height of EACH hemisphere's map in texels (the disc fills it).");
  p.push_back(omniAxisParamDecl(
      "dp.axis", "Split axis", "Dual paraboloid",
      "Hemisphere 0 looks along +axis, hemisphere 1 along -axis: the split plane (the discs' "
      "rims, where texels are 4 times denser per steradian than at the centres) is "
      "perpendicular to it. A spot uses its own axis and one hemisphere."));
  p.push_back(
      switchParam("tessellation", "Tessellation", "Dual paraboloid", true)
          .withHelp("Split long triangles (and tessellate each edge by how far the paraboloid "
                    "bends it) before mapping vertices. Off: the scene as loaded, edges straight "
                    "in the map where they should curve: long triangles' shadows are the wrong "
                    "shape (depth stays exact per texel)."));
  TechniqueInfo info{"dual-paraboloid", "Dual-paraboloid shadow map",
                     "Omni-directional shadows with two maps (Brabec, Annen, Seidel 2002; seed "
                     "001): each hemisphere around a point light maps to a disc through a "
                     "paraboloid, per tessellated vertex, with exact depth per texel.",
                     std::move(p)};
  info.passes = {{"paraboloid halves", "Paraboloid hemispheres",
                  "Render the scene's distance from the light twice, once per hemisphere, "
                  "each mapped to a disc by the paraboloid (x, y) / (1 + z): not a projection, "
                  "so straight edges become curves; the tessellator cuts long triangles so "
                  "their edges follow them, and every texel's depth is the distance to the "
                  "triangle's plane along its own direction.",
                  "omni"}};
  info.publications = {
      omniMapsPublicationDecl(
          "half.*.map",
          "Each hemisphere's map (window depth = distance / far), i = 0 (along dp.axis), 1.",
          "4 B x min(resolution, 2048)^2 x hemispheres (2 for a point light)", 2),
      {"dp.far_m", PublicationKind::Number, "The depth range's far end (m).", "", {}},
  };
  info.lights = {LightType::Point, LightType::Spot};
  // Both halves (a point light's), before the first frame.
  info.checkParams = omniMapsCheck(2, "dual-paraboloid: 2 maps");
  return info;
}

DualParaboloidShadowMap::DualParaboloidShadowMap(const gl::ShaderLibrary& lib)
    : OmniRayMap(lib, depthDesc(), "paraboloid maps (array)") {}

void DualParaboloidShadowMap::renderShadows(FrameContext& ctx) {
  const int res = ctx.params.getInt("resolution");
  const bool tess = ctx.params.getBool("tessellation");
  const bool spot = ctx.light.type == LightType::Spot;
  const omni::ParaboloidFrame frame = omni::paraboloidFrame(
      spot ? glm::dvec3(ctx.light.spotAxis()) : omniAxisOf(ctx.params, "dp.axis"));
  fitFrame(ctx, frame.x, frame.y, frame.axis);
  halves_ = spot ? 1 : 2;

  auto pass = ctx.timer.scope("paraboloid halves");
  ensureHalves(res, halves_, "dual-paraboloid: " + std::to_string(halves_) + " maps");
  glEnable(GL_CLIP_DISTANCE0);
  for (int i = 0; i < halves_; ++i) {
    beginHalf(i, res);
    depthProgram_.set("u_dpHalfIndex", i);
    depthProgram_.set("u_tessOn", tess ? 1 : 0);
    depthProgram_.set("u_toleranceTexels", kToleranceTexels);
    depthProgram_.set("u_mapTexels", float(res));
    ctx.sceneGpu.draw(depthProgram_, SL_UNIT_MATERIAL, true,
                      tess ? SceneGpu::Geometry::SplitLongTriangles : SceneGpu::Geometry::AsLoaded);
  }
  glDisable(GL_CLIP_DISTANCE0);
  publishHalves(ctx, "dp.far_m", "half.", halves_);
}

void DualParaboloidShadowMap::bindLookup(const gl::Program& resolve, int firstUnit) const {
  bindHalves(resolve, firstUnit, "u_dpMaps");
  resolve.set("u_dpHalves", halves_);
}

}  // namespace sl
