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

std::vector<ParamDecl> shadowMapParamDecls(int defaultResolution) {
  return {
      {.key = "resolution",
       .label = "Resolution",
       .group = "Shadow map",
       .type = ParamType::Int,
       .defaultValue = double(defaultResolution),
       .minValue = 64,
       .maxValue = 16384,
       .step = 64,
       .help = "Shadow map width and height in texels.",
       .memoryKnob = true},
      {.key = "bias.slope",
       .label = "Slope term",
       .group = "Bias",
       .type = ParamType::Float,
       .defaultValue = 0.25,
       .minValue = 0.0,
       .maxValue = 16.0,
       .step = 0.25,
       .help =
           "Extra depth in the lookup: this many times the receiver plane's depth change over one "
           "local shadow-map texel (the plane itself is compared exactly at the sampled texel's "
           "centre; this covers curvature and rounding).",
       .uniform = "u_biasSlope"},
      {.key = "bias.constant",
       .label = "Constant bias",
       .group = "Bias",
       .type = ParamType::Float,
       .defaultValue = 0.001,
       .minValue = 0.0,
       .maxValue = 1.0,
       .step = 0.001,
       .help = "Extra depth in the lookup, in metres along the light direction.",
       .uniform = "u_biasConstantM"},
      {.key = "bias.normal",
       .label = "Normal offset",
       .group = "Bias",
       .type = ParamType::Float,
       .defaultValue = 0.5,
       .minValue = 0.0,
       .maxValue = 8.0,
       .step = 0.25,
       .help =
           "Receiver offset along its normal before the lookup, in local shadow-map texels (the "
           "largest side, warp compression included), times the sine of the light angle.",
       .uniform = "u_biasNormal"},
      {.key = "pcf",
       .label = "PCF radius",
       .group = "Filtering",
       .type = ParamType::Int,
       .defaultValue = 0,
       .minValue = 0,
       .maxValue = 3,
       .step = 1,
       .help =
           "Percentage-closer filtering kernel radius in texels for the shaded image (0 = hard). "
           "Metrics always use the hard test.",
       .uniform = "u_pcfRadius"},
  };
}

}  // namespace sl
