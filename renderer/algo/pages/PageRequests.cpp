// algo/pages/PageRequests: per-pixel page requests, dedup, compaction, sort + unique. The
// GPU pass shaders/rmsm/requests.comp follows these functions line by line.
#include "PageRequests.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sl::pages {

int requestLevel(glm::vec2 dUvDx, glm::vec2 dUvDy, const VirtualLayout& layout, int lodBias) {
  const float v = static_cast<float>(layout.virtualResolution);
  const glm::vec2 dX = dUvDx * v;
  const glm::vec2 dY = dUvDy * v;
  const float area = std::abs(dX.x * dY.y - dX.y * dY.x);
  if (!(area > 0.0f)) return 0;
  const float lod = 0.5f * std::log2(area);  // log2(sqrt(A))
  const int level = static_cast<int>(std::floor(lod)) - lodBias;
  return std::clamp(level, 0, layout.topLevel());
}

PageKey requestPage(glm::vec2 st, int level, const VirtualLayout& layout) {
  if (!(st.x >= 0.0f && st.x <= 1.0f && st.y >= 0.0f && st.y <= 1.0f)) return kNoPage;
  const int n = layout.pagesPerSide(level);
  const int x = std::min(static_cast<int>(st.x * static_cast<float>(n)), n - 1);
  const int y = std::min(static_cast<int>(st.y * static_cast<float>(n)), n - 1);
  return packPage(PageId{level, x, y});
}

namespace {
void checkSize(std::size_t size, int width, int height) {
  if (width < 1 || height < 1 || size != static_cast<std::size_t>(width) * height)
    throw std::invalid_argument("page requests: " + std::to_string(size) +
                                " pixels do not make a " + std::to_string(width) + " x " +
                                std::to_string(height) + " image");
}

// The step to the neighbour at +1 along one axis, or from the one at -1, or zero; with
// same-surface derivatives, first the one of them on the pixel's surface.
glm::vec2 screenStep(const PixelUv& here, const PixelUv* next, const PixelUv* prev,
                     Derivatives derivatives) {
  const bool nextOk = next && next->covered, prevOk = prev && prev->covered;
  if (derivatives == Derivatives::SameSurface) {
    if (nextOk && sameSurface(here, *next)) return next->st - here.st;
    if (prevOk && sameSurface(here, *prev)) return here.st - prev->st;
  }
  if (nextOk) return next->st - here.st;
  if (prevOk) return here.st - prev->st;
  return glm::vec2(0.0f);
}
}  // namespace

bool sameSurface(const PixelUv& here, const PixelUv& other) {
  const glm::vec3 d = other.position - here.position;
  const float offPlane = std::abs(glm::dot(d, here.normal));
  return offPlane <= float(SL_RMSM_SAME_SURFACE_PLANE) * glm::length(d) &&
         glm::dot(here.normal, other.normal) >= float(SL_RMSM_SAME_SURFACE_NORMAL_COS);
}

std::vector<PageKey> pixelRequests(std::span<const PixelUv> pixels, int width, int height,
                                   const VirtualLayout& layout, int lodBias,
                                   Derivatives derivatives) {
  checkSize(pixels.size(), width, height);
  std::vector<PageKey> out(pixels.size(), kNoPage);
  auto at = [&](int x, int y) -> const PixelUv* {
    if (x < 0 || y < 0 || x >= width || y >= height) return nullptr;
    return &pixels[static_cast<std::size_t>(y) * width + x];
  };
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const PixelUv& p = *at(x, y);
      if (!p.covered) continue;
      const glm::vec2 dX = screenStep(p, at(x + 1, y), at(x - 1, y), derivatives);
      const glm::vec2 dY = screenStep(p, at(x, y + 1), at(x, y - 1), derivatives);
      out[static_cast<std::size_t>(y) * width + x] =
          requestPage(p.st, requestLevel(dX, dY, layout, lodBias), layout);
    }
  return out;
}

std::vector<PageKey> dedupRequests(std::span<const PageKey> requests, int width, int height) {
  checkSize(requests.size(), width, height);
  std::vector<PageKey> out(requests.size(), kNoPage);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * width + x;
      const PageKey k = requests[i];
      if (k == kNoPage) continue;
      if (x > 0 && requests[i - 1] == k) continue;
      if (y > 0 && requests[i - width] == k) continue;
      out[i] = k;
    }
  return out;
}

std::vector<PageKey> compactRequests(std::span<const PageKey> requests) {
  std::vector<PageKey> out;
  for (PageKey k : requests)
    if (k != kNoPage) out.push_back(k);
  return out;
}

std::vector<PageKey> sortUnique(std::span<const PageKey> requests) {
  std::vector<PageKey> out(requests.begin(), requests.end());
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace sl::pages
