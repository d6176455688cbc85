// The uniform shadow map against the exact Embree reference, and the reference against
// the analytic shadow of plane-box; plus the golden image of the default scene.
#include <cmath>

#include "GlTestEnv.h"
#include "metrics/GoldenImage.h"
#include "scene/PlaneBoxAnalytic.h"

namespace sl {
namespace {

TEST(UniformAccuracy, PlaneBoxAt4096AgreesWithReference) {
  auto r = test::makeRenderer("plane-box", "uniform");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->params().set("resolution", 4096));
  ASSERT_FALSE(r->renderFrame(512, 384, 0));
  auto err = r->computeError();
  EXPECT_GT(err.stats.covered, 100000u);
  EXPECT_LT(err.stats.errorPct, 0.5) << "false lit " << err.stats.falseLitPct << "%, false shadow "
                                     << err.stats.falseShadowPct << "%";
  test::expectNoGlErrors(*r);
}

TEST(UniformAccuracy, ErrorRisesAsResolutionFalls) {
  auto r = test::makeRenderer("plane-box", "uniform");
  ASSERT_TRUE(r);
  double previous = -1.0;
  for (int res : {4096, 512, 64}) {
    ASSERT_FALSE(r->params().set("resolution", res));
    ASSERT_FALSE(r->renderFrame(320, 240, 0));
    double e = r->computeError().stats.errorPct;
    EXPECT_GT(e, previous) << "resolution " << res;
    previous = e;
  }
}

TEST(UniformAccuracy, ReferenceMatchesAnalyticShadowSquare) {
  auto r = test::makeRenderer("plane-box", "uniform");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->renderFrame(320, 240, 0));
  auto err = r->computeError();
  const glm::vec3 L = r->light().directionalTowards();
  size_t ground = 0, disagree = 0;
  for (size_t i = 0; i < err.frame.positions.size(); ++i) {
    const glm::vec4& p = err.frame.positions[i];
    if (p.w <= 0.0f || std::abs(p.y) > 1e-3f || err.frame.normals[i].y < 0.99f) continue;
    glm::vec2 xz(p.x, p.z);
    if (std::abs(planeBoxShadowSignedDistanceM(xz, L)) < 2e-3f) continue;  // on the border
    ++ground;
    bool analyticLit = !planeBoxAnalyticShadow(xz, L);
    if (analyticLit != (err.referenceMask[i] == 1)) ++disagree;
  }
  EXPECT_GT(ground, 10000u);
  EXPECT_EQ(disagree, 0u);
}

TEST(Golden, DefaultSceneUniform) {
  auto r = test::makeRenderer("default", "uniform");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->renderFrame(480, 270, 0));
  ImageRGBA8 img = r->readback().color;
  // llvmpipe is deterministic on one machine; the tolerance absorbs Mesa version drift.
  GoldenTolerance tol{24, 0.01};
  GoldenResult g =
      compareToGolden(img, std::filesystem::path(SHADOWLAB_GOLDEN_DIR) / "default-uniform.png", tol,
                      test::testOut("golden"), "default-uniform");
  EXPECT_TRUE(g.pass) << g.message;
}

// The warped techniques: diagonal's row seen from its end (the warp and, for DA-RTW, the
// rotation at work), after 3 frames so DA-RTW has turned its frustum. Same tolerance.
TEST(Golden, DiagonalRowEndRtw) {
  for (const char* technique : {"rtw-backward", "da-rtw"}) {
    auto r = test::makeRenderer("diagonal", technique);
    ASSERT_TRUE(r);
    const Camera* rowEnd = test::bookmark(*r->scene(), "row-end");
    ASSERT_TRUE(rowEnd);
    r->setCamera(*rowEnd);
    ASSERT_FALSE(r->params().set("resolution", 1024));
    for (int f = 0; f < 3; ++f) ASSERT_FALSE(r->renderFrame(480, 270, 0));
    ImageRGBA8 img = r->readback().color;
    const std::string name = std::string("diagonal-") + technique;
    GoldenResult g =
        compareToGolden(img, std::filesystem::path(SHADOWLAB_GOLDEN_DIR) / (name + ".png"),
                        GoldenTolerance{24, 0.01}, test::testOut("golden"), name);
    EXPECT_TRUE(g.pass) << g.message;
    test::expectNoGlErrors(*r);
  }
}

}  // namespace
}  // namespace sl
