// algo/OutsideView: frustum corners from clip matrices (the camera's own projection gives its
// frustumCorners), the centre of projection of a perspective matrix, the segments drawn for a
// technique's outlines, the third camera seeing every segment end, and the partition colours
// (algo/PartitionColours) a light map's box is drawn in.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "algo/OutsideView.h"
#include "algo/PartitionColours.h"
#include "common/shared_constants.h"

namespace sl {
namespace {

Camera mainCamera() {
  Camera c;
  c.position = {0.0f, 2.0f, 5.0f};
  c.target = {0.0f, 1.0f, -10.0f};
  c.nearM = 0.5f;
  c.farM = 300.0f;
  c.fovYDeg = 50.0f;
  return c;
}

Aabb bounds() {
  Aabb b;
  b.extend(glm::vec3(-20.0f, 0.0f, -40.0f));
  b.extend(glm::vec3(20.0f, 10.0f, 10.0f));
  return b;
}

void expectNear(const glm::vec3& a, const glm::vec3& b, float tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

TEST(OutsideView, ClipCubeCornersOfTheCameraAreItsFrustumCorners) {
  const Camera c = mainCamera();
  const float aspect = 16.0f / 9.0f;
  const auto corners = clipCubeCorners(c.projection(aspect) * c.view());
  const auto expected = c.frustumCorners(aspect, c.nearM, c.farM);
  for (int i = 0; i < 4; ++i) expectNear(corners[size_t(i)], expected[size_t(i)], 1e-4f);
  for (int i = 4; i < 8; ++i) expectNear(corners[size_t(i)], expected[size_t(i)], 0.05f);
}

TEST(OutsideView, ProjectionCentreOfAPerspectiveIsTheEyeAndNoneForOrtho) {
  const Camera c = mainCamera();
  const auto centre = projectionCentre(c.projection(1.0f) * c.view());
  ASSERT_TRUE(centre.has_value());
  expectNear(*centre, c.position, 1e-3f);
  const glm::mat4 ortho = glm::ortho(-3.0f, 4.0f, -2.0f, 5.0f, 1.0f, 30.0f) * c.view();
  EXPECT_FALSE(projectionCentre(ortho).has_value());
}

TEST(OutsideView, CameraFrustumStopsAtTheDeepestPointOfTheBounds) {
  const Camera c = mainCamera();
  // The bounds' deepest corner along the forward axis: z = -40 at the far side.
  const float farM = outlineFarM(c, bounds());
  float deepest = 0.0f;
  for (const glm::vec3& p : bounds().corners())
    deepest = std::max(deepest, glm::dot(p - c.position, c.forward()));
  EXPECT_FLOAT_EQ(farM, deepest);
  EXPECT_LT(farM, c.farM);
  EXPECT_FLOAT_EQ(outlineFarM(c, Aabb{}), c.farM);  // invalid bounds: the camera's far
}

TEST(OutsideView, SegmentsPerRole) {
  const Camera c = mainCamera();
  FrameOutlines o;
  // Two light maps (orthographic boxes) and a split between them; a perspective warp frustum.
  const glm::mat4 lightView = glm::lookAt(glm::vec3(0, 30, 0), glm::vec3(0), glm::vec3(0, 0, -1));
  o.frusta.push_back(FrustumOutline::fromClip(
      glm::ortho(-5.0f, 5.0f, -5.0f, 5.0f, 1.0f, 40.0f) * lightView, OutlineRole::LightMap, 0));
  o.frusta.push_back(FrustumOutline::fromClip(
      glm::ortho(-15.0f, 15.0f, -15.0f, 15.0f, 1.0f, 40.0f) * lightView, OutlineRole::LightMap, 1));
  o.frusta.push_back(FrustumOutline::fromClip(
      glm::perspective(glm::radians(40.0f), 1.0f, 2.0f, 30.0f) * lightView, OutlineRole::Warp, 0));
  EXPECT_FALSE(o.frusta[0].apex.has_value());
  EXPECT_TRUE(o.frusta[2].apex.has_value());
  o.splitDepthsM = {8.0f, 1e4f};  // the second lies beyond the drawn far: skipped
  const auto segs = outlineSegments(c, 1.5f, bounds(), o);
  auto count = [&](OutlineRole r) {
    return std::count_if(segs.begin(), segs.end(),
                         [&](const OutlineSegment& s) { return s.role == r; });
  };
  EXPECT_EQ(count(OutlineRole::Camera), 12);
  EXPECT_EQ(count(OutlineRole::Split), 4);
  EXPECT_EQ(count(OutlineRole::LightMap), 24);
  EXPECT_EQ(count(OutlineRole::Warp), 12 + 4);  // 12 edges + 4 lines to the centre
  // The warp's extra lines end at its centre of projection, the light view's eye, and are
  // not framed by the third camera; every other segment is.
  int toCentre = 0;
  for (const OutlineSegment& s : segs) {
    const bool toApex =
        s.role == OutlineRole::Warp && glm::length(s.b - glm::vec3(0, 30, 0)) < 1e-3f;
    toCentre += toApex ? 1 : 0;
    EXPECT_EQ(s.framed, !toApex);
  }
  EXPECT_EQ(toCentre, 4);
  // Light maps take the partition colours: map 0 red, map 1 green.
  EXPECT_GT(outlineColour(OutlineRole::LightMap, 0).r, 0.8f);
  EXPECT_GT(outlineColour(OutlineRole::LightMap, 1).g, 0.7f);
  EXPECT_EQ(outlineColour(OutlineRole::LightMap, 9), outlineColour(OutlineRole::LightMap, 1));
}

TEST(OutsideView, ThirdCameraSeesEverySegmentEnd) {
  const Camera c = mainCamera();
  FrameOutlines o;
  const glm::mat4 lightView = glm::lookAt(glm::vec3(0, 30, 0), glm::vec3(0), glm::vec3(0, 0, -1));
  o.frusta.push_back(FrustumOutline::fromClip(
      glm::ortho(-25.0f, 25.0f, -25.0f, 25.0f, 1.0f, 40.0f) * lightView, OutlineRole::LightMap, 0));
  const float aspect = 16.0f / 9.0f;
  const auto segs = outlineSegments(c, aspect, bounds(), o);
  for (float az : {0.0f, 60.0f, 135.0f, -90.0f}) {
    for (float el : {-30.0f, 10.0f, 35.0f, 80.0f}) {
      OutsideViewSettings set;
      set.azimuthDeg = az;
      set.elevationDeg = el;
      const Camera out = fitOutsideCamera(c, aspect, segs, set);
      ASSERT_FALSE(out.validate().has_value()) << az << " " << el;
      const glm::mat4 vp = out.projection(aspect) * out.view();
      for (const OutlineSegment& s : segs)
        for (const glm::vec3& p : {s.a, s.b}) {
          const glm::vec4 clip = vp * glm::vec4(p, 1.0f);
          ASSERT_GT(clip.w, 0.0f);
          for (int i = 0; i < 3; ++i)
            EXPECT_LE(std::abs(clip[i] / clip.w), 1.0f) << az << " " << el;
        }
    }
  }
  // Azimuth 0 looks along the main camera's horizontal forward.
  OutsideViewSettings behind;
  behind.azimuthDeg = 0.0f;
  behind.elevationDeg = 0.0f;
  const Camera out = fitOutsideCamera(c, aspect, segs, behind);
  glm::vec3 f = c.forward();
  f.y = 0.0f;
  EXPECT_GT(glm::dot(glm::normalize(f), out.forward()), 0.999f);
}

// The one C++ copy of the overlay colours: the shader constants, wrapped mod 8 both ways,
// eight distinct colours, and a light map's outline in its map's colour.
TEST(PartitionColours, AreTheSharedConstantsWrappedModEight) {
  const float first[3] = {SL_PARTITION_COLOUR_0}, last[3] = {SL_PARTITION_COLOUR_7};
  expectNear(partitionColour(0), glm::vec3(first[0], first[1], first[2]), 0.0f);
  expectNear(partitionColour(7), glm::vec3(last[0], last[1], last[2]), 0.0f);
  EXPECT_EQ(SL_PARTITION_COLOURS, 8);
  for (int i = 0; i < SL_PARTITION_COLOURS; ++i) {
    EXPECT_EQ(partitionColour(i + SL_PARTITION_COLOURS), partitionColour(i)) << i;
    EXPECT_EQ(partitionColour(i - SL_PARTITION_COLOURS), partitionColour(i)) << i;
    EXPECT_EQ(outlineColour(OutlineRole::LightMap, i), partitionColour(i)) << i;
    for (int j = 0; j < i; ++j) EXPECT_NE(partitionColour(i), partitionColour(j)) << i << " " << j;
  }
}

}  // namespace
}  // namespace sl
