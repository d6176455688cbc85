// algo/pages/PageViews: the Pages panel's images (PageViews.h).
#include "PageViews.h"

#include <algorithm>
#include <limits>

namespace sl::pages {

std::vector<float> levelStates(const PageTable& table, std::span<const PageKey> uniqueRequests,
                               int level) {
  const VirtualLayout& layout = table.layout();
  const int n = layout.pagesPerSide(level);
  std::vector<float> out(static_cast<std::size_t>(n) * n, float(PageState::Empty));
  const std::span<const int> slots = table.level(level);
  for (std::size_t i = 0; i < out.size(); ++i)
    if (slots[i] >= 0) out[i] = float(PageState::Fallback);
  for (PageKey k : uniqueRequests) {
    const PageId p = unpackPage(k);
    if (p.level != level) continue;
    const std::size_t i = static_cast<std::size_t>(p.y) * n + p.x;
    out[i] = float(slots[i] >= 0 ? PageState::Requested : PageState::Coarsened);
  }
  return out;
}

std::vector<float> servedLevels(const PageTable& table) {
  const std::vector<std::uint32_t> f = table.finalised();
  const int n = table.layout().finestPagesPerSide();
  std::vector<float> out(static_cast<std::size_t>(n) * n);
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = f[i] == SL_PAGE_NONE ? std::numeric_limits<float>::quiet_NaN() : float(f[i] & 31u);
  return out;
}

std::vector<float> requestHeat(const VirtualLayout& layout, std::span<const PageKey> requests) {
  // Counts per page of every level, then each level adds its parent's, top down.
  std::vector<std::vector<float>> heat(layout.levels());
  for (int l = 0; l < layout.levels(); ++l) {
    const int n = layout.pagesPerSide(l);
    heat[l].assign(static_cast<std::size_t>(n) * n, 0.0f);
  }
  for (PageKey k : requests) {
    const PageId p = unpackPage(k);
    if (p.level < 0 || p.level >= layout.levels()) continue;
    const int n = layout.pagesPerSide(p.level);
    if (p.x < 0 || p.y < 0 || p.x >= n || p.y >= n) continue;
    heat[p.level][static_cast<std::size_t>(p.y) * n + p.x] += 1.0f;
  }
  for (int l = layout.topLevel() - 1; l >= 0; --l) {
    const int n = layout.pagesPerSide(l);
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        heat[l][static_cast<std::size_t>(y) * n + x] +=
            heat[l + 1][static_cast<std::size_t>(y / 2) * (n / 2) + x / 2];
  }
  return heat[0];
}

std::vector<float> poolLevels(const Allocation& allocation, int capacity) {
  std::vector<float> out(static_cast<std::size_t>(std::max(capacity, 0)),
                         std::numeric_limits<float>::quiet_NaN());
  for (std::size_t i = 0; i < allocation.pages.size(); ++i) {
    const int s = allocation.slots[i];
    if (s >= 0 && s < capacity) out[static_cast<std::size_t>(s)] = float(allocation.pages[i].level);
  }
  return out;
}

}  // namespace sl::pages
