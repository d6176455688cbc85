// The `spherical` (lat-long) technique on the GPU: the depth pass stores, texel for texel,
// the distance a CPU ray cast along the texel's centre direction finds (seam, poles, a pole
// on a shared edge included); the lookup's half and uv equal omni::latLongHalfUv on a
// sphere of directions; omni-room within 0.5 % of the exact reference at 2048 for two pole
// axes; exact coverage off shows the per-vertex artifact; at equal memory its error against
// the cube's and the dual paraboloid's; memory exact, point and spot.
#include <algorithm>
#include <cmath>
#include <functional>

#include "GlTestEnv.h"
#include "algo/omni/LatLongMapping.h"
#include "algo/omni/OmniMapping.h"
#include "common/shared_constants.h"
#include "gl/Gl.h"

namespace sl {
namespace {

/// The nearest hit along `dir` from `L` over every triangle of `scene` with barycentric
/// tolerance `edgeEps` (negative: shrunk triangles), or -1.
double nearestHit(const Scene& scene, const glm::dvec3& L, const glm::dvec3& dir, double edgeEps) {
  double best = -1.0;
  for (const MeshPrimitive& p : scene.primitives)
    for (std::size_t i = 0; i + 2 < p.indices.size(); i += 3) {
      const double t = omni::rayTriangleDistance(
          L, dir, glm::dvec3(p.positions[p.indices[i]]), glm::dvec3(p.positions[p.indices[i + 1]]),
          glm::dvec3(p.positions[p.indices[i + 2]]), edgeEps);
      if (t > 0.0 && (best < 0.0 || t < best)) best = t;
    }
  return best;
}

TEST(Spherical, DepthPassMatchesCpuRayCastPerTexel) {
  // Every texel of both halves against a CPU ray cast along its centre direction
  // (omni::latLongTexelCentreDirection, omni::rayTriangleDistance in double): the stored
  // value must be omni::storedDistance of the nearest hit, or exactly 1 where nothing is
  // hit. Texels whose ray passes within 1e-4 (barycentric) of a triangle's edge are skipped
  // (the answer changes with the tolerance there). The floor's diagonal runs under the light:
  // the south pole lies ON a shared edge (pole axis y). Tolerance 2e-6 of the depth range:
  // float32 ray-triangle distances at up to 6 m along float directions (sin/cos of the
  // texel's angles), worst measured 6.6e-7 (omni-room: 4.1e-7).
  test::eglContext().makeCurrent();
  for (const char* sceneName : {"roof", "omni-room"}) {
    Renderer r;
    std::shared_ptr<Scene> scene;
    if (std::string(sceneName) == "roof") {
      scene = test::roofOverFloor(1.0f);
      r.setScene(scene);
      r.setLight(Light::point({0.0f, 1.0f, 0.0f}));
    } else {
      auto owned = test::makeRenderer("omni-room", "spherical");
      ASSERT_TRUE(owned);
      scene = std::const_pointer_cast<Scene>(owned->scene());
      r.setScene(scene);
      r.setLight(owned->light());
    }
    ASSERT_FALSE(r.setTechnique("spherical"));
    r.requestPublications({"sph.half.*.map", "sph.far_m"});
    const glm::dvec3 L(r.light().positionM);
    for (auto [axisIndex, axis] : {std::pair{0, glm::dvec3(0, 1, 0)}, {1, glm::dvec3(1, 0, 0)}}) {
      const int res = std::string(sceneName) == "roof" ? 96 : 64;
      SCOPED_TRACE(std::string(sceneName) + " axis " + std::to_string(axisIndex));
      ASSERT_FALSE(r.params().set("sph.axis", axisIndex));
      ASSERT_FALSE(r.params().set("resolution", res));
      ASSERT_FALSE(r.renderFrame(32, 32, 0));
      const Publication& pub = r.publication();
      ASSERT_EQ(pub.images.size(), 2u);
      const double farM = pub.numbers.at("sph.far_m");
      const omni::LatLongFrame frame = omni::latLongFrame(axis);
      double worst = 0.0;
      std::size_t hits = 0, empty = 0, skipped = 0;
      for (int h = 0; h < omni::kLatLongHalves; ++h) {
        const FloatImage& img = pub.images.at("sph.half." + std::to_string(h) + ".map");
        ASSERT_EQ(img.width, res);
        ASSERT_EQ(img.height, res);
        for (int y = 0; y < res; ++y)
          for (int x = 0; x < res; ++x) {
            const glm::dvec3 d = omni::latLongTexelCentreDirection(frame, {h * res + x, y}, res);
            const double outer = nearestHit(*scene, L, d, 1e-4);
            const double inner = nearestHit(*scene, L, d, -1e-4);
            if (std::abs(outer - inner) > 1e-9) {
              ++skipped;
              continue;
            }
            const float stored = img.values[std::size_t(y) * std::size_t(res) + std::size_t(x)];
            if (outer < 0.0) {
              ++empty;
              ASSERT_EQ(stored, 1.0f) << "half " << h << " texel " << x << ", " << y;
              continue;
            }
            ++hits;
            const double err = std::abs(double(stored) - omni::storedDistance(outer, 0.0, farM));
            worst = std::max(worst, err);
            ASSERT_LT(err, 2e-6) << "half " << h << " texel " << x << ", " << y;
          }
      }
      std::printf("[ spherical ] %s axis %d: %zu hits, %zu empty, %zu skipped, worst %.2g\n",
                  sceneName, axisIndex, hits, empty, skipped, worst);
      EXPECT_GT(hits, std::size_t(res * res / 2));
      EXPECT_LT(skipped, std::size_t(res * res / 10));
      if (std::string(sceneName) == "roof") {
        EXPECT_GT(empty, std::size_t(res * res / 4));
      }
    }
  }
  test::eglContext().makeCurrent();
}

TEST(Spherical, GpuLookupMatchesCpuMappingOnTheSphere) {
  // As DualParaboloid.GpuLookupMatchesCpuMappingOnTheSphere: the camera at the light looks
  // along 14 directions; without the normal offset the resolve's map index is the half and
  // its uv omni::latLongHalfUv's within 1e-4 (float32), except within 1e-4 rad of the
  // halves' borders (longitude 0 and ±180°: float ties) and of the poles (longitude
  // undefined).
  auto r = test::makeRenderer("omni-room", "spherical");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->params().set("bias.normal", 0.0));
  ASSERT_FALSE(r->params().set("resolution", 256));
  const glm::vec3 L = r->light().positionM;
  const std::vector<glm::vec3> looks = test::sphereLookDirections();
  for (auto [axisIndex, axis] : {std::pair{0, glm::dvec3(0, 1, 0)}, {2, glm::dvec3(0, 0, 1)}}) {
    SCOPED_TRACE(axisIndex);
    ASSERT_FALSE(r->params().set("sph.axis", axisIndex));
    const omni::LatLongFrame frame = omni::latLongFrame(axis);
    std::size_t compared = 0;
    int halves = 0;
    for (const glm::vec3& look : looks) {
      Camera c;
      c.position = L;
      c.target = L + look;
      c.up = std::abs(look.y) > 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
      c.fovYDeg = 100.0f;
      c.nearM = 0.05f;
      c.farM = 20.0f;
      r->setCamera(c);
      ASSERT_FALSE(r->renderFrame(96, 96, 0));
      const FrameReadback f = r->readback();
      for (std::size_t i = 0; i < f.positions.size(); ++i) {
        if (f.positions[i].w <= 0.0f) continue;
        const glm::dvec3 d = glm::dvec3(glm::vec3(f.positions[i])) - glm::dvec3(L);
        const omni::LatLong ll = omni::latLong(frame, d);
        if (std::abs(ll.longitudeRad) < 1e-4 || std::abs(std::abs(ll.longitudeRad) - M_PI) < 1e-4 ||
            std::abs(ll.latitudeRad) > 0.5 * M_PI - 1e-4)
          continue;
        const omni::LatLongHalfCoord cpu = omni::latLongHalfUv(frame, d);
        ++compared;
        halves |= 1 << cpu.half;
        ASSERT_EQ(int(f.mapIndex[i]), cpu.half) << "pixel " << i;
        EXPECT_NEAR(f.texel[i].x, cpu.uv.x, 1e-4) << "pixel " << i;
        EXPECT_NEAR(f.texel[i].y, cpu.uv.y, 1e-4) << "pixel " << i;
      }
    }
    EXPECT_EQ(halves, 3);
    EXPECT_GT(compared, 100000u);
  }
  test::expectNoGlErrors(*r);
}

TEST(Spherical, OmniRoomAt2048AgreesWithReference) {
  auto r = test::makeRenderer("omni-room", "spherical");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->params().set("resolution", 2048));
  for (int axis : {0, 1}) {
    ASSERT_FALSE(r->params().set("sph.axis", axis));
    for (const CameraBookmark& b : r->scene()->cameras) {
      SCOPED_TRACE(b.name + " axis " + std::to_string(axis));
      r->setCamera(b.camera);
      ASSERT_FALSE(r->renderFrame(512, 384, 0));
      const auto err = r->computeError();
      EXPECT_GT(err.stats.covered, 150000u);
      EXPECT_LT(err.stats.errorPct, 0.5) << "false lit " << err.stats.falseLitPct
                                         << "%, false shadow " << err.stats.falseShadowPct;
    }
  }
  test::expectNoGlErrors(*r);
}

TEST(Spherical, PerVertexCoverageShowsTheArtifact) {
  // Without exact coverage the table top's triangles, which hold the south pole (the floor
  // under the bulb), are drawn from their three mapped corners: their shadow on the floor
  // is lost or misplaced, many times the exact error.
  auto r = test::makeRenderer("omni-room", "spherical");
  ASSERT_TRUE(r);
  r->setCamera(*test::bookmark(*r->scene(), "floor"));
  ASSERT_FALSE(r->params().set("resolution", 1024));
  ASSERT_FALSE(r->renderFrame(512, 384, 0));
  const double exact = r->computeError().stats.errorPct;
  ASSERT_FALSE(r->params().set("sph.exactCoverage", 0));
  ASSERT_FALSE(r->renderFrame(512, 384, 0));
  const double perVertex = r->computeError().stats.errorPct;
  EXPECT_GT(perVertex, 10.0 * exact) << "exact " << exact << "%, per vertex " << perVertex << "%";
}

TEST(Spherical, AtEqualMemoryErrorIsComparableToCubeAndParaboloid) {
  // 6 x 1024^2 cube texels against 2 x 1774^2 (0.04 % more) for the paraboloid and the
  // lat-long map, every omni-room bookmark at 512 x 384: the mean error of each is printed;
  // the lat-long map's stays within 1.5 times the better of the other two (its equator,
  // where the walls are, is denser than a cube face's centre at this memory, its poles
  // spend texels on the floor under the bulb and the ceiling over it).
  auto r = test::makeRenderer("omni-room", "cube");
  ASSERT_TRUE(r);
  double mean[3] = {0, 0, 0};
  const char* ids[3] = {"cube", "dual-paraboloid", "spherical"};
  const int res[3] = {1024, 1774, 1774};
  const auto& cams = r->scene()->cameras;
  for (int t = 0; t < 3; ++t) {
    ASSERT_FALSE(r->setTechnique(ids[t]));
    ASSERT_FALSE(r->params().set("resolution", res[t]));
    for (const CameraBookmark& b : cams) {
      r->setCamera(b.camera);
      ASSERT_FALSE(r->renderFrame(512, 384, 0));
      mean[t] += r->computeError().stats.errorPct / double(cams.size());
    }
  }
  std::printf(
      "[ spherical ] omni-room mean error at equal memory: cube %.3f %%, dual-paraboloid "
      "%.3f %%, spherical %.3f %%\n",
      mean[0], mean[1], mean[2]);
  EXPECT_LT(mean[2], 1.5 * std::min(mean[0], mean[1]));
}

/// An 8 m floor (y = 0) under a point light at (0, 1, 0) and one roof polygon at y = 0.5
/// (a fan over `roofXz`, x and z in metres): its shadow on the floor is the polygon doubled
/// about the point under the light (the south pole with sph.axis y).
std::shared_ptr<Scene> floorWithRoof(const std::vector<glm::vec2>& roofXz) {
  auto s = std::make_shared<Scene>();
  s->name = "floor-with-roof";
  Material dark;
  dark.baseColorFactor = {0.25f, 0.25f, 0.25f, 1.0f};
  s->materials.push_back(dark);
  MeshPrimitive floor;
  floor.positions = {{-4, 0, -4}, {4, 0, -4}, {4, 0, 4}, {-4, 0, 4}};
  floor.normals.assign(4, glm::vec3(0, 1, 0));
  floor.indices = {0, 2, 1, 0, 3, 2};
  floor.material = 0;
  s->primitives.push_back(floor);
  MeshPrimitive roof;
  for (const glm::vec2& p : roofXz) roof.positions.push_back({p.x, 0.5f, p.y});
  roof.normals.assign(roofXz.size(), glm::vec3(0, 1, 0));
  for (std::uint32_t i = 1; i + 1 < roofXz.size(); ++i)
    roof.indices.insert(roof.indices.end(), {0, i, i + 1});
  roof.material = 0;
  s->primitives.push_back(roof);
  s->bounds.min = {-4.0f, 0.0f, -4.0f};
  s->bounds.max = {4.0f, 0.5f, 4.0f};
  return s;
}

TEST(Spherical, PcfReachesAcrossTheSeamAndOverThePole) {
  // 64-high map, pole axis y: the seam is the floor's half-line z = 0, x < 0 (longitude
  // 180°: the last column, then column 0), the south pole the point under the light.
  // Seam: a roof wedge between longitudes 180° - 0.5 rad and 180° - 1 texel (its edges are
  // meridians: they project onto themselves) shadows column W - 2 and beyond; floor pixels
  // in column 0 within 0.45 texel of the seam are lit under a hard lookup, and PCF radius 2
  // must darken them (5 of 25 taps wrap to column W - 2; clamped taps would all be lit).
  // Pole: a roof over x > 0.005 m shadows the bottom rows' texels on the x > 0 side; floor
  // pixels in row 0 (r < 0.045 m) on the x < 0 side (x < -0.3 r) are lit hard, and PCF's
  // taps beyond row 0 land half way round (rows 0 and 1 at the opposite longitude), in that
  // shadow. Away from any shadow (3 texels and more) PCF equals the hard lookup exactly (no
  // acne from the wrapped taps).
  const double dLon = M_PI / 64.0;
  auto lonXz = [](double lon, double r) {  // frame x = +x, y = -z: longitude atan2(-z, x)
    return glm::vec2(float(r * std::cos(lon)), float(-r * std::sin(lon)));
  };
  struct Case {
    const char* name;
    std::vector<glm::vec2> roof;
    glm::vec3 look;
    std::function<bool(const glm::vec4&)> nearSeam, farFromShadow;
  };
  const std::vector<Case> cases = {
      {"seam",
       {lonXz(M_PI - 0.5, 0.3), lonXz(M_PI - 0.5, 1.5), lonXz(M_PI - dLon, 1.5),
        lonXz(M_PI - dLon, 0.3)},
       {-1.0f, 0.0f, 0.05f},
       [&](const glm::vec4& P) {
         const double lon = std::atan2(-double(P.z), double(P.x)), r = std::hypot(P.x, P.z);
         return lon < -M_PI + 0.45 * dLon && r > 0.9 && r < 1.1;
       },
       [&](const glm::vec4& P) {
         const double lon = std::atan2(-double(P.z), double(P.x));
         return lon > -M_PI + 3.0 * dLon && lon < -M_PI / 2.0;
       }},
      {"pole",
       {{0.005f, -1.0f}, {2.0f, -1.0f}, {2.0f, 1.0f}, {0.005f, 1.0f}},
       {-0.08f, 0.0f, 0.0f},
       [](const glm::vec4& P) {
         const float r = std::hypot(P.x, P.z);
         return r < 0.045f && P.x < -0.3f * r && P.x < -0.003f;
       },
       [](const glm::vec4& P) { return P.x < -0.16f; }},
  };
  test::eglContext().makeCurrent();
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    Renderer r;
    r.setScene(floorWithRoof(c.roof));
    ASSERT_FALSE(r.setTechnique("spherical"));
    r.setLight(Light::point({0.0f, 1.0f, 0.0f}));
    ASSERT_FALSE(r.params().set("resolution", 64));
    Camera cam;  // under the roof, straight down
    cam.position = c.look + glm::vec3(0.0f, 0.4f, 0.0f);
    cam.target = c.look;
    cam.up = {1.0f, 0.0f, 0.0f};
    cam.fovYDeg = 40.0f;
    cam.nearM = 0.01f;
    cam.farM = 5.0f;
    r.setCamera(cam);
    auto render = [&](int pcf) {
      EXPECT_FALSE(r.params().set("pcf", pcf));
      EXPECT_FALSE(r.renderFrame(256, 256, 0));
      return r.readback();
    };
    const FrameReadback hard = render(0), soft = render(2);
    auto grey = [&](const FrameReadback& f, std::size_t i) {
      return int(f.color.pixels[i * 4 + 1]);
    };
    int darkened = 0, litCompared = 0;
    for (std::size_t i = 0; i < soft.positions.size(); ++i) {
      const glm::vec4 P = soft.positions[i];
      if (P.w <= 0.0f || P.y > 0.01f) continue;  // the floor only
      if (c.farFromShadow(P)) {
        EXPECT_EQ(grey(soft, i), grey(hard, i)) << "P " << P.x << ", " << P.z;
        ++litCompared;
      }
      if (c.nearSeam(P) && hard.hardMask[i] == SL_MASK_LIT) {
        EXPECT_LT(grey(soft, i), grey(hard, i) - 4) << "P " << P.x << ", " << P.z;
        ++darkened;
      }
    }
    std::printf("[ spherical ] pcf %s: %d darkened, %d compared\n", c.name, darkened, litCompared);
    EXPECT_GT(litCompared, 500);
    EXPECT_GT(darkened, 20);
    test::expectNoGlErrors(r);
  }
}

TEST(Spherical, MemoryIsExactForPointAndSpot) {
  auto r = test::makeRenderer("omni-room", "uniform");
  ASSERT_TRUE(r);
  const std::uint64_t before = gl::allocatedBytes();
  ASSERT_FALSE(r->setTechnique("spherical"));
  ASSERT_FALSE(r->renderFrame(160, 90, 0));
  const std::uint64_t renderer = gl::allocatedBytes() - before - r->stats().memory.bytes();
  r->requestPublications({"sph.half.*.map"});
  for (auto [res, spot] : {std::pair{512, false}, {256, true}, {128, false}}) {
    SCOPED_TRACE(res);
    r->setLight(spot ? Light::spot({0.2f, 2.9f, 0.1f}, {0, -1, 0}, 60.0f)
                     : Light::point({0.2f, 1.7f, 0.1f}));
    ASSERT_FALSE(r->params().set("resolution", res));
    ASSERT_FALSE(r->renderFrame(160, 90, 0));
    const MemoryStats& m = r->stats().memory;
    EXPECT_EQ(m.bytes(), gl::allocatedBytes() - before - renderer);
    EXPECT_EQ(m.bytes(), 4ull * 2ull * std::uint64_t(res) * std::uint64_t(res));
    EXPECT_EQ(r->publication().images.size(), 2u);
  }
  test::expectNoGlErrors(*r);
}

}  // namespace
}  // namespace sl
