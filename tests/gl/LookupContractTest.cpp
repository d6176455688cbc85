// The lookup contract (core/Technique.h, shaders/common/resolve.frag) with techniques that
// live only in tests: a lookup over several maps (uniform as 2x2 sub-maps, each with its own
// matrix) and a deferred resolve (uniform resolved in its own compute pass) must give
// uniform's hard mask, and aliasing m and the grid uv of the SELECTED map. Plus the
// "declared once" checks: misspelled uniforms and parameter keys fail loudly.
#include <cmath>
#include <cstdio>
#include <fstream>

#include "GlTestEnv.h"
#include "TestTechniques.h"
#include "core/ParamBinding.h"
#include "gl/ShaderLibrary.h"

namespace sl {
namespace {

struct Frames {
  FrameReadback uniform, other;
};

Frames renderBoth(const std::string& scene, const std::string& technique, int w, int h) {
  Frames f;
  auto r = test::makeTestRenderer(scene, "uniform");
  EXPECT_TRUE(r);
  if (!r) return f;
  EXPECT_FALSE(r->renderFrame(w, h, 0));
  f.uniform = r->readback();
  EXPECT_FALSE(r->setTechnique(technique));
  EXPECT_FALSE(r->renderFrame(w, h, 0));
  f.other = r->readback();
  test::expectNoGlErrors(*r);
  return f;
}

size_t maskDifferences(const Frames& f) {
  size_t differ = 0;
  for (size_t i = 0; i < f.uniform.hardMask.size(); ++i)
    differ += f.uniform.hardMask[i] != f.other.hardMask[i];
  return differ;
}

/// Pixels whose 2x2 quad (the derivatives' neighbourhood) is covered in both frames.
bool quadCovered(const FrameReadback& f, int x, int y) {
  for (int dy = 0; dy < 2; ++dy)
    for (int dx = 0; dx < 2; ++dx) {
      const int qx = (x & ~1) + dx, qy = (y & ~1) + dy;
      if (qx >= f.width || qy >= f.height) return false;
      if (f.positions[size_t(qy) * size_t(f.width) + size_t(qx)].w <= 0.0f) return false;
    }
  return true;
}

// uniform split into a 2x2 array: the hard mask is uniform's. Sub-map k's texel grid is
// uniform's (res/2 texels over half the extent), its depths are the same plane at the same
// centres and the bias terms scale identically; only float rounding of the composed matrix
// (S_k * M instead of M) can move a sample by an ulp, which flips a test only where the
// receiver's depth equals the stored depth within that ulp (contact edges) or where a
// pixel's uv sits on a texel border. Measured: 0 differing pixels on both scenes; the
// tolerance allows 0.01 % of covered pixels for other Mesa versions.
TEST(LookupContract, ArrayOfSubMapsGivesUniformsHardMaskAndSelectedMapsUvAndM) {
  for (const char* scene : {"plane-box", "default"}) {
    SCOPED_TRACE(scene);
    constexpr int kW = 480, kH = 270;
    const Frames f = renderBoth(scene, "uniform-array2x2", kW, kH);
    ASSERT_EQ(f.other.hardMask.size(), size_t(kW * kH));
    size_t covered = 0;
    for (std::uint8_t m : f.uniform.hardMask) covered += m != 255;
    const size_t differ = maskDifferences(f);
    std::printf("[%s] 2x2 sub-maps: %zu of %zu covered pixels differ from uniform\n", scene, differ,
                covered);
    EXPECT_GT(covered, size_t(kW * kH / 4));
    EXPECT_LE(double(differ), 1e-4 * double(covered));

    // The grid uv is the SELECTED sub-map's: 2 u - kx per axis, and m (derivatives of the
    // selected map's texel coordinate, res/2 texels per half extent) is uniform's.
    size_t uvChecked = 0, uvOff = 0, mChecked = 0, mOff = 0, usedMaps = 0;
    bool used[4] = {};
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        const size_t i = size_t(y) * kW + size_t(x);
        if (f.uniform.positions[i].w <= 0.0f) continue;
        const glm::vec2 u = f.uniform.texel[i], a = f.other.texel[i];
        if (u.x < 0.001f || u.x > 0.999f || u.y < 0.001f || u.y > 0.999f) continue;
        if (std::abs(u.x - 0.5f) < 0.001f || std::abs(u.y - 0.5f) < 0.001f) continue;
        const int kx = u.x >= 0.5f, ky = u.y >= 0.5f;
        used[kx + 2 * ky] = true;
        ++uvChecked;
        if (std::abs(a.x - (2.0f * u.x - float(kx))) > 1e-5f ||
            std::abs(a.y - (2.0f * u.y - float(ky))) > 1e-5f)
          ++uvOff;
        // m over quads that stay inside one sub-map (the seam's quads straddle two maps).
        if (!quadCovered(f.uniform, x, y)) continue;
        const float mu = f.uniform.aliasing[i], ma = f.other.aliasing[i];
        if (!(mu > 0.0f)) continue;
        ++mChecked;
        if (std::abs(ma - mu) > 1e-3f * mu) ++mOff;
      }
    for (bool b : used) usedMaps += b;
    std::printf("[%s] uv: %zu checked, %zu off; m: %zu checked, %zu off by > 0.1 %%\n", scene,
                uvChecked, uvOff, mChecked, mOff);
    EXPECT_EQ(usedMaps, 4u) << "the view should reach all four sub-maps";
    EXPECT_GT(uvChecked, covered / 2);
    EXPECT_EQ(uvOff, 0u);
    // Quads across the seam see derivatives of two maps' coordinates (measured: 0.4 % of
    // plane-box's pixels, 0.9 % of default's, all next to the seams): allow 1.5 %.
    EXPECT_GT(mChecked, covered / 2);
    EXPECT_LE(double(mOff), 0.015 * double(mChecked));
  }
}

// uniform resolved in the technique's own compute pass: the same lookup code per pixel, so
// the hard mask, filtered visibility and grid uv are the fragment resolve's exactly. m comes
// from finite differences over the pixel's quad instead of dFdx/dFdy: equal where the
// rasteriser's derivatives are per-row/column differences inside the quad ("fine"); a
// coarse rasteriser uses one row for the whole quad, which on these smooth receivers moves
// m by well under 1 %. Measured on llvmpipe (fine derivatives): m identical on every pixel.
TEST(LookupContract, DeferredResolveGivesUniformsHardMaskUvAndM) {
  for (const char* scene : {"plane-box", "default"}) {
    SCOPED_TRACE(scene);
    constexpr int kW = 480, kH = 270;
    const Frames f = renderBoth(scene, "uniform-deferred", kW, kH);
    ASSERT_EQ(f.other.hardMask.size(), size_t(kW * kH));
    EXPECT_EQ(maskDifferences(f), 0u);
    size_t uvOff = 0, mChecked = 0, mOff = 0;
    double maxRel = 0.0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        const size_t i = size_t(y) * kW + size_t(x);
        if (f.uniform.positions[i].w <= 0.0f) {
          EXPECT_EQ(f.other.aliasing[i], 0.0f);
          continue;
        }
        if (f.uniform.texel[i] != f.other.texel[i]) ++uvOff;
        const float mu = f.uniform.aliasing[i], md = f.other.aliasing[i];
        if (!quadCovered(f.uniform, x, y) || !(mu > 0.0f)) continue;
        ++mChecked;
        const double rel = std::abs(double(md) - double(mu)) / double(mu);
        maxRel = std::max(maxRel, rel);
        if (rel > 0.01) ++mOff;
      }
    std::printf(
        "[%s] deferred: uv off on %zu pixels; m: %zu checked, %zu off by > 1 %%, max "
        "relative difference %.2e\n",
        scene, uvOff, mChecked, mOff, maxRel);
    EXPECT_EQ(uvOff, 0u);
    EXPECT_GT(mChecked, size_t(kW * kH / 4));
    // Quads on depth discontinuities (a box edge in front of the ground) differ in which
    // surface each row sees: allow 1 % of pixels beyond 1 %.
    EXPECT_LE(double(mOff), 0.01 * double(mChecked));
    // The colour uses the technique's filtered visibility: identical images.
    EXPECT_EQ(f.uniform.color.pixels, f.other.color.pixels);
  }
}

// A ParamDecl naming a uniform that none of the technique's programs (nor its resolve
// pass) declares refuses the technique, naming the parameter and the uniform.
TEST(DeclaredOnce, MisspelledUniformInAParamDeclRefusesTheTechnique) {
  auto r = test::makeTestRenderer("plane-box", "uniform");
  ASSERT_TRUE(r);
  auto err = r->setTechnique("typo-uniform");
  ASSERT_TRUE(err);
  EXPECT_NE(err->find("u_biasSlpoe"), std::string::npos) << *err;
  EXPECT_NE(err->find("bias.extra"), std::string::npos) << *err;
  EXPECT_EQ(r->techniqueId(), "uniform");
  EXPECT_FALSE(r->renderFrame(64, 48, 0));
  test::expectNoGlErrors(*r);
}

// A technique reading a misspelled parameter key: the frame fails with the key named, the
// renderer keeps working.
TEST(DeclaredOnce, MisspelledParameterKeyInATechniqueFailsTheFrame) {
  auto r = test::makeTestRenderer("plane-box", "typo-key");
  ASSERT_TRUE(r);
  auto err = r->renderFrame(64, 48, 0);
  ASSERT_TRUE(err);
  EXPECT_NE(err->find("resolutoin"), std::string::npos) << *err;
  EXPECT_FALSE(r->setTechnique("uniform"));
  EXPECT_FALSE(r->renderFrame(64, 48, 0));
  test::expectNoGlErrors(*r);
}

// gl::Program::set refuses names its preprocessed sources do not declare; a declared
// uniform the compiler dropped is fine. bindParams sets a declared parameter's uniform.
TEST(DeclaredOnce, ProgramSetOnAnUndeclaredUniformThrowsAndBindParamsSetsDeclaredOnes) {
  test::eglContext().makeCurrent();
  auto dir = test::testOut("declared");
  std::ofstream(dir / "p.frag") << "uniform float u_used;\n"
                                   "uniform float u_unused;  // optimised out\n"
                                   "layout(binding = 3) uniform sampler2D u_tex, u_other[2];\n"
                                   "out vec4 c;\n"
                                   "void main() { c = vec4(u_used); }\n";
  gl::ShaderLibrary lib(dir);
  gl::Program prog(lib, {"p", {{GL_FRAGMENT_SHADER, "p.frag"}}, {}, {}});
  EXPECT_NO_THROW(prog.set("u_used", 1.0f));
  EXPECT_NO_THROW(prog.set("u_unused", 1.0f));
  EXPECT_NO_THROW(prog.set("u_other[1]", 2));
  EXPECT_TRUE(prog.declares("u_tex"));
  try {
    prog.set("u_usde", 1.0f);
    FAIL() << "set on a misspelled uniform did not throw";
  } catch (const gl::UnknownUniformError& e) {
    EXPECT_NE(std::string(e.what()).find("u_usde"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("u_used"), std::string::npos) << e.what();
  }

  ParamSet params({{.key = "gain",
                    .label = "Gain",
                    .group = "Test",
                    .type = ParamType::Float,
                    .defaultValue = 0.25,
                    .minValue = 0.0,
                    .maxValue = 1.0,
                    .uniform = "u_used"},
                   {.key = "unbound", .label = "Unbound", .group = "Test"}});
  ASSERT_FALSE(params.set("gain", 0.75));
  EXPECT_EQ(bindParams(prog, params), 1);
  float v = 0.0f;
  glGetUniformfv(prog.id(), prog.location("u_used"), &v);
  EXPECT_EQ(v, 0.75f);
  const gl::Program* programs[] = {&prog};
  EXPECT_FALSE(checkParamUniforms(params.decls(), programs));
  ParamDecl typo = params.decls()[0];
  typo.uniform = "u_usde";
  auto err = checkParamUniforms(std::span(&typo, 1), programs);
  ASSERT_TRUE(err);
  EXPECT_NE(err->find("u_usde"), std::string::npos) << *err;
}

}  // namespace
}  // namespace sl
