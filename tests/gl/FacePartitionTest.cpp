// The `face-partition` technique (Lloyd et al. 2006 §5.1) against the Embree reference on the
// dueling scene (camera into a low sun) and `default`, with the light behind the viewer, the
// per-pixel selection against its CPU mirror (algo/partition/FacePartitionFit), exact memory,
// declared passes == timed passes; the combined scheme (face.zsplits): its selection, memory,
// publications and outlines.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <set>

#include "GlTestEnv.h"
#include "algo/partition/FacePartitionFit.h"
#include "common/shared_constants.h"
#include "gl/Gl.h"
#include "panels/partition/PartitionPanelKeys.h"

namespace sl {
namespace {

using Sets = std::vector<std::pair<const char*, double>>;

struct Measured {
  double errorPct = -1.0;
  std::map<std::string, double> numbers;
};

/// Error (%) of `technique` with `sets` on `scene` at 320x180 (camera bookmark `camera`,
/// optionally another light), after 3 frames; the publication's numbers when asked.
Measured run(const std::string& scene, const char* camera, const std::string& technique,
             const Sets& sets, std::optional<Light> light = {}, std::set<std::string> keys = {}) {
  auto r = test::makeRenderer(scene, technique);
  Measured out;
  if (!r) return out;
  if (camera) {
    const Camera* c = test::bookmark(*r->scene(), camera);
    EXPECT_TRUE(c) << camera;
    if (c) r->setCamera(*c);
  }
  if (light) r->setLight(*light);
  for (const auto& [k, v] : sets) EXPECT_FALSE(r->params().set(k, v)) << k;
  r->requestPublications(keys);
  for (int f = 0; f < 3; ++f) EXPECT_FALSE(r->renderFrame(320, 180, 0));
  out.errorPct = r->computeError().stats.errorPct;
  out.numbers = r->publication().numbers;
  test::expectNoGlErrors(*r);
  return out;
}

// dueling, `into-sun`: the light 14 degrees up behind the far end, inside the view cone.
// LiSPSM sees a square frustum and falls back to the uniform map (the same error, to the
// bit); the face partitions still warp. Same total texels: 5 x 1024^2 against 2290^2.
// Measured (llvmpipe, 320x180): face-partition 1.123 %, lispsm = uniform 1.849 %; no warp in
// the faces (warp.eta -1) 3.976 %; every face warped along the view vector instead of its
// bisector 1.76 %.
TEST(FacePartition, BeatsLispsmAndUniformOnDuelingFrusta) {
  const Measured face = run("dueling", "into-sun", "face-partition", {{"resolution", 1024}}, {},
                            {"partition.active", "partition.*.warp.fallback", "faces.front"});
  const Measured lispsm = run("dueling", "into-sun", "lispsm", {{"resolution", 2290}}, {},
                              {"warp.fallback", "warp.fallback_cause"});
  const Measured uniform = run("dueling", "into-sun", "uniform", {{"resolution", 2290}});
  const Measured flat =
      run("dueling", "into-sun", "face-partition", {{"resolution", 1024}, {"warp.eta", -1.0}});
  std::printf(
      "dueling: face-partition 5x1024^2 %.3f %%, lispsm 2290^2 %.3f %%, uniform %.3f %%, "
      "faces unwarped %.3f %%\n",
      face.errorPct, lispsm.errorPct, uniform.errorPct, flat.errorPct);
  EXPECT_EQ(lispsm.numbers.at("warp.fallback"), 1.0);
  EXPECT_EQ(lispsm.numbers.at("warp.fallback_cause"), 2.0);  // light in front
  EXPECT_DOUBLE_EQ(lispsm.errorPct, uniform.errorPct);
  EXPECT_EQ(face.numbers.at("faces.front"), 0.0);  // v . y > 0: the back faces
  EXPECT_EQ(face.numbers.at("partition.active"), 5.0);
  EXPECT_EQ(face.numbers.at("partition.3.warp.fallback"), 0.0);  // the bottom face warps
  EXPECT_LT(face.errorPct, 0.75 * lispsm.errorPct);
  EXPECT_LT(face.errorPct, 1.4);
  EXPECT_LT(face.errorPct, 0.5 * flat.errorPct);  // the warp is what wins
}

// Light behind the viewer (azimuth 0, elevation 14: inside the view cone from behind):
// LiSPSM reverts to uniform, face partitioning (front faces now) keeps the lower error.
// Measured: face-partition 0.422 %, lispsm = uniform 0.632 %.
TEST(FacePartition, LightBehindTheViewerKeepsLowerErrorThanLispsm) {
  const Light behind = Light::directional(0.0f, 14.0f);
  const Measured face = run("dueling", "into-sun", "face-partition", {{"resolution", 1024}}, behind,
                            {"faces.front", "partition.active"});
  const Measured lispsm = run("dueling", "into-sun", "lispsm", {{"resolution", 2290}}, behind,
                              {"warp.fallback", "warp.fallback_cause"});
  std::printf("dueling, light behind: face-partition %.3f %%, lispsm %.3f %%\n", face.errorPct,
              lispsm.errorPct);
  EXPECT_EQ(lispsm.numbers.at("warp.fallback"), 1.0);
  EXPECT_EQ(lispsm.numbers.at("warp.fallback_cause"), 1.0);  // light behind
  EXPECT_EQ(face.numbers.at("faces.front"), 1.0);
  EXPECT_GE(face.numbers.at("partition.active"), 4.0);
  EXPECT_LT(face.errorPct, 0.8 * lispsm.errorPct);
  EXPECT_LT(face.errorPct, 0.6);
}

// `default` (overview, light 35 degrees up at the side: three faces used). Measured: 0.595 %
// (uniform 2048^2: 0.158 %, lispsm 2048^2: 0.297 %): away from the dueling case one warp
// serves this view well, and face partitioning spends 5 maps where 3 are used.
TEST(FacePartition, DefaultSceneIsAccurate) {
  const Measured face =
      run("default", nullptr, "face-partition", {{"resolution", 1024}}, {}, {"partition.active"});
  std::printf("default: face-partition 5x1024^2 %.3f %%\n", face.errorPct);
  EXPECT_EQ(face.numbers.at("partition.active"), 3.0);
  EXPECT_LT(face.errorPct, 0.8);
}

// The map index the resolve pass wrote per pixel equals the CPU mirror's selection for the
// pixel's world position (the same camera, aspect, scene bounds and light), with bias.normal 0
// (the GPU selects again after the normal offset: the map of P + offset). The GPU works in
// float: a pixel may differ only where the ray's exit distances through two faces are within
// 1 mm, at most 0.1 % of the pixels. With face.zsplits 3 the slice is chosen by view depth
// first: a pixel may also differ where its depth is within 1 mm of a split (the gap).
// Measured: 0 mismatches of 33,202 pixels for each light, with 1, 2 and 3 slices.
TEST(FacePartition, SelectionOnGpuMatchesTheCpuMirror) {
  for (const int zsplits : {1, 2, 3})
    for (const Light light : {Light::directional(180.0f, 14.0f), Light::directional(0.0f, 14.0f),
                              Light::directional(120.0f, 40.0f)}) {
      SCOPED_TRACE(zsplits);
      auto r = test::makeRenderer("dueling", "face-partition");
      ASSERT_TRUE(r);
      r->setCamera(*test::bookmark(*r->scene(), "into-sun"));
      r->setLight(light);
      ASSERT_FALSE(r->params().set("bias.normal", 0.0));  // the map of P itself, not of P + offset
      ASSERT_FALSE(r->params().set("face.zsplits", zsplits));
      ASSERT_FALSE(r->params().set("resolution", 256));  // the selection does not read the maps
      ASSERT_FALSE(r->renderFrame(320, 180, 0));
      const FrameReadback fr = r->readback();
      partition::FacePartitionFit fit;
      ASSERT_FALSE(partition::fitFacePartitions(r->camera(), double(320.0f / 180.0f),
                                                r->scene()->bounds,
                                                glm::dvec3(light.directionalTowards()), 0.0, fit,
                                                zsplits, partition::FaceNesting::FacesFirst));
      std::size_t covered = 0, mismatched = 0, far = 0;
      std::set<int> used, slices;
      for (std::size_t i = 0; i < fr.positions.size(); ++i) {
        if (fr.positions[i].w <= 0.0f) continue;
        ++covered;
        double gap = 0.0;
        const int cpu =
            partition::selectFacePartition(fit.selection, glm::dvec3(fr.positions[i]), &gap);
        used.insert(cpu);
        slices.insert(cpu / partition::kFaceSlots);
        if (cpu == int(fr.mapIndex[i])) continue;
        ++mismatched;
        if (gap > 1e-3) ++far;
      }
      std::printf(
          "light (%.2f %.2f %.2f): %zu covered, %zu mismatched, %zu beyond 1 mm, %zu "
          "partitions used\n",
          double(light.directionalTowards().x), double(light.directionalTowards().y),
          double(light.directionalTowards().z), covered, mismatched, far, used.size());
      EXPECT_GT(covered, 20000u);
      EXPECT_GE(used.size(), 2u);
      // Pixels on both sides of a split (3 slices: the first ends 0.97 m away, before the
      // ground the camera sees: 2 slices serve pixels).
      EXPECT_EQ(int(slices.size()), std::min(zsplits, 2));
      EXPECT_EQ(far, 0u);
      EXPECT_LE(double(mismatched), 0.001 * double(covered));
      test::expectNoGlErrors(*r);
    }
}

// memory() lists every byte: 5 slots per depth slice of resolution^2 32-bit depths, whatever
// the light.
TEST(FacePartition, MemoryIsExact) {
  auto r = test::makeRenderer("dueling", "uniform");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->renderFrame(160, 90, 0));
  const std::uint64_t before = gl::allocatedBytes() - r->stats().memory.bytes();
  ASSERT_FALSE(r->setTechnique("face-partition"));
  struct Case {
    int res;
    float azimuth;
    int zsplits;
  };
  for (const Case c : {Case{512, 180.0f, 1},
                       {256, 0.0f, 1},
                       {384, 90.0f, 1},
                       {256, 180.0f, 2},
                       {128, 0.0f, 4},
                       {384, 90.0f, 3}}) {
    SCOPED_TRACE(c.res);
    SCOPED_TRACE(c.zsplits);
    r->setLight(Light::directional(c.azimuth, 30.0f));
    ASSERT_FALSE(r->params().set("resolution", c.res));
    ASSERT_FALSE(r->params().set("face.zsplits", c.zsplits));
    ASSERT_FALSE(r->renderFrame(160, 90, 0));
    const MemoryStats& m = r->stats().memory;
    EXPECT_EQ(m.bytes(), gl::allocatedBytes() - before) << "memory() must list every byte";
    EXPECT_EQ(m.bytes(),
              4ull * std::uint64_t(c.res) * std::uint64_t(c.res) * 5 * std::uint64_t(c.zsplits));
  }
  // Out of range: refused with the range named.
  auto err = r->params().set("face.zsplits", 5);
  ASSERT_TRUE(err);
  EXPECT_NE(err->find("face.zsplits"), std::string::npos) << *err;
  test::expectNoGlErrors(*r);
}

// Every declared pass is timed, in order; the Partitions panel's keys cost what is declared,
// and its m per slot is the readback's.
TEST(FacePartition, DeclaredPassesAndPanelKeys) {
  auto r = test::makeRenderer("dueling", "face-partition");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->params().set("resolution", 256));
  const std::set<std::string> keys = ui::partition::partitionsPanelKeys();
  r->requestPublications(keys);
  for (int f = 0; f < 2; ++f) ASSERT_FALSE(r->renderFrame(160, 90, 0));
  std::vector<std::string> declared;
  const TechniqueInfo* info = Renderer::findTechnique("face-partition");
  ASSERT_TRUE(info);
  for (const PassDecl& p : framePassDecls(*info)) declared.push_back(p.id);
  test::expectDeclaredPassesOpened(r->stats(), declared);
  const Publication& pub = r->publication();
  EXPECT_EQ(pub.images.size(), 5u);
  EXPECT_EQ(pub.numbers.at("partition.count"), 5.0);
  int warpedSlots = 0;
  for (int i = 0; i < 5; ++i) {
    const std::string k = "partition." + std::to_string(i);
    ASSERT_TRUE(pub.images.count(k + ".map")) << k;
    EXPECT_EQ(pub.images.at(k + ".map").width, 256);
    EXPECT_GE(pub.numbers.at(k + ".far"), pub.numbers.at(k + ".near"));
    // The panel's warp column: warped with its n', or not (then n' 0).
    const double warped = pub.numbers.at(k + ".warped"),
                 nPrime = pub.numbers.at(k + ".warp.n_prime");
    EXPECT_TRUE(warped == 0.0 || warped == 1.0) << k;
    EXPECT_EQ(warped == 1.0, nPrime > 0.0) << k << " n' " << nPrime;
    warpedSlots += warped == 1.0 ? 1 : 0;
  }
  EXPECT_GE(warpedSlots, 3);  // the side faces warp (the near face falls back: square)
  EXPECT_EQ(r->stats().publicationBytes, declaredPublicationBytes(*info, r->params(), keys));
  EXPECT_EQ(r->stats().publicationBytes, 5ull * 256 * 256 * 4 + 5ull * (SL_CASCADE_M_BINS + 2) * 4);
  // m per slot (core/PartitionMStats, as cascades): of the previous frame's resolve, which a
  // still camera repeats exactly: the pixels that selected each slot, their largest m, a p95
  // within one 1/8-octave bin above the exact one; every pixel counted once.
  const FrameReadback fr = r->readback();
  double covered = 0.0;
  for (float m : fr.aliasing) covered += m > 0.0f ? 1.0 : 0.0;
  const double counted = test::expectPartitionMMatches(pub, fr, 5);
  EXPECT_GT(covered, 0.0);
  EXPECT_EQ(counted, covered);
  // 5 maps of 16384^2 would be 5 GiB: refused with the sizes named, the renderer keeps working.
  ASSERT_FALSE(r->params().set("resolution", 16384));
  auto err = r->renderFrame(64, 36, 0);
  ASSERT_TRUE(err);
  EXPECT_NE(err->find("5 maps of 16384^2 need 5120 MiB"), std::string::npos) << *err;
  ASSERT_FALSE(r->params().set("resolution", 256));
  EXPECT_FALSE(r->renderFrame(160, 90, 0));
  // A point light is refused with a message, the renderer keeps working.
  r->setLight(Light::point({0.0f, 3.0f, 0.0f}, 20.0f));
  EXPECT_TRUE(r->renderFrame(160, 90, 0));
  r->setLight(Light::directional(180.0f, 14.0f));
  EXPECT_FALSE(r->renderFrame(160, 90, 0));
  test::expectNoGlErrors(*r);
}

// face.zsplits 2 (the combined scheme): 10 slots, each published (map, slice, numbers, m) at
// the declared cost, the Partitions panel's keys for all of them; the outside view draws the
// split plane at face.split.1 and one light frustum per active (slice, face) slot.
TEST(FacePartition, ZSplitsPublishEverySlotAndTheSplit) {
  auto r = test::makeRenderer("dueling", "face-partition");
  ASSERT_TRUE(r);
  r->setCamera(*test::bookmark(*r->scene(), "into-sun"));
  ASSERT_FALSE(r->params().set("resolution", 128));
  ASSERT_FALSE(r->params().set("face.zsplits", 2));
  ASSERT_FALSE(r->rendererParams().setFromString("view.outside", "on"));
  std::set<std::string> keys = ui::partition::partitionsPanelKeys();
  r->requestPublications(keys);
  for (int f = 0; f < 2; ++f) ASSERT_FALSE(r->renderFrame(160, 90, 0));
  const TechniqueInfo* info = Renderer::findTechnique("face-partition");
  ASSERT_TRUE(info);
  const Publication& pub = r->publication();
  EXPECT_EQ(pub.numbers.at("partition.count"), 10.0);
  EXPECT_EQ(pub.images.size(), 10u);
  for (int i = 0; i < 10; ++i) {
    const std::string k = "partition." + std::to_string(i);
    ASSERT_TRUE(pub.images.count(k + ".map")) << k;
    EXPECT_EQ(pub.images.at(k + ".map").width, 128);
  }
  EXPECT_EQ(r->stats().publicationBytes, declaredPublicationBytes(*info, r->params(), keys));
  EXPECT_EQ(r->stats().publicationBytes,
            10ull * 128 * 128 * 4 + 10ull * (SL_CASCADE_M_BINS + 2) * 4);
  const FrameReadback fr = r->readback();
  double covered = 0.0;
  std::set<int> slices;
  for (std::size_t p = 0; p < fr.aliasing.size(); ++p)
    if (fr.aliasing[p] > 0.0f) {
      covered += 1.0;
      slices.insert(int(fr.mapIndex[p]) / 5);
    }
  EXPECT_EQ(test::expectPartitionMMatches(pub, fr, 10), covered);
  EXPECT_EQ(slices, (std::set<int>{0, 1}));  // both slices serve pixels
  // The slice numbers, the split and the outside view's outlines.
  r->requestPublications({"face.split.*", "partition.*.active", "partition.*.slice",
                          "partition.*.near", "partition.*.far"});
  ASSERT_FALSE(r->renderFrame(160, 90, 0));
  const auto& n = r->publication().numbers;
  const double z0 = n.at("face.split.0"), z1 = n.at("face.split.1"), z2 = n.at("face.split.2");
  EXPECT_NEAR(z1, std::sqrt(z0 * z2), 1e-9 * z2);  // the log split of 2 slices
  std::set<int> active;
  for (int i = 0; i < 10; ++i) {
    const std::string k = "partition." + std::to_string(i);
    EXPECT_EQ(n.at(k + ".slice"), double(i / 5));
    if (n.at(k + ".active") != 1.0) continue;
    active.insert(i);
    const double lo = i < 5 ? z0 : z1, hi = i < 5 ? z1 : z2;
    EXPECT_GE(n.at(k + ".near"), lo - 1e-6 * z2) << k;
    EXPECT_LE(n.at(k + ".far"), hi + 1e-6 * z2) << k;
  }
  EXPECT_GE(active.size(), 6u);
  const auto& outlines = r->stats().outlines;
  ASSERT_EQ(outlines.splitDepthsM.size(), 1u);
  EXPECT_FLOAT_EQ(outlines.splitDepthsM[0], float(z1));
  std::set<int> boxes;
  for (const FrustumOutline& f : outlines.frusta)
    if (f.role == OutlineRole::LightMap) boxes.insert(f.map);
  EXPECT_EQ(boxes, active);
  test::expectNoGlErrors(*r);
}

}  // namespace
}  // namespace sl
