// Aliasing m through the omni mappings, seams included: with the camera AT the light, a
// pixel's texel coordinate depends only on its direction, so the m the resolve measures must
// equal the mapping's own density (algo/omni: texels per steradian) times the pixel's solid
// angle — on every pixel, at cube face edges and the paraboloid rim too, where neighbouring
// pixels select different maps (resolve.frag maps the neighbour into the pixel's own map).
#include <algorithm>
#include <cmath>

#include "GlTestEnv.h"
#include "algo/omni/OmniMapping.h"

namespace sl {
namespace {

struct SeamCase {
  const char* technique;
  int resolution;
};

/// Direction `d`'s texel coordinate in map `map` of `sc` (a cube face's plane, a paraboloid
/// hemisphere), continued beyond the map's edge: the CPU side of shadowMapUvOf.
glm::dvec2 texelInMap(const SeamCase& sc, int map, const glm::dvec3& d) {
  glm::dvec2 uv;
  if (std::string(sc.technique) == "cube") {
    const omni::CubeFaceBasis b = omni::cubeFaceBasis(map);
    const double f = glm::dot(d, b.forward);
    uv = 0.5 + 0.5 * glm::dvec2(glm::dot(d, b.right), glm::dot(d, b.up)) / f;
  } else {
    const omni::ParaboloidFrame fr = omni::paraboloidFrame({0, 1, 0});  // dp.axis = y
    const glm::dvec3 u = glm::normalize(d);
    glm::dvec3 l(glm::dot(u, fr.x), glm::dot(u, fr.y), glm::dot(u, fr.axis));
    if (map == 1) l = {l.x, -l.y, -l.z};
    uv = 0.5 + 0.5 * glm::dvec2(l.x, l.y) / (1.0 + l.z);
  }
  return uv * double(sc.resolution);
}

class OmniAliasing : public ::testing::TestWithParam<SeamCase> {};

TEST_P(OmniAliasing, MeasuredMIsTheMappingsDensityEverywhereIncludingSeams) {
  // The camera stands at the light and looks along the 14 sphere directions, rolled 30° so
  // the seams cross the image's 2x2 quads. Two expectations per covered pixel:
  // 1. the resolve's finite difference: the texels of the pixel and of its quad partners
  //    (x ^ 1, y ^ 1: fine derivatives), ALL in the pixel's own map, m = 1/sqrt(|dX x dY|),
  //    within 1e-3 (float32 positions);
  // 2. the meaning: m = 1/sqrt(density(d) x pixel solid angle), the mapping's texels per
  //    steradian (algo/omni) times cos^3(a)/f^2 of a pinhole pixel, within 10 % (a one-pixel
  //    difference where m changes by up to 3 % per pixel near a cube corner).
  // Measured across two maps, a seam pixel's m is off by orders of magnitude.
  const SeamCase sc = GetParam();
  auto r = test::makeRenderer("omni-room", sc.technique);
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->params().set("bias.normal", 0.0));
  ASSERT_FALSE(r->params().set("resolution", sc.resolution));
  const glm::dvec3 L(r->light().positionM);
  const omni::ParaboloidFrame frame = omni::paraboloidFrame({0, 1, 0});
  const int size = 96;
  const double fovYDeg = 100.0, roll = glm::radians(30.0);
  const double f = 0.5 * size / std::tan(glm::radians(fovYDeg) / 2.0);
  std::size_t seamPixels = 0, compared = 0;
  double worstFd = 0.0, worstDensity = 0.0;
  for (const glm::vec3& look : test::sphereLookDirections()) {
    const glm::dvec3 forward = glm::normalize(glm::dvec3(look));
    const glm::dvec3 up0 = std::abs(look.y) > 0.9f ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, up0));
    const glm::dvec3 up = glm::normalize(glm::cross(right, forward));
    Camera c;
    c.position = glm::vec3(L);
    c.target = c.position + look;
    c.up = glm::vec3(std::cos(roll) * up + std::sin(roll) * right);
    c.fovYDeg = float(fovYDeg);
    c.nearM = 0.05f;
    c.farM = 20.0f;
    r->setCamera(c);
    ASSERT_FALSE(r->renderFrame(size, size, 0));
    const FrameReadback fr = r->readback();
    auto dir = [&](std::size_t i) { return glm::dvec3(glm::vec3(fr.positions[i])) - L; };
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const std::size_t i = std::size_t(y) * size + std::size_t(x);
        const std::size_t ix = std::size_t(y) * size + std::size_t(x ^ 1);
        const std::size_t iy = std::size_t(y ^ 1) * size + std::size_t(x);
        if (fr.positions[i].w <= 0.0f || fr.positions[ix].w <= 0.0f || fr.positions[iy].w <= 0.0f)
          continue;
        const int map = fr.mapIndex[i];
        const bool seam = fr.mapIndex[ix] != map || fr.mapIndex[iy] != map;
        const glm::dvec2 t = texelInMap(sc, map, dir(i));
        const glm::dvec2 dX = texelInMap(sc, map, dir(ix)) - t;
        const glm::dvec2 dY = texelInMap(sc, map, dir(iy)) - t;
        const double finiteDifference = 1.0 / std::sqrt(std::abs(dX.x * dY.y - dX.y * dY.x));
        const glm::dvec3 d = glm::normalize(dir(i));
        const double cosA = glm::dot(d, forward);
        const double density = std::string(sc.technique) == "cube"
                                   ? omni::cubeTexelsPerSteradian(d, sc.resolution)
                                   : omni::paraboloidTexelsPerSteradian(frame, d, sc.resolution);
        const double analytic = 1.0 / std::sqrt(density * cosA * cosA * cosA / (f * f));
        const double m = fr.aliasing[i];
        const double relFd = std::abs(m / finiteDifference - 1.0);
        const double relDensity = std::abs(m / analytic - 1.0);
        worstFd = std::max(worstFd, relFd);
        worstDensity = std::max(worstDensity, relDensity);
        ++compared;
        seamPixels += seam;
        if (relFd >= 1e-3 || relDensity >= 0.1) {
          ADD_FAILURE() << "pixel (" << x << ", " << y << ") of map " << map
                        << (seam ? " at a seam" : "") << ": m " << m << ", finite difference "
                        << finiteDifference << ", density " << analytic;
          return;  // one message per case is enough
        }
      }
  }
  std::printf(
      "%s %d^2: %zu pixels (%zu at seams); worst |m / finite difference - 1| = %.2g, "
      "|m / density - 1| = %.3f\n",
      sc.technique, sc.resolution, compared, seamPixels, worstFd, worstDensity);
  EXPECT_GT(compared, 100000u);
  EXPECT_GT(seamPixels, 1000u);  // the seams are in the test
  test::expectNoGlErrors(*r);
}

INSTANTIATE_TEST_SUITE_P(Maps, OmniAliasing,
                         ::testing::Values(SeamCase{"cube", 256}, SeamCase{"dual-paraboloid", 256}),
                         [](const auto& p) {
                           return std::string(p.param.technique) == "cube" ? "Cube"
                                                                           : "DualParaboloid";
                         });

}  // namespace
}  // namespace sl
