// The view's grid overlay (view.overlay=warp-grid, SL_OVERLAY_GRID in
// shaders/common/composite.frag) through the omni mappings: it draws a line every
// 1/SL_GRID_LINES_PER_MAP of the map each pixel SELECTED (a cube face, a paraboloid hemisphere), so
// on the scene it shows the cube's faces and the paraboloid's texel grid. The selected map's uv is
// checked against algo/omni's mapping by Cube.GpuLookupMatchesCpuFaceMappingOnTheSphere and
// DualParaboloid.GpuLookup...; here the composite is checked against that uv, pixel by pixel, on
// every bookmark of omni-room:
//  - where the uv is farther from a line than the largest screen derivative the composite's
//    fwidth can see (d >= 1), the pixel is exactly the image without the overlay;
//  - where it is within a quarter of the smallest one (d <= 1/4: line >= 3/4), the pixel
//    changed; this includes every quad across a face or hemisphere seam whose uv jumps;
//  - lines are drawn on every face / both hemispheres the view sees.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "GlTestEnv.h"
#include "common/shared_constants.h"

namespace sl {
namespace {

struct GridCase {
  const char* technique;
  int resolution;
};

class OmniGridOverlay : public ::testing::TestWithParam<GridCase> {};

/// The distance of g to its nearest integer, as composite.frag computes it.
float lineDistance(float g) {
  return std::abs(g - std::floor(g - 0.5f) - 0.5f - 0.5f);
}

TEST_P(OmniGridOverlay, LinesFollowTheSelectedMapsUv) {
  auto r = test::makeRenderer("omni-room", GetParam().technique);
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->params().set("resolution", GetParam().resolution));
  constexpr int W = 256, H = 192;  // even: the composite's 2x2 quads pair the read-back rows
  const float lines = float(SL_GRID_LINES_PER_MAP);
  std::size_t far = 0, on = 0, onChanged = 0, farChanged = 0, seamQuads = 0, seamChanged = 0;
  int mapsWithLines = 0;
  std::string firstWrong;  // the first pixel off every line that the overlay changed
  for (const CameraBookmark& b : r->scene()->cameras) {
    SCOPED_TRACE(b.name);
    r->setCamera(b.camera);
    ASSERT_FALSE(r->rendererParams().setFromString("view.overlay", "none"));
    ASSERT_FALSE(r->renderFrame(W, H, 0));
    const ImageRGBA8 plain = r->readback().color;
    ASSERT_FALSE(r->rendererParams().setFromString("view.overlay", "warp-grid"));
    ASSERT_FALSE(r->renderFrame(W, H, 0));
    const FrameReadback f = r->readback();
    ASSERT_EQ(f.color.pixels.size(), plain.pixels.size());
    for (int y = 0; y < H; ++y) {
      for (int x = 0; x < W; ++x) {
        const int x0 = x & ~1, y0 = y & ~1;
        const std::size_t q[4] = {std::size_t(y0 * W + x0), std::size_t(y0 * W + x0 + 1),
                                  std::size_t((y0 + 1) * W + x0),
                                  std::size_t((y0 + 1) * W + x0 + 1)};
        if (std::any_of(q, q + 4, [&](std::size_t j) { return f.positions[j].w <= 0.0f; }))
          continue;
        const std::size_t i = std::size_t(y * W + x);
        bool changed = false;
        for (int c = 0; c < 3; ++c)
          changed = changed || f.color.pixels[i * 4 + c] != plain.pixels[i * 4 + c];
        // fwidth per axis: |dFdx| + |dFdy| within the quad; fine or coarse derivatives take
        // the difference along either row / column, so bound it by the smallest and largest.
        double dMin = 1e30, dMax = 1e30;  // min over axes of distance / w, w largest / smallest
        for (int a = 0; a < 2; ++a) {
          auto g = [&](int k) { return f.texel[q[k]][a] * lines; };
          const float dx0 = std::abs(g(1) - g(0)), dx1 = std::abs(g(3) - g(2));
          const float dy0 = std::abs(g(2) - g(0)), dy1 = std::abs(g(3) - g(1));
          const double wMax = double(std::max(dx0, dx1)) + double(std::max(dy0, dy1));
          const double wMin =
              std::max(double(std::min(dx0, dx1)) + double(std::min(dy0, dy1)), 1e-6);
          const double dist = lineDistance(f.texel[i][a] * lines);
          dMin = std::min(dMin, dist / std::max(wMax, 1e-6));
          dMax = std::min(dMax, dist / wMin);
        }
        const bool seam = f.mapIndex[q[0]] != f.mapIndex[q[1]] ||
                          f.mapIndex[q[0]] != f.mapIndex[q[2]] ||
                          f.mapIndex[q[0]] != f.mapIndex[q[3]];
        if (seam) {
          ++seamQuads;
          seamChanged += changed;
        }
        if (dMin >= 1.0) {
          ++far;
          farChanged += changed;
          if (changed && firstWrong.empty())
            firstWrong = b.name + " pixel " + std::to_string(x) + "," + std::to_string(y) +
                         " (d >= " + std::to_string(dMin) + ")";
        } else if (dMax <= 0.25) {
          ++on;
          onChanged += changed;
          if (changed) mapsWithLines |= 1 << f.mapIndex[i];
        }
      }
    }
  }
  std::printf(
      "%s: %zu pixels off the lines (%zu changed), %zu on them (%zu changed), %zu in "
      "seam quads (%zu changed)\n",
      GetParam().technique, far, farChanged, on, onChanged, seamQuads, seamChanged);
  // 4 bookmarks of 256x192 (measured: cube 94445 off / 33885 on the lines, 4489 of 4532 seam
  // quads changed; paraboloid 132613 / 19084, 1102 of 1148; lat-long 132531 / 19933, 2739 of
  // 2764).
  EXPECT_GT(far, 50000u);
  EXPECT_EQ(farChanged, 0u) << "no grid line there, but the overlay changed it: " << firstWrong;
  EXPECT_GT(on, 10000u);
  EXPECT_EQ(onChanged, on);
  EXPECT_GT(seamQuads, 500u);
  EXPECT_GT(seamChanged, seamQuads * 9 / 10);  // a seam is drawn as a line
  EXPECT_EQ(mapsWithLines, std::string(GetParam().technique) == "cube" ? 0x3f : 0x3);
  test::expectNoGlErrors(*r);
}

INSTANTIATE_TEST_SUITE_P(Omni, OmniGridOverlay,
                         ::testing::Values(GridCase{"cube", 512}, GridCase{"dual-paraboloid", 1024},
                                           GridCase{"spherical", 1024}),
                         [](const auto& p) {
                           const std::string id = p.param.technique;
                           return id == "cube"        ? "Cube"
                                  : id == "spherical" ? "Spherical"
                                                      : "DualParaboloid";
                         });

}  // namespace
}  // namespace sl
