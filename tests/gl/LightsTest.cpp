// Positional lights on the GPU: uniform's one perspective map for a spot against the exact
// reference (spot-box, 4096^2 map), and techniques refusing a light they do not support
// (an error naming both, a neutral frame) instead of rendering a wrong image.
#include <algorithm>

#include "GlTestEnv.h"

namespace sl {
namespace {

TEST(Lights, UniformSpotBoxAt4096AgreesWithReference) {
  // The frame is 512x384 (not 4096^2) to keep llvmpipe fast; the map is 4096^2.
  auto r = test::makeRenderer("spot-box", "uniform");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->light().type, LightType::Spot);
  ASSERT_FALSE(r->params().set("resolution", 4096));
  for (const char* cam : {"overview", "edge-closeup"}) {
    SCOPED_TRACE(cam);
    const Camera* c = test::bookmark(*r->scene(), cam);
    ASSERT_TRUE(c);
    r->setCamera(*c);
    ASSERT_FALSE(r->renderFrame(512, 384, 0));
    auto err = r->computeError();
    EXPECT_GT(err.stats.covered, 100000u);
    // Both the cone's edge and the occluder's shadow are in view: some lit, some not.
    const auto lit = std::count(err.referenceMask.begin(), err.referenceMask.end(), 1);
    EXPECT_GT(lit, 10000);
    EXPECT_LT(err.stats.errorPct, 0.5) << "false lit " << err.stats.falseLitPct
                                       << "%, false shadow " << err.stats.falseShadowPct << "%";
  }
  test::expectNoGlErrors(*r);
}

TEST(Lights, SpotErrorFallsWithResolution) {
  auto r = test::makeRenderer("spot-box", "uniform");
  ASSERT_TRUE(r);
  double previous = 1e9;
  for (int res : {128, 1024, 4096}) {
    ASSERT_FALSE(r->params().set("resolution", res));
    ASSERT_FALSE(r->renderFrame(320, 240, 0));
    const double e = r->computeError().stats.errorPct;
    EXPECT_LT(e, previous) << "resolution " << res;
    previous = e;
  }
}

TEST(Lights, UnsupportedLightIsRefusedWithANeutralFrame) {
  auto r = test::makeRenderer("point-box", "uniform");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->light().type, LightType::Point);
  auto err = r->renderFrame(64, 48, 0);
  ASSERT_TRUE(err);
  EXPECT_EQ(*err, "technique 'uniform' supports: directional, spot; the light is a point light");
  // RTW: directional only, so the spot is refused too.
  auto rtw = test::makeRenderer("spot-box", "rtw-backward");
  ASSERT_TRUE(rtw);
  auto e2 = rtw->renderFrame(64, 48, 0);
  ASSERT_TRUE(e2);
  EXPECT_EQ(*e2, "technique 'rtw-backward' supports: directional; the light is a spot light");
  // A directional light on the same scene renders.
  rtw->setLight(Light::directional(35, 50));
  EXPECT_FALSE(rtw->renderFrame(64, 48, 0));
  // Every technique renders some light; the ones without a directional light (cube, for
  // point and spot) refuse it the same way.
  for (const TechniqueInfo& t : Renderer::techniques()) {
    ASSERT_FALSE(t.lights.empty()) << t.id;
    if (checkLightSupport(t, LightType::Directional)) {
      auto d = test::makeRenderer("plane-box", t.id);
      ASSERT_TRUE(d);
      auto e = d->renderFrame(64, 48, 0);
      ASSERT_TRUE(e) << t.id;
      EXPECT_NE(e->find("the light is a directional light"), std::string::npos) << *e;
    }
  }
}

}  // namespace
}  // namespace sl
