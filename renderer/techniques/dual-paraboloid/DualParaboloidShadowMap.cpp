// Dual-paraboloid shadow map (DualParaboloidShadowMap.h): frame and depth range, the two
// tessellated depth passes, the lookup's uniforms.
#include "DualParaboloidShadowMap.h"

#include <algorithm>
#include <stdexcept>

#include "common/shared_constants.h"
#include "core/Publish.h"
#include "core/SceneGpu.h"
#include "core/ShadowPass.h"

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

const glm::dvec3 kAxes[3] = {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}};

}  // namespace

TechniqueInfo DualParaboloidShadowMap::info() {
  std::vector<ParamDecl> p = shadowMapParamDecls(2048);
  for (ParamDecl& d : p)
    if (d.key == "resolution")
      d.help = "Width and height of EACH hemisphere's map in texels (the disc fills it).";
  p.push_back({.key = "dp.axis",
               .label = "Split axis",
               .group = "Dual paraboloid",
               .type = ParamType::Enum,
               .defaultValue = 0,
               .minValue = 0,
               .maxValue = 2,
               .step = 1,
               .enumNames = {"y", "x", "z"},
               .help = "Hemisphere 0 looks along +axis, hemisphere 1 along -axis: the split "
                       "plane (the discs' rims, where texels are 4 times denser per steradian "
                       "than at the centres) is perpendicular to it. A spot uses its own axis "
                       "and one hemisphere."});
  p.push_back({.key = "tessellation",
               .label = "Tessellation",
               .group = "Dual paraboloid",
               .type = ParamType::Bool,
               .defaultValue = 1,
               .minValue = 0,
               .maxValue = 1,
               .help = "Split long triangles (and tessellate each edge by how far the "
                       "paraboloid bends it) before mapping vertices. Off: the scene as "
                       "loaded, edges straight in the map where they should curve: long "
                       "triangles' shadows are the wrong shape (depth stays exact per texel)."});
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
      {"half.*.map", PublicationKind::ImageSet,
       "Each hemisphere's map (window depth = distance / far), i = 0 (along dp.axis), 1.",
       "4 B x min(resolution, 2048)^2 x hemispheres (2 for a point light)",
       [](const ParamSet& ps) {
         const int r = ps.getInt("resolution");
         return publishedImageBytes(r, r) * 2;
       }},
      {"dp.far_m", PublicationKind::Number, "The depth range's far end (m).", "", {}},
  };
  info.lights = {LightType::Point, LightType::Spot};
  // Both halves (a point light's), before the first frame.
  info.checkParams = [](const ParamSet& ps) {
    return DepthMapArray::sizeError(int(ps.getInt("resolution")), 2, "dual-paraboloid: 2 maps",
                                    "resolution");
  };
  return info;
}

DualParaboloidShadowMap::DualParaboloidShadowMap(const gl::ShaderLibrary& lib)
    : depthProgram_(lib, depthDesc()) {}

void DualParaboloidShadowMap::setMapping(const gl::Program& program) const {
  program.set("u_dpLight", lightPosM_);
  program.set("u_dpX", glm::vec3(frame_.x));
  program.set("u_dpY", glm::vec3(frame_.y));
  program.set("u_dpAxis", glm::vec3(frame_.axis));
  program.set("u_dpNearM", nearM_);
  program.set("u_dpFarM", farM_);
}

void DualParaboloidShadowMap::renderShadows(FrameContext& ctx) {
  const int res = ctx.params.getInt("resolution");
  const bool tess = ctx.params.getBool("tessellation");
  if (auto err = ctx.light.validate()) throw std::runtime_error(*err);
  if (!ctx.scene.bounds.valid()) throw std::runtime_error("scene: empty bounds (no geometry)");
  const bool spot = ctx.light.type == LightType::Spot;
  lightPosM_ = ctx.light.positionM;
  frame_ = omni::paraboloidFrame(spot ? glm::dvec3(ctx.light.spotAxis())
                                      : kAxes[std::clamp(ctx.params.getInt("dp.axis"), 0, 2)]);
  halves_ = spot ? 1 : 2;
  float far = 0.0f;
  for (const glm::vec3& c : ctx.scene.bounds.corners())
    far = std::max(far, glm::length(c - lightPosM_));
  if (ctx.light.rangeM > 0.0f) far = std::min(far, ctx.light.rangeM);
  nearM_ = 0.0f;
  farM_ = 1.01f * std::max(far, 1e-3f);

  auto pass = ctx.timer.scope("paraboloid halves");
  maps_.ensure(res, halves_, "dual-paraboloid: " + std::to_string(halves_) + " maps", "resolution");
  glEnable(GL_CLIP_DISTANCE0);
  for (int i = 0; i < halves_; ++i) {
    beginDepthPass(maps_.layerFramebuffer(i), res, res);
    depthProgram_.use();
    setMapping(depthProgram_);
    depthProgram_.set("u_dpHalfIndex", i);
    depthProgram_.set("u_tessOn", tess ? 1 : 0);
    depthProgram_.set("u_toleranceTexels", kToleranceTexels);
    depthProgram_.set("u_mapTexels", float(res));
    ctx.sceneGpu.draw(depthProgram_, SL_UNIT_MATERIAL, true,
                      tess ? SceneGpu::Geometry::SplitLongTriangles : SceneGpu::Geometry::AsLoaded);
  }
  glDisable(GL_CLIP_DISTANCE0);
  publishNumber(ctx, "dp.far_m", farM_);
  for (int i = 0; i < halves_; ++i)
    publishDepthLayer(ctx, "half." + std::to_string(i) + ".map", maps_.texture(), i);
}

void DualParaboloidShadowMap::bindLookup(const gl::Program& resolve, int firstUnit) const {
  glBindTextureUnit(GLuint(firstUnit), maps_.texture().id());
  resolve.set("u_dpMaps", firstUnit);
  resolve.set("u_dpHalves", halves_);
  setMapping(resolve);
}

MemoryStats DualParaboloidShadowMap::memory() const {
  MemoryStats m;
  maps_.addMemory(m, "paraboloid maps (array)");
  return m;
}

std::optional<std::string> DualParaboloidShadowMap::reloadShaders(const gl::ShaderLibrary& lib) {
  return depthProgram_.rebuild(lib);
}

}  // namespace sl
