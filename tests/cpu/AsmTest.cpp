// algo/asm (adaptive shadow maps, Fernando et al. 2001): the refine key, edge finding on a
// hand-made shadow image, the page cache's coarse map, refinement iterations that stop,
// budget, cache hits, least-recently-used eviction and invalidation, the Pages panel's states of
// the cache; the paper's edge test (a texel on a shadow edge of the map) and the terminator it
// does not refine. Exact expectations.
#include <gtest/gtest.h>

#include <stdexcept>

#include "algo/asm/AdaptivePages.h"
#include "algo/pages/PageRequests.h"
#include "algo/pages/PageViews.h"

namespace sl::adaptive {
namespace {

using pages::kNoPage;
using pages::packPage;

// 1024² virtual texels in 128² pages: 8, 4, 2, 1 pages per side on levels 0..3.
const pages::VirtualLayout kSmall{.virtualResolution = 1024, .pageSize = 128};

TEST(AsmRefineKey, OnlyWhenTheServingPageIsCoarserThanTheLod) {
  // st (0.3, 0.6) at level 1 (4 pages a side): page (1, 2).
  EXPECT_EQ(refineKey({0.3f, 0.6f}, 1, 3, kSmall), packPage({1, 1, 2}));
  EXPECT_EQ(refineKey({0.3f, 0.6f}, 0, 1, kSmall), packPage({0, 2, 4}));
  EXPECT_EQ(refineKey({0.3f, 0.6f}, 1, 1, kSmall), kNoPage);  // fine enough already
  EXPECT_EQ(refineKey({0.3f, 0.6f}, 2, 1, kSmall), kNoPage);
  EXPECT_EQ(refineKey({1.5f, 0.6f}, 0, 3, kSmall), kNoPage);  // outside the map
}

// The paper's edge test (Fernando et al. 2001) on an 8² map: the left half holds an occluder
// at depth 0.3, the right half the receiver plane itself. A receiver at depth 0.5 is on a
// shadow edge of the map only at the two texel columns where the occluder ends.
TEST(AsmMapEdges, TexelOnAShadowEdgeOfTheMap) {
  std::vector<float> depth(64);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) depth[std::size_t(y * 8 + x)] = x < 4 ? 0.3f : 0.5f;
  const DepthGrid map{depth, 8};
  auto edgeAt = [&](int x, float bias) {
    MapReceiver r;
    r.uv = {(float(x) + 0.5f) / 8.0f, 0.5f};
    r.z = 0.5f;
    r.bias = bias;
    return mapTexelOnShadowEdge(map, r);
  };
  const bool want[8] = {false, false, false, true, true, false, false, false};
  for (int x = 0; x < 8; ++x) EXPECT_EQ(edgeAt(x, 0.0f), want[x]) << "texel " << x;
  // A receiver in front of the occluder sees no shadow, so no edge either.
  for (int x = 0; x < 8; ++x) EXPECT_FALSE(edgeAt(x, 0.25f)) << "texel " << x;
  // The neighbours are clamped to the map at its border.
  MapReceiver corner;
  corner.uv = {0.0f, 0.0f};
  corner.z = 0.5f;
  EXPECT_FALSE(mapTexelOnShadowEdge(map, corner));
  EXPECT_THROW(mapTexelOnShadowEdge({depth, 7}, corner), std::invalid_argument);
  EXPECT_THROW(mapTexelOnShadowEdge({{}, 0}, corner), std::invalid_argument);
}

// A terminator: one tilted surface, unoccluded, whose right half faces away from the light
// (the resolve counts those pixels shadowed). The screen-mask test refines along the
// terminator; the paper's test, which compares depths in the map only, requests nothing.
TEST(AsmMapEdges, ATerminatorIsNoEdgeOfTheMap) {
  const int n = 16;
  std::vector<float> depth(std::size_t(n * n));
  auto plane = [](glm::vec2 uv) { return 0.4f + 0.2f * uv.x + 0.05f * uv.y; };
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      depth[std::size_t(y * n + x)] = plane((glm::vec2(x, y) + 0.5f) / float(n));
  const DepthGrid map{depth, n};
  const int w = 8, h = 4;
  std::vector<TestedPixel> px(std::size_t(w * h));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      MapReceiver r;
      r.uv = {(float(x) + 0.3f) / float(w), (float(y) + 0.6f) / float(h)};
      r.z = plane(r.uv);
      r.gradient = {0.2f, 0.05f};
      r.bias = 1e-5f;
      TestedPixel& p = px[std::size_t(y * w + x)];
      p.mask = x < w / 2 ? SL_MASK_LIT : SL_MASK_SHADOWED;  // back-facing on the right
      p.served = packPage({3, 0, 0});
      p.refine = packPage({0, x, y});
      p.mapEdge = mapTexelOnShadowEdge(map, r) ? 1u : 0u;
      EXPECT_EQ(p.mapEdge, 0u) << x << ", " << y;
    }
  int screenRequests = 0;
  for (PageKey k : findEdges(px, w, h, EdgeTest::ScreenMask))
    screenRequests += k != kNoPage && (k & kTouchBit) == 0;
  EXPECT_EQ(screenRequests, 2 * h);  // the two columns either side of the terminator
  for (PageKey k : findEdges(px, w, h, EdgeTest::MapTexel))
    EXPECT_EQ(k, packPage({3, 0, 0}) | kTouchBit);
}

// With EdgeTest::MapTexel only mapEdge counts, not the masks of the neighbours.
TEST(AsmMapEdges, FindEdgesReadsTheMapEdgeFlag) {
  std::vector<TestedPixel> px(3);
  for (int i = 0; i < 3; ++i)
    px[std::size_t(i)] = {SL_MASK_LIT, packPage({3, 0, 0}), packPage({0, i, 0}), 0u};
  px[1].mapEdge = 1u;
  px[2].mask = SL_MASK_SHADOWED;
  const PageKey touch = packPage({3, 0, 0}) | kTouchBit;
  EXPECT_EQ(findEdges(px, 3, 1, EdgeTest::MapTexel),
            (std::vector<PageKey>{touch, packPage({0, 1, 0}), touch}));
  EXPECT_EQ(findEdges(px, 3, 1, EdgeTest::ScreenMask),
            (std::vector<PageKey>{touch, packPage({0, 1, 0}), packPage({0, 2, 0})}));
}

// A 4 x 3 image (row 0 at the bottom): lit on the left, shadowed on the right, one empty
// pixel. Edge pixels are those with a covered 4-neighbour of the other mask.
TEST(AsmEdges, HandMadeShadowImage) {
  constexpr std::uint32_t L = SL_MASK_LIT, S = SL_MASK_SHADOWED, E = SL_MASK_EMPTY;
  const std::uint32_t masks[12] = {L, L, S, S,   // y = 0
                                   L, L, S, E,   // y = 1
                                   L, L, L, S};  // y = 2
  std::vector<TestedPixel> px(12);
  for (int i = 0; i < 12; ++i) {
    px[std::size_t(i)].mask = masks[i];
    if (masks[i] != E) {
      px[std::size_t(i)].served = packPage({3, 0, 0});
      px[std::size_t(i)].refine = packPage({0, i % 4, i / 4});
    }
  }
  px[1].refine = kNoPage;  // an edge pixel whose page is fine enough: touches instead
  const std::vector<PageKey> k = findEdges(px, 4, 3);
  const PageKey touch = packPage({3, 0, 0}) | kTouchBit;
  const std::vector<PageKey> want = {touch,
                                     touch,
                                     packPage({0, 2, 0}),
                                     touch,  // y = 0
                                     touch,
                                     packPage({0, 1, 1}),
                                     packPage({0, 2, 1}),
                                     kNoPage,  // y = 1
                                     touch,
                                     touch,
                                     packPage({0, 2, 2}),
                                     packPage({0, 3, 2})};  // y = 2
  EXPECT_EQ(k, want);
  // (1, 0): lit with a shadowed right neighbour, but no refine key -> touch. (3, 0): shadowed,
  // neighbours (2, 0) shadowed, (3, 1) empty -> no edge. (2, 2) lit above shadowed (2, 1).
  EXPECT_THROW(findEdges(px, 4, 4), std::invalid_argument);
}

// A uniform image has no edge: only touches.
TEST(AsmEdges, NoEdgeNoRequest) {
  std::vector<TestedPixel> px(
      6, TestedPixel{SL_MASK_SHADOWED, packPage({2, 1, 1}), packPage({0, 0, 0})});
  for (PageKey k : findEdges(px, 3, 2)) EXPECT_EQ(k, packPage({2, 1, 1}) | kTouchBit);
}

TEST(AsmCache, CoarseMapFirstAndBadArguments) {
  EXPECT_THROW(PageCache(kSmall, 3, 2), std::invalid_argument);  // 4 coarse pages
  EXPECT_THROW(PageCache(kSmall, 8, 4), std::invalid_argument);  // no level 4
  try {
    PageCache(kSmall, 3, 2);
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "asm: pool.pages = 3 cannot hold the 4 pages of the coarse map; raise "
                 "pool.pages or lower asm.coarse.resolution");
  }
  PageCache c(kSmall, 8, 2);
  std::vector<int> slots;
  const std::vector<PageId> coarse = c.invalidate(slots);
  EXPECT_EQ(coarse, (std::vector<PageId>{{2, 0, 0}, {2, 1, 0}, {2, 0, 1}, {2, 1, 1}}));
  EXPECT_EQ(slots, (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(c.pool().usedCount(), 4);
  EXPECT_EQ(c.table().resolve({0, 5, 6}).page, (PageId{2, 1, 1}));
  EXPECT_EQ(c.invalidations(), 1);
}

// Iterations: requests allocate, coarsest first; the same keys again allocate nothing (the loop
// stops); touches count hits in a later frame; the budget defers the rest.
TEST(AsmCache, RefineStopsAndCountsHits) {
  PageCache c(kSmall, 8, 2);
  std::vector<int> slots;
  c.invalidate(slots);
  c.beginFrame();
  const std::vector<PageKey> keys = pages::sortUnique(std::vector<PageKey>{
      packPage({0, 1, 1}), packPage({1, 3, 3}), packPage({2, 0, 0}) | kTouchBit});
  Refinement r = c.refine(keys, 10);
  EXPECT_EQ(r.requests, 2);
  EXPECT_EQ(r.allocated, (std::vector<PageId>{{1, 3, 3}, {0, 1, 1}}));  // coarsest first
  EXPECT_EQ(r.slots, (std::vector<int>{4, 5}));
  EXPECT_EQ(r.hits, 1);  // the coarse page (2, 0, 0) was allocated in frame 0
  EXPECT_EQ(c.table().resolve({0, 1, 1}).slot, 5);
  // Iteration 2 of the same frame: the pages are there, nothing new -> the loop stops.
  r = c.refine(keys, 10);
  EXPECT_TRUE(r.allocated.empty());
  EXPECT_EQ(r.alreadyCached, 2);
  EXPECT_EQ(r.hits, 0);  // allocated or touched in this frame already
  // Next frame: the cached pages are hits.
  c.beginFrame();
  r = c.refine(
      std::vector<PageKey>{packPage({0, 1, 1}) | kTouchBit, packPage({1, 3, 3}) | kTouchBit}, 10);
  EXPECT_EQ(r.hits, 2);
  EXPECT_EQ(c.lastUsed(5), 2);
  EXPECT_EQ(c.allocatedIn(5), 1);
  // Budget: 3 requests, 1 allowed.
  r = c.refine(pages::sortUnique(std::vector<PageKey>{packPage({0, 4, 4}), packPage({0, 5, 4}),
                                                      packPage({0, 6, 4})}),
               1);
  EXPECT_EQ(r.allocated, (std::vector<PageId>{{0, 4, 4}}));
  EXPECT_EQ(r.deferred, 2);
}

// asm.render = superpages (the lecture's loop: "allocate new page in quadtree, bin requests
// into superpages, render shadow data into superpages, copy"): what an iteration bins is what it
// allocated, each new page in exactly one superpage, the block of its level holding it; pages
// cached by an earlier iteration are not binned again, so a superpage can hold only some of
// its block's pages.
TEST(AsmCache, SuperpagesBinOnlyTheNewPagesOfAnIteration) {
  // 4096² in 128² pages: 32, 16, 8, 4, 2, 1 pages a side; a 1024² superpage is 8 x 8 pages.
  const pages::VirtualLayout layout{.virtualResolution = 4096, .pageSize = 128};
  PageCache c(layout, 64, 3);  // coarse level 3: 4 x 4 pages
  std::vector<int> slots;
  EXPECT_EQ(c.invalidate(slots).size(), 16u);
  c.beginFrame();
  // Iteration 1: two pages of level 0 in different blocks, one of level 1, one touch.
  std::vector<PageKey> keys =
      pages::sortUnique(std::vector<PageKey>{packPage({0, 1, 1}), packPage({0, 9, 2}),
                                             packPage({1, 3, 0}), packPage({3, 0, 0}) | kTouchBit});
  Refinement r = c.refine(keys, 100);
  ASSERT_EQ(r.allocated.size(), 3u);
  std::vector<pages::Superpage> bins = pages::binSuperpages(r.allocated, layout, 1024);
  ASSERT_EQ(bins.size(), 3u);  // level 0 blocks (0, 0) and (1, 0); level 1 block (0, 0)
  int binned = 0;
  for (const pages::Superpage& s : bins) {
    EXPECT_EQ(s.pagesPerSide, 8);
    for (const PageId& p : s.pages) {
      ++binned;
      EXPECT_EQ(p.level, s.level);
      EXPECT_EQ(p.x / 8, s.x);
      EXPECT_EQ(p.y / 8, s.y);
      EXPECT_GE(c.table().slot(p), 16);  // allocated, past the coarse map's slots
    }
  }
  EXPECT_EQ(binned, 3);
  // Iteration 2: the same pages again (now cached) plus one new page in iteration 1's first
  // block: only the new page is binned, alone in that block's superpage.
  keys = pages::sortUnique(std::vector<PageKey>{packPage({0, 1, 1}), packPage({0, 9, 2}),
                                                packPage({1, 3, 0}), packPage({0, 2, 1})});
  r = c.refine(keys, 100);
  EXPECT_EQ(r.alreadyCached, 3);
  ASSERT_EQ(r.allocated, (std::vector<PageId>{{0, 2, 1}}));
  bins = pages::binSuperpages(r.allocated, layout, 1024);
  ASSERT_EQ(bins.size(), 1u);
  EXPECT_EQ((PageId{bins[0].level, bins[0].x, bins[0].y}), (PageId{0, 0, 0}));
  EXPECT_EQ(bins[0].pages, (std::vector<PageId>{{0, 2, 1}}));
  // Nothing new: nothing to bin, and the loop stops.
  r = c.refine(keys, 100);
  EXPECT_TRUE(r.allocated.empty());
  EXPECT_TRUE(pages::binSuperpages(r.allocated, layout, 1024).empty());
}

// A full pool evicts the least recently used page not used this frame (never the coarse map),
// lowest slot among equals; when every page was used this frame the request is refused.
TEST(AsmCache, EvictsLeastRecentlyUsedAndRefusesWhenAllInUse) {
  PageCache c(kSmall, 6, 2);  // 4 coarse + 2 pages
  std::vector<int> slots;
  c.invalidate(slots);
  c.beginFrame();                                          // frame 1
  c.refine(std::vector<PageKey>{packPage({0, 0, 0})}, 8);  // slot 4
  c.beginFrame();                                          // frame 2
  c.refine(std::vector<PageKey>{packPage({0, 7, 7})}, 8);  // slot 5
  c.beginFrame();                                          // frame 3
  Refinement r = c.refine(std::vector<PageKey>{packPage({1, 2, 2})}, 8);
  EXPECT_EQ(r.evicted, 1);
  EXPECT_EQ(c.evictedThisFrame(), (std::vector<PageId>{{0, 0, 0}}));  // used in frame 1
  EXPECT_EQ(r.slots, (std::vector<int>{4}));
  EXPECT_EQ(c.table().slot({0, 0, 0}), -1);
  EXPECT_EQ(c.table().resolve({0, 0, 0}).page, (PageId{2, 0, 0}));  // falls back to coarse
  // Slot 5 touched this frame: a new request finds nothing to evict.
  r = c.refine(
      pages::sortUnique(std::vector<PageKey>{packPage({0, 7, 7}) | kTouchBit, packPage({0, 3, 3})}),
      8);
  EXPECT_EQ(r.refused, 1);
  EXPECT_TRUE(r.allocated.empty());
  EXPECT_EQ(c.pool().usedCount(), 6);
  EXPECT_THROW(c.refine(std::vector<PageKey>{packPage({0, 8, 0})}, 8), std::invalid_argument);
}

// Invalidation (the light or the geometry moved): every page dropped, the coarse map again.
TEST(AsmCache, InvalidateDropsEveryPage) {
  PageCache c(kSmall, 8, 2);
  std::vector<int> slots;
  c.invalidate(slots);
  c.beginFrame();
  c.refine(std::vector<PageKey>{packPage({0, 2, 2}), packPage({1, 0, 1})}, 8);
  EXPECT_EQ(c.pool().usedCount(), 6);
  c.beginFrame();
  const std::vector<PageId> again = c.invalidate(slots);
  EXPECT_EQ(again.size(), 4u);
  EXPECT_EQ(c.pool().usedCount(), 4);
  EXPECT_EQ(c.table().slot({0, 2, 2}), -1);
  EXPECT_EQ(c.table().resolve({0, 2, 2}).page, (PageId{2, 0, 0}));
  EXPECT_EQ(c.invalidations(), 2);
  EXPECT_EQ(c.lastUsed(5), -1);
}

// The Pages panel's view of the cache, per level and frame: new this frame, kept and used (a
// hit), kept and unused, evicted this frame, requested but refused; the pool's slot levels.
TEST(AsmCache, PanelStatesPerLevel) {
  using pages::PageState;
  auto grid = [](int n, PageState fill, std::vector<std::pair<PageId, PageState>> cells) {
    std::vector<float> g(std::size_t(n) * std::size_t(n), float(fill));
    for (const auto& [p, s] : cells)
      g[std::size_t(p.y) * std::size_t(n) + std::size_t(p.x)] = float(s);
    return g;
  };
  const std::vector<PageKey> none;
  PageCache c(kSmall, 6, 2);  // 4 coarse pages (level 2: 2 x 2) + 2
  std::vector<int> slots;
  c.invalidate(slots);  // frame 0: the coarse map is new
  EXPECT_EQ(cacheLevelStates(c, none, 2), grid(2, PageState::New, {}));
  EXPECT_EQ(cacheLevelStates(c, none, 0), grid(8, PageState::Empty, {}));

  c.beginFrame();  // frame 1: one page; the coarse pages untouched
  std::vector<PageKey> req{packPage({0, 0, 0})};
  c.refine(req, 8);
  EXPECT_EQ(cacheLevelStates(c, req, 0), grid(8, PageState::Empty, {{{0, 0, 0}, PageState::New}}));
  EXPECT_EQ(cacheLevelStates(c, req, 2), grid(2, PageState::CachedIdle, {}));

  c.beginFrame();  // frame 2: another page, a coarse page touched
  c.refine(
      pages::sortUnique(std::vector<PageKey>{packPage({0, 7, 7}), packPage({2, 1, 0}) | kTouchBit}),
      8);
  EXPECT_EQ(
      cacheLevelStates(c, std::vector<PageKey>{packPage({0, 7, 7})}, 0),
      grid(8, PageState::Empty, {{{0, 0, 0}, PageState::CachedIdle}, {{0, 7, 7}, PageState::New}}));
  EXPECT_EQ(cacheLevelStates(c, none, 2),
            grid(2, PageState::CachedIdle, {{{2, 1, 0}, PageState::CachedHit}}));

  c.beginFrame();  // frame 3: (1, 2, 2) evicts (0, 0, 0); (0, 3, 3) refused (all in use)
  c.refine(std::vector<PageKey>{packPage({1, 2, 2})}, 8);
  c.refine(
      pages::sortUnique(std::vector<PageKey>{packPage({0, 7, 7}) | kTouchBit, packPage({0, 3, 3})}),
      8);
  req = pages::sortUnique(std::vector<PageKey>{packPage({1, 2, 2}), packPage({0, 3, 3})});
  EXPECT_EQ(cacheLevelStates(c, req, 0), grid(8, PageState::Empty,
                                              {{{0, 0, 0}, PageState::Evicted},
                                               {{0, 7, 7}, PageState::CachedHit},
                                               {{0, 3, 3}, PageState::Pending}}));
  EXPECT_EQ(cacheLevelStates(c, req, 1), grid(4, PageState::Empty, {{{1, 2, 2}, PageState::New}}));
  EXPECT_EQ(cacheLevelStates(c, req, 2), grid(2, PageState::CachedIdle, {}));
  EXPECT_EQ(cachePoolLevels(c), (std::vector<float>{2, 2, 2, 2, 1, 0}));

  c.beginFrame();  // frame 4: nothing evicted any more
  EXPECT_TRUE(c.evictedThisFrame().empty());
  EXPECT_EQ(cacheLevelStates(c, none, 0),
            grid(8, PageState::Empty, {{{0, 7, 7}, PageState::CachedIdle}}));
}

}  // namespace
}  // namespace sl::adaptive
