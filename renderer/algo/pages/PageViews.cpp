// algo/pages/PageViews: the Pages panel's images (PageViews.h).
#include "PageViews.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

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

std::vector<float> poolLevels(std::span<const PageId> pages, std::span<const int> slots,
                              int capacity) {
  std::vector<float> out(static_cast<std::size_t>(std::max(capacity, 0)),
                         std::numeric_limits<float>::quiet_NaN());
  for (std::size_t i = 0; i < std::min(pages.size(), slots.size()); ++i) {
    const int s = slots[i];
    if (s >= 0 && s < capacity) out[static_cast<std::size_t>(s)] = float(pages[i].level);
  }
  return out;
}

std::vector<std::uint8_t> pageBorders(std::span<const glm::vec2> uv,
                                      std::span<const std::uint8_t> map,
                                      std::span<const std::uint8_t> covered, int width, int height,
                                      std::span<const int> pagesPerSide) {
  const std::size_t n = std::size_t(std::max(width, 0)) * std::size_t(std::max(height, 0));
  if (uv.size() != n || map.size() != n || covered.size() != n)
    throw std::invalid_argument("pageBorders: the images must hold width x height pixels");
  // Per pixel: its page (map, x, y), or map = -1 when uncovered or its map has no pages.
  std::vector<glm::ivec3> page(n, glm::ivec3(-1));
  for (std::size_t i = 0; i < n; ++i) {
    const int m = map[i];
    const int cells = m < int(pagesPerSide.size()) ? pagesPerSide[std::size_t(m)] : 0;
    if (!covered[i] || cells <= 0) continue;
    const glm::ivec2 c = glm::clamp(glm::ivec2(glm::floor(uv[i] * float(cells))), glm::ivec2(0),
                                    glm::ivec2(cells - 1));
    page[i] = glm::ivec3(m, c);
  }
  std::vector<std::uint8_t> out(n, 0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const glm::ivec3 k = page[std::size_t(y) * std::size_t(width) + std::size_t(x)];
      if (k.x < 0) continue;
      const int dx[4] = {-1, 1, 0, 0}, dy[4] = {0, 0, -1, 1};
      for (int d = 0; d < 4; ++d) {
        const int qx = x + dx[d], qy = y + dy[d];
        if (qx < 0 || qy < 0 || qx >= width || qy >= height) continue;
        const glm::ivec3 o = page[std::size_t(qy) * std::size_t(width) + std::size_t(qx)];
        if (o.x >= 0 && o != k) out[std::size_t(y) * std::size_t(width) + std::size_t(x)] = 1;
      }
    }
  return out;
}

}  // namespace sl::pages
