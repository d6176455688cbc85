// algo/partition/CascadeFit: every slice ∩ scene inside its partition's light frustum, the
// split chain, stabilisation (extent unchanged as the camera turns, bounds on whole texels
// as it moves), the measured depth range, and bad input named.
#include <gtest/gtest.h>

#include <cmath>

#include "algo/Focus.h"
#include "algo/partition/CascadeFit.h"

namespace sl::partition {
namespace {

Camera lookingDownZ() {
  Camera c;
  c.position = {0.0f, 2.0f, 0.0f};
  c.target = {0.0f, 1.5f, -10.0f};
  c.nearM = 0.1f;
  c.farM = 500.0f;
  c.fovYDeg = 50.0f;
  return c;
}

Aabb box(glm::vec3 lo, glm::vec3 hi) {
  Aabb b;
  b.extend(lo);
  b.extend(hi);
  return b;
}

const glm::vec3 kLight = glm::normalize(glm::vec3(0.4f, 0.8f, 0.3f));

// Left edge of the orthographic projection in light view space (metres).
double orthoLeft(const glm::mat4& proj) {
  return -(1.0 + proj[3][0]) / proj[0][0];
}
double orthoBottom(const glm::mat4& proj) {
  return -(1.0 + proj[3][1]) / proj[1][1];
}

TEST(CascadeFit, EverySliceOfTheSceneIsInsideItsPartition) {
  const Camera cam = lookingDownZ();
  const Aabb scene = box({-20, 0, -300}, {20, 10, 5});
  for (bool stable : {false, true}) {
    for (SplitScheme split : {SplitScheme::Uniform, SplitScheme::Log, SplitScheme::Practical}) {
      SCOPED_TRACE(std::string(splitSchemeName(split)) + (stable ? " stabilised" : " tight"));
      CascadeSettings s;
      s.partitions = 5;
      s.split = split;
      s.stabilize = stable;
      CascadeFit fit;
      ASSERT_FALSE(fitCascades(cam, 16.0f / 9.0f, scene, kLight, s, fit));
      ASSERT_EQ(fit.parts.size(), 5u);
      ASSERT_EQ(fit.splits.size(), 6u);
      EXPECT_NEAR(fit.parts.front().nearM, fit.nearM, 1e-9);
      EXPECT_NEAR(fit.parts.back().farM, fit.farM, 1e-9);
      EXPECT_LE(fit.farM, 305.0 * 1.1);  // clipped to the scene, not the camera's 500 m
      for (size_t i = 0; i < fit.parts.size(); ++i) {
        const CascadePart& p = fit.parts[i];
        if (i > 0) {
          EXPECT_DOUBLE_EQ(p.nearM, fit.parts[i - 1].farM);
        }
        const auto pts = intersectFrustumWithBox(
            cam.frustumCorners(16.0f / 9.0f, float(p.nearM), float(p.farM)), scene);
        ASSERT_FALSE(pts.empty());
        for (const glm::vec3& q : pts) {
          const glm::vec4 c = p.viewProj * glm::vec4(q, 1.0f);
          EXPECT_LE(std::abs(c.x), 1.0f + 1e-4f) << "partition " << i;
          EXPECT_LE(std::abs(c.y), 1.0f + 1e-4f) << "partition " << i;
          EXPECT_LE(std::abs(c.z), 1.0f + 1e-4f) << "partition " << i;
        }
        // Every caster of the scene between the light and the slice is in the depth range.
        for (const glm::vec3& corner : scene.corners())
          EXPECT_GE((p.viewProj * glm::vec4(corner, 1.0f)).z, -1.0f - 1e-4f);
        EXPECT_NEAR(p.texelM, std::max(p.extentM.x, p.extentM.y) / s.resolution, 1e-12);
      }
      // Near partitions are smaller (finer texels) than far ones.
      EXPECT_LT(fit.parts.front().texelM, fit.parts.back().texelM);
    }
  }
}

TEST(CascadeFit, LogSplitsAreGeometric) {
  CascadeSettings s;
  s.partitions = 4;
  s.split = SplitScheme::Log;
  s.stabilize = false;
  CascadeFit fit;
  ASSERT_FALSE(
      fitCascades(lookingDownZ(), 1.0f, box({-50, 0, -600}, {50, 10, 50}), kLight, s, fit));
  const double ratio = fit.splits[1] / fit.splits[0];
  for (size_t i = 1; i + 1 < fit.splits.size(); ++i)
    EXPECT_NEAR(fit.splits[i + 1] / fit.splits[i], ratio, 1e-9 * ratio);
}

// The scene is much larger than the view: the split range is the camera's (quantised),
// so turning the camera must not change any extent and moving it keeps every partition's
// bounds on whole texels.
TEST(CascadeFit, StabilisedExtentIgnoresTurnsAndBoundsSnapToTexels) {
  const Aabb scene = box({-5000, -1, -5000}, {5000, 10, 5000});
  CascadeSettings s;
  s.partitions = 4;
  s.resolution = 1024;
  CascadeFit base;
  ASSERT_FALSE(fitCascades(lookingDownZ(), 1.5f, scene, kLight, s, base));
  for (int step = 1; step <= 20; ++step) {
    Camera c = lookingDownZ();
    c.look(float(step) * 1.7f, float(step % 5) * 0.4f);
    c.position += glm::vec3(0.013f, 0.0f, -0.021f) * float(step);
    c.target += glm::vec3(0.013f, 0.0f, -0.021f) * float(step);
    CascadeFit fit;
    ASSERT_FALSE(fitCascades(c, 1.5f, scene, kLight, s, fit));
    for (size_t i = 0; i < fit.parts.size(); ++i) {
      const CascadePart& p = fit.parts[i];
      EXPECT_DOUBLE_EQ(p.extentM.x, base.parts[i].extentM.x) << "step " << step << " part " << i;
      const double l = orthoLeft(p.proj) / p.texelM, b = orthoBottom(p.proj) / p.texelM;
      EXPECT_NEAR(l, std::round(l), 2e-3 * std::max(1.0, std::abs(l) * 1e-3)) << i;
      EXPECT_NEAR(b, std::round(b), 2e-3 * std::max(1.0, std::abs(b) * 1e-3)) << i;
    }
  }
}

TEST(CascadeFit, MeasuredDepthRangeNarrowsTheSplits) {
  const Aabb scene = box({-20, 0, -300}, {20, 10, 5});
  CascadeSettings s;
  s.stabilize = false;
  CascadeFit wide, narrow;
  ASSERT_FALSE(fitCascades(lookingDownZ(), 1.0f, scene, kLight, s, wide));
  s.visibleDepthM = glm::dvec2(3.0, 80.0);
  ASSERT_FALSE(fitCascades(lookingDownZ(), 1.0f, scene, kLight, s, narrow));
  EXPECT_NEAR(narrow.nearM, 3.0, 1e-9);
  EXPECT_NEAR(narrow.farM, 80.0, 1e-9);
  EXPECT_LT(wide.nearM, 1.0);
  EXPECT_LT(narrow.parts.front().texelM, wide.parts.front().texelM);
}

TEST(CascadeFit, BadInputIsNamed) {
  CascadeSettings s;
  s.partitions = 9;
  CascadeFit fit;
  auto e = fitCascades(lookingDownZ(), 1.0f, box({-1, 0, -1}, {1, 1, 1}), kLight, s, fit);
  ASSERT_TRUE(e);
  EXPECT_NE(e->find("partitions must be 1..8"), std::string::npos) << *e;
  s.partitions = 2;
  e = fitCascades(lookingDownZ(), 1.0f, Aabb{}, kLight, s, fit);
  ASSERT_TRUE(e);
  EXPECT_NE(e->find("bounds"), std::string::npos) << *e;
}

}  // namespace
}  // namespace sl::partition

namespace sl::partition {
namespace {
TEST(CascadeFit, DepthRangeHysteresis) {
  const glm::dvec2 first = holdDepthRange(std::nullopt, {2.0, 100.0});
  EXPECT_NEAR(first.x, 2.0 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(first.y, 100.0 * std::sqrt(2.0), 1e-12);
  // Small motions: held.
  EXPECT_EQ(holdDepthRange(first, {1.9, 110.0}), first);
  EXPECT_EQ(holdDepthRange(first, {2.5, 90.0}), first);
  // Outside: re-centred on the new range.
  EXPECT_NEAR(holdDepthRange(first, {1.0, 100.0}).x, 1.0 / std::sqrt(2.0), 1e-12);
  // Much narrower than held (the camera came close to a wall): re-fitted, not kept wide.
  EXPECT_NEAR(holdDepthRange(first, {10.0, 20.0}).y, 20.0 * std::sqrt(2.0), 1e-12);
}
}  // namespace
}  // namespace sl::partition

namespace sl::partition {
namespace {
TEST(CascadeFit, HistogramQuantile) {
  // 16 bins over log2 in [-8, 8): one octave each. 90 values in bin 8 ([1, 2)), 10 in bin 10
  // ([4, 8)): the median's bin ends at 2, the 95th percentile's at 8.
  std::vector<std::uint32_t> bins(16, 0);
  bins[8] = 90;
  bins[10] = 10;
  EXPECT_DOUBLE_EQ(histogramQuantileLog2(bins, 0.5, -8.0, 8.0), 2.0);
  EXPECT_DOUBLE_EQ(histogramQuantileLog2(bins, 0.9, -8.0, 8.0), 2.0);
  EXPECT_DOUBLE_EQ(histogramQuantileLog2(bins, 0.95, -8.0, 8.0), 8.0);
  EXPECT_DOUBLE_EQ(histogramQuantileLog2(bins, 1.0, -8.0, 8.0), 8.0);
  EXPECT_EQ(histogramQuantileLog2(std::vector<std::uint32_t>(16, 0), 0.95, -8.0, 8.0), 0.0);
}
}  // namespace
}  // namespace sl::partition
