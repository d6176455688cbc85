// The virtual shadow map of resolution-matched shadow maps (Lefohn, Sengupta, Owens 2007;
// techniques.md §5): a square virtual map cut into pages of `pageSize`² texels, a quadtree
// whose page table is a mip chain (level 0 = the finest pages, the top level one page over
// the whole map unless the tree is cut at maxLevels; an entry = the page's slot in one physical
// pool), the pool's free-list allocator, allocation of a frame's unique page requests (the pool
// running out coarsens the finest requested pages, group by group, and counts them, never fails)
// and the binning of pages into superpages. Plain C++: the GL side
// (renderer/core/paged/PagedMap) renders what this allocates; the keys are the GPU's
// (shaders/common/shared_constants.h SL_PAGE_*).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "common/shared_constants.h"

namespace sl::pages {

using PageKey = std::uint32_t;
inline constexpr PageKey kNoPage = SL_PAGE_NONE;

/// One page of the quadtree: its level (0 = finest) and its place in that level's grid.
struct PageId {
  int level = 0;
  int x = 0, y = 0;
  bool operator==(const PageId&) const = default;
};

/// level << 26 | y << 13 | x (SL_PAGE_KEY_*): sorting keys sorts by level, then row, column.
PageKey packPage(PageId p);
PageId unpackPage(PageKey key);
/// The page one level coarser that contains `p`.
PageId parentPage(PageId p);

/// The virtual map's size in texels and pages.
struct VirtualLayout {
  int virtualResolution = 16384;  ///< texels per side of the virtual map (power of two)
  int pageSize = 128;             ///< texels per side of a page (power of two)
  /// At most this many levels: the quadtree is cut below its root when deeper (the lookup
  /// holds SL_PAGED_LOOKUP_LEVELS maps, one per level), and its top level has several pages.
  int maxLevels = SL_PAGE_MAX_LEVELS;
  /// Empty when valid, else a message naming the bad value.
  std::string validate() const;
  int finestPagesPerSide() const { return virtualResolution / pageSize; }
  /// min(log2(finestPagesPerSide) + 1, maxLevels): level 0 the finest pages.
  int levels() const;
  int topLevel() const { return levels() - 1; }
  int topPages() const { return pagesPerSide(topLevel()) * pagesPerSide(topLevel()); }
  int pagesPerSide(int level) const { return finestPagesPerSide() >> level; }
  /// Virtual texels per page texel at `level` (2^level).
  int texelScale(int level) const { return 1 << level; }
};

/// The physical pool: `capacity` page slots, handed out from a free list (lowest slot first
/// when nothing was released), given back one by one or all at once.
class PagePool {
 public:
  explicit PagePool(int capacity);
  int capacity() const { return capacity_; }
  int freeCount() const { return static_cast<int>(free_.size()); }
  int usedCount() const { return capacity_ - freeCount(); }
  /// A free slot, or nothing when the pool is exhausted.
  std::optional<int> allocate();
  /// Gives `slot` back; throws std::invalid_argument for a slot out of range or already free.
  void release(int slot);
  void releaseAll();

 private:
  int capacity_ = 0;
  std::vector<int> free_;   ///< a stack: back() is handed out next
  std::vector<char> used_;  ///< per slot
};

/// The finest allocated page covering a page-table entry (the lookup's fallback).
struct ResolvedPage {
  int slot = -1;  ///< -1: no allocated page covers it (the root not allocated)
  PageId page;    ///< the allocated page itself (its level <= the entry's level when found)
};

/// The page table: one grid of slots per level (a mip chain), -1 = not allocated.
class PageTable {
 public:
  explicit PageTable(const VirtualLayout& layout);
  const VirtualLayout& layout() const { return layout_; }
  int slot(PageId p) const;
  void set(PageId p, int slot);
  void clear();
  /// The entry itself when allocated, else its finest allocated ancestor.
  ResolvedPage resolve(PageId p) const;
  /// One level's entries, row by row (y = 0 first), pagesPerSide(level)² of them.
  std::span<const int> level(int level) const { return levels_.at(level); }
  /// Every level finalised for the GPU: per entry the resolved page packed as
  /// slot << 5 | page level (SL_PAGE_NONE when nothing covers it), level 0 first, row by row.
  std::vector<std::uint32_t> finalised() const;

 private:
  VirtualLayout layout_;
  std::vector<std::vector<int>> levels_;
};

/// What allocating a frame's requests did.
struct Allocation {
  int requested = 0;  ///< unique pages asked for (after sort + unique)
  /// Requests that got a coarser page than they asked for because the pool ran out (each
  /// counted once, at its first coarsening).
  int coarsened = 0;
  int coarseningSteps = 0;    ///< how many times pages of the finest level present moved up
  std::vector<PageId> pages;  ///< allocated, in slot order of allocation (root first)
  std::vector<int> slots;     ///< the slot of pages[i]
};

/// Allocates every page of the top level (the fallback of every lookup: one root page
/// unless maxLevels cut the tree) and then `uniqueRequests` (sorted, unique keys) into an
/// empty pool and table, coarsest level first. When they do not fit, pages of the finest
/// level present move to their parents, sibling group by sibling group, the groups that make
/// the fewest pages coarser per page freed first, until they fit (a level whose groups free
/// nothing moves up whole); the top level alone fits a pool of topPages(). Throws
/// std::invalid_argument when the pool is in use or smaller than topPages(), or a key lies outside
/// the layout.
Allocation allocatePages(std::span<const PageKey> uniqueRequests, PagePool& pool, PageTable& table);

/// Pages binned into superpages: square blocks of `superpageSize`² virtual-level texels of
/// one level (Lefohn et al. render each superpage once, then copy its pages into the pool).
struct Superpage {
  int level = 0;
  int x = 0, y = 0;           ///< the block in its level's grid of superpages
  int pagesPerSide = 1;       ///< superpageSize / pageSize
  std::vector<PageId> pages;  ///< the pages inside, in the order given
};
/// One superpage per (level, block) holding at least one of `pages`, ordered by level,
/// then row, then column. A level with fewer pages than a superpage side is one block.
std::vector<Superpage> binSuperpages(std::span<const PageId> pages, const VirtualLayout& layout,
                                     int superpageSize = 1024);

/// A pool texture's shape: `columns` x `rows` pages, every slot used (pages = columns * rows).
struct PoolShape {
  int columns = 0, rows = 0;
  int pages() const { return columns * rows; }
};
/// The pool of the most pages of `pageBytes` each that fits in `bytes`, its texture at most
/// `maxPagesPerSide` pages a side (columns >= rows, the squarest shape of that many pages).
/// Nothing when not even `minPages` fit. The pool's bytes are then pages() * pageBytes <=
/// bytes, the rest less than a few pages (pages() is the largest product columns * rows of
/// sides <= maxPagesPerSide that does not exceed bytes / pageBytes).
std::optional<PoolShape> fitPoolToBytes(std::uint64_t bytes, std::uint64_t pageBytes,
                                        int maxPagesPerSide, int minPages);

}  // namespace sl::pages
