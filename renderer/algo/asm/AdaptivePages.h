// Adaptive shadow maps (Fernando, Fernandez, Bala, Greenberg 2001; techniques.md §5, the
// lecture's construction loop): a coarse map first, then iterations of edge finding (a camera
// pixel whose shadow test differs from a neighbour's, served by a page coarser than its LOD,
// asks for the page at its LOD), page requests, allocation and render, until no request is
// left or the frame's budget is spent. Pages are KEPT between frames in a cache (least
// recently used evicted when the pool is full) and dropped together when the light or the
// geometry changes. Plain C++ over the RMSM machinery (algo/pages: layout, keys, page table,
// pool): the CPU reference of shaders/asm/edges.comp and the `asm` technique's allocator.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "algo/ShadowBias.h"
#include "algo/pages/VirtualPages.h"
#include "common/shared_constants.h"

namespace sl::adaptive {

using pages::PageId;
using pages::PageKey;

/// The most refinement iterations a frame runs (asm.iterations' maximum: each is a pass).
inline constexpr int kMaxIterations = 4;
/// A key with this bit is no request: the pixel used (touched) that allocated page.
inline constexpr PageKey kTouchBit = SL_ASM_TOUCH_BIT;

/// What makes a camera pixel an edge pixel (asm.edge; SL_ASM_EDGE_*).
enum class EdgeTest : int {
  /// Its shadow mask differs from a 4-neighbour's in the camera image (the tool's test: it
  /// also fires at a terminator, where a pixel facing away from the light counts as shadowed).
  ScreenMask = SL_ASM_EDGE_SCREEN,
  /// The shadow-map texel its test reads lies on a shadow edge of the map (Fernando et al.
  /// 2001): the pixel's depth tests at that texel and its 4 neighbours do not all agree.
  MapTexel = SL_ASM_EDGE_MAP,
};

/// What the shadow-test pass (shaders/asm/test.comp) writes per camera pixel.
struct TestedPixel {
  std::uint32_t mask = SL_MASK_EMPTY;  ///< SL_MASK_LIT / SL_MASK_SHADOWED / SL_MASK_EMPTY
  PageKey served = pages::kNoPage;     ///< the allocated page whose depth the test read
  PageKey refine = pages::kNoPage;     ///< the page at the pixel's LOD when finer than served
  std::uint32_t mapEdge = 0;           ///< 1: the texel it read lies on a shadow edge of the map
};

/// One level of a depth map as a plain grid: `size` x `size` window depths at texel centres,
/// row by row (v up), light uv [0, 1]^2.
struct DepthGrid {
  std::span<const float> depth;
  int size = 0;
};

/// The paper's edge test (Fernando et al. 2001) for one receiver: the hard depth test of
/// `receiver` (receiverInMap: its plane evaluated at each texel centre, less its bias, against
/// the stored depth) at the texel holding receiver.uv and at its 4 neighbours (clamped to the
/// map, as depthMapTexelTest clamps); true when they do not all agree. A receiver whose
/// neighbourhood is its own surface (a terminator: back-facing but not occluded) is no edge.
/// GLSL: the map-edge loop of shaders/asm/test.comp. Throws std::invalid_argument when the
/// grid's size does not match its depths.
bool mapTexelOnShadowEdge(const DepthGrid& map, const MapReceiver& receiver);

/// The page at `neededLevel` holding light uv `st` when the page serving the pixel is coarser
/// (servedLevel > neededLevel), else kNoPage ("page not in ASM" of the lecture).
PageKey refineKey(glm::vec2 st, int neededLevel, int servedLevel,
                  const pages::VirtualLayout& layout);

/// Edge finding, per pixel (row by row): with EdgeTest::ScreenMask a covered pixel whose mask
/// differs from a covered 4-neighbour's lies on a shadow edge, with EdgeTest::MapTexel a
/// covered pixel whose mapEdge is set; an edge pixel with a refine key asks for that page;
/// every other covered pixel touches its served page (served | kTouchBit); an uncovered pixel
/// gives kNoPage. The result goes through pages::dedupRequests / compactRequests like RMSM's.
std::vector<PageKey> findEdges(std::span<const TestedPixel> pixels, int width, int height,
                               EdgeTest test = EdgeTest::ScreenMask);

/// What one refinement step did.
struct Refinement {
  int requests = 0;       ///< distinct page requests (keys without kTouchBit)
  int alreadyCached = 0;  ///< requests whose page was allocated already (touched instead)
  int evicted = 0;        ///< pages evicted (least recently used) to make room
  int refused = 0;        ///< requests left: the pool holds only pages used this frame
  int deferred = 0;       ///< requests left because the budget was spent
  int hits = 0;           ///< pages first used this frame that were allocated in an earlier frame
  std::vector<PageId> allocated;  ///< new pages to render, coarsest level first
  std::vector<int> slots;         ///< the slot of allocated[i]
};

/// The page cache: a page table and a pool that persist between frames. The coarse level
/// (every page of it) is allocated by invalidate() (call it first, and whenever the light or
/// the geometry changed) and never evicted; finer pages come from refine() and stay until
/// evicted or invalidated.
class PageCache {
 public:
  /// Throws std::invalid_argument when the layout is invalid, coarseLevel lies outside
  /// [0, topLevel] or the pool cannot hold the coarse level's pages.
  PageCache(const pages::VirtualLayout& layout, int poolPages, int coarseLevel);

  const pages::VirtualLayout& layout() const { return table_.layout(); }
  const pages::PageTable& table() const { return table_; }
  const pages::PagePool& pool() const { return pool_; }
  int coarseLevel() const { return coarseLevel_; }
  std::uint64_t frame() const { return frame_; }
  int invalidations() const { return invalidations_; }

  /// Drops every page and allocates the coarse level again; returns its pages (to render,
  /// in row order) and their slots through `slots`.
  std::vector<PageId> invalidate(std::vector<int>& slots);
  /// A new frame: pages used before it become candidates for eviction; evictedThisFrame()
  /// starts empty.
  void beginFrame() {
    ++frame_;
    evicted_.clear();
  }
  /// One iteration's sorted unique keys (pages::sortUnique of the compacted list): touches
  /// mark their pages used this frame; requests, coarsest level first, take a free slot, else
  /// the least recently used page not used this frame (oldest frame, then lowest slot; coarse
  /// pages never), at most `budget` new pages.
  Refinement refine(std::span<const PageKey> keys, int budget);

  /// Per slot: the frame a page was last used (allocated or touched), the frame it was
  /// allocated; -1 for a free slot.
  std::int64_t lastUsed(int slot) const { return slots_.at(std::size_t(slot)).lastUsed; }
  std::int64_t allocatedIn(int slot) const { return slots_.at(std::size_t(slot)).allocated; }
  /// The page a slot holds (valid only when lastUsed(slot) >= 0).
  PageId pageIn(int slot) const { return slots_.at(std::size_t(slot)).page; }
  /// Pages evicted during the current frame (for the Pages panel).
  const std::vector<PageId>& evictedThisFrame() const { return evicted_; }

 private:
  struct Slot {
    PageId page;
    std::int64_t lastUsed = -1;
    std::int64_t allocated = -1;
    bool coarse = false;
  };
  void touch(int slot, Refinement& r);
  int evictOne();  ///< -1 when nothing may be evicted

  pages::PageTable table_;
  pages::PagePool pool_;
  int coarseLevel_ = 0;
  std::vector<Slot> slots_;
  std::uint64_t frame_ = 0;
  std::vector<PageId> evicted_;
  int invalidations_ = 0;
};

/// The Pages panel's page table for the cache after a frame: per entry of `level`, row by row,
/// a pages::PageState: New (allocated this frame), CachedHit (allocated earlier, used this
/// frame), CachedIdle (allocated earlier, unused), else Evicted (evicted this frame), else
/// Pending (in `requested`, this frame's sorted unique request keys, without kTouchBit), else
/// Empty.
std::vector<float> cacheLevelStates(const PageCache& cache, std::span<const PageKey> requested,
                                    int level);
/// Per pool slot: the level of the page the cache holds there, NaN when free.
std::vector<float> cachePoolLevels(const PageCache& cache);

}  // namespace sl::adaptive
