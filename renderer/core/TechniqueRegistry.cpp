// The list of techniques. Adding a technique: its folder under techniques/ and shaders/,
// and one line here.
#include "core/Technique.h"
#include "techniques/rtw/RtwShadowMap.h"
#include "techniques/uniform/UniformShadowMap.h"

namespace sl {

namespace {
template <RtwShadowMap::Analysis A, bool Rotation>
TechniqueEntry rtwEntry(const char* id) {
  return {RtwShadowMap::info(id), [](const gl::ShaderLibrary& lib) -> std::unique_ptr<Technique> {
            return std::make_unique<RtwShadowMap>(lib, RtwShadowMap::Config{A, Rotation});
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
  };
  return list;
}

std::vector<ParamDecl> shadowMapParamDecls(int defaultResolution) {
  return {
      {"resolution",
       "Resolution",
       "Shadow map",
       ParamType::Int,
       double(defaultResolution),
       64,
       16384,
       64,
       {},
       "Shadow map width and height in texels."},
      {"bias.slope",
       "Slope term",
       "Bias",
       ParamType::Float,
       0.25,
       0.0,
       16.0,
       0.25,
       {},
       "Extra depth in the lookup: this many times the receiver plane's depth change over one "
       "local shadow-map texel (the plane itself is compared exactly at the sampled texel's "
       "centre; this covers curvature and rounding)."},
      {"bias.constant",
       "Constant bias",
       "Bias",
       ParamType::Float,
       0.001,
       0.0,
       1.0,
       0.001,
       {},
       "Extra depth in the lookup, in metres along the light direction."},
      {"bias.normal",
       "Normal offset",
       "Bias",
       ParamType::Float,
       0.5,
       0.0,
       8.0,
       0.25,
       {},
       "Receiver offset along its normal before the lookup, in local shadow-map texels (the "
       "largest side, warp compression included), times the sine of the light angle."},
      {"pcf",
       "PCF radius",
       "Filtering",
       ParamType::Int,
       0,
       0,
       3,
       1,
       {},
       "Percentage-closer filtering kernel radius in texels for the shaded image (0 = hard). "
       "Metrics always use the hard test."},
  };
}

}  // namespace sl
