// The `dual-paraboloid` technique on the GPU: its lookup's hemisphere and uv equal
// omni::paraboloidUv on a sphere of directions; omni-room at 2048^2 per hemisphere within
// 0.5 % of the exact reference, for every split axis; tessellation off shows the artifact
// (long triangles' edges straight in the map); a spot uses one hemisphere; memory exact.
#include <algorithm>
#include <cmath>

#include "GlTestEnv.h"
#include "algo/omni/OmniMapping.h"
#include "gl/Gl.h"

namespace sl {
namespace {

TEST(DualParaboloid, GpuLookupMatchesCpuMappingOnTheSphere) {
  // As Cube.GpuLookupMatchesCpuFaceMappingOnTheSphere: the camera at the light looks along
  // 14 directions; without the normal offset, the resolve's map index is the hemisphere and
  // its uv omni::paraboloidUv's, within 1e-4 (float32), except within 1e-4 of the split
  // plane (float ties). Both split axes x and y.
  auto r = test::makeRenderer("omni-room", "dual-paraboloid");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->params().set("bias.normal", 0.0));
  ASSERT_FALSE(r->params().set("resolution", 256));
  const glm::vec3 L = r->light().positionM;
  const std::vector<glm::vec3> looks = test::sphereLookDirections();
  for (auto [axisIndex, axis] : {std::pair{0, glm::dvec3(0, 1, 0)}, {1, glm::dvec3(1, 0, 0)}}) {
    SCOPED_TRACE(axisIndex);
    ASSERT_FALSE(r->params().set("dp.axis", axisIndex));
    const omni::ParaboloidFrame frame = omni::paraboloidFrame(axis);
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
        if (std::abs(glm::dot(d, axis)) < 1e-4 * glm::length(d)) continue;
        const omni::ParaboloidCoord cpu = omni::paraboloidUv(frame, d);
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

TEST(DualParaboloid, OmniRoomAt2048AgreesWithReference) {
  auto r = test::makeRenderer("omni-room", "dual-paraboloid");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->params().set("resolution", 2048));
  for (int axis : {0, 1, 2}) {
    ASSERT_FALSE(r->params().set("dp.axis", axis));
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

TEST(DualParaboloid, TessellationOffShowsTheLongTriangleArtifact) {
  // The table top's long edges stay straight in the map untessellated: its shadow on the
  // floor shrinks (false lit) by several times the tessellated error.
  auto r = test::makeRenderer("omni-room", "dual-paraboloid");
  ASSERT_TRUE(r);
  r->setCamera(*test::bookmark(*r->scene(), "floor"));
  ASSERT_FALSE(r->params().set("resolution", 2048));
  ASSERT_FALSE(r->renderFrame(512, 384, 0));
  const double on = r->computeError().stats.errorPct;
  ASSERT_FALSE(r->params().set("tessellation", 0));
  ASSERT_FALSE(r->renderFrame(512, 384, 0));
  const auto off = r->computeError().stats;
  EXPECT_GT(off.errorPct, 4.0 * on) << "on " << on << "%, off " << off.errorPct << "%";
  EXPECT_GT(off.falseLitPct, off.falseShadowPct);
}

TEST(DualParaboloid, SpotUsesOneHemisphereAndMemoryIsExact) {
  auto r = test::makeRenderer("omni-room", "uniform");
  ASSERT_TRUE(r);
  const std::uint64_t before = gl::allocatedBytes();
  ASSERT_FALSE(r->setTechnique("dual-paraboloid"));
  ASSERT_FALSE(r->renderFrame(160, 90, 0));
  const std::uint64_t renderer = gl::allocatedBytes() - before - r->stats().memory.bytes();
  r->requestPublications({"half.*.map"});
  for (auto [res, spot] : {std::pair{512, false}, {256, true}, {128, false}}) {
    SCOPED_TRACE(res);
    r->setLight(spot ? Light::spot({0.2f, 2.9f, 0.1f}, {0, -1, 0}, 60.0f)
                     : Light::point({0.2f, 1.7f, 0.1f}));
    ASSERT_FALSE(r->params().set("resolution", res));
    ASSERT_FALSE(r->renderFrame(160, 90, 0));
    const MemoryStats& m = r->stats().memory;
    EXPECT_EQ(m.bytes(), gl::allocatedBytes() - before - renderer);
    EXPECT_EQ(m.bytes(), 4ull * std::uint64_t(res) * std::uint64_t(res) * (spot ? 1u : 2u));
    EXPECT_EQ(r->publication().images.size(), spot ? 1u : 2u);
  }
  test::expectNoGlErrors(*r);
}

}  // namespace
}  // namespace sl
