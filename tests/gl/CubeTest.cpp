// The `cube` technique on the GPU: its lookup selects the face and uv algo/omni computes on
// the CPU for every direction around the light; its faces store the distance from the light
// (omni::storedDistance of the CPU-mapped texel centre's hit); omni-room at 1024^2 per face within
// 0.5 % of the exact reference (layered and six passes give the same mask); a spot renders only the
// faces its cone reaches; memory() lists every byte; declared passes are the timed ones.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "GlTestEnv.h"
#include "algo/omni/OmniMapping.h"
#include "gl/Gl.h"

namespace sl {
namespace {

TEST(Cube, GpuLookupMatchesCpuFaceMappingOnTheSphere) {
  // The camera stands at the light and looks along the 6 axes and the 8 cube diagonals
  // (100° fov): every pixel's P - light is a direction of the sphere. Without the normal
  // offset the resolve's selected map (mapIndex) and uv (texel) are the face and uv of
  // omni::cubeFaceUv(P - light). Tolerance: uv within 1e-4 (a tenth of a texel at 1024^2;
  // float32 positions and matrices), the face exact except where the two largest |d|
  // components differ by under 1e-4 of the largest (float ties at the seams).
  auto r = test::makeRenderer("omni-room", "cube");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->params().set("bias.normal", 0.0));
  const glm::vec3 L = r->light().positionM;
  const std::vector<glm::vec3> looks = test::sphereLookDirections();
  std::size_t compared = 0, ties = 0;
  int facesSeen = 0;
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
      const omni::CubeCoord cpu = omni::cubeFaceUv(d);
      glm::dvec3 a = glm::abs(d);
      std::sort(&a[0], &a[0] + 3);
      if (a[2] - a[1] < 1e-4 * a[2]) {
        ++ties;
        continue;
      }
      ++compared;
      facesSeen |= 1 << cpu.face;
      ASSERT_EQ(int(f.mapIndex[i]), cpu.face) << "pixel " << i;
      EXPECT_NEAR(f.texel[i].x, cpu.uv.x, 1e-4) << "pixel " << i;
      EXPECT_NEAR(f.texel[i].y, cpu.uv.y, 1e-4) << "pixel " << i;
    }
  }
  EXPECT_EQ(facesSeen, 0x3f);
  EXPECT_GT(compared, 100000u);
  EXPECT_LT(ties, compared / 100);
  test::expectNoGlErrors(*r);
}

TEST(Cube, FacesStoreTheDistanceFromTheLight) {
  // A roof (y = 0.5, x in [0.5, 2], z in [-1, 0]) over an 8 m floor, the light at (0, 1, 0).
  // For every texel of every face the CPU maps its centre to a direction
  // (omni::cubeTexelCentreDirection) and meets the two planes with it (the first hit inside
  // its rectangle, |P - L|): the face must store omni::storedDistance(|P - L|, near, far)
  // there, and exactly 1 (nothing) where the ray meets neither (the upper half). Texels
  // whose centre ray passes within 1 mm of a rectangle's edge are skipped (coverage there
  // is the rasterizer's call: vertices snap to 1/256 texel). Tolerance 5e-7 of the depth
  // range (2.9e-6 m of 5.8 m): the position relative to the light is interpolated in
  // float32 at up to 5.7 m (a few float ulps: 1e-7 relative), the stored float's own ulp is
  // 6e-8 (measured worst: 1.2e-7 of the range at 256^2).
  // Layered and six passes store the same maps, bit for bit.
  test::eglContext().makeCurrent();
  Renderer r;
  r.setScene(test::roofOverFloor(1.0f));
  ASSERT_FALSE(r.setTechnique("cube"));
  const glm::dvec3 L(0.0, 1.0, 0.0);
  r.setLight(Light::point(glm::vec3(L)));
  r.requestPublications({"face.*.map", "cube.near_m", "cube.far_m"});
  for (int res : {64, 256}) {
    SCOPED_TRACE(res);
    ASSERT_FALSE(r.params().set("resolution", res));
    std::map<std::string, FloatImage> maps[2];
    for (int layered : {1, 0}) {
      ASSERT_FALSE(r.params().set("cube.layered", layered));
      ASSERT_FALSE(r.renderFrame(32, 32, 0));
      maps[layered] = r.publication().images;
    }
    ASSERT_EQ(maps[0].size(), 6u);
    for (const auto& [key, img] : maps[1])
      EXPECT_EQ(img.values, maps[0].at(key).values) << key << ": layered != six passes";
    const double nearM = r.publication().numbers.at("cube.near_m");
    const double farM = r.publication().numbers.at("cube.far_m");
    const double tolerance = 5e-7;
    double worst = 0.0;
    std::size_t hits = 0, empty = 0, skipped = 0;
    for (int f = 0; f < omni::kCubeFaces; ++f) {
      const FloatImage& img = maps[1].at("face." + std::to_string(f) + ".map");
      ASSERT_EQ(img.width, res);
      for (int y = 0; y < res; ++y)
        for (int x = 0; x < res; ++x) {
          const glm::dvec3 d = omni::cubeTexelCentreDirection({f, {x, y}}, res);
          // The first of roof and floor inside its rectangle; the margin to its edges.
          double t = -1.0, margin = 1e9;
          auto meet = [&](double planeY, glm::dvec2 lo, glm::dvec2 hi) {
            if (t > 0.0 || d.y >= 0.0) return;
            const double s = (planeY - L.y) / d.y;
            const glm::dvec3 P = L + s * d;
            const double m = std::min({P.x - lo.x, hi.x - P.x, P.z - lo.y, hi.y - P.z});
            margin = std::min(margin, std::abs(m));
            if (m > 0.0) t = s;
          };
          meet(0.5, {0.5, -1.0}, {2.0, 0.0});
          meet(0.0, {-4.0, -4.0}, {4.0, 4.0});
          if (margin < 1e-3) {
            ++skipped;
            continue;
          }
          const float stored = img.values[std::size_t(y) * std::size_t(res) + std::size_t(x)];
          if (t < 0.0) {
            ++empty;
            ASSERT_EQ(stored, 1.0f) << "face " << f << " texel " << x << ", " << y;
            continue;
          }
          ++hits;
          const double want = omni::storedDistance(t, nearM, farM);
          worst = std::max(worst, std::abs(double(stored) - want));
          ASSERT_NEAR(stored, want, tolerance)
              << "face " << f << " texel " << x << ", " << y << ": |P - L| = " << t << " m";
        }
    }
    std::printf(
        "cube %d^2: %zu texels hit (worst |stored - distance| %.3g of the range, "
        "%.3g m), %zu empty, %zu skipped at edges\n",
        res, hits, worst, worst * (farM - nearM), empty, skipped);
    EXPECT_GT(hits, std::size_t(res * res * 2));   // the floor fills -y and half of 4 sides
    EXPECT_GT(empty, std::size_t(res * res * 2));  // +y and the upper halves
    EXPECT_LT(skipped, hits / 50);
  }
  test::expectNoGlErrors(r);
}

TEST(Cube, OmniRoomAt1024PerFaceAgreesWithReference) {
  // 512x384 frames (llvmpipe), every bookmark: the floor under the table, the ceiling over
  // the plate, the walls. Layered and six-pass rendering store the same maps: same mask.
  auto r = test::makeRenderer("omni-room", "cube");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->params().set("resolution", 1024));
  for (const CameraBookmark& b : r->scene()->cameras) {
    SCOPED_TRACE(b.name);
    r->setCamera(b.camera);
    ASSERT_FALSE(r->params().set("cube.layered", 1));
    ASSERT_FALSE(r->renderFrame(512, 384, 0));
    const auto layered = r->computeError();
    EXPECT_GT(layered.stats.covered, 150000u);
    const auto shadowed = std::count(layered.referenceMask.begin(), layered.referenceMask.end(), 0);
    EXPECT_GT(shadowed, 2000);  // shadows in view
    EXPECT_LT(layered.stats.errorPct, 0.5) << "false lit " << layered.stats.falseLitPct
                                           << "%, false shadow " << layered.stats.falseShadowPct;
    ASSERT_FALSE(r->params().set("cube.layered", 0));
    ASSERT_FALSE(r->renderFrame(512, 384, 0));
    EXPECT_EQ(r->readback().hardMask, layered.frame.hardMask);
  }
  test::expectNoGlErrors(*r);
}

TEST(Cube, ErrorFallsWithResolution) {
  auto r = test::makeRenderer("omni-room", "cube");
  ASSERT_TRUE(r);
  double previous = 1e9;
  for (int res : {64, 256, 1024}) {
    ASSERT_FALSE(r->params().set("resolution", res));
    ASSERT_FALSE(r->renderFrame(320, 240, 0));
    const double e = r->computeError().stats.errorPct;
    EXPECT_LT(e, previous) << "resolution " << res;
    previous = e;
  }
}

TEST(Cube, SpotRendersOnlyTheFacesItsConeReaches) {
  auto r = test::makeRenderer("spot-yard", "cube");
  ASSERT_TRUE(r);
  r->requestPublications({"cube.faces", "face.*.map"});
  ASSERT_FALSE(r->params().set("resolution", 512));
  ASSERT_FALSE(r->renderFrame(320, 240, 0));
  const Publication& pub = r->publication();
  ASSERT_TRUE(pub.numbers.count("cube.faces"));
  EXPECT_EQ(pub.numbers.at("cube.faces"), 3.0);
  // +x, -y, +z (omni::cubeFacesInCone): their maps and no other.
  std::vector<std::string> maps;
  for (const auto& [k, v] : pub.images) maps.push_back(k);
  EXPECT_EQ(maps, (std::vector<std::string>{"face.0.map", "face.3.map", "face.4.map"}));
  EXPECT_EQ(r->stats().memory.texels(), 3u * 512u * 512u);
  EXPECT_LT(r->computeError().stats.errorPct, 0.5);
  test::expectNoGlErrors(*r);
}

TEST(Cube, MemoryIsExact) {
  auto r = test::makeRenderer("omni-room", "uniform");  // uniform refuses the point light
  ASSERT_TRUE(r);
  const std::uint64_t before = gl::allocatedBytes();
  ASSERT_FALSE(r->setTechnique("cube"));
  ASSERT_FALSE(r->renderFrame(160, 90, 0));  // the renderer's own targets
  const std::uint64_t renderer = gl::allocatedBytes() - before - r->stats().memory.bytes();
  for (auto [res, layered, spot] :
       {std::tuple{512, 1, false}, {256, 0, false}, {128, 1, true}, {1024, 0, true}}) {
    SCOPED_TRACE(res);
    r->setLight(spot ? Light::spot({0.2f, 2.9f, 0.1f}, {0, -1, 0}, 60.0f)
                     : Light::point({0.2f, 1.7f, 0.1f}));
    ASSERT_FALSE(r->params().set("resolution", res));
    ASSERT_FALSE(r->params().set("cube.layered", layered));
    ASSERT_FALSE(r->renderFrame(160, 90, 0));
    const MemoryStats& m = r->stats().memory;
    EXPECT_EQ(m.bytes(), gl::allocatedBytes() - before - renderer)
        << "memory() must list every byte";
    // A spot straight down with a 60° cone reaches -y and the four sides: 5 faces.
    EXPECT_EQ(m.bytes(), 4ull * std::uint64_t(res) * std::uint64_t(res) * (spot ? 5u : 6u));
  }
  test::expectNoGlErrors(*r);
}

TEST(Cube, DeclaredPassesAreTimedAndPublicationsDeclared) {
  auto r = test::makeRenderer("omni-room", "cube");
  ASSERT_TRUE(r);
  const TechniqueInfo* info = Renderer::findTechnique("cube");
  ASSERT_TRUE(info);
  EXPECT_EQ(info->lights, (std::vector<LightType>{LightType::Point, LightType::Spot}));
  ASSERT_FALSE(r->params().set("resolution", 128));
  r->requestPublications({"*"});
  for (int layered : {1, 0}) {
    ASSERT_FALSE(r->params().set("cube.layered", layered));
    ASSERT_FALSE(r->renderFrame(160, 90, 0));
    std::vector<std::string> declared;
    for (const PassDecl& p : framePassDecls(*info)) declared.push_back(p.id);
    test::expectDeclaredPassesOpened(r->stats(), declared);
    const Publication& pub = r->publication();
    EXPECT_EQ(pub.images.size(), 6u);  // six faces for a point light
    for (const auto& [k, img] : pub.images) {
      EXPECT_TRUE(info->findPublication(k)) << k;
      EXPECT_EQ(img.width, 128);
    }
    EXPECT_EQ(pub.numbers.at("cube.faces"), 6.0);
  }
  test::expectNoGlErrors(*r);
}

}  // namespace
}  // namespace sl
