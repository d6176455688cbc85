// algo/CameraNavigation: the view's camera rates. A drag across the view's height orbits the
// same angle at any window size, a pan keeps the point under the cursor under it, a wheel
// notch moves a fixed share of the distance and never through the target nor beyond a few
// scene sizes, flying covers a share of the scene per second; degenerate inputs (a view
// without height, empty bounds, a camera at its target) have defined results.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "algo/CameraNavigation.h"

namespace sl {
namespace {

Camera levelCamera() {
  Camera c;
  c.position = {3.0f, 1.0f, 8.0f};
  c.target = {3.0f, 1.0f, 0.0f};  // 8 m away, looking down -z, level
  c.fovYDeg = 50.0f;
  return c;
}

Aabb box(glm::vec3 min, glm::vec3 max) {
  Aabb b;
  b.extend(min);
  b.extend(max);
  return b;
}

/// Where `p` lands in a viewport of w x h pixels (y down) through `camera`.
glm::vec2 project(const Camera& camera, glm::vec3 p, int w, int h) {
  const glm::vec4 clip =
      camera.projection(float(w) / float(h)) * camera.view() * glm::vec4(p, 1.0f);
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  return {(ndc.x * 0.5f + 0.5f) * float(w), (0.5f - ndc.y * 0.5f) * float(h)};
}

void expectNear(glm::vec3 a, glm::vec3 b, float eps) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}

TEST(CameraNavigation, ScaleIsTheBoundsDiagonalElseTheDistanceElseOneMetre) {
  const Camera c = levelCamera();
  EXPECT_FLOAT_EQ(navigationScaleM(box({0, 0, 0}, {3, 4, 12}), c), 13.0f);
  EXPECT_FLOAT_EQ(navigationScaleM(Aabb{}, c), 8.0f);                     // empty
  EXPECT_FLOAT_EQ(navigationScaleM(box({1, 1, 1}, {1, 1, 1}), c), 8.0f);  // a point
  Camera atTarget = c;
  atTarget.position = atTarget.target;
  EXPECT_FLOAT_EQ(navigationScaleM(Aabb{}, atTarget), 1.0f);
}

TEST(CameraNavigation, ADragAcrossTheViewsHeightOrbitsHalfATurnAtAnySize) {
  EXPECT_FLOAT_EQ(orbitDegPerPixel(600), 0.3f);
  EXPECT_FLOAT_EQ(orbitDegPerPixel(1200), 0.15f);
  EXPECT_EQ(orbitDegPerPixel(0), 0.0f);
  EXPECT_EQ(orbitDegPerPixel(-5), 0.0f);
  const Camera c = levelCamera();
  for (int h : {300, 1080}) {
    const Camera turned = orbitByDrag(c, float(h), 0.0f, h);
    // Half a turn around the target: the other side, same height and distance.
    expectNear(turned.position, {3.0f, 1.0f, -8.0f}, 1e-4f);
    expectNear(turned.target, c.target, 0.0f);
    // A quarter of the height: a quarter turn; dragging right moves the camera to its left.
    const Camera quarter = orbitByDrag(c, float(h) / 2.0f, 0.0f, h);
    expectNear(quarter.position, {-5.0f, 1.0f, 0.0f}, 1e-4f);
  }
  // Dragging down raises the camera over the target (pitch), by the same rate.
  const Camera up = orbitByDrag(c, 0.0f, 100.0f, 600);  // 30 degrees
  EXPECT_NEAR(up.position.y - 1.0f, 8.0f * std::sin(glm::radians(30.0f)), 1e-4f);
  EXPECT_NEAR(glm::length(up.position - up.target), 8.0f, 1e-4f);
  // No height: nothing turns.
  expectNear(orbitByDrag(c, 50.0f, 50.0f, 0).position, c.position, 0.0f);
}

TEST(CameraNavigation, ADragAcrossTheViewsHeightLooksByTheFieldOfView) {
  const Camera c = levelCamera();
  EXPECT_FLOAT_EQ(lookDegPerPixel(c, 500), 0.1f);
  EXPECT_EQ(lookDegPerPixel(c, 0), 0.0f);
  for (int h : {240, 900}) {
    const Camera turned = lookByDrag(c, float(h), 0.0f, h);
    const float angleDeg =
        glm::degrees(std::acos(std::clamp(glm::dot(turned.forward(), c.forward()), -1.0f, 1.0f)));
    EXPECT_NEAR(angleDeg, 50.0f, 1e-2f) << h;
    EXPECT_GT(turned.forward().x, 0.0f);  // dragging right turns right
    expectNear(turned.position, c.position, 0.0f);
  }
}

TEST(CameraNavigation, PanKeepsThePointUnderTheCursorUnderIt) {
  const Camera c = levelCamera();
  EXPECT_NEAR(panMetresPerPixel(c, 800), 2.0f * 8.0f * std::tan(glm::radians(25.0f)) / 800.0f,
              1e-7f);
  for (const glm::ivec2 size : {glm::ivec2(800, 600), glm::ivec2(300, 1000)}) {
    for (const glm::vec2 drag : {glm::vec2(40.0f, 0.0f), glm::vec2(-25.0f, 60.0f)}) {
      const Camera panned = panByDrag(c, drag.x, drag.y, size.y);
      // The old target (at the target's depth, under the cursor where the drag started at
      // the centre) is under the cursor where it ended.
      const glm::vec2 at = project(panned, c.target, size.x, size.y);
      EXPECT_NEAR(at.x, float(size.x) / 2.0f + drag.x, 1e-3f);
      EXPECT_NEAR(at.y, float(size.y) / 2.0f + drag.y, 1e-3f);
      expectNear(panned.forward(), c.forward(), 1e-6f);
    }
  }
  expectNear(panByDrag(c, 10.0f, 10.0f, 0).position, c.position, 0.0f);
  Camera atTarget = c;
  atTarget.position = atTarget.target;
  EXPECT_EQ(panMetresPerPixel(atTarget, 600), 0.0f);
  expectNear(panByDrag(atTarget, 10.0f, 10.0f, 600).position, atTarget.position, 0.0f);
}

TEST(CameraNavigation, AWheelNotchMovesAShareOfTheDistanceAndBack) {
  EXPECT_FLOAT_EQ(dollyFactor(1.0f), 0.85f);
  EXPECT_FLOAT_EQ(dolliedDistanceM(10.0f, 1.0f, 100.0f), 8.5f);
  EXPECT_FLOAT_EQ(dolliedDistanceM(8.5f, -1.0f, 100.0f), 10.0f);
  EXPECT_FLOAT_EQ(dolliedDistanceM(100.0f, 2.0f, 1000.0f), 72.25f);
  // Half notches of a fine wheel add up to whole ones.
  EXPECT_NEAR(dolliedDistanceM(dolliedDistanceM(10.0f, 0.5f, 100.0f), 0.5f, 100.0f), 8.5f, 1e-5f);
}

TEST(CameraNavigation, DollyNeverGoesThroughTheTargetNorBeyondFourSceneSizes) {
  // Scene 100 m: in to 0.1 m at most, out to 400 m at most.
  EXPECT_FLOAT_EQ(dolliedDistanceM(10.0f, 1000.0f, 100.0f), 0.1f);
  EXPECT_FLOAT_EQ(dolliedDistanceM(10.0f, -1000.0f, 100.0f), 400.0f);
  // Already beyond a limit: never further past it, never pulled back to it.
  EXPECT_FLOAT_EQ(dolliedDistanceM(500.0f, -1.0f, 100.0f), 500.0f);
  EXPECT_FLOAT_EQ(dolliedDistanceM(500.0f, 1.0f, 100.0f), 425.0f);
  EXPECT_FLOAT_EQ(dolliedDistanceM(0.05f, 1.0f, 100.0f), 0.05f);
  EXPECT_FLOAT_EQ(dolliedDistanceM(0.085f, -1.0f, 100.0f), 0.1f);
  // Degenerate: no distance, no notches, not a number.
  EXPECT_EQ(dolliedDistanceM(0.0f, 1.0f, 100.0f), 0.0f);
  EXPECT_EQ(dolliedDistanceM(10.0f, 0.0f, 100.0f), 10.0f);
  EXPECT_EQ(dolliedDistanceM(10.0f, std::numeric_limits<float>::quiet_NaN(), 100.0f), 10.0f);
}

TEST(CameraNavigation, DollyMovesAlongTheViewRay) {
  const Camera c = levelCamera();
  const Aabb scene = box({-5, 0, -5}, {5, 0, 5});  // diagonal 14.14 m
  const Camera in = dollyByWheel(c, 1.0f, scene);
  expectNear(in.position, {3.0f, 1.0f, 6.8f}, 1e-5f);
  expectNear(in.target, c.target, 0.0f);
  const Camera far = dollyByWheel(c, -100.0f, scene);
  EXPECT_NEAR(glm::length(far.position - far.target), 4.0f * std::sqrt(200.0f), 1e-3f);
  EXPECT_GT(far.position.z, 8.0f);
  // Empty bounds: the camera's distance is the scale (out to 4 times it).
  EXPECT_NEAR(glm::length(dollyByWheel(c, -100.0f, Aabb{}).position - c.target), 32.0f, 1e-4f);
  // A camera at its target has no direction to move along: it stays.
  Camera atTarget = c;
  atTarget.position = atTarget.target;
  expectNear(dollyByWheel(atTarget, 1.0f, scene).position, atTarget.target, 0.0f);
}

TEST(CameraNavigation, FlyingCoversAShareOfTheScenePerSecond) {
  EXPECT_FLOAT_EQ(flySpeedMPerS(20.0f, false), 7.0f);
  EXPECT_FLOAT_EQ(flySpeedMPerS(20.0f, true), 28.0f);
  EXPECT_FLOAT_EQ(flyStepM(20.0f, 0.05f, false), 0.35f);
  EXPECT_FLOAT_EQ(flyStepM(20.0f, 2.0f, false), 0.7f);  // a stalled tick: 0.1 s at most
  EXPECT_EQ(flyStepM(20.0f, -1.0f, false), 0.0f);
  EXPECT_EQ(flyStepM(20.0f, std::numeric_limits<float>::infinity(), false), 0.0f);
  // The same share of a small and a large scene in the same time.
  EXPECT_FLOAT_EQ(flyStepM(0.2f, 0.05f, false) / 0.2f, flyStepM(2000.0f, 0.05f, false) / 2000.0f);
}

}  // namespace
}  // namespace sl
