// Aliasing m through the omni mappings, seams included: with the camera AT the light, a
// pixel's texel coordinate depends only on its direction, so the m the resolve measures must
// equal the mapping's own density (algo/omni: texels per steradian) times the pixel's solid
// angle — on every pixel, at cube face edges, the paraboloid rim and the lat-long map's
// halves' borders (its seam included) too, where neighbouring pixels select different maps
// (resolve.frag maps the neighbour into the pixel's own map).
#include <algorithm>
#include <cmath>

#include "GlTestEnv.h"
#include "algo/omni/LatLongMapping.h"
#include "algo/omni/OmniMapping.h"

namespace sl {
namespace {

struct SeamCase {
  const char* technique;
  int resolution;
};

/// Direction `d`'s texel coordinate in map `map` of `sc` (a cube face's plane, a paraboloid
/// hemisphere, a lat-long half), continued beyond the map's edge: the CPU side of
/// shadowMapUvOf.
glm::dvec2 texelInMap(const SeamCase& sc, int map, const glm::dvec3& d) {
  glm::dvec2 uv;
  if (std::string(sc.technique) == "spherical") {
    uv = omni::latLongUvInHalf(omni::latLongFrame({0, 1, 0}), map, d);  // sph.axis = y
  } else if (std::string(sc.technique) == "cube") {
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

/// The 2x2 quad of a pixel in a frame read back (row 0 = top; the quads of an even-sized
/// frame pair the same rows either way): the pixel, its x and y partners.
struct Quad {
  std::size_t i, ix, iy;
  Quad(int x, int y, int w) {
    i = std::size_t(y) * std::size_t(w) + std::size_t(x);
    ix = std::size_t(y) * std::size_t(w) + std::size_t(x ^ 1);
    iy = std::size_t(y ^ 1) * std::size_t(w) + std::size_t(x);
  }
  bool covered(const FrameReadback& f) const {
    return f.positions[i].w > 0.0f && f.positions[ix].w > 0.0f && f.positions[iy].w > 0.0f;
  }
  bool seam(const FrameReadback& f) const {
    return f.mapIndex[ix] != f.mapIndex[i] || f.mapIndex[iy] != f.mapIndex[i];
  }
};

/// m of the pixel as one finite difference in ITS map: the partners' directions from the
/// light `L` mapped into the pixel's map.
double finiteDifferenceM(const SeamCase& sc, const FrameReadback& f, const Quad& q,
                         const glm::dvec3& L) {
  auto dir = [&](std::size_t j) { return glm::dvec3(glm::vec3(f.positions[j])) - L; };
  const int map = f.mapIndex[q.i];
  const glm::dvec2 t = texelInMap(sc, map, dir(q.i));
  const glm::dvec2 dX = texelInMap(sc, map, dir(q.ix)) - t;
  const glm::dvec2 dY = texelInMap(sc, map, dir(q.iy)) - t;
  return 1.0 / std::sqrt(std::abs(dX.x * dY.y - dX.y * dY.x));
}

class OmniAliasing : public ::testing::TestWithParam<SeamCase> {
 protected:
  /// omni-room with the case's technique and resolution, without the normal offset (the
  /// texel looked up is the surface point's own).
  void SetUp() override {
    r = test::makeRenderer("omni-room", GetParam().technique);
    ASSERT_TRUE(r);
    ASSERT_FALSE(r->params().set("bias.normal", 0.0));
    ASSERT_FALSE(r->params().set("resolution", GetParam().resolution));
    L = glm::dvec3(r->light().positionM);
  }
  std::unique_ptr<Renderer> r;
  glm::dvec3 L{0.0};
};

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
  const omni::ParaboloidFrame frame = omni::paraboloidFrame({0, 1, 0});
  const omni::LatLongFrame latLong = omni::latLongFrame({0, 1, 0});
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
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const Quad q(x, y, size);
        if (!q.covered(fr)) continue;
        const std::size_t i = q.i;
        const int map = fr.mapIndex[i];
        const bool seam = q.seam(fr);
        const double finiteDifference = finiteDifferenceM(sc, fr, q, L);
        const glm::dvec3 d = glm::normalize(glm::dvec3(glm::vec3(fr.positions[i])) - L);
        const double cosA = glm::dot(d, forward);
        const std::string id = sc.technique;
        const double density = id == "cube" ? omni::cubeTexelsPerSteradian(d, sc.resolution)
                               : id == "spherical"
                                   ? omni::latLongTexelsPerSteradian(latLong, d, sc.resolution)
                                   : omni::paraboloidTexelsPerSteradian(frame, d, sc.resolution);
        // Lat-long within 3° of a pole: the density grows as 1 / cos(latitude) and a quad's
        // partners lie at quite other longitudes (the finite difference still holds).
        const bool nearPole = id == "spherical" && std::abs(d.y) > std::cos(glm::radians(3.0));
        const double analytic = 1.0 / std::sqrt(density * cosA * cosA * cosA / (f * f));
        const double m = fr.aliasing[i];
        const double relFd = std::abs(m / finiteDifference - 1.0);
        const double relDensity = nearPole ? 0.0 : std::abs(m / analytic - 1.0);
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
  // The seams are in the test (lat-long has two: longitude 0 and 180°).
  EXPECT_GT(seamPixels, std::string(sc.technique) == "spherical" ? 500u : 1000u);
  test::expectNoGlErrors(*r);
}

TEST_P(OmniAliasing, MeasuredMIsOneMapsFiniteDifferenceFromEveryBookmark) {
  // From the scene's own cameras (not at the light): per covered pixel whose quad partners
  // are covered, m = 1/sqrt(|dX x dY|) with dX, dY the partners' texels minus the pixel's,
  // all in the pixel's own map (the partners' surface points mapped into it), within 1 %
  // (float32 differences on grazing surfaces); seam pixels included, silhouettes not.
  // Without the normal offset, so the texel is the point's own.
  const SeamCase sc = GetParam();
  const int w = 320, h = 180;
  std::size_t seamPixels = 0, compared = 0;
  for (const CameraBookmark& b : r->scene()->cameras) {
    SCOPED_TRACE(b.name);
    r->setCamera(b.camera);
    ASSERT_FALSE(r->renderFrame(w, h, 0));
    const FrameReadback fr = r->readback();
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const Quad q(x, y, w);
        if (!q.covered(fr)) continue;
        const std::size_t i = q.i;
        // On one plane only: across a silhouette the partner may look the light up in any
        // direction and a finite difference means nothing (and float32 cancels).
        const glm::vec3 N(fr.normals[i]);
        auto onPlane = [&](std::size_t j) {
          return glm::dot(N, glm::vec3(fr.normals[j])) > 0.999f &&
                 std::abs(glm::dot(N, glm::vec3(fr.positions[j] - fr.positions[i]))) < 1e-3f;
        };
        if (!onPlane(q.ix) || !onPlane(q.iy)) continue;
        const int map = fr.mapIndex[i];
        const double expected = finiteDifferenceM(sc, fr, q, L);
        ++compared;
        const bool seam = q.seam(fr);
        seamPixels += seam;
        if (std::abs(fr.aliasing[i] / expected - 1.0) >= 1e-2) {
          ADD_FAILURE() << "pixel (" << x << ", " << y << ") of map " << map
                        << (seam ? " at a seam" : "") << ": m " << fr.aliasing[i]
                        << ", finite difference " << expected;
          return;
        }
      }
  }
  std::printf("%s: %zu pixels, %zu at seams\n", sc.technique, compared, seamPixels);
  EXPECT_GT(seamPixels, 100u);
  test::expectNoGlErrors(*r);
}

INSTANTIATE_TEST_SUITE_P(Maps, OmniAliasing,
                         ::testing::Values(SeamCase{"cube", 256}, SeamCase{"dual-paraboloid", 256},
                                           SeamCase{"spherical", 256}),
                         [](const auto& p) {
                           const std::string id = p.param.technique;
                           return id == "cube"        ? "Cube"
                                  : id == "spherical" ? "Spherical"
                                                      : "DualParaboloid";
                         });

}  // namespace
}  // namespace sl
