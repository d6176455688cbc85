// The `virtual-tiled` technique (the brute-force baseline of Giegl & Wimmer 2007): n x n tiles
// of one reused texture, applied by a deferred compute pass. Against the Embree reference and
// against `uniform` at the same virtual resolution (the same fit cut into tiles: nearly the
// same hard mask), exact memory (one tile, whatever n), the declared passes timed.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "GlTestEnv.h"
#include "gl/Gl.h"

namespace sl {
namespace {

struct Rendered {
  double errorPct = -1.0;
  FrameReadback frame;
};

Rendered render(const std::string& technique, std::vector<std::pair<const char*, double>> sets) {
  auto r = test::makeRenderer("plane-box", technique);
  Rendered out;
  if (!r) return out;
  for (const auto& [k, v] : sets) EXPECT_FALSE(r->params().set(k, v)) << k;
  EXPECT_FALSE(r->renderFrame(160, 120, 0));
  out.errorPct = r->computeError().stats.errorPct;
  out.frame = r->readback();
  test::expectNoGlErrors(*r);
  return out;
}

// 4 x 4 tiles of 128² = a 512² virtual map: the uniform 512² map's fit cut in 16, each tile
// with its own bias scale (the same texel size) — the hard masks agree but for a few pixels
// where the normal offset crosses a tile edge. Measured (llvmpipe, 160x120): see the printout.
TEST(VirtualTiled, MatchesUniformAtTheSameVirtualResolution) {
  const Rendered tiled = render("virtual-tiled", {{"tiles", 4}, {"tile.resolution", 128}});
  const Rendered uniform = render("uniform", {{"resolution", 512}});
  const Rendered coarse = render("uniform", {{"resolution", 128}});
  ASSERT_EQ(tiled.frame.hardMask.size(), uniform.frame.hardMask.size());
  std::size_t covered = 0, differ = 0, empty = 0, mPixels = 0, mClose = 0;
  std::set<int> maps;
  for (std::size_t i = 0; i < tiled.frame.hardMask.size(); ++i) {
    if (uniform.frame.hardMask[i] == SL_MASK_EMPTY) {
      EXPECT_EQ(tiled.frame.hardMask[i], SL_MASK_EMPTY);
      continue;
    }
    ++covered;
    if (tiled.frame.hardMask[i] == SL_MASK_EMPTY) ++empty;
    if (tiled.frame.hardMask[i] != uniform.frame.hardMask[i]) ++differ;
    maps.insert(tiled.frame.mapIndex[i]);
    // m of the tile's texel coordinate: the tile texels are the uniform map's texels.
    if (uniform.frame.aliasing[i] > 0.0f && tiled.frame.aliasing[i] > 0.0f) {
      ++mPixels;
      if (std::abs(tiled.frame.aliasing[i] / uniform.frame.aliasing[i] - 1.0f) <= 0.05f) ++mClose;
    }
  }
  std::printf(
      "plane-box 160x120: virtual-tiled 4x4x128^2 %.3f %%, uniform 512^2 %.3f %%, "
      "uniform 128^2 %.3f %%, %zu of %zu pixels differ from uniform 512^2\n",
      tiled.errorPct, uniform.errorPct, coarse.errorPct, differ, covered);
  // m: finite differences of the unoffset receiver's full-map uv in a compute pass against
  // the resolve pass's dFdx/dFdy of the offset one; they part at silhouettes (measured: 35 of
  // 18544 pixels beyond 5 %).
  std::printf("m within 5 %% of uniform's: %zu of %zu pixels\n", mClose, mPixels);
  EXPECT_GE(double(mClose), 0.99 * double(mPixels));
  EXPECT_GT(covered, 5000u);
  EXPECT_EQ(empty, 0u) << "every covered pixel belongs to a tile";
  EXPECT_LE(double(differ), 0.005 * double(covered));
  EXPECT_NEAR(tiled.errorPct, uniform.errorPct, 0.25);
  EXPECT_LT(tiled.errorPct, coarse.errorPct);
  EXPECT_GT(maps.size(), 3u) << "the map index is the tile";
}

// With tile.warp = lispsm the 4 x 4 tiles of 128² are the LiSPSM 512² map of `lispsm` cut
// in 16: each tile the warp's frustum cropped to its uv square (warp::uvRectCrop), so the hard
// masks agree but for the few pixels whose normal offset crosses a tile edge, as unwarped.
TEST(VirtualTiled, LispsmTilesMatchLispsmAtTheSameVirtualResolution) {
  auto lispsm = test::makeRenderer("plane-box", "lispsm");
  ASSERT_TRUE(lispsm);
  EXPECT_FALSE(lispsm->params().set("resolution", 512));
  lispsm->requestPublications({"warp.fallback"});
  ASSERT_FALSE(lispsm->renderFrame(160, 120, 0));
  ASSERT_EQ(lispsm->publication().numbers.at("warp.fallback"), 0.0) << "the warp is used";
  const FrameReadback warped = lispsm->readback();
  const double warpedError = lispsm->computeError().stats.errorPct;
  const Rendered tiled =
      render("virtual-tiled", {{"tiles", 4}, {"tile.resolution", 128}, {"tile.warp", 1}});
  const Rendered unwarped = render("virtual-tiled", {{"tiles", 4}, {"tile.resolution", 128}});
  ASSERT_EQ(tiled.frame.hardMask.size(), warped.hardMask.size());
  std::size_t covered = 0, differ = 0, differUnwarped = 0, mPixels = 0, mClose = 0;
  for (std::size_t i = 0; i < warped.hardMask.size(); ++i) {
    if (warped.hardMask[i] == SL_MASK_EMPTY) continue;
    ++covered;
    if (tiled.frame.hardMask[i] != warped.hardMask[i]) ++differ;
    if (unwarped.frame.hardMask[i] != warped.hardMask[i]) ++differUnwarped;
    if (warped.aliasing[i] > 0.0f && tiled.frame.aliasing[i] > 0.0f) {
      ++mPixels;
      if (std::abs(tiled.frame.aliasing[i] / warped.aliasing[i] - 1.0f) <= 0.05f) ++mClose;
    }
  }
  std::printf(
      "plane-box 160x120: virtual-tiled 4x4x128^2 LiSPSM %.3f %% (unwarped %.3f %%), lispsm "
      "512^2 %.3f %%; %zu of %zu pixels differ from lispsm (unwarped tiles: %zu); m within 5 "
      "%%: %zu of %zu\n",
      tiled.errorPct, unwarped.errorPct, warpedError, differ, covered, differUnwarped, mClose,
      mPixels);
  EXPECT_GT(covered, 5000u);
  EXPECT_LE(double(differ), 0.005 * double(covered));
  EXPECT_LT(differ, differUnwarped) << "the warp is what makes the tiles lispsm's";
  EXPECT_GE(double(mClose), 0.99 * double(mPixels));
  EXPECT_NEAR(tiled.errorPct, warpedError, 0.25);
}

// memory() lists the one tile texture (tile.resolution² depths, whatever the tile count) and
// the eye-space depth buffer (one float per pixel).
TEST(VirtualTiled, MemoryIsOneTile) {
  auto r = test::makeRenderer("plane-box", "uniform");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->renderFrame(80, 60, 0));
  const std::uint64_t before = gl::allocatedBytes() - r->stats().memory.bytes();
  ASSERT_FALSE(r->setTechnique("virtual-tiled"));
  for (auto [tiles, res] : {std::pair{2, 256}, {3, 64}, {5, 64}}) {
    SCOPED_TRACE(tiles);
    ASSERT_FALSE(r->params().set("tiles", tiles));
    ASSERT_FALSE(r->params().set("tile.resolution", res));
    ASSERT_FALSE(r->renderFrame(80, 60, 0));
    const MemoryStats& m = r->stats().memory;
    EXPECT_EQ(m.bytes(), gl::allocatedBytes() - before) << "memory() must list every byte";
    EXPECT_EQ(m.bytes(), 4ull * std::uint64_t(res) * std::uint64_t(res) + 4ull * 80 * 60);
  }
  test::expectNoGlErrors(*r);
}

// The tiles run inside the renderer's resolve (PassDecl::duringResolve): every declared pass
// is timed, in the declared order.
TEST(VirtualTiled, DeclaredPassesAreTimed) {
  auto r = test::makeRenderer("plane-box", "virtual-tiled");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->params().set("tiles", 2));
  ASSERT_FALSE(r->params().set("tile.resolution", 64));
  ASSERT_FALSE(r->renderFrame(80, 60, 0));
  std::vector<std::string> declared;
  const TechniqueInfo* info = Renderer::findTechnique("virtual-tiled");
  ASSERT_TRUE(info);
  for (const PassDecl& p : framePassDecls(*info)) declared.push_back(p.id);
  test::expectDeclaredPassesOpened(r->stats(), declared);
  const std::vector<std::string>& opened = r->stats().passOrder;
  EXPECT_NE(std::find(opened.begin(), opened.end(), "tile depth"), opened.end());
  ASSERT_GE(opened.size(), 2u);
  EXPECT_EQ(opened[1], "eye depth") << "the eye-space depth buffer right after the G-buffer";
  // A bad value is refused with the range.
  auto err = r->params().set("tiles", 0);
  ASSERT_TRUE(err);
  EXPECT_NE(err->find("tiles"), std::string::npos) << *err;
}

// Per-tile times (virtual_tiled.tile_ms): one (depth, apply) pair per tile, n² of them, from
// the very scopes the passes "tile depth" and "tile apply" sum — so the curve sums to those
// passes within float rounding (the curve holds floats: 1e-4 ms plus 1e-5 relative).
TEST(VirtualTiled, PublishesEachTilesTimes) {
  auto r = test::makeRenderer("plane-box", "virtual-tiled");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->params().set("tiles", 3));
  ASSERT_FALSE(r->params().set("tile.resolution", 64));
  r->requestPublications({"virtual_tiled.tile_ms"});
  // Timer queries: the times arrive a frame late, read without waiting, so the first frame
  // is finished before the second reads them.
  for (int f = 0; f < 2; ++f) {
    glFinish();
    ASSERT_FALSE(r->renderFrame(80, 60, 0));
  }
  ASSERT_TRUE(r->publication().curves.count("virtual_tiled.tile_ms"));
  const std::vector<float>& c = r->publication().curves.at("virtual_tiled.tile_ms");
  ASSERT_EQ(c.size(), 2u * 9u) << "a (depth, apply) pair per tile";
  double depth = 0.0, apply = 0.0;
  for (std::size_t k = 0; k < 9; ++k) {
    EXPECT_GE(c[2 * k], 0.0f);
    EXPECT_GE(c[2 * k + 1], 0.0f);
    depth += c[2 * k];
    apply += c[2 * k + 1];
  }
  const double passDepth = r->stats().passMs("tile depth"),
               passApply = r->stats().passMs("tile apply");
  std::printf(
      "virtual-tiled 3x3x64^2, 80x60: tiles' depth %.3f ms (pass %.3f), apply %.3f ms (pass "
      "%.3f)\n",
      depth, passDepth, apply, passApply);
  EXPECT_GT(passDepth, 0.0);
  EXPECT_NEAR(depth, passDepth, 1e-4 + 1e-5 * passDepth);
  EXPECT_NEAR(apply, passApply, 1e-4 + 1e-5 * passApply);
  test::expectNoGlErrors(*r);
}

// The grouping itself (core/FrameStats tileTimingCurve), exact: depth scopes add up until the
// next apply scope closes the tile; other passes are skipped; trailing depth (a tile not yet
// applied: a progressive call's last bands) is not listed.
TEST(VirtualTiled, TileTimingCurveGroupsDepthScopesUntilEachApply) {
  const std::vector<PassTiming> seq = {
      {"gbuffer", 9.0},    {"eye depth", 1.0},  {"resolve", 0.5},     {"tile depth", 2.0},
      {"tile depth", 3.0}, {"tile apply", 4.0}, {"tile apply", 0.25}, {"tile depth", 6.0},
      {"fallback", 7.0},   {"tile apply", 8.0}, {"tile depth", 5.0}};
  EXPECT_EQ(tileTimingCurve(seq, "tile depth", "tile apply"),
            (std::vector<float>{5.0f, 4.0f, 0.0f, 0.25f, 6.0f, 8.0f}));
  EXPECT_TRUE(tileTimingCurve({}, "tile depth", "tile apply").empty());
}

// Progressive resolve (Renderer::setProgressiveBudget, the GUI's continuous rendering): a
// budget of ~0 ms does one tile per call; the targets keep the earlier calls' tiles, so once
// all 16 are done the frame equals the one-call frame pixel for pixel (every target, the
// colour, the error). Partial frames say how far they are; a camera move restarts at tile 1;
// budget 0 renders complete frames again.
TEST(VirtualTiled, ProgressiveThenCompleteEqualsOneCall) {
  auto r = test::makeRenderer("plane-box", "virtual-tiled");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->params().set("tiles", 4));
  ASSERT_FALSE(r->params().set("tile.resolution", 128));
  ASSERT_FALSE(r->renderFrame(160, 120, 0));
  EXPECT_FALSE(r->stats().progress) << "no budget: one call, no progress";
  EXPECT_TRUE(r->stats().complete());
  const FrameReadback oneCall = r->readback();
  const double oneCallPct = r->computeError().stats.errorPct;

  // A different view first, so that the targets hold other pixels when the tiles start.
  const Camera original = r->camera();
  Camera moved = original;
  moved.orbit(30.0f, 10.0f);
  r->setCamera(moved);
  ASSERT_FALSE(r->renderFrame(160, 120, 0));
  r->setCamera(original);

  r->setProgressiveBudget(1e-6);  // one tile per call
  int calls = 0;
  std::vector<int> done;
  for (; calls < 40; ++calls) {
    ASSERT_FALSE(r->renderFrame(160, 120, 0));
    const auto& p = r->stats().progress;
    ASSERT_TRUE(p);
    EXPECT_EQ(p->total, 16);
    done.push_back(p->done);
    if (p->shownComplete) break;
    EXPECT_FALSE(r->stats().complete());
  }
  ASSERT_EQ(done.size(), 16u) << "one tile per call";
  for (int i = 0; i < 16; ++i) EXPECT_EQ(done[std::size_t(i)], i + 1);
  EXPECT_TRUE(r->stats().progress->completedNow);
  EXPECT_TRUE(r->stats().complete());
  const FrameReadback progressive = r->readback();
  EXPECT_EQ(progressive.hardMask, oneCall.hardMask);
  EXPECT_EQ(progressive.aliasing, oneCall.aliasing);
  EXPECT_EQ(progressive.texel, oneCall.texel);
  EXPECT_EQ(progressive.mapIndex, oneCall.mapIndex);
  EXPECT_EQ(progressive.color.pixels, oneCall.color.pixels);
  EXPECT_EQ(r->computeError().stats.errorPct, oneCallPct);

  // The same view again: refreshed in place, the shown frame stays complete and equal.
  ASSERT_FALSE(r->renderFrame(160, 120, 0));
  EXPECT_EQ(r->stats().progress->done, 1);
  EXPECT_TRUE(r->stats().complete());
  EXPECT_EQ(r->readback().hardMask, oneCall.hardMask);

  // A camera move restarts: partial again, from the first tile.
  r->setCamera(moved);
  ASSERT_FALSE(r->renderFrame(160, 120, 0));
  EXPECT_EQ(r->stats().progress->done, 1);
  EXPECT_FALSE(r->stats().complete());
  // A large budget finishes the rest in one call; budget 0: complete frames, no progress.
  r->setProgressiveBudget(1e9);
  ASSERT_FALSE(r->renderFrame(160, 120, 0));
  EXPECT_EQ(r->stats().progress->done, 16);
  EXPECT_TRUE(r->stats().complete());
  r->setProgressiveBudget(0.0);
  ASSERT_FALSE(r->renderFrame(160, 120, 0));
  EXPECT_FALSE(r->stats().progress);
  test::expectNoGlErrors(*r);
}

// A tile of 1024 rows resolves progressively in two bands of 512 (kProgressiveBandRows): one
// unit per call, the note's tiles are units / 2, the complete frame is the one-call frame.
// With the outside view on (a one-call resolve reusing the tile texture after the main one),
// a tile interrupted mid-way starts again at its first band and is finished in that call, so
// the frame still completes and is still equal.
TEST(VirtualTiled, ProgressiveBandsThenCompleteEqualsOneCall) {
  for (const bool outside : {false, true}) {
    SCOPED_TRACE(outside ? "outside view on" : "outside view off");
    auto r = test::makeRenderer("plane-box", "virtual-tiled");
    ASSERT_TRUE(r);
    ASSERT_FALSE(r->params().set("tiles", 2));
    ASSERT_FALSE(r->params().set("tile.resolution", 1024));
    ASSERT_FALSE(r->rendererParams().setFromString("view.outside", outside ? "on" : "off"));
    ASSERT_FALSE(r->renderFrame(160, 120, 0));
    const FrameReadback oneCall = r->readback();
    const double oneCallPct = r->computeError().stats.errorPct;
    ASSERT_GT(oneCallPct, 0.0);

    r->setProgressiveBudget(1e-6);  // one unit per call (a whole tile after a restart)
    std::vector<int> done;
    for (int calls = 0; calls < 40; ++calls) {
      ASSERT_FALSE(r->renderFrame(160, 120, 0));
      const auto& p = r->stats().progress;
      ASSERT_TRUE(p);
      EXPECT_EQ(p->total, 8);
      EXPECT_EQ(p->unitsPerTile, 2);
      done.push_back(p->done);
      if (p->shownComplete) break;
    }
    const std::vector<int> expected = {1, 2, 3, 4, 5, 6, 7, 8};
    EXPECT_EQ(done, expected) << "one band per call, or the rest of a restarted tile";
    ASSERT_TRUE(r->stats().complete());
    const FrameReadback progressive = r->readback();
    EXPECT_EQ(progressive.hardMask, oneCall.hardMask);
    EXPECT_EQ(progressive.aliasing, oneCall.aliasing);
    EXPECT_EQ(progressive.texel, oneCall.texel);
    EXPECT_EQ(progressive.color.pixels, oneCall.color.pixels);
    EXPECT_EQ(r->computeError().stats.errorPct, oneCallPct);
    test::expectNoGlErrors(*r);
  }
}

// A technique that resolves in one call ignores the budget: complete frames, no progress.
TEST(VirtualTiled, ProgressiveBudgetLeavesOtherTechniquesWhole) {
  auto r = test::makeRenderer("plane-box", "uniform");
  ASSERT_TRUE(r);
  r->setProgressiveBudget(1e-6);
  ASSERT_FALSE(r->renderFrame(80, 60, 0));
  EXPECT_FALSE(r->stats().progress);
  EXPECT_TRUE(r->stats().complete());
}

}  // namespace
}  // namespace sl
