// What the Pages panel draws, computed from the CPU side of one RMSM or ASM frame (algo/pages,
// algo/asm): the state of every page-table entry per level, the level that serves each finest
// page, the frame's requests as a heat map over the finest pages, and each pool slot's level.
// No GL: rmsm and asm publish these only while requested (pages.*), without any readback.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "VirtualPages.h"

namespace sl::pages {

/// A page-table entry as the panel colours it (the float value of its cell).
enum class PageState : int {
  Empty = 0,      ///< neither asked for nor allocated
  Requested = 1,  ///< asked for and allocated
  Fallback = 2,   ///< allocated, not asked for (the top level; an ancestor of coarsened ones)
  Coarsened = 3,  ///< asked for, served by an ancestor because the pool ran out
  // ASM's page cache (algo/asm cacheLevelStates): pages live across frames.
  New = 4,         ///< allocated this frame (the coarse map after an invalidation included)
  CachedHit = 5,   ///< kept from an earlier frame and used this frame (a cache hit)
  CachedIdle = 6,  ///< kept from an earlier frame, not used this frame (eviction candidate)
  Evicted = 7,     ///< evicted this frame (least recently used), not held any more
  Pending = 8,     ///< requested this frame, not allocated (budget spent or pool refused)
};
inline constexpr int kPageStates = 9;

/// Per entry of `level`, row by row (y = 0 first): its PageState; `uniqueRequests` sorted.
std::vector<float> levelStates(const PageTable& table, std::span<const PageKey> uniqueRequests,
                               int level);
/// Per finest page (finestPagesPerSide², row by row): the level of the page serving it.
std::vector<float> servedLevels(const PageTable& table);
/// Per finest page: how many of `requests` (e.g. the compacted list, duplicates counted) ask
/// for a page containing it, at any level.
std::vector<float> requestHeat(const VirtualLayout& layout, std::span<const PageKey> requests);
/// Per pool slot: the level of the page it holds (pages[i] in slots[i]), NaN when free.
std::vector<float> poolLevels(std::span<const PageId> pages, std::span<const int> slots,
                              int capacity);
inline std::vector<float> poolLevels(const Allocation& allocation, int capacity) {
  return poolLevels(allocation.pages, allocation.slots, capacity);
}

/// The page-border overlay (view.overlay pages, common/composite.frag) on the CPU: per pixel
/// (`width` x `height`, any row order), 1 when it is covered, its map `map[i]` has pages
/// (pagesPerSide[map] > 0) and a covered 4-neighbour with pages uses another page — another
/// map, or another floor(uv * pagesPerSide[map]) (clamped to the grid); else 0.
std::vector<std::uint8_t> pageBorders(std::span<const glm::vec2> uv,
                                      std::span<const std::uint8_t> map,
                                      std::span<const std::uint8_t> covered, int width, int height,
                                      std::span<const int> pagesPerSide);

}  // namespace sl::pages
