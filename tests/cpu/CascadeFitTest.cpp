// algo/partition/CascadeFit: every slice ∩ scene inside its partition's light frustum, the
// split chain, stabilisation (extent unchanged as the camera turns, bounds on whole texels
// as it moves), the measured depth range, bad input named, and partition.warp (LiSPSM per
// partition, the per-partition fallback, the slice outline in map uv).
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "algo/Focus.h"
#include "algo/partition/CascadeFit.h"
#include "algo/partition/StorageFactor.h"

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

// A small scene seen whole from inside (a 6 x 3 x 5 m room, the camera's far plane at 30 m):
// the deep slices' bounding spheres are far wider than the room. Clamped, every such slice
// covers exactly the room's light-space square (the same for any camera: stable) and its
// texels are finer; the near slice, smaller than the room, keeps its sphere; unclamped, the
// spheres as before. Every slice ∩ room stays inside its map either way.
TEST(CascadeFit, StabilisedSliceWiderThanTheSceneCoversTheScene) {
  const Aabb room = box({-3, 0, -2.5}, {3, 3, 2.5});
  Camera cam;
  cam.position = {-2.6f, 1.7f, -2.1f};
  cam.target = {0.1f, 0.5f, 0.7f};
  cam.nearM = 0.05f;
  cam.farM = 30.0f;
  cam.fovYDeg = 60.0f;
  CascadeSettings s;
  s.partitions = 4;
  s.resolution = 1024;
  CascadeFit clamped, sphere, turned;
  ASSERT_FALSE(fitCascades(cam, 16.0f / 9.0f, room, kLight, s, clamped));
  Camera other = cam;
  other.look(23.0f, -4.0f);
  other.position += glm::vec3(0.4f, 0.0f, 0.3f);
  ASSERT_FALSE(fitCascades(other, 16.0f / 9.0f, room, kLight, s, turned));
  s.clampToScene = false;
  ASSERT_FALSE(fitCascades(cam, 16.0f / 9.0f, room, kLight, s, sphere));
  int clampedParts = 0;
  for (size_t i = 0; i < clamped.parts.size(); ++i) {
    const CascadePart &c = clamped.parts[i], &o = sphere.parts[i];
    EXPECT_FALSE(o.sceneClamped);
    if (c.sceneClamped) {
      ++clampedParts;
      EXPECT_LT(c.texelM, o.texelM) << i;
      // The room's corners span the map along its larger side exactly.
      double lo = 1e9, hi = -1e9;
      for (const glm::vec3& q : room.corners()) {
        const glm::vec4 p = c.viewProj * glm::vec4(q, 1.0f);
        EXPECT_LE(std::abs(p.x), 1.0f + 1e-3f) << i;
        EXPECT_LE(std::abs(p.y), 1.0f + 1e-3f) << i;
        lo = std::min({lo, double(p.x), double(p.y)});
        hi = std::max({hi, double(p.x), double(p.y)});
      }
      EXPECT_GT(hi - lo, 1.9) << i;
      // Camera-free: a turned and moved camera whose slice is clamped gets the same map.
      if (turned.parts[i].sceneClamped) {
        EXPECT_DOUBLE_EQ(turned.parts[i].extentM.x, c.extentM.x);
        EXPECT_NEAR(orthoLeft(turned.parts[i].proj), orthoLeft(c.proj), 1e-9);
      }
    } else {
      EXPECT_DOUBLE_EQ(c.extentM.x, o.extentM.x) << i;
    }
    const auto pts = intersectFrustumWithBox(
        cam.frustumCorners(16.0f / 9.0f, float(c.nearM), float(c.farM)), room);
    for (const glm::vec3& q : pts) {
      const glm::vec4 p = c.viewProj * glm::vec4(q, 1.0f);
      EXPECT_LE(std::abs(p.x), 1.0f + 1e-4f) << i;
      EXPECT_LE(std::abs(p.y), 1.0f + 1e-4f) << i;
    }
  }
  EXPECT_GE(clampedParts, 2);
  EXPECT_FALSE(clamped.parts.front().sceneClamped);
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

// partition.warp: each partition warped with LiSPSM fitted around slice ∩ scene. Every
// point of the slice ∩ scene lands inside its map (after the perspective divide, w > 0),
// n' is the LiSPSM value of that slice's depth range (eq. 11 at eta = 0, Wimmer's general
// form), and over the slice's body the warp's maximum aliasing (the paper's S = M_x M_z of
// that body) is below the orthographic fit's: the point of warping every partition.
namespace sl::partition {
namespace {

TEST(CascadeFit, WarpedPartitionsCoverTheirSliceWithLispsm) {
  const Camera cam = lookingDownZ();
  const Aabb scene = box({-20, 0, -300}, {20, 10, 5});
  const float aspect = 16.0f / 9.0f;
  CascadeSettings s;
  s.partitions = 4;
  s.split = SplitScheme::Log;
  s.warp = true;
  CascadeFit fit;
  ASSERT_FALSE(fitCascades(cam, aspect, scene, kLight, s, fit));
  ASSERT_EQ(fit.parts.size(), 4u);
  const warp::ViewFrustum view = warp::ViewFrustum::fromCamera(cam, aspect);
  for (size_t i = 0; i < fit.parts.size(); ++i) {
    SCOPED_TRACE("partition " + std::to_string(i));
    const CascadePart& p = fit.parts[i];
    ASSERT_TRUE(p.warpFit);
    ASSERT_TRUE(p.warped()) << p.warpFit->fallbackReason;
    EXPECT_EQ(p.warpFit->fallbackCause, warp::FallbackCause::None);
    EXPECT_NEAR(p.warpFit->eta, 0.0, 1e-12);
    EXPECT_NEAR(p.warpFit->nPrime, p.warpFit->nPrimeLispsm, 1e-9 * p.warpFit->nPrime);
    const auto pts =
        intersectFrustumWithBox(cam.frustumCorners(aspect, float(p.nearM), float(p.farM)), scene);
    ASSERT_FALSE(pts.empty());
    std::vector<glm::dvec3> body(pts.begin(), pts.end());
    for (const glm::dvec3& q : body) {
      const glm::dvec4 c = glm::dmat4(p.viewProj) * glm::dvec4(q, 1.0);
      ASSERT_GT(c.w, 0.0);
      EXPECT_LE(std::abs(c.x / c.w), 1.0 + 1e-5);
      EXPECT_LE(std::abs(c.y / c.w), 1.0 + 1e-5);
      EXPECT_LE(std::abs(c.z / c.w), 1.0 + 1e-5);
    }
    // The same body, fitted orthographically (n' infinite): larger maximum aliasing.
    warp::WarpSettings ortho;
    ortho.kind = warp::WarpKind::Uniform;
    warp::WarpFit flat;
    ASSERT_FALSE(warp::fitWarp(view, body, glm::dvec3(kLight), ortho, flat));
    const Storage warped = storageOfBody(view, *p.warpFit, body);
    const Storage uniform = storageOfBody(view, flat, body);
    EXPECT_LT(warped.s, uniform.s);
    // The coarsest texel (at the slice's far face) is what texelM reports.
    EXPECT_GT(p.texelM, 0.0);
  }
}

// Light behind the viewer, inside the view cone: the frustum looks square from the light
// for every slice; each partition falls back to uniform, says why, and is stabilised
// exactly as without partition.warp.
TEST(CascadeFit, WarpFallsBackPerPartitionWhenTheFrustumLooksSquare) {
  const Camera cam = lookingDownZ();
  const Aabb scene = box({-20, 0, -300}, {20, 10, 5});
  // Towards the light: 6 degrees off the view axis, behind the camera (exactly on the axis
  // is the degenerate case: no direction to warp along).
  const glm::vec3 back = glm::normalize(cam.position - cam.target);
  const glm::vec3 behind =
      glm::normalize(back + 0.1f * glm::normalize(glm::cross(back, {0, 1, 0})));
  CascadeSettings s;
  s.partitions = 3;
  CascadeFit plain, warped;
  ASSERT_FALSE(fitCascades(cam, 1.0f, scene, behind, s, plain));
  s.warp = true;
  ASSERT_FALSE(fitCascades(cam, 1.0f, scene, behind, s, warped));
  for (size_t i = 0; i < warped.parts.size(); ++i) {
    const CascadePart& p = warped.parts[i];
    ASSERT_TRUE(p.warpFit);
    EXPECT_FALSE(p.warped());
    EXPECT_TRUE(p.warpFit->fallback);
    EXPECT_EQ(p.warpFit->fallbackCause, warp::FallbackCause::SquareLightBehind);
    EXPECT_EQ(p.viewProj, plain.parts[i].viewProj);
    EXPECT_DOUBLE_EQ(p.texelM, plain.parts[i].texelM);
  }
  // eta = -1 is the uniform map too (no fallback: asked for).
  s.eta = -1.0;
  ASSERT_FALSE(fitCascades(cam, 1.0f, scene, kLight, s, warped));
  for (const CascadePart& p : warped.parts) {
    EXPECT_FALSE(p.warped());
    EXPECT_FALSE(p.warpFit->fallback);
  }
  s.eta = 1.5;
  const auto e = fitCascades(cam, 1.0f, scene, kLight, s, warped);
  ASSERT_TRUE(e);
  EXPECT_NE(e->find("warp.eta"), std::string::npos) << *e;
}

// The slice outline of the Partitions panel: an orthographic map of the unit cube sees the
// 12 edges of a box inside it where they are; a perspective map clips edges behind its
// centre (w <= 0) and everything to [-1, 2]^2.
TEST(CascadeFit, SliceEdgesInMapUv) {
  // corners of the cube [-0.5, 0.5]^3 in ViewFrustum::corners order (z = -0.5 near ring).
  std::array<glm::dvec3, 8> c;
  const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
  for (int i = 0; i < 4; ++i) {
    c[size_t(i)] = {0.5 * sx[i], 0.5 * sy[i], -0.5};
    c[size_t(4 + i)] = {0.5 * sx[i], 0.5 * sy[i], 0.5};
  }
  const glm::mat4 ortho = glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, -1.0f, 1.0f);
  std::vector<float> e = sliceEdgesInMapUv(c, ortho);
  ASSERT_EQ(e.size(), 48u);
  for (float v : e) EXPECT_TRUE(std::abs(v - 0.25f) < 1e-6f || std::abs(v - 0.75f) < 1e-6f) << v;
  // Looking down -z from z = 0 (the cube's centre): the near ring (z = -0.5) is in front,
  // the far ring (z = +0.5) behind: the 4 far edges vanish, the 4 sides are cut at w > 0
  // and run off towards infinity, clipped to the [-1, 2]^2 square.
  const glm::mat4 persp = glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 10.0f);
  e = sliceEdgesInMapUv(c, persp);
  ASSERT_EQ(e.size(), 32u);
  for (float v : e) {
    EXPECT_GE(v, -1.0f - 1e-5f);
    EXPECT_LE(v, 2.0f + 1e-5f);
  }
  // The near ring: a square of side 1 at distance 0.5 under a 90-degree frustum: the map.
  for (size_t k = 0; k < 4; ++k)
    for (size_t j = 0; j < 4; ++j)
      EXPECT_TRUE(std::abs(e[k * 8 + j] - 0.0f) < 1e-5f || std::abs(e[k * 8 + j] - 1.0f) < 1e-5f);
}

}  // namespace
}  // namespace sl::partition
