// The benchmark metrics on cases with known answers (issue 5): perspective aliasing m of a
// uniform map on a plane facing the light against the analytic texel-to-pixel ratio, and
// no mask change or false flicker on a static scene.
#include <cmath>

#include "GlTestEnv.h"
#include "algo/Focus.h"
#include "algo/metrics/BenchStats.h"
#include "metrics/ShadowReference.h"

namespace sl {
namespace {

// Camera straight above the plane-box ground looking down, light straight down: the ground
// faces both, so a ground pixel's footprint is the same square everywhere, of side
// 2 d tan(fovY / 2) / H metres, and a texel's is extent / resolution (the renderer fits the
// light frustum; fitDirectionalLight gives the same fit). m = texel side / pixel side.
TEST(Metrics, AliasingOnAPlaneFacingTheLightIsTheAnalyticRatio) {
  auto r = test::makeRenderer("plane-box", "uniform");
  ASSERT_TRUE(r);
  constexpr int kSize = 256;
  constexpr float kHeightM = 6.0f, kFovDeg = 60.0f;
  Camera cam;
  cam.position = {0.0f, kHeightM, 0.0f};
  cam.target = {0.0f, 0.0f, 0.0f};
  cam.up = {0.0f, 0.0f, -1.0f};
  cam.fovYDeg = kFovDeg;
  cam.nearM = 0.1f;
  cam.farM = 20.0f;
  ASSERT_FALSE(cam.validate());
  r->setCamera(cam);
  Light light;
  light.azimuthDeg = 0.0f;
  light.elevationDeg = 90.0f;
  r->setLight(light);

  LightFit fit;
  ASSERT_FALSE(fitDirectionalLight(cam, 1.0f, r->scene()->bounds, light.directionalTowards(),
                                   FocusSettings{}, fit));
  const double pixelM = 2.0 * kHeightM * std::tan(glm::radians(kFovDeg) / 2.0) / kSize;

  for (int res : {128, 1024}) {
    SCOPED_TRACE("resolution " + std::to_string(res));
    ASSERT_FALSE(r->params().set("resolution", res));
    ASSERT_FALSE(r->renderFrame(kSize, kSize, 0));
    FrameReadback f = r->readback();
    ASSERT_EQ(f.aliasing.size(), std::size_t(kSize) * kSize);
    // Ground pixels whose 3x3 neighbourhood is ground too (derivatives come from 2x2 quads,
    // so pixels next to the box see its edge).
    auto ground = [&](int x, int y) {
      const glm::vec4& p = f.positions[std::size_t(y) * kSize + std::size_t(x)];
      return p.w > 0.0f && std::abs(p.y) < 1e-3f;
    };
    double sum = 0.0;
    std::size_t n = 0;
    for (int y = 1; y + 1 < kSize; ++y)
      for (int x = 1; x + 1 < kSize; ++x) {
        bool all = true;
        for (int dy = -1; dy <= 1 && all; ++dy)
          for (int dx = -1; dx <= 1 && all; ++dx) all = ground(x + dx, y + dy);
        if (!all) continue;
        sum += f.aliasing[std::size_t(y) * kSize + std::size_t(x)];
        ++n;
      }
    ASSERT_GT(n, std::size_t(kSize * kSize / 2));
    const double texelM = std::sqrt(double(fit.extentM.x) * double(fit.extentM.y)) / res;
    const double analytic = texelM / pixelM;
    const double mean = sum / double(n);
    EXPECT_NEAR(mean, analytic, 0.05 * analytic)
        << "texel " << texelM << " m, pixel " << pixelM << " m, light extent " << fit.extentM.x
        << " x " << fit.extentM.y << " m";
    // The summary the CLI reports agrees on these pixels' scale.
    AliasingStats s = computeAliasingStats(f.aliasing, f.hardMask);
    EXPECT_GT(s.pixels, n);
    EXPECT_NEAR(percentile(std::span<const float>(f.aliasing), 50.0), analytic, 0.05 * analytic);
  }
  test::expectNoGlErrors(*r);
}

TEST(Metrics, StaticSceneHasNoMaskChangeAndNoFlicker) {
  auto r = test::makeRenderer("plane-box", "uniform");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->params().set("resolution", 512));  // coarse: plenty of wrong pixels
  ShadowReference reference(*r->scene());
  std::vector<std::uint8_t> previousMask, previousReference;
  for (int frame = 0; frame < 3; ++frame) {
    ASSERT_FALSE(r->renderFrame(320, 180, 0));
    FrameReadback f = r->readback();
    std::vector<std::uint8_t> ref;
    reference.evaluate(f.positions, f.normals, r->light().directionalTowards(), ref);
    if (frame > 0) {
      MaskChange c = compareConsecutiveMasks(previousMask, f.hardMask);
      FlickerStats fl = computeFlicker(previousMask, f.hardMask, previousReference, ref);
      EXPECT_GT(c.compared, 10000u);
      EXPECT_EQ(c.changed, 0u) << "frame " << frame;
      EXPECT_EQ(fl.flicker, 0u) << "frame " << frame;
      EXPECT_EQ(fl.pct, 0.0);
    }
    previousMask = f.hardMask;
    previousReference = ref;
  }
  test::expectNoGlErrors(*r);
}

}  // namespace
}  // namespace sl
