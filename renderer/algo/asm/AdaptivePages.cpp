// Adaptive shadow maps (AdaptivePages.h): edge finding and the page cache.
#include "AdaptivePages.h"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>

#include "algo/pages/PageRequests.h"
#include "algo/pages/PageViews.h"

namespace sl::adaptive {

PageKey refineKey(glm::vec2 st, int neededLevel, int servedLevel,
                  const pages::VirtualLayout& layout) {
  if (servedLevel <= neededLevel) return pages::kNoPage;
  return pages::requestPage(st, neededLevel, layout);
}

bool mapTexelOnShadowEdge(const DepthGrid& map, const MapReceiver& receiver) {
  if (map.size <= 0 || map.depth.size() != std::size_t(map.size) * std::size_t(map.size))
    throw std::invalid_argument("mapTexelOnShadowEdge: " + std::to_string(map.depth.size()) +
                                " depths for a " + std::to_string(map.size) + "² map");
  const float n = float(map.size);
  const glm::ivec2 texel =
      glm::clamp(glm::ivec2(glm::floor(receiver.uv * n)), glm::ivec2(0), glm::ivec2(map.size - 1));
  auto litAt = [&](glm::ivec2 offset) {
    const glm::ivec2 t = glm::clamp(texel + offset, glm::ivec2(0), glm::ivec2(map.size - 1));
    const glm::vec2 centre = (glm::vec2(t) + 0.5f) / n;
    const float z =
        receiverDepthAt(receiver.uv, receiver.z, receiver.gradient, centre) - receiver.bias;
    return z <= map.depth[std::size_t(t.y) * std::size_t(map.size) + std::size_t(t.x)];
  };
  const bool centre = litAt({0, 0});
  for (glm::ivec2 o : {glm::ivec2(-1, 0), glm::ivec2(1, 0), glm::ivec2(0, -1), glm::ivec2(0, 1)})
    if (litAt(o) != centre) return true;
  return false;
}

std::vector<PageKey> findEdges(std::span<const TestedPixel> pixels, int width, int height,
                               EdgeTest test) {
  if (pixels.size() != std::size_t(width) * std::size_t(height))
    throw std::invalid_argument("findEdges: " + std::to_string(pixels.size()) + " pixels for a " +
                                std::to_string(width) + " x " + std::to_string(height) + " image");
  std::vector<PageKey> out(pixels.size(), pages::kNoPage);
  auto at = [&](int x, int y) -> const TestedPixel& {
    return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)];
  };
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const TestedPixel& p = at(x, y);
      if (p.mask == SL_MASK_EMPTY) continue;
      bool edge = test == EdgeTest::MapTexel && p.mapEdge != 0;
      const int nx[4] = {x - 1, x + 1, x, x};
      const int ny[4] = {y, y, y - 1, y + 1};
      for (int i = 0; i < 4 && test == EdgeTest::ScreenMask; ++i) {
        if (nx[i] < 0 || ny[i] < 0 || nx[i] >= width || ny[i] >= height) continue;
        const std::uint32_t m = at(nx[i], ny[i]).mask;
        edge = edge || (m != SL_MASK_EMPTY && m != p.mask);
      }
      PageKey& k = out[std::size_t(y) * std::size_t(width) + std::size_t(x)];
      if (edge && p.refine != pages::kNoPage)
        k = p.refine;
      else if (p.served != pages::kNoPage)
        k = p.served | kTouchBit;
    }
  return out;
}

namespace {

const pages::VirtualLayout& validated(const pages::VirtualLayout& layout) {
  if (const std::string e = layout.validate(); !e.empty()) throw std::invalid_argument("asm: " + e);
  return layout;
}

}  // namespace

PageCache::PageCache(const pages::VirtualLayout& layout, int poolPages, int coarseLevel)
    : table_(validated(layout)), pool_(poolPages), coarseLevel_(coarseLevel) {
  if (coarseLevel < 0 || coarseLevel > layout.topLevel())
    throw std::invalid_argument("asm: the coarse level " + std::to_string(coarseLevel) +
                                " lies outside the quadtree's levels 0.." +
                                std::to_string(layout.topLevel()));
  const long coarsePages =
      long(layout.pagesPerSide(coarseLevel)) * layout.pagesPerSide(coarseLevel);
  if (long(poolPages) < coarsePages)
    throw std::invalid_argument("asm: pool.pages = " + std::to_string(poolPages) +
                                " cannot hold the " + std::to_string(coarsePages) +
                                " pages of the coarse map; raise pool.pages or lower "
                                "asm.coarse.resolution");
  slots_.resize(std::size_t(poolPages));
}

std::vector<PageId> PageCache::invalidate(std::vector<int>& slots) {
  table_.clear();
  pool_.releaseAll();
  std::fill(slots_.begin(), slots_.end(), Slot{});
  evicted_.clear();
  ++invalidations_;
  std::vector<PageId> out;
  slots.clear();
  const int n = layout().pagesPerSide(coarseLevel_);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const PageId p{coarseLevel_, x, y};
      const int slot = *pool_.allocate();  // the constructor checked the pool holds them
      table_.set(p, slot);
      slots_[std::size_t(slot)] = {p, std::int64_t(frame_), std::int64_t(frame_), true};
      out.push_back(p);
      slots.push_back(slot);
    }
  return out;
}

void PageCache::touch(int slot, Refinement& r) {
  Slot& s = slots_[std::size_t(slot)];
  if (s.lastUsed < std::int64_t(frame_) && s.allocated < std::int64_t(frame_)) ++r.hits;
  s.lastUsed = std::int64_t(frame_);
}

int PageCache::evictOne() {
  int best = -1;
  for (int i = 0; i < int(slots_.size()); ++i) {
    const Slot& s = slots_[std::size_t(i)];
    if (s.lastUsed < 0 || s.coarse || s.lastUsed >= std::int64_t(frame_)) continue;
    if (best < 0 || s.lastUsed < slots_[std::size_t(best)].lastUsed) best = i;
  }
  if (best < 0) return -1;
  Slot& s = slots_[std::size_t(best)];
  table_.set(s.page, -1);
  pool_.release(best);
  evicted_.push_back(s.page);
  s = Slot{};
  return best;
}

Refinement PageCache::refine(std::span<const PageKey> keys, int budget) {
  Refinement r;
  std::vector<PageId> requests;
  for (PageKey k : keys) {
    if (k == pages::kNoPage) continue;
    const bool touchKey = (k & kTouchBit) != 0;
    const PageId p = pages::unpackPage(k & ~kTouchBit);
    if (p.level < 0 || p.level >= layout().levels() || p.x < 0 || p.y < 0 ||
        p.x >= layout().pagesPerSide(p.level) || p.y >= layout().pagesPerSide(p.level))
      throw std::invalid_argument("asm: page key " + std::to_string(k) +
                                  " lies outside the virtual map");
    const int slot = table_.slot(p);
    if (touchKey) {
      if (slot >= 0) touch(slot, r);
      continue;
    }
    ++r.requests;
    if (slot >= 0) {
      ++r.alreadyCached;
      touch(slot, r);
    } else {
      requests.push_back(p);
    }
  }
  // Coarsest level first (the quadtree refines top-down), then row, column.
  std::stable_sort(requests.begin(), requests.end(),
                   [](const PageId& a, const PageId& b) { return a.level > b.level; });
  for (std::size_t i = 0; i < requests.size(); ++i) {
    if (int(r.allocated.size()) >= budget) {
      r.deferred = int(requests.size() - i);
      break;
    }
    std::optional<int> slot = pool_.allocate();
    if (!slot) {
      const int freed = evictOne();
      if (freed < 0) {
        r.refused = int(requests.size() - i);
        break;
      }
      ++r.evicted;
      slot = pool_.allocate();
    }
    table_.set(requests[i], *slot);
    slots_[std::size_t(*slot)] = {requests[i], std::int64_t(frame_), std::int64_t(frame_), false};
    r.allocated.push_back(requests[i]);
    r.slots.push_back(*slot);
  }
  return r;
}

std::vector<float> cacheLevelStates(const PageCache& cache, std::span<const PageKey> requested,
                                    int level) {
  using pages::PageState;
  const pages::VirtualLayout& layout = cache.layout();
  const int n = layout.pagesPerSide(level);
  std::vector<float> out(std::size_t(n) * std::size_t(n), float(PageState::Empty));
  auto at = [&](const PageId& p) -> float& {
    return out[std::size_t(p.y) * std::size_t(n) + std::size_t(p.x)];
  };
  for (PageKey k : requested) {
    const PageId p = pages::unpackPage(k & ~kTouchBit);
    if (p.level == level) at(p) = float(PageState::Pending);
  }
  for (const PageId& p : cache.evictedThisFrame())
    if (p.level == level) at(p) = float(PageState::Evicted);
  const std::int64_t frame = std::int64_t(cache.frame());
  const std::span<const int> slots = cache.table().level(level);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const int s = slots[i];
    if (s < 0) continue;
    out[i] = float(cache.allocatedIn(s) >= frame ? PageState::New
                   : cache.lastUsed(s) >= frame  ? PageState::CachedHit
                                                 : PageState::CachedIdle);
  }
  return out;
}

std::vector<float> cachePoolLevels(const PageCache& cache) {
  const int capacity = cache.pool().capacity();
  std::vector<PageId> held;
  std::vector<int> slots;
  for (int s = 0; s < capacity; ++s)
    if (cache.lastUsed(s) >= 0) {
      held.push_back(cache.pageIn(s));
      slots.push_back(s);
    }
  return pages::poolLevels(held, slots, capacity);
}

}  // namespace sl::adaptive
