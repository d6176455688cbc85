// The outside view (view.outside): its lines appear where the CPU projection of the published
// frusta says (algo/OutsideView), one light frustum per cascade, the metrics and the hard
// mask do not change with the toggle, face-partition's faces and warps, the aliasing overlay
// in the main view only, and a golden image of lispsm on corridor seen from outside.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "GlTestEnv.h"
#include "algo/OutsideView.h"
#include "metrics/GoldenImage.h"

namespace sl {
namespace {

constexpr int kW = 480, kH = 270;

/// Share of sample points along the segments of `role` (and `map`) that have a pixel of the
/// segment's colour (within 1/255 per channel) within `radius` pixels in `img` (row 0 = top).
double foundShare(const ImageRGBA8& img, const Camera& outside,
                  const std::vector<OutlineSegment>& segs, OutlineRole role, int map, int radius) {
  const float aspect = float(img.width) / float(img.height);
  const glm::mat4 vp = outside.projection(aspect) * outside.view();
  auto toPixel = [&](const glm::vec3& p) {
    const glm::vec4 c = vp * glm::vec4(p, 1.0f);
    return glm::vec2((c.x / c.w * 0.5f + 0.5f) * float(img.width),
                     (0.5f - c.y / c.w * 0.5f) * float(img.height));
  };
  int samples = 0, found = 0;
  for (const OutlineSegment& s : segs) {
    if (s.role != role || (role == OutlineRole::LightMap && s.map != map)) continue;
    const glm::vec2 a = toPixel(s.a), b = toPixel(s.b);
    if (glm::length(b - a) < 8.0f) continue;  // too short to sample apart from its ends
    const glm::ivec3 want = glm::ivec3(glm::round(s.colour * 255.0f));
    for (int k = 1; k < 10; ++k) {
      const glm::vec2 q = glm::mix(a, b, float(k) / 10.0f);
      ++samples;
      bool hit = false;
      for (int dy = -radius; dy <= radius && !hit; ++dy)
        for (int dx = -radius; dx <= radius && !hit; ++dx) {
          const int x = int(std::floor(q.x)) + dx, y = int(std::floor(q.y)) + dy;
          if (x < 0 || y < 0 || x >= img.width || y >= img.height) continue;
          const std::uint8_t* px = &img.pixels[(size_t(y) * size_t(img.width) + size_t(x)) * 4];
          hit = std::abs(px[0] - want.r) <= 1 && std::abs(px[1] - want.g) <= 1 &&
                std::abs(px[2] - want.b) <= 1;
        }
      found += hit ? 1 : 0;
    }
  }
  return samples ? double(found) / double(samples) : -1.0;
}

std::vector<OutlineSegment> segmentsOf(const Renderer& r) {
  return outlineSegments(r.camera(), float(kW) / float(kH), r.scene()->bounds, r.stats().outlines);
}

TEST(OutsideView, CameraAndWarpLinesLieWhereTheCpuProjects) {
  auto r = test::makeRenderer("corridor", "lispsm");
  ASSERT_TRUE(r);
  r->setCamera(*test::bookmark(*r->scene(), "start"));
  ASSERT_FALSE(r->params().set("resolution", 1024));
  ASSERT_FALSE(r->rendererParams().setFromString("view.outside", "on"));
  ASSERT_FALSE(r->renderFrame(kW, kH, 0));
  ASSERT_TRUE(r->stats().outsideCamera);
  const Camera outsideCamera = *r->stats().outsideCamera;
  const FrameReadback frame = r->readback();
  ASSERT_EQ(frame.outside.width, kW);
  const auto segs = segmentsOf(*r);
  // lispsm warps here: the unwarped light box and the warp's frustum are published.
  int boxes = 0, warps = 0;
  for (const FrustumOutline& f : r->stats().outlines.frusta)
    (f.role == OutlineRole::Warp ? warps : boxes) += 1;
  EXPECT_EQ(boxes, 1);
  EXPECT_EQ(warps, 1);
  const double camera =
      foundShare(frame.outside, *r->stats().outsideCamera, segs, OutlineRole::Camera, 0, 2);
  const double warp =
      foundShare(frame.outside, *r->stats().outsideCamera, segs, OutlineRole::Warp, 0, 2);
  std::printf("camera frustum lines found at %.1f %% of samples, warp %.1f %%\n", 100 * camera,
              100 * warp);
  EXPECT_GE(camera, 0.9);
  EXPECT_GE(warp, 0.9);
  // Off: the same samples find (almost) none of those colours in the main camera's image.
  ASSERT_FALSE(r->rendererParams().setFromString("view.outside", "off"));
  ASSERT_FALSE(r->renderFrame(kW, kH, 0));
  EXPECT_FALSE(r->stats().outsideCamera);
  const FrameReadback off = r->readback();
  EXPECT_TRUE(off.outside.pixels.empty());
  EXPECT_LT(foundShare(off.color, outsideCamera, segs, OutlineRole::Warp, 0, 2), 0.1);
  EXPECT_LT(foundShare(off.color, outsideCamera, segs, OutlineRole::Camera, 0, 2), 0.1);
  test::expectNoGlErrors(*r);
}

TEST(OutsideView, CascadesDrawOneLightFrustumPerMapAndTheSplits) {
  auto r = test::makeRenderer("corridor", "cascades");
  ASSERT_TRUE(r);
  r->setCamera(*test::bookmark(*r->scene(), "start"));
  ASSERT_FALSE(r->params().set("partitions", 4));
  ASSERT_FALSE(r->params().set("resolution", 512));
  ASSERT_FALSE(r->rendererParams().setFromString("view.outside", "on"));
  for (int f = 0; f < 2; ++f) ASSERT_FALSE(r->renderFrame(kW, kH, 0));
  const FrameOutlines& o = r->stats().outlines;
  ASSERT_EQ(o.frusta.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(o.frusta[size_t(i)].role, OutlineRole::LightMap);
    EXPECT_EQ(o.frusta[size_t(i)].map, i);
  }
  EXPECT_EQ(o.splitDepthsM.size(), 3u);
  const FrameReadback frame = r->readback();
  const auto segs = segmentsOf(*r);
  // Each map's box shows in its partition colour (later maps overdraw shared edges: half).
  // The near cascades of corridor are metres wide in a kilometre-wide view: a map whose edges
  // all project shorter than 8 pixels has no samples (-1) and is not counted.
  int measured = 0;
  for (int i = 0; i < 4; ++i) {
    const double share =
        foundShare(frame.outside, *r->stats().outsideCamera, segs, OutlineRole::LightMap, i, 2);
    std::printf("map %d: light frustum lines found at %.1f %% of samples\n", i, 100 * share);
    if (share < 0.0) continue;
    ++measured;
    EXPECT_GE(share, 0.5) << "map " << i;
  }
  EXPECT_GE(measured, 2);
  EXPECT_GE(foundShare(frame.outside, *r->stats().outsideCamera, segs, OutlineRole::Split, 0, 2),
            0.5);
  test::expectNoGlErrors(*r);
}

// face-partition on dueling into the sun (the back faces, LiSPSM's square-frustum case): one
// light frustum per active face, coloured by its slot (the overlay's map index), and a warping
// frustum for each face that warps; both drawn where the CPU projection says.
TEST(OutsideView, FacePartitionDrawsEveryActiveFaceAndItsWarp) {
  auto r = test::makeRenderer("dueling", "face-partition");
  ASSERT_TRUE(r);
  r->setCamera(*test::bookmark(*r->scene(), "into-sun"));
  ASSERT_FALSE(r->params().set("resolution", 512));
  ASSERT_FALSE(r->rendererParams().setFromString("view.outside", "on"));
  r->requestPublications({"partition.active", "partition.*.active", "partition.*.warp.eta"});
  ASSERT_FALSE(r->renderFrame(kW, kH, 0));
  const auto& numbers = r->publication().numbers;
  const int active = int(numbers.at("partition.active"));
  EXPECT_EQ(active, 5);  // test FacePartition.BeatsLispsmAndUniformOnDuelingFrusta: all 5
  std::set<int> activeSlots, warpedSlots;
  for (int i = 0; i < 5; ++i) {
    const std::string key = "partition." + std::to_string(i);
    if (numbers.at(key + ".active") != 1.0) continue;
    activeSlots.insert(i);
    if (numbers.at(key + ".warp.eta") > -1.0) warpedSlots.insert(i);
  }
  ASSERT_EQ(int(activeSlots.size()), active);
  EXPECT_GE(warpedSlots.size(), 4u);  // the four side faces warp along their bisectors
  std::set<int> boxes, warps;
  for (const FrustumOutline& f : r->stats().outlines.frusta) {
    std::set<int>& into = f.role == OutlineRole::Warp ? warps : boxes;
    EXPECT_TRUE(into.insert(f.map).second) << "map " << f.map << " twice";
    EXPECT_TRUE(f.role == OutlineRole::LightMap || f.role == OutlineRole::Warp);
  }
  EXPECT_EQ(boxes, activeSlots);
  EXPECT_EQ(warps, warpedSlots);
  EXPECT_TRUE(r->stats().outlines.splitDepthsM.empty());  // faces, not depth slices

  const FrameReadback frame = r->readback();
  const auto segs = segmentsOf(*r);
  const Camera& outside = *r->stats().outsideCamera;
  // Faces share edges (a later slot overdraws an earlier one's): half of the samples. The
  // near face's light prism here is a tube 0.17 m across and 90 m long along the light (the
  // near plane's width): its edges lie inside the side faces' bundle, sub-pixel apart, and
  // are overdrawn (0 % found). A box thinner than 1 % of its length is not counted.
  auto thin = [&](int slot) {
    for (const FrustumOutline& f : r->stats().outlines.frusta) {
      if (f.role != OutlineRole::LightMap || f.map != slot) continue;
      const float e[3] = {glm::length(f.corners[1] - f.corners[0]),
                          glm::length(f.corners[3] - f.corners[0]),
                          glm::length(f.corners[4] - f.corners[0])};
      return std::min({e[0], e[1], e[2]}) < 0.01f * std::max({e[0], e[1], e[2]});
    }
    return false;
  };
  int measured = 0;
  for (int i : activeSlots) {
    const double share = foundShare(frame.outside, outside, segs, OutlineRole::LightMap, i, 2);
    std::printf("face slot %d: light frustum lines found at %.1f %% of samples%s\n", i, 100 * share,
                thin(i) ? " (a thin tube inside the bundle: not counted)" : "");
    if (share < 0.0 || thin(i)) continue;
    ++measured;
    EXPECT_GE(share, 0.5) << "slot " << i;
  }
  EXPECT_GE(measured, 4);
  const double warp = foundShare(frame.outside, outside, segs, OutlineRole::Warp, 0, 2);
  const double camera = foundShare(frame.outside, outside, segs, OutlineRole::Camera, 0, 2);
  std::printf("warp frusta lines found at %.1f %%, camera %.1f %%\n", 100 * warp, 100 * camera);
  EXPECT_GE(warp, 0.5);
  EXPECT_GE(camera, 0.5);
  test::expectNoGlErrors(*r);
}

// The metrics measure the main camera: two renderers, one with the outside view, give the
// same hard mask, error and aliasing, frame for frame.
TEST(OutsideView, MetricsDoNotChangeWithTheToggle) {
  for (const char* technique : {"uniform", "lispsm", "cascades", "rtw-backward"}) {
    auto plain = test::makeRenderer("corridor", technique);
    auto outside = test::makeRenderer("corridor", technique);
    ASSERT_TRUE(plain && outside);
    for (Renderer* r : {plain.get(), outside.get()}) {
      r->setCamera(*test::bookmark(*r->scene(), "start-level"));
      ASSERT_FALSE(r->params().set("resolution", 512));
    }
    ASSERT_FALSE(outside->rendererParams().setFromString("view.outside", "on"));
    for (int f = 0; f < 3; ++f) {
      ASSERT_FALSE(plain->renderFrame(320, 180, 0));
      ASSERT_FALSE(outside->renderFrame(320, 180, 0));
    }
    const Renderer::ErrorResult a = plain->computeError(), b = outside->computeError();
    EXPECT_EQ(a.frame.hardMask, b.frame.hardMask) << technique;
    EXPECT_EQ(a.frame.aliasing, b.frame.aliasing) << technique;
    EXPECT_EQ(a.frame.color.pixels, b.frame.color.pixels) << technique;
    EXPECT_EQ(a.stats.errorPct, b.stats.errorPct) << technique;
    EXPECT_TRUE(a.frame.outside.pixels.empty());
    ASSERT_EQ(b.frame.outside.pixels.size(), b.frame.color.pixels.size()) << technique;
    EXPECT_NE(b.frame.outside.pixels, b.frame.color.pixels) << technique;
    test::expectNoGlErrors(*plain);
    test::expectNoGlErrors(*outside);
  }
}

// m is a footprint in the main camera's pixels: the outside view is drawn without the aliasing
// overlay (the main view keeps it), while the partition overlay, a property of the scene
// point, shows from outside too.
TEST(OutsideView, AliasingOverlayOnlyInTheMainView) {
  auto r = test::makeRenderer("corridor", "cascades");
  ASSERT_TRUE(r);
  r->setCamera(*test::bookmark(*r->scene(), "start-level"));
  ASSERT_FALSE(r->params().set("resolution", 512));
  ASSERT_FALSE(r->rendererParams().setFromString("view.outside", "on"));
  auto frameWith = [&](const char* overlay) {
    EXPECT_FALSE(r->rendererParams().setFromString("view.overlay", overlay)) << overlay;
    for (int f = 0; f < 2; ++f) EXPECT_FALSE(r->renderFrame(320, 180, 0));
    return r->readback();
  };
  const FrameReadback none = frameWith("none"), aliasing = frameWith("aliasing"),
                      partition = frameWith("partition");
  EXPECT_NE(aliasing.color.pixels, none.color.pixels);      // the main view has the overlay
  EXPECT_EQ(aliasing.outside.pixels, none.outside.pixels);  // the outside view has not
  EXPECT_NE(partition.color.pixels, none.color.pixels);
  EXPECT_NE(partition.outside.pixels, none.outside.pixels);
  test::expectNoGlErrors(*r);
}

TEST(Golden, CorridorLispsmOutsideView) {
  auto r = test::makeRenderer("corridor", "lispsm");
  ASSERT_TRUE(r);
  r->setCamera(*test::bookmark(*r->scene(), "start"));
  ASSERT_FALSE(r->params().set("resolution", 1024));
  ASSERT_FALSE(r->rendererParams().setFromString("view.outside", "on"));
  ASSERT_FALSE(r->renderFrame(kW, kH, 0));
  GoldenResult g = compareToGolden(
      r->readback().outside,
      std::filesystem::path(SHADOWLAB_GOLDEN_DIR) / "corridor-lispsm-outside.png",
      GoldenTolerance{24, 0.01}, test::testOut("golden"), "corridor-lispsm-outside");
  EXPECT_TRUE(g.pass) << g.message;
  test::expectNoGlErrors(*r);
}

}  // namespace
}  // namespace sl
