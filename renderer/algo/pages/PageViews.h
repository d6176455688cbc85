// What the Pages panel draws, computed from the CPU side of one RMSM frame (algo/pages): the
// state of every page-table entry per level, the level that serves each finest page, the
// frame's requests as a heat map over the finest pages, and each pool slot's level. No GL:
// the rmsm technique publishes these only while requested (pages.*), without any readback.
#pragma once

#include <span>
#include <vector>

#include "VirtualPages.h"

namespace sl::pages {

/// A page-table entry as the panel colours it (the float value of its cell).
enum class PageState : int {
  Empty = 0,      ///< neither asked for nor allocated
  Requested = 1,  ///< asked for and allocated
  Fallback = 2,   ///< allocated, not asked for (the top level; an ancestor of coarsened ones)
  Coarsened = 3,  ///< asked for, served by an ancestor because the pool ran out
};

/// Per entry of `level`, row by row (y = 0 first): its PageState; `uniqueRequests` sorted.
std::vector<float> levelStates(const PageTable& table, std::span<const PageKey> uniqueRequests,
                               int level);
/// Per finest page (finestPagesPerSide², row by row): the level of the page serving it.
std::vector<float> servedLevels(const PageTable& table);
/// Per finest page: how many of `requests` (e.g. the compacted list, duplicates counted) ask
/// for a page containing it, at any level.
std::vector<float> requestHeat(const VirtualLayout& layout, std::span<const PageKey> requests);
/// Per pool slot: the level of the page it holds, NaN when free.
std::vector<float> poolLevels(const Allocation& allocation, int capacity);

}  // namespace sl::pages
