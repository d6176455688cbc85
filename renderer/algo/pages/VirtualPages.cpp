// algo/pages/VirtualPages: keys, the layout, the pool's free list, the page table (mip
// chain with fallback to the finest allocated ancestor), allocation with coarsening when the
// pool runs out, superpage binning. See VirtualPages.h.
#include "VirtualPages.h"

#include <algorithm>
#include <bit>
#include <map>
#include <stdexcept>

namespace sl::pages {

namespace {
constexpr PageKey kCoordMask = (1u << SL_PAGE_KEY_COORD_BITS) - 1u;

bool isPowerOfTwo(int v) {
  return v > 0 && (v & (v - 1)) == 0;
}
}  // namespace

PageKey packPage(PageId p) {
  return (static_cast<PageKey>(p.level) << SL_PAGE_KEY_LEVEL_SHIFT) |
         (static_cast<PageKey>(p.y) << SL_PAGE_KEY_COORD_BITS) | static_cast<PageKey>(p.x);
}

PageId unpackPage(PageKey key) {
  return PageId{static_cast<int>(key >> SL_PAGE_KEY_LEVEL_SHIFT),
                static_cast<int>(key & kCoordMask),
                static_cast<int>((key >> SL_PAGE_KEY_COORD_BITS) & kCoordMask)};
}

PageId parentPage(PageId p) {
  return PageId{p.level + 1, p.x / 2, p.y / 2};
}

std::string VirtualLayout::validate() const {
  if (!isPowerOfTwo(pageSize) || pageSize < 8)
    return "page.size must be a power of two of at least 8, got " + std::to_string(pageSize);
  if (!isPowerOfTwo(virtualResolution) || virtualResolution < pageSize)
    return "virtual.resolution must be a power of two of at least page.size (" +
           std::to_string(pageSize) + "), got " + std::to_string(virtualResolution);
  if (maxLevels < 1 || maxLevels > SL_PAGE_MAX_LEVELS)
    return "the page quadtree needs 1.." + std::to_string(SL_PAGE_MAX_LEVELS) +
           " levels, got at most " + std::to_string(maxLevels);
  if (virtualResolution / pageSize > SL_PAGE_MAX_PER_SIDE)
    return "virtual.resolution / page.size must be at most " +
           std::to_string(SL_PAGE_MAX_PER_SIDE) + " pages per side, got " +
           std::to_string(virtualResolution / pageSize);
  return {};
}

int VirtualLayout::levels() const {
  return std::min(std::countr_zero(static_cast<unsigned>(finestPagesPerSide())) + 1, maxLevels);
}

PagePool::PagePool(int capacity) : capacity_(capacity) {
  if (capacity < 1)
    throw std::invalid_argument("a page pool needs at least one page, got " +
                                std::to_string(capacity));
  releaseAll();
}

std::optional<int> PagePool::allocate() {
  if (free_.empty()) return std::nullopt;
  const int slot = free_.back();
  free_.pop_back();
  used_[slot] = 1;
  return slot;
}

void PagePool::release(int slot) {
  if (slot < 0 || slot >= capacity_)
    throw std::invalid_argument("page slot " + std::to_string(slot) + " outside the pool of " +
                                std::to_string(capacity_));
  if (!used_[slot])
    throw std::invalid_argument("page slot " + std::to_string(slot) + " is already free");
  used_[slot] = 0;
  free_.push_back(slot);
}

void PagePool::releaseAll() {
  free_.resize(capacity_);
  for (int i = 0; i < capacity_; ++i) free_[i] = capacity_ - 1 - i;
  used_.assign(capacity_, 0);
}

PageTable::PageTable(const VirtualLayout& layout) : layout_(layout) {
  if (const std::string e = layout.validate(); !e.empty()) throw std::invalid_argument(e);
  levels_.resize(layout.levels());
  clear();
}

void PageTable::clear() {
  for (int l = 0; l < layout_.levels(); ++l) {
    const int n = layout_.pagesPerSide(l);
    levels_[l].assign(static_cast<std::size_t>(n) * n, -1);
  }
}

namespace {
bool inside(const VirtualLayout& layout, PageId p) {
  if (p.level < 0 || p.level >= layout.levels()) return false;
  const int n = layout.pagesPerSide(p.level);
  return p.x >= 0 && p.y >= 0 && p.x < n && p.y < n;
}
std::string describe(PageId p) {
  return "page (level " + std::to_string(p.level) + ", " + std::to_string(p.x) + ", " +
         std::to_string(p.y) + ")";
}
}  // namespace

int PageTable::slot(PageId p) const {
  if (!inside(layout_, p)) throw std::invalid_argument(describe(p) + " outside the page table");
  return levels_[p.level][static_cast<std::size_t>(p.y) * layout_.pagesPerSide(p.level) + p.x];
}

void PageTable::set(PageId p, int slot) {
  if (!inside(layout_, p)) throw std::invalid_argument(describe(p) + " outside the page table");
  levels_[p.level][static_cast<std::size_t>(p.y) * layout_.pagesPerSide(p.level) + p.x] = slot;
}

ResolvedPage PageTable::resolve(PageId p) const {
  for (PageId q = p; q.level < layout_.levels(); q = parentPage(q)) {
    const int s = slot(q);
    if (s >= 0) return ResolvedPage{s, q};
  }
  return ResolvedPage{};
}

std::vector<std::uint32_t> PageTable::finalised() const {
  // Top level first: an entry is its own page when allocated, else its parent's entry
  // (resolve() for every entry, in one pass over the table).
  std::vector<std::size_t> offset(layout_.levels() + 1, 0);
  for (int l = 0; l < layout_.levels(); ++l) offset[l + 1] = offset[l] + levels_[l].size();
  std::vector<std::uint32_t> out(offset.back(), SL_PAGE_NONE);
  for (int l = layout_.topLevel(); l >= 0; --l) {
    const int n = layout_.pagesPerSide(l);
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * n + x;
        const int s = levels_[l][i];
        if (s >= 0)
          out[offset[l] + i] = (static_cast<std::uint32_t>(s) << 5) | static_cast<std::uint32_t>(l);
        else if (l < layout_.topLevel())
          out[offset[l] + i] =
              out[offset[l + 1] + static_cast<std::size_t>(y / 2) * (n / 2) + x / 2];
      }
  }
  return out;
}

Allocation allocatePages(std::span<const PageKey> uniqueRequests, PagePool& pool,
                         PageTable& table) {
  if (pool.usedCount() != 0)
    throw std::invalid_argument("allocatePages needs an empty pool, " +
                                std::to_string(pool.usedCount()) + " slots are in use");
  const VirtualLayout& layout = table.layout();
  std::vector<PageKey> wanted(uniqueRequests.begin(), uniqueRequests.end());
  for (PageKey k : wanted)
    if (!inside(layout, unpackPage(k)))
      throw std::invalid_argument("request " + describe(unpackPage(k)) +
                                  " outside the virtual map");
  table.clear();

  const int top = layout.topLevel();
  if (pool.capacity() < layout.topPages())
    throw std::invalid_argument("a pool of " + std::to_string(pool.capacity()) +
                                " pages cannot hold the " + std::to_string(layout.topPages()) +
                                " pages of the coarsest level");

  Allocation a;
  a.requested = static_cast<int>(wanted.size());
  // Coarsen while the requests and the top level do not fit: the finest level present moves
  // to its parents. Each request is counted once, at its first coarsening (`original`).
  std::vector<char> original(wanted.size(), 1);
  auto pagesNeeded = [&] {
    int below = 0;
    for (PageKey k : wanted) below += unpackPage(k).level < top ? 1 : 0;
    return below + layout.topPages();
  };
  while (pagesNeeded() > pool.capacity()) {
    int finest = layout.topLevel();
    for (PageKey k : wanted) finest = std::min(finest, unpackPage(k).level);
    // The finest level's pages grouped by parent. Moving a group to its parent frees
    // `saving` pages (its children, less one unless the parent is wanted or on the top
    // level) and makes `children` pages coarser: groups go in order of the fewest pages
    // made coarser per page freed, until the excess is freed. When no group frees a page
    // (lone children of unwanted parents), the whole level moves up.
    struct Group {
      PageKey parent;
      int children, saving;
    };
    std::map<PageKey, int> children;  // parent -> wanted children at `finest`
    for (PageKey k : wanted)
      if (unpackPage(k).level == finest) ++children[packPage(parentPage(unpackPage(k)))];
    std::vector<Group> groups;
    for (const auto& [parent, n] : children) groups.push_back({parent, n, 0});
    for (Group& g : groups) {
      const bool parentHeld = unpackPage(g.parent).level == top ||
                              std::binary_search(wanted.begin(), wanted.end(), g.parent);
      g.saving = g.children - (parentHeld ? 0 : 1);
    }
    std::stable_sort(groups.begin(), groups.end(), [](const Group& l, const Group& r) {
      if ((l.saving > 0) != (r.saving > 0)) return l.saving > 0;
      return l.children * r.saving < r.children * l.saving;  // children / saving, ascending
    });
    std::vector<PageKey> moved;  // parents of the groups that move up
    int freed = 0;
    const int excess = pagesNeeded() - pool.capacity();
    for (const Group& g : groups) {
      if (g.saving <= 0 || freed >= excess) break;
      moved.push_back(g.parent);
      freed += g.saving;
    }
    if (moved.empty())
      for (const Group& g : groups) moved.push_back(g.parent);
    std::sort(moved.begin(), moved.end());
    std::vector<std::pair<PageKey, char>> next;
    for (std::size_t i = 0; i < wanted.size(); ++i) {
      const PageId p = unpackPage(wanted[i]);
      const PageKey parent = packPage(parentPage(p));
      if (p.level != finest || !std::binary_search(moved.begin(), moved.end(), parent)) {
        next.emplace_back(wanted[i], original[i]);
        continue;
      }
      if (original[i]) ++a.coarsened;
      next.emplace_back(parent, 0);
    }
    std::sort(next.begin(), next.end());
    // Unique by key; a key that some request asked for as such stays "original" (it sorts last).
    std::vector<PageKey> keys;
    std::vector<char> orig;
    for (const auto& [k, o] : next) {
      if (!keys.empty() && keys.back() == k) {
        orig.back() = static_cast<char>(orig.back() | o);
        continue;
      }
      keys.push_back(k);
      orig.push_back(o);
    }
    wanted = std::move(keys);
    original = std::move(orig);
    ++a.coarseningSteps;
  }

  // The whole top level first, then the requests below it: coarsest level first, then by
  // row and column.
  std::vector<PageId> order;
  const int topSide = layout.pagesPerSide(top);
  for (int y = 0; y < topSide; ++y)
    for (int x = 0; x < topSide; ++x) order.push_back(PageId{top, x, y});
  std::vector<PageId> below;
  for (PageKey k : wanted)
    if (unpackPage(k).level < top) below.push_back(unpackPage(k));
  std::sort(below.begin(), below.end(), [](const PageId& l, const PageId& r) {
    if (l.level != r.level) return l.level > r.level;
    return packPage(l) < packPage(r);
  });
  order.insert(order.end(), below.begin(), below.end());
  for (const PageId& p : order) {
    const std::optional<int> s = pool.allocate();
    if (!s) throw std::logic_error("allocatePages: the pool ran out after coarsening");
    table.set(p, *s);
    a.pages.push_back(p);
    a.slots.push_back(*s);
  }
  return a;
}

std::vector<Superpage> binSuperpages(std::span<const PageId> pages, const VirtualLayout& layout,
                                     int superpageSize) {
  if (!isPowerOfTwo(superpageSize) || superpageSize < layout.pageSize)
    throw std::invalid_argument("the superpage size must be a power of two of at least " +
                                std::to_string(layout.pageSize) + ", got " +
                                std::to_string(superpageSize));
  const int perSide = superpageSize / layout.pageSize;
  std::map<PageKey, Superpage> bins;  // keyed like pages: level, row, column of the block
  for (const PageId& p : pages) {
    if (!inside(layout, p)) throw std::invalid_argument(describe(p) + " outside the virtual map");
    const PageId block{p.level, p.x / perSide, p.y / perSide};
    Superpage& s = bins[packPage(block)];
    s.level = block.level;
    s.x = block.x;
    s.y = block.y;
    s.pagesPerSide = perSide;
    s.pages.push_back(p);
  }
  std::vector<Superpage> out;
  for (auto& [k, s] : bins) out.push_back(std::move(s));
  return out;
}

std::optional<PoolShape> fitPoolToBytes(std::uint64_t bytes, std::uint64_t pageBytes,
                                        int maxPagesPerSide, int minPages) {
  if (pageBytes == 0 || maxPagesPerSide < 1)
    throw std::invalid_argument("fitPoolToBytes: pageBytes and maxPagesPerSide must be positive");
  const std::uint64_t side = std::uint64_t(maxPagesPerSide);
  const std::uint64_t most = std::min(bytes / pageBytes, side * side);
  if (most < std::uint64_t(std::max(minPages, 1))) return std::nullopt;
  // Every row count r: the most columns c <= side with c * r <= most; the largest product
  // wins, the squarest (fewest columns) among equals.
  PoolShape best;
  for (std::uint64_t r = 1; r <= side && r <= most; ++r) {
    const std::uint64_t c = std::min(side, most / r);
    if (c < r) break;
    const auto pages = c * r;
    if (pages > std::uint64_t(best.pages()) ||
        (pages == std::uint64_t(best.pages()) && int(c) < best.columns))
      best = {int(c), int(r)};
  }
  return best;
}

}  // namespace sl::pages
