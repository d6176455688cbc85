// Shared fixture for the headless GL tests: one surfaceless EGL 4.5 core context for the
// whole test binary, and a helper that fails the test on any GL debug-output error.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>

#include "core/Renderer.h"
#include "gl/EglContext.h"
#include "scene/GltfLoader.h"

namespace sl::test {

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

/// A renderer on the shared context with a built-in scene and its first camera.
inline std::unique_ptr<Renderer> makeRenderer(const std::string& scene,
                                              const std::string& technique) {
  eglContext().makeCurrent();
  auto r = std::make_unique<Renderer>();
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

inline void expectNoGlErrors(Renderer& r) {
  for (const std::string& e : r.takeGlErrors()) ADD_FAILURE() << "GL error: " << e;
}

}  // namespace sl::test
