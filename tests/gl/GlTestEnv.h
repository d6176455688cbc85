// Shared fixture for the headless GL tests: one surfaceless EGL 4.5 core context for the
// whole test binary, a helper that fails the test on any GL debug-output error, and the check
// of per-partition m against a readback (cascades, face-partition).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/Renderer.h"
#include "gl/EglContext.h"
#include "scene/GltfLoader.h"

namespace sl::test {

/// 14 directions over the sphere: the 6 axes and the 8 cube diagonals (unit), for a camera
/// at an omni light looking every way (cube and dual-paraboloid lookup parity).
inline std::vector<glm::vec3> sphereLookDirections() {
  std::vector<glm::vec3> looks = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                  {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  for (float sx : {-1.0f, 1.0f})
    for (float sy : {-1.0f, 1.0f})
      for (float sz : {-1.0f, 1.0f}) looks.push_back(glm::normalize(glm::vec3(sx, sy, sz)));
  return looks;
}

inline gl::EglContext& eglContext() {
  static gl::EglContext ctx;
  return ctx;
}

inline std::filesystem::path testOut(const std::string& sub = {}) {
  std::filesystem::path p = std::filesystem::path(SHADOWLAB_TEST_OUT) / "gl" / sub;
  std::filesystem::create_directories(p);
  return p;
}

inline std::shared_ptr<Scene> loadBuiltin(const std::string& name) {
  SceneLoadResult r = loadSceneByNameOrPath(name);
  EXPECT_TRUE(r) << r.error;
  return r.scene;
}

/// An 8 m floor (y = 0) under a point light at (0, 1, 0), and a roof quad at y = 0.5 over
/// x in [shadowFromX / 2, 2], z in [-1, 0]: its shadow on the floor begins at x =
/// shadowFromX and covers z < 0 only (OmniPcf's seams; Cube's stored distances).
inline std::shared_ptr<Scene> roofOverFloor(float shadowFromX) {
  auto s = std::make_shared<Scene>();
  s->name = "roof-over-floor";
  Material dark;  // lit floor well below white: the colour shows the filtered visibility
  dark.baseColorFactor = {0.25f, 0.25f, 0.25f, 1.0f};
  s->materials.push_back(dark);
  auto quad = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
    MeshPrimitive q;
    q.positions = {a, b, c, d};
    q.normals.assign(4, glm::vec3(0, 1, 0));
    q.indices = {0, 2, 1, 0, 3, 2};
    q.material = 0;
    s->primitives.push_back(q);
  };
  quad({-4, 0, -4}, {4, 0, -4}, {4, 0, 4}, {-4, 0, 4});
  const float x0 = shadowFromX / 2.0f;
  quad({x0, 0.5f, -1}, {2, 0.5f, -1}, {2, 0.5f, 0}, {x0, 0.5f, 0});
  s->bounds.min = {-4.0f, 0.0f, -4.0f};
  s->bounds.max = {4.0f, 0.5f, 4.0f};
  return s;
}

/// A renderer on the shared context with a built-in scene and its first camera (`options`:
/// e.g. a forced timing method).
inline std::unique_ptr<Renderer> makeRenderer(const std::string& scene,
                                              const std::string& technique,
                                              const RendererOptions& options = {}) {
  eglContext().makeCurrent();
  auto r = std::make_unique<Renderer>(options);
  auto s = loadBuiltin(scene);
  if (!s) return nullptr;
  r->setScene(s);
  r->setCamera(s->cameras.empty() ? s->defaultCamera() : s->cameras.front().camera);
  EXPECT_FALSE(r->setTechnique(technique));
  return r;
}

/// The scene's camera bookmark called `name`, or null.
inline const Camera* bookmark(const Scene& scene, const std::string& name) {
  for (const CameraBookmark& b : scene.cameras)
    if (b.name == name) return &b.camera;
  return nullptr;
}

/// The last frame opened exactly the declared passes, in the declared order
/// (FrameStats::passOrder: that frame's whatever the timing method). Where `passes` holds that
/// frame's times (glFinish timing) they name the same passes; timer-query times arrive a frame
/// late (Renderer.TimerQueryTimesNameThePassesOfTheFrameTheyTimed checks those).
inline void expectDeclaredPassesOpened(const FrameStats& stats,
                                       const std::vector<std::string>& declared) {
  EXPECT_EQ(stats.passOrder, declared);
  std::vector<std::string> timed;
  for (const PassTiming& p : stats.passes) timed.push_back(p.name);
  if (stats.timingMethod == "glFinish+wallclock") {
    EXPECT_EQ(timed, stats.passOrder);
  }
}

inline void expectNoGlErrors(Renderer& r) {
  for (const std::string& e : r.takeGlErrors()) ADD_FAILURE() << "GL error: " << e;
}

/// partition.<i>.m.* (core/PartitionMStats) of maps 0..maps-1 against `frame` (the resolve
/// those statistics came from): the pixels that selected each map, their largest m, a p95
/// within one 1/8-octave bin above the exact one. Returns the pixels counted over all maps.
inline double expectPartitionMMatches(const Publication& pub, const FrameReadback& frame,
                                      int maps) {
  double counted = 0.0;
  for (int i = 0; i < maps; ++i) {
    std::vector<float> ms;
    for (std::size_t p = 0; p < frame.aliasing.size(); ++p)
      if (frame.aliasing[p] > 0.0f && frame.mapIndex[p] == i) ms.push_back(frame.aliasing[p]);
    const std::string k = "partition." + std::to_string(i) + ".m.";
    EXPECT_EQ(pub.numbers.at(k + "pixels"), double(ms.size())) << i;
    counted += pub.numbers.at(k + "pixels");
    std::printf("map %d: %zu pixels, m p95 %.3f max %.3f\n", i, ms.size(),
                pub.numbers.at(k + "p95"), pub.numbers.at(k + "max"));
    if (ms.empty()) continue;
    std::sort(ms.begin(), ms.end());
    EXPECT_FLOAT_EQ(float(pub.numbers.at(k + "max")), ms.back()) << i;
    const double p95 = ms[std::min(ms.size() - 1, std::size_t(0.95 * double(ms.size())))];
    EXPECT_GE(pub.numbers.at(k + "p95"), p95 * 0.999) << i;
    EXPECT_LE(pub.numbers.at(k + "p95"), p95 * 1.091 * 1.001) << i;
  }
  return counted;
}

}  // namespace sl::test
