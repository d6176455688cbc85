// The depth-only light pass in two builds (core/ShadowPass.h DepthProgram): primitives whose
// material is not alpha-tested are drawn with the opaque build (no discard), alpha-tested ones
// with the alpha test. The depth this writes must be the single alpha-testing program's,
// texel for texel, and the alpha-tested casters must keep their holes.
#include <cstdio>
#include <functional>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "GlTestEnv.h"
#include "common/shared_constants.h"
#include "core/SceneGpu.h"
#include "core/ShadowPass.h"
#include "gl/Gl.h"
#include "gl/ShaderLibrary.h"

namespace sl {
namespace {

constexpr int kSize = 256;

/// The scene's depth from above at an angle, into a kSize² map, read back.
std::vector<float> depthOf(const Scene& scene, const std::function<void(const glm::mat4&)>& draw) {
  gl::Texture map = gl::Texture::create2D(GL_DEPTH_COMPONENT32F, kSize, kSize);
  gl::Framebuffer fbo = gl::Framebuffer::create();
  fbo.attach(GL_DEPTH_ATTACHMENT, map);
  fbo.setDrawBuffers(0);
  fbo.checkComplete("depth program test");
  const glm::vec3 c = (scene.bounds.min + scene.bounds.max) * 0.5f;
  const float r = glm::length(scene.bounds.max - scene.bounds.min) * 0.5f;
  const glm::vec3 towards = glm::normalize(glm::vec3(0.4f, 1.0f, 0.3f));
  const glm::mat4 viewProj = glm::ortho(-r, r, -r, r, 0.0f, 4.0f * r) *
                             glm::lookAt(c + towards * 2.0f * r, c, glm::vec3(0, 0, 1));
  beginDepthPass(fbo.id(), kSize, kSize);
  draw(viewProj);
  std::vector<float> depth(std::size_t(kSize) * kSize);
  glGetTextureImage(map.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                    GLsizei(depth.size() * sizeof(float)), depth.data());
  return depth;
}

TEST(DepthProgram, TheOpaqueBuildWritesTheSameDepthAndAlphaTestedCastersKeepTheirHoles) {
  test::eglContext().makeCurrent();
  gl::ShaderLibrary lib(gl::ShaderLibrary::defaultRoot());
  auto scene = test::loadBuiltin("default");  // an alpha-tested (MASK) fence among opaque boxes
  ASSERT_TRUE(scene);
  int masked = 0;
  for (const Material& m : scene->materials) masked += m.alphaMode == AlphaMode::Mask;
  ASSERT_GT(masked, 0) << "the scene must have an alpha-tested material";
  const SceneGpu gpu(*scene);

  DepthProgram split(lib);
  gl::Program alphaTested(lib, depthProgramDesc(false)), opaque(lib, depthProgramDesc(true));
  const auto drawWith = [&](const gl::Program& p) {
    return [&](const glm::mat4& vp) {
      p.use();
      p.set("u_lightViewProj", vp);
      gpu.draw(p, SL_UNIT_MATERIAL);
    };
  };
  const std::vector<float> reference = depthOf(*scene, drawWith(alphaTested));
  const std::vector<float> fast = depthOf(*scene, [&](const glm::mat4& vp) {
    split.use();
    split.set("u_lightViewProj", vp);
    split.draw(gpu);
  });
  const std::vector<float> noAlphaTest = depthOf(*scene, drawWith(opaque));
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));

  int differ = 0, holes = 0, covered = 0;
  for (std::size_t i = 0; i < reference.size(); ++i) {
    differ += fast[i] != reference[i];
    holes += noAlphaTest[i] != reference[i];
    covered += reference[i] < 1.0f;
  }
  std::printf(
      "DepthProgram: %d of %zu texels covered; split vs alpha-testing program: %d "
      "differ; without any alpha test: %d differ (the holes)\n",
      covered, reference.size(), differ, holes);
  EXPECT_GT(covered, kSize * kSize / 4) << "the scene must fill the map";
  EXPECT_EQ(differ, 0) << "the two builds must write exactly the alpha-testing program's depth";
  EXPECT_GT(holes, 0) << "the alpha-tested casters lost their holes: the test cannot see them";
}

}  // namespace
}  // namespace sl
