// "Declared once": the uniform declarations gl::Program checks names against
// (algo/GlslUniforms), a misspelled parameter key, and the constants C++ and GLSL share
// (shaders/common/shared_constants.h) agreeing with the C++ that mirrors them.
#include <gtest/gtest.h>

#include "algo/GlslUniforms.h"
#include "algo/Params.h"
#include "algo/metrics/BenchStats.h"
#include "algo/rtw/Warp.h"
#include "common/shared_constants.h"
#include "metrics/ErrorMetrics.h"

namespace sl {
namespace {

TEST(DeclaredOnce, DeclaredUniformsFindsEveryFormAndIgnoresComments) {
  const std::set<std::string> names = declaredUniforms(
      "#include \"x\"\n"
      "uniform float u_a;\n"
      "uniform vec2 u_b, u_c[4];  // uniform float u_commented;\n"
      "/* uniform int u_block_comment; */\n"
      "layout(r32ui, binding = 0) readonly uniform uimage2D u_im;\n"
      "layout(binding = SL_UNIT_G_POSITION) uniform sampler2D u_gPosition;\n"
      "uniform mat4 u_mapViewProj[SL_MAX_DEPTH_MAPS];\n"
      "uniform float u_init = 1.0;\n"
      "uniform Block { vec4 u_member; float u_other; };\n"
      "float u_uniformish;\n"
      "void main() { float uniformity = u_a; }\n");
  EXPECT_EQ(names, (std::set<std::string>{"u_a", "u_b", "u_c", "u_im", "u_gPosition",
                                          "u_mapViewProj", "u_init", "u_member", "u_other"}));
  EXPECT_FALSE(names.count("u_biasSlpoe"));  // a misspelling is simply not there
  EXPECT_EQ(uniformBaseName("u_weights[3]"), "u_weights");
  EXPECT_EQ(uniformBaseName("u_x"), "u_x");
}

TEST(DeclaredOnce, MisspelledParameterKeyIsAnErrorNamingIt) {
  ParamSet p({{.key = "resolution",
               .label = "Resolution",
               .group = "Shadow map",
               .type = ParamType::Int,
               .defaultValue = 1024,
               .minValue = 64,
               .maxValue = 16384,
               .uniform = ""}});
  try {
    (void)p.get("resolutoin");
    FAIL() << "get() of a misspelled key returned a value";
  } catch (const std::out_of_range& e) {
    EXPECT_NE(std::string(e.what()).find("resolutoin"), std::string::npos) << e.what();
  }
  auto err = p.set("resolutoin", 512);
  ASSERT_TRUE(err);
  EXPECT_NE(err->find("resolution"), std::string::npos) << *err;  // lists the known keys
}

TEST(DeclaredOnce, SharedConstantsAreTheOnesTheCppUses) {
  EXPECT_EQ(kMaskLit, SL_MASK_LIT);
  EXPECT_EQ(kMaskShadowed, SL_MASK_SHADOWED);
  EXPECT_EQ(kMaskUncovered, SL_MASK_EMPTY);
  EXPECT_EQ(kStatsMaskUncovered, SL_MASK_EMPTY);
  EXPECT_EQ(rtw::gaussianWeights(1000, 4.0f).size(), size_t(2 * SL_BLUR_MAX_RADIUS + 1));
  EXPECT_LE(SL_OVERLAY_NONE, SL_OVERLAY_GRID);
}

}  // namespace
}  // namespace sl
