// The list of techniques. Adding a technique: its folder under techniques/ and shaders/,
// and one line here.
#include <stdexcept>

#include "core/Technique.h"
#include "techniques/asm/AsmShadowMap.h"
#include "techniques/cascades/CascadedShadowMap.h"
#include "techniques/facepartition/FacePartitionShadowMap.h"
#include "techniques/fvsm/FittedVirtualShadowMap.h"
#include "techniques/cube/CubeShadowMap.h"
#include "techniques/dual-paraboloid/DualParaboloidShadowMap.h"
#include "techniques/perspective/PerspectiveShadowMap.h"
#include "techniques/rmsm/RmsmShadowMap.h"
#include "techniques/rtw/RtwShadowMap.h"
#include "techniques/spherical/SphericalShadowMap.h"
#include "techniques/uniform/UniformShadowMap.h"
#include "techniques/virtual-tiled/VirtualTiledShadowMap.h"

namespace sl {

namespace {
template <RtwShadowMap::Analysis A, bool Rotation>
TechniqueEntry rtwEntry(const char* id) {
  return {RtwShadowMap::info(id), [](const gl::ShaderLibrary& lib) -> std::unique_ptr<Technique> {
            return std::make_unique<RtwShadowMap>(lib, RtwShadowMap::Config{A, Rotation});
          }};
}

template <PerspectiveShadowMap::Kind K>
TechniqueEntry perspectiveEntry(const char* id) {
  return {PerspectiveShadowMap::info(id),
          [](const gl::ShaderLibrary& lib) -> std::unique_ptr<Technique> {
            return std::make_unique<PerspectiveShadowMap>(lib, K);
          }};
}

template <typename T>
TechniqueEntry entry() {
  return {T::info(), [](const gl::ShaderLibrary& lib) -> std::unique_ptr<Technique> {
            return std::make_unique<T>(lib);
          }};
}
}  // namespace

const std::vector<TechniqueEntry>& techniqueRegistry() {
  static const std::vector<TechniqueEntry> list = {
      entry<UniformShadowMap>(),
      rtwEntry<RtwShadowMap::Analysis::Forward, false>("rtw-forward"),
      rtwEntry<RtwShadowMap::Analysis::Backward, false>("rtw-backward"),
      rtwEntry<RtwShadowMap::Analysis::Hybrid, false>("rtw-hybrid"),
      rtwEntry<RtwShadowMap::Analysis::Backward, true>("da-rtw"),
      perspectiveEntry<PerspectiveShadowMap::Kind::Psm>("psm"),
      perspectiveEntry<PerspectiveShadowMap::Kind::Lispsm>("lispsm"),
      perspectiveEntry<PerspectiveShadowMap::Kind::Tsm>("tsm"),
      entry<CascadedShadowMap>(),
      entry<FacePartitionShadowMap>(),
      entry<CubeShadowMap>(),
      entry<DualParaboloidShadowMap>(),
      entry<SphericalShadowMap>(),
      entry<RmsmShadowMap>(),
      entry<AsmShadowMap>(),
      entry<VirtualTiledShadowMap>(),
      entry<FittedVirtualShadowMap>(),
  };
  return list;
}

void setParamHelp(std::vector<ParamDecl>& decls, const std::string& key, std::string help) {
  for (ParamDecl& d : decls)
    if (d.key == key) {
      d.help = std::move(help);
      return;
    }
  throw std::logic_error("setParamHelp: no parameter '" + key + "'");
}

std::vector<ParamDecl> shadowMapParamDecls(int defaultResolution, std::string resolutionHelp) {
  std::vector<ParamDecl> decls = {
      intParam("resolution", "Resolution", "Shadow map", defaultResolution, {64, 16384, 64})
          .withHelp("Shadow map width and height in texels.")
          .asMemoryKnob(),
      floatParam("bias.slope", "Slope term", "Bias", 0.25, {0.0, 16.0, 0.25})
          .withUniform("u_biasSlope")
          .withHelp("Extra depth in the lookup: this many times the receiver plane's depth change "
                    "over one local shadow-map texel (the plane itself is compared exactly at the "
                    "sampled texel's centre; this covers curvature and rounding)."),
      floatParam("bias.constant", "Constant bias", "Bias", 0.001, {0.0, 1.0, 0.001})
          .withUniform("u_biasConstantM")
          .withHelp("Extra depth in the lookup, in metres along the light direction."),
      floatParam("bias.normal", "Normal offset", "Bias", 0.5, {0.0, 8.0, 0.25})
          .withUniform("u_biasNormal")
          .withHelp(
              "Receiver offset along its normal before the lookup, in local shadow-map texels (the "
              "largest side, warp compression included), times the sine of the light angle."),
      intParam("pcf", "PCF radius", "Filtering", 0, {0, 3, 1})
          .withUniform("u_pcfRadius")
          .withHelp("Percentage-closer filtering kernel radius in texels for the shaded image (0 = "
                    "hard). Metrics always use the hard test."),
  };
  if (!resolutionHelp.empty()) setParamHelp(decls, "resolution", std::move(resolutionHelp));
  return decls;
}

}  // namespace sl
