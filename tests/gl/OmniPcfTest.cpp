// PCF across the seams of the omni maps: taps beyond a cube face's edge read the
// neighbouring face (shaders/cube/lookup.glsl, shadowMapDepthAcross), taps beyond a
// paraboloid's rim read the other hemisphere (shaders/dual-paraboloid/lookup.glsl,
// dpTexelTest). A shadow that begins one texel beyond the seam must darken the filtered
// result of the pixels in the seam's last texel, and a lit floor must stay exactly lit
// (no acne from reading across).
#include "GlTestEnv.h"
#include "common/shared_constants.h"

namespace sl {
namespace {

struct SeamPcfCase {
  const char* technique;
  const char* axisParam;  ///< a parameter to set to 1 (dp.axis = x), or null
  float seamX;            ///< where the floor crosses the seam (m)
};

class OmniPcf : public ::testing::TestWithParam<SeamPcfCase> {};

TEST_P(OmniPcf, FilteringReachesAcrossTheSeam) {
  // 64^2 maps: at the seam the texels are 1/32 m wide along x on the floor (cube: the -y
  // face's edge at x = 1, distance 1 along its axis; paraboloid split along x: its rim at
  // x = 0, 2/64 rad at 1 m). The shadow begins one texel beyond the seam. PCF radius 2:
  // pixels within half a texel of the seam (its last texel: the rim need not fall on a
  // texel border) have a fifth of their taps in that shadow, so they are
  // darker than under a hard lookup (where they are lit); clamped at the seam every tap
  // would read the lit edge texel (no penumbra: the same colour). Where no shadow is within
  // reach (z > 0.1), PCF is exactly the hard lookup's colour, seam or not.
  const SeamPcfCase sc = GetParam();
  const float texelM = 1.0f / 32.0f;
  test::eglContext().makeCurrent();
  Renderer r;
  r.setScene(test::roofOverFloor(sc.seamX + texelM));
  ASSERT_FALSE(r.setTechnique(sc.technique));
  r.setLight(Light::point({0.0f, 1.0f, 0.0f}));
  ASSERT_FALSE(r.params().set("resolution", 64));
  if (sc.axisParam) {
    ASSERT_FALSE(r.params().set(sc.axisParam, 1));
  }
  Camera cam;  // under the roof, straight down at the seam
  cam.position = {sc.seamX, 0.4f, 0.0f};
  cam.target = {sc.seamX, 0.0f, 0.0f};
  cam.up = {1.0f, 0.0f, 0.0f};
  cam.fovYDeg = 40.0f;
  cam.nearM = 0.1f;
  cam.farM = 5.0f;
  r.setCamera(cam);
  const int size = 128;
  auto render = [&](int pcf) {
    EXPECT_FALSE(r.params().set("pcf", pcf));
    EXPECT_FALSE(r.renderFrame(size, size, 0));
    return r.readback();
  };
  const FrameReadback hard = render(0), soft = render(2);
  auto grey = [&](const FrameReadback& f, std::size_t i) { return int(f.color.pixels[i * 4 + 1]); };
  int darkened = 0, litCompared = 0;
  for (std::size_t i = 0; i < soft.positions.size(); ++i) {
    const glm::vec4 P = soft.positions[i];
    ASSERT_GT(P.w, 0.0f);
    if (P.z > 0.1f) {
      EXPECT_EQ(grey(soft, i), grey(hard, i)) << "P " << P.x << ", " << P.z;
      ++litCompared;
    }
    if (P.z < -0.1f && P.x < sc.seamX && P.x > sc.seamX - 0.45f * texelM &&
        hard.hardMask[i] == SL_MASK_LIT) {
      EXPECT_LT(grey(soft, i), grey(hard, i) - 4)
          << "P " << P.x << ", " << P.z << ": no penumbra from across the seam";
      ++darkened;
    }
  }
  EXPECT_GT(litCompared, 1000);
  EXPECT_GT(darkened, 50);
  test::expectNoGlErrors(r);
}

INSTANTIATE_TEST_SUITE_P(Maps, OmniPcf,
                         ::testing::Values(SeamPcfCase{"cube", nullptr, 1.0f},
                                           SeamPcfCase{"dual-paraboloid", "dp.axis", 0.0f}),
                         [](const auto& p) {
                           return std::string(p.param.technique) == "cube" ? "CubeFaceEdge"
                                                                           : "ParaboloidRim";
                         });

}  // namespace
}  // namespace sl
