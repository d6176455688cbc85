// algo/pages: the virtual map's layout and keys, the pool's free list, the page table's mip
// chain and fallback, allocation (including the pool running out: coarser pages, counted),
// per-pixel requests and their LOD, dedup, compaction, sort + unique, superpage binning.
// Exact expectations throughout.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "algo/pages/PageRequests.h"
#include "algo/pages/PageViews.h"
#include "algo/pages/VirtualPages.h"

namespace sl::pages {
namespace {

// 1024² virtual texels in 128² pages: 8, 4, 2, 1 pages per side on levels 0..3.
const VirtualLayout kSmall{.virtualResolution = 1024, .pageSize = 128};

PageKey key(int level, int x, int y) {
  return packPage(PageId{level, x, y});
}

// Four level-0 pages in a row and one level-1 page: too many for a pool of 3 (the
// exhaustion tests).
std::vector<PageKey> fiveRequests() {
  return {key(0, 0, 0), key(0, 1, 0), key(0, 2, 0), key(0, 3, 0), key(1, 3, 3)};
}

TEST(Pages, KeysPackLevelRowColumnAndSortThatWay) {
  EXPECT_EQ(key(2, 3, 1), (2u << 26) | (1u << 13) | 3u);
  EXPECT_EQ(unpackPage(key(5, 8191, 17)), (PageId{5, 8191, 17}));
  EXPECT_LT(key(0, 7, 0), key(0, 0, 1));  // row before column
  EXPECT_LT(key(0, 7, 7), key(1, 0, 0));  // level first
  EXPECT_EQ(parentPage(PageId{0, 5, 6}), (PageId{1, 2, 3}));
}

TEST(Pages, LayoutLevelsAndValidation) {
  EXPECT_EQ(kSmall.validate(), "");
  EXPECT_EQ(kSmall.levels(), 4);
  EXPECT_EQ(kSmall.topLevel(), 3);
  EXPECT_EQ(kSmall.pagesPerSide(0), 8);
  EXPECT_EQ(kSmall.pagesPerSide(3), 1);
  EXPECT_EQ(kSmall.texelScale(2), 4);
  EXPECT_EQ((VirtualLayout{65536, 128}).levels(), 10);
  EXPECT_EQ((VirtualLayout{1000, 128}).validate(),
            "virtual.resolution must be a power of two of at least page.size (128), got 1000");
  EXPECT_EQ((VirtualLayout{1024, 96}).validate(),
            "page.size must be a power of two of at least 8, got 96");
  EXPECT_EQ((VirtualLayout{1 << 20, 64}).validate(),
            "virtual.resolution / page.size must be at most 8192 pages per side, got 16384");
  EXPECT_THROW(PageTable(VirtualLayout{1024, 2048}), std::invalid_argument);
}

TEST(Pages, PoolHandsOutTheLowestSlotsThenRunsOutAndReusesReleasedOnes) {
  PagePool pool(3);
  EXPECT_EQ(pool.allocate(), 0);
  EXPECT_EQ(pool.allocate(), 1);
  EXPECT_EQ(pool.allocate(), 2);
  EXPECT_EQ(pool.allocate(), std::nullopt);
  EXPECT_EQ(pool.usedCount(), 3);
  pool.release(1);
  EXPECT_EQ(pool.freeCount(), 1);
  EXPECT_THROW(pool.release(1), std::invalid_argument);
  EXPECT_THROW(pool.release(3), std::invalid_argument);
  EXPECT_EQ(pool.allocate(), 1);
  pool.releaseAll();
  EXPECT_EQ(pool.freeCount(), 3);
  EXPECT_EQ(pool.allocate(), 0);
  EXPECT_THROW(PagePool(0), std::invalid_argument);
}

TEST(Pages, PageTableFallsBackToTheFinestAllocatedAncestor) {
  PageTable table(kSmall);
  EXPECT_EQ(table.resolve(PageId{0, 4, 6}).slot, -1);  // nothing allocated
  table.set(PageId{3, 0, 0}, 0);                       // root
  table.set(PageId{0, 5, 6}, 7);
  EXPECT_EQ(table.resolve(PageId{0, 5, 6}).slot, 7);
  EXPECT_EQ(table.resolve(PageId{0, 4, 6}).page, (PageId{3, 0, 0}));
  table.set(PageId{1, 2, 3}, 2);
  const ResolvedPage r = table.resolve(PageId{0, 4, 6});
  EXPECT_EQ(r.slot, 2);
  EXPECT_EQ(r.page, (PageId{1, 2, 3}));
  EXPECT_THROW(table.slot(PageId{1, 4, 0}), std::invalid_argument);

  const std::vector<std::uint32_t> f = table.finalised();
  ASSERT_EQ(f.size(), 64u + 16u + 4u + 1u);
  EXPECT_EQ(f[6 * 8 + 4], (2u << 5) | 1u);       // level 0 (4, 6) -> slot 2, level 1
  EXPECT_EQ(f[6 * 8 + 5], (7u << 5) | 0u);       // itself
  EXPECT_EQ(f[0], (0u << 5) | 3u);               // level 0 (0, 0) -> root
  EXPECT_EQ(f[64 + 3 * 4 + 2], (2u << 5) | 1u);  // level 1 (2, 3) itself
  EXPECT_EQ(f[64 + 16 + 4], (0u << 5) | 3u);     // the root
  table.clear();
  EXPECT_EQ(table.finalised()[0], SL_PAGE_NONE);
}

TEST(Pages, AllocationPutsTheRootFirstThenCoarseToFine) {
  PagePool pool(8);
  PageTable table(kSmall);
  const std::vector<PageKey> requests = {key(0, 1, 1), key(0, 2, 1), key(1, 0, 0)};
  const Allocation a = allocatePages(requests, pool, table);
  EXPECT_EQ(a.requested, 3);
  EXPECT_EQ(a.coarsened, 0);
  EXPECT_EQ(a.coarseningSteps, 0);
  const std::vector<PageId> pages = {{3, 0, 0}, {1, 0, 0}, {0, 1, 1}, {0, 2, 1}};
  EXPECT_EQ(a.pages, pages);
  EXPECT_EQ(a.slots, (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(pool.usedCount(), 4);
  EXPECT_EQ(table.slot(PageId{0, 2, 1}), 3);
  EXPECT_EQ(table.resolve(PageId{0, 3, 3}).page, (PageId{3, 0, 0}));
  EXPECT_EQ(table.resolve(PageId{0, 1, 0}).page, (PageId{1, 0, 0}));
  // A used pool or a key outside the map is refused.
  EXPECT_THROW(allocatePages(requests, pool, table), std::invalid_argument);
  pool.releaseAll();
  const std::vector<PageKey> outside = {key(1, 4, 0)};
  EXPECT_THROW(allocatePages(outside, pool, table), std::invalid_argument);
}

TEST(Pages, ExhaustedPoolCoarsensTheFinestLevelAndCountsIt) {
  PagePool pool(3);
  PageTable table(kSmall);
  // 5 pages + the root = 6 > 3. Step 1: level 0's two pairs -> (1,0,0), (1,1,0), each
  // freeing one page: 3 + root = 4 > 3, 4 coarsened. Step 2: (1,0,0), (1,1,0) -> (2,0,0)
  // frees one; the lone (1,3,3) would free none and stays: (2,0,0), (1,3,3) + root = 3.
  const std::vector<PageKey> requests = fiveRequests();
  const Allocation a = allocatePages(requests, pool, table);
  EXPECT_EQ(a.requested, 5);
  EXPECT_EQ(a.coarsened, 4);
  EXPECT_EQ(a.coarseningSteps, 2);
  const std::vector<PageId> pages = {{3, 0, 0}, {2, 0, 0}, {1, 3, 3}};
  EXPECT_EQ(a.pages, pages);
  EXPECT_EQ(pool.freeCount(), 0);
  EXPECT_EQ(table.resolve(PageId{0, 2, 0}).page, (PageId{2, 0, 0}));
  EXPECT_EQ(table.resolve(PageId{1, 3, 3}).page, (PageId{1, 3, 3}));
  EXPECT_EQ(table.resolve(PageId{0, 7, 7}).page, (PageId{1, 3, 3}));

  // A pool of one page holds the root alone: every lookup finds it.
  PagePool one(1);
  PageTable t1(kSmall);
  const Allocation b = allocatePages(requests, one, t1);
  EXPECT_EQ(b.pages, (std::vector<PageId>{{3, 0, 0}}));
  EXPECT_EQ(b.coarsened, 5);
  EXPECT_EQ(b.coarseningSteps, 4);  // the lone (1,3,3) moves up alone in step 3
  EXPECT_EQ(t1.resolve(PageId{0, 7, 7}).slot, 0);
}

TEST(Pages, CappedQuadtreeKeepsItsWholeTopLevel) {
  // 4096² in 128² pages would be 6 levels (32 .. 1 a side); cut at 3: 32, 16, 8 a side.
  const VirtualLayout capped{.virtualResolution = 4096, .pageSize = 128, .maxLevels = 3};
  EXPECT_EQ(capped.levels(), 3);
  EXPECT_EQ(capped.topPages(), 64);
  EXPECT_EQ((VirtualLayout{4096, 128, 0}).validate(),
            "the page quadtree needs 1..14 levels, got at most 0");
  PageTable table(capped);
  PagePool small(63);
  EXPECT_THROW(allocatePages({}, small, table), std::invalid_argument);
  // 64 top pages + 3 requests = 67 > 66: the pair under (1,0,0) moves up (frees one); the
  // lone (0,31,31) would free nothing and stays.
  PagePool pool(66);
  const std::vector<PageKey> requests = {key(0, 0, 0), key(0, 1, 0), key(0, 31, 31)};
  const Allocation a = allocatePages(requests, pool, table);
  EXPECT_EQ(a.coarsened, 2);
  EXPECT_EQ(a.coarseningSteps, 1);
  ASSERT_EQ(a.pages.size(), 66u);
  EXPECT_EQ(a.pages[0], (PageId{2, 0, 0}));
  EXPECT_EQ(a.pages[9], (PageId{2, 1, 1}));  // row by row
  EXPECT_EQ(a.pages[64], (PageId{1, 0, 0}));
  EXPECT_EQ(a.pages[65], (PageId{0, 31, 31}));
  EXPECT_EQ(table.resolve(PageId{0, 20, 4}).page, (PageId{2, 5, 1}));
  EXPECT_EQ(table.resolve(PageId{0, 1, 1}).page, (PageId{1, 0, 0}));
}

TEST(Pages, FinalisedTableIsResolveOfEveryEntry) {
  const VirtualLayout capped{.virtualResolution = 4096, .pageSize = 128, .maxLevels = 4};
  std::mt19937 rng(3);
  std::vector<PageKey> requests;
  for (int i = 0; i < 40; ++i) {
    const int level = int(rng() % 3);
    const int n = capped.pagesPerSide(level);
    requests.push_back(key(level, int(rng() % n), int(rng() % n)));
  }
  requests = sortUnique(requests);
  PagePool pool(30);
  PageTable table(capped);
  const Allocation a = allocatePages(requests, pool, table);
  EXPECT_GT(a.coarsened, 0);
  const std::vector<std::uint32_t> f = table.finalised();
  std::size_t i = 0;
  for (int l = 0; l < capped.levels(); ++l)
    for (int y = 0; y < capped.pagesPerSide(l); ++y)
      for (int x = 0; x < capped.pagesPerSide(l); ++x, ++i) {
        const ResolvedPage r = table.resolve(PageId{l, x, y});
        ASSERT_GE(r.slot, 0);
        EXPECT_EQ(f[i], (std::uint32_t(r.slot) << 5) | std::uint32_t(r.page.level));
      }
  EXPECT_EQ(i, f.size());
}

TEST(Pages, RequestLevelIsTheFloorOfLog2SqrtArea) {
  const float t = 1.0f / 1024.0f;                              // one virtual texel of kSmall
  EXPECT_EQ(requestLevel({t, 0}, {0, t}, kSmall), 0);          // A = 1
  EXPECT_EQ(requestLevel({2 * t, 0}, {0, 2 * t}, kSmall), 1);  // A = 4
  EXPECT_EQ(requestLevel({4 * t, 0}, {0, t}, kSmall), 1);      // A = 4
  EXPECT_EQ(requestLevel({3 * t, 0}, {0, 3 * t}, kSmall), 1);  // log2 3 = 1.58
  EXPECT_EQ(requestLevel({2 * t, 2 * t}, {2 * t, -2 * t}, kSmall), 1);  // A = 8: 1.5
  EXPECT_EQ(requestLevel({4 * t, 0}, {0, 4 * t}, kSmall), 2);           // A = 16
  EXPECT_EQ(requestLevel({0.5f, 0}, {0, 0.5f}, kSmall), 3);             // clamped to the top
  EXPECT_EQ(requestLevel({t, 0}, {2 * t, 0}, kSmall), 0);               // A = 0: finest
  EXPECT_EQ(requestLevel({0.5f * t, 0}, {0, 0.5f * t}, kSmall), 0);     // finer than a texel
  EXPECT_EQ(requestLevel({4 * t, 0}, {0, 4 * t}, kSmall, 1), 1);        // lod.bias 1: finer
  EXPECT_EQ(requestLevel({4 * t, 0}, {0, 4 * t}, kSmall, 3), 0);        // clamped at 0
  EXPECT_EQ(requestLevel({0.5f, 0}, {0, 0.5f}, kSmall, 1), 3);          // log2 512 - 1 = 8: top
}

TEST(Pages, RequestPageIsThePageContainingTheUv) {
  EXPECT_EQ(requestPage({0.5f, 0.25f}, 0, kSmall), key(0, 4, 2));
  EXPECT_EQ(requestPage({0.5f, 0.25f}, 1, kSmall), key(1, 2, 1));
  EXPECT_EQ(requestPage({0.5f, 0.25f}, 3, kSmall), key(3, 0, 0));
  EXPECT_EQ(requestPage({1.0f, 1.0f}, 0, kSmall), key(0, 7, 7));
  EXPECT_EQ(requestPage({-0.01f, 0.5f}, 0, kSmall), kNoPage);
  EXPECT_EQ(requestPage({0.5f, 1.01f}, 0, kSmall), kNoPage);
}

TEST(Pages, PixelRequestsUseForwardThenBackwardDifferences) {
  // 2 x 2 pixels, steps of 2 texels along x and 8 along y: A = 16, level 2 (2 pages a side).
  const float t = 1.0f / 1024.0f;
  auto uv = [&](int x, int y) { return glm::vec2(0.1f + 2 * t * x, 0.6f + 8 * t * y); };
  std::vector<PixelUv> px = {
      {uv(0, 0), true}, {uv(1, 0), true}, {uv(0, 1), true}, {uv(1, 1), true}};
  EXPECT_EQ(pixelRequests(px, 2, 2, kSmall), (std::vector<PageKey>(4, key(2, 0, 1))));
  // (1, 1) uncovered: no request there; (0, 1) has no x step and (1, 0) no y step: A = 0.
  px[3].covered = false;
  EXPECT_EQ(pixelRequests(px, 2, 2, kSmall),
            (std::vector<PageKey>{key(2, 0, 1), key(0, 0, 4), key(0, 0, 4), kNoPage}));
  EXPECT_THROW(pixelRequests(px, 3, 2, kSmall), std::invalid_argument);
}

// A silhouette: pixels 0-1 of each row on a near plane, 2-3 on a plane 5 m behind it, far
// apart in light uv. Pixel 1's right neighbour is on the far plane: the neighbour's step asks
// for the coarsest level, the same-surface step (back to pixel 0) for the finest.
TEST(Pages, SameSurfaceDerivativesDoNotStepAcrossASilhouette) {
  const int w = 4, h = 2;
  std::vector<PixelUv> px(w * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const bool near = x < 2;
      PixelUv& p = px[std::size_t(y) * w + x];
      p.covered = true;
      p.position = glm::vec3(0.01f * float(x), 0.01f * float(y), near ? 0.0f : -5.0f);
      p.normal = glm::vec3(0.0f, 0.0f, 1.0f);
      p.st = glm::vec2((near ? 0.1f : 0.6f) + 0.001f * float(x), 0.1f + 0.001f * float(y));
    }
  EXPECT_TRUE(sameSurface(px[0], px[1]));
  EXPECT_FALSE(sameSurface(px[1], px[2]));  // 5 m off the plane over 1 cm
  PixelUv tilted = px[0];
  tilted.position = px[1].position;
  tilted.normal = glm::normalize(glm::vec3(1.0f, 0.0f, 1.0f));  // a crease: normals 45° apart
  EXPECT_FALSE(sameSurface(px[0], tilted));
  const auto neighbour = pixelRequests(px, w, h, kSmall, 0, Derivatives::Neighbour);
  const auto same = pixelRequests(px, w, h, kSmall, 0, Derivatives::SameSurface);
  for (int y = 0; y < h; ++y) {
    const std::size_t i = std::size_t(y) * w + 1;
    EXPECT_EQ(unpackPage(neighbour[i]).level, kSmall.topLevel()) << y;
    EXPECT_EQ(unpackPage(same[i]).level, 0) << y;
    // Elsewhere both step within one surface: the same keys.
    for (int x : {0, 2, 3})
      EXPECT_EQ(same[std::size_t(y) * w + x], neighbour[std::size_t(y) * w + x]);
  }
}

TEST(Pages, DedupKeepsARequestOnlyWhenLeftAndLowerNeighboursDiffer) {
  const PageKey A = key(0, 0, 0), B = key(0, 1, 0), C = key(1, 1, 1), D = key(2, 0, 0);
  const PageKey N = kNoPage;
  // Row 0 is the bottom row.
  const std::vector<PageKey> grid = {A, A, B, B,  //
                                     A, A, B, C,  //
                                     D, A, N, C};
  const std::vector<PageKey> kept = dedupRequests(grid, 4, 3);
  EXPECT_EQ(kept, (std::vector<PageKey>{A, N, B, N,  //
                                        N, N, N, C,  //
                                        D, N, N, N}));
  EXPECT_EQ(compactRequests(kept), (std::vector<PageKey>{A, B, C, D}));
  EXPECT_EQ(sortUnique(std::vector<PageKey>{5, 3, 5, 1, 3}), (std::vector<PageKey>{1, 3, 5}));
}

TEST(Pages, DedupLosesNoPage) {
  // Every page keeps its lowest, leftmost pixel: the unique set survives dedup.
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> pick(0, 5);
  const int w = 37, h = 23;
  std::vector<PageKey> grid(w * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      // Runs of equal keys, as neighbouring pixels ask for the same page.
      const int v = pick(rng);
      grid[y * w + x] = v == 0 ? kNoPage : key(0, (x / 5 + v / 3) % 8, (y / 4) % 8);
    }
  const std::vector<PageKey> kept = compactRequests(dedupRequests(grid, w, h));
  const std::vector<PageKey> all = compactRequests(grid);
  EXPECT_LT(kept.size(), all.size());
  EXPECT_EQ(sortUnique(kept), sortUnique(all));
}

TEST(Pages, SuperpagesBinPagesByLevelAndBlock) {
  const VirtualLayout layout{4096, 128};  // 32 finest pages a side; 8 per 1024² superpage
  const std::vector<PageId> pages = {{0, 1, 1}, {0, 9, 2}, {0, 7, 7}, {1, 3, 0}, {0, 8, 8}};
  const std::vector<Superpage> s = binSuperpages(pages, layout, 1024);
  ASSERT_EQ(s.size(), 4u);
  EXPECT_EQ((PageId{s[0].level, s[0].x, s[0].y}), (PageId{0, 0, 0}));
  EXPECT_EQ(s[0].pages, (std::vector<PageId>{{0, 1, 1}, {0, 7, 7}}));
  EXPECT_EQ((PageId{s[1].level, s[1].x, s[1].y}), (PageId{0, 1, 0}));
  EXPECT_EQ((PageId{s[2].level, s[2].x, s[2].y}), (PageId{0, 1, 1}));
  EXPECT_EQ(s[2].pages, (std::vector<PageId>{{0, 8, 8}}));
  EXPECT_EQ((PageId{s[3].level, s[3].x, s[3].y}), (PageId{1, 0, 0}));
  EXPECT_EQ(s[3].pagesPerSide, 8);
  EXPECT_THROW(binSuperpages(pages, layout, 100), std::invalid_argument);
}

// The pool of a byte budget: the most pages that fit, every slot of its texture used.
TEST(Pages, PoolFitsTheBytesItIsGiven) {
  const std::uint64_t page = 4ull * 128 * 128;  // a 128² DEPTH_COMPONENT32F page: 64 KiB
  // Uniform 2048²'s 16 MiB: 256 pages, the squarest shape.
  auto fit = fitPoolToBytes(16ull << 20, page, 128, 16);
  ASSERT_TRUE(fit);
  EXPECT_EQ(fit->pages(), 256);
  EXPECT_EQ(fit->columns, 16);
  fit = fitPoolToBytes((11ull << 20) - 1, page, 128, 16);
  ASSERT_TRUE(fit);
  EXPECT_EQ(fit->pages(), 175);  // 11 MiB is 176 pages; one byte less leaves 175 = 25 x 7
  EXPECT_EQ(fit->columns * fit->rows, 175);
  EXPECT_LE(fit->columns, 128);
  EXPECT_GE(fit->columns, fit->rows);
  // A prime count of pages beyond one row: the next smaller product (c * r <= 131, c <= 16).
  fit = fitPoolToBytes(131 * page, page, 16, 1);
  ASSERT_TRUE(fit);
  EXPECT_EQ(fit->pages(), 130);  // 13 x 10
  // The texture's side caps it: at most 4 x 4 pages.
  fit = fitPoolToBytes(100 * page, page, 4, 1);
  ASSERT_TRUE(fit);
  EXPECT_EQ(fit->pages(), 16);
  // Every budget: never more bytes than given, never more than a few pages left over (at most
  // 8 of up to 2000: the product of two sides of at most 128 nearest below the count).
  for (std::uint64_t pages = 16; pages < 2000; pages += 7) {
    const std::uint64_t bytes = pages * page + 12345;
    fit = fitPoolToBytes(bytes, page, 128, 16);
    ASSERT_TRUE(fit) << pages;
    EXPECT_LE(std::uint64_t(fit->pages()) * page, bytes) << pages;
    EXPECT_LE(pages - std::uint64_t(fit->pages()), 8u) << pages;
  }
  EXPECT_FALSE(fitPoolToBytes(15 * page, page, 128, 16));  // the top level does not fit
  EXPECT_THROW(fitPoolToBytes(page, 0, 128, 1), std::invalid_argument);
}

TEST(Pages, PanelViewsOfOneFrame) {
  // The exhaustion case above: 5 requests, a pool of 3 -> root, (2,0,0), (1,3,3).
  PagePool pool(3);
  PageTable table(kSmall);
  const std::vector<PageKey> requests = fiveRequests();
  const Allocation a = allocatePages(requests, pool, table);
  const std::vector<float> level0 = levelStates(table, requests, 0);
  ASSERT_EQ(level0.size(), 64u);
  EXPECT_EQ(level0[0], float(PageState::Coarsened));
  EXPECT_EQ(level0[3], float(PageState::Coarsened));
  EXPECT_EQ(level0[4], float(PageState::Empty));
  EXPECT_EQ(levelStates(table, requests, 1)[3 * 4 + 3], float(PageState::Requested));
  EXPECT_EQ(levelStates(table, requests, 2)[0], float(PageState::Fallback));  // not asked for
  EXPECT_EQ(levelStates(table, requests, 3)[0], float(PageState::Fallback));
  // Asked for and given: the level-2 page in a roomy pool.
  PagePool roomy(8);
  PageTable t2(kSmall);
  const std::vector<PageKey> one = {key(2, 1, 0)};
  allocatePages(one, roomy, t2);
  EXPECT_EQ(levelStates(t2, one, 2)[1], float(PageState::Requested));

  const std::vector<float> served = servedLevels(table);
  EXPECT_EQ(served[0], 2.0f);          // (0,0,0) -> (2,0,0)
  EXPECT_EQ(served[7 * 8 + 7], 1.0f);  // (0,7,7) -> (1,3,3)
  EXPECT_EQ(served[0 * 8 + 7], 3.0f);  // (0,7,0) -> the root

  // Heat: (0,1,0) twice and (1,0,0) once; (0,1,0) lies in (1,0,0).
  const std::vector<float> heat =
      requestHeat(kSmall, std::vector<PageKey>{key(0, 1, 0), key(0, 1, 0), key(1, 0, 0)});
  EXPECT_EQ(heat[1], 3.0f);
  EXPECT_EQ(heat[0], 1.0f);
  EXPECT_EQ(heat[8 + 1], 1.0f);
  EXPECT_EQ(heat[2], 0.0f);

  const std::vector<float> slots = poolLevels(a, 4);
  EXPECT_EQ(slots[0], 3.0f);
  EXPECT_EQ(slots[1], 2.0f);
  EXPECT_EQ(slots[2], 1.0f);
  EXPECT_TRUE(std::isnan(slots[3]));
}

// The page-border overlay's CPU mirror on a hand-made 5 x 3 image (map 0: 2 x 2 pages, map 1:
// one page): a pixel is a border when a covered 4-neighbour with pages uses another page (the
// other cell of map 0, or map 1); an uncovered pixel, a map without pages (5) and uv 1.0
// (clamped into the last page) draw and cause nothing.
TEST(Pages, PageBordersWhereTheNeighboursPageDiffers) {
  const float u[5] = {0.1f, 0.2f, 0.4f, 0.6f, 1.0f};
  std::vector<glm::vec2> uv;
  for (int y = 0; y < 3; ++y)
    for (float x : u) uv.emplace_back(x, 0.25f);
  const std::vector<std::uint8_t> map = {0, 0, 0, 0, 0,  //
                                         5, 0, 0, 0, 1,  //
                                         0, 0, 0, 0, 0};
  const std::vector<std::uint8_t> covered = {1, 1, 1, 1, 1,  //
                                             1, 1, 1, 1, 1,  //
                                             0, 1, 1, 1, 1};
  const std::vector<int> cells = {2, 1};
  EXPECT_EQ(pageBorders(uv, map, covered, 5, 3, cells),
            (std::vector<std::uint8_t>{0, 0, 1, 1, 1,  //
                                       0, 0, 1, 1, 1,  //
                                       0, 0, 1, 1, 1}));
  // No pages anywhere: no border.
  EXPECT_EQ(pageBorders(uv, map, covered, 5, 3, {}), std::vector<std::uint8_t>(15, 0));
  EXPECT_THROW(pageBorders(uv, map, covered, 4, 3, cells), std::invalid_argument);
}

}  // namespace
}  // namespace sl::pages
