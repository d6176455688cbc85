// The tiled techniques' eye-space depth buffer (core/tiled/EyeDepthBuffer; Giegl &
// Wimmer 2007 §3.2, eq. 1) on real frames of diagonal and corridor: it holds −z_eye of the
// G-buffer's positions, and the world positions rebuilt from it with eq. 1 — on the GPU by the
// very GLSL the tile apply and SMTMM passes include (common/tiled/eye_depth.glsl), on the CPU
// by algo/fvsm eyePosition — are the G-buffer's within float rounding.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "GlTestEnv.h"
#include "algo/fvsm/Fvsm.h"
#include "gl/Gl.h"
#include "gl/ShaderLibrary.h"
#include "core/tiled/EyeDepthBuffer.h"

namespace sl {
namespace {

// Tolerances, relative to the pixel's eye depth d (float32: 2^-24 = 6e-8 per rounding):
// the buffer is one float matrix-vector product of the G-buffer's position, the rebuild eq.
// 1's products and the inverse view's; the G-buffer's own position was interpolated in float
// on the ray through the pixel's centre. Measured (llvmpipe, 320x180): depth 1.2e-7 on both
// scenes; rebuilt GPU 3.4e-7 (diagonal), 5.3e-7 (corridor), CPU (double from the float depth)
// 2.6e-7, 4.7e-7. The bounds are about 4x those: a wrong term of eq. 1 (a pixel's half offset,
// a sign of b, the aspect) moves positions by 1e-3 d or more.
constexpr double kDepthTol = 5e-7;    // |buffer − (−z_eye(P))| / d
constexpr double kRebuildTol = 2e-6;  // |rebuilt − P| / d, GPU and CPU

TEST(EyeDepth, RebuiltPositionsMatchTheGBuffer) {
  gl::ShaderLibrary lib(gl::ShaderLibrary::defaultRoot());
  for (const char* scene : {"diagonal", "corridor"}) {
    SCOPED_TRACE(scene);
    auto r = test::makeRenderer(scene, "virtual-tiled");
    ASSERT_TRUE(r);
    ASSERT_FALSE(r->params().set("tiles", 2));
    ASSERT_FALSE(r->params().set("tile.resolution", 64));
    const int w = 320, h = 180;
    ASSERT_FALSE(r->renderFrame(w, h, 0));
    const FrameReadback rb = r->readback();
    std::vector<glm::vec4> gpos(std::size_t(w) * h);  // bottom row first, as in GL
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        gpos[std::size_t(y) * w + x] = rb.positions[std::size_t(h - 1 - y) * w + x];
    gl::Texture gPosition = gl::Texture::create2D(GL_RGBA32F, w, h);
    glTextureSubImage2D(gPosition.id(), 0, 0, 0, w, h, GL_RGBA, GL_FLOAT, gpos.data());
    const glm::mat4 view = r->camera().view();
    const glm::mat4 proj = r->camera().projection(float(w) / float(h));

    EyeDepthBuffer eye(lib);
    eye.update(gPosition, w, h, view, proj);
    std::vector<float> depth(std::size_t(w) * h);
    glGetTextureImage(eye.texture().id(), 0, GL_RED, GL_FLOAT,
                      GLsizei(depth.size() * sizeof(float)), depth.data());

    gl::Program rebuild(
        lib,
        {"eye_depth_rebuild",
         {{GL_COMPUTE_SHADER, std::string(SHADOWLAB_TEST_SHADER_DIR) + "/eye_depth_rebuild.comp"}},
         {},
         {}});
    gl::Texture world = gl::Texture::create2D(GL_RGBA32F, w, h);
    rebuild.use();
    eye.bind(rebuild);
    glBindImageTexture(0, world.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute(GLuint((w + 7) / 8), GLuint((h + 7) / 8), 1);
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
    std::vector<glm::vec4> rebuilt(std::size_t(w) * h);
    glGetTextureImage(world.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(rebuilt.size() * sizeof(glm::vec4)),
                      rebuilt.data());

    const fvsm::EyeProjection terms = fvsm::eyeProjectionOf(glm::dmat4(proj));
    fvsm::EyeDepthView ev;
    ev.width = w;
    ev.height = h;
    ev.tanHalfFovX = terms.tanHalfFov.x;
    ev.tanHalfFovY = terms.tanHalfFov.y;
    ev.ndcOffset = terms.ndcOffset;
    ev.eyeDepthM = depth;
    const glm::dmat4 eyeFromWorld(view);
    const glm::dmat4 worldFromEye = glm::inverse(eyeFromWorld);
    std::size_t covered = 0;
    double maxDepth = 0.0, maxGpu = 0.0, maxCpu = 0.0;
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const std::size_t i = std::size_t(y) * w + x;
        const glm::vec4 P = gpos[i];
        ASSERT_EQ(depth[i] > 0.0f, P.w > 0.0f) << x << "," << y;
        if (P.w <= 0.0f) {
          ASSERT_EQ(rebuilt[i].w, 0.0f) << x << "," << y;
          continue;
        }
        ++covered;
        ASSERT_EQ(rebuilt[i].w, 1.0f);
        const glm::dvec3 p(P);
        const double d = -(eyeFromWorld * glm::dvec4(p, 1.0)).z;
        maxDepth = std::max(maxDepth, std::abs(double(depth[i]) - d) / d);
        maxGpu = std::max(maxGpu, glm::length(glm::dvec3(rebuilt[i]) - p) / d);
        const glm::dvec3 e = fvsm::eyePosition(ev, glm::dvec2(x, y) + 0.5, double(depth[i]));
        const glm::dvec3 cpu(worldFromEye * glm::dvec4(e, 1.0));
        maxCpu = std::max(maxCpu, glm::length(cpu - p) / d);
      }
    }
    std::printf(
        "%s %dx%d: %zu covered pixels; max |depth error| / d %.2e, max |rebuilt - P| / d: "
        "GPU (eye_depth.glsl) %.2e, CPU (fvsm::eyePosition) %.2e\n",
        scene, w, h, covered, maxDepth, maxGpu, maxCpu);
    EXPECT_GT(covered, std::size_t(w) * h / 4);
    EXPECT_LE(maxDepth, kDepthTol);
    EXPECT_LE(maxGpu, kRebuildTol);
    EXPECT_LE(maxCpu, kRebuildTol);
    test::expectNoGlErrors(*r);
  }
}

}  // namespace
}  // namespace sl
