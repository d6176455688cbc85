// Blur, importance floor, prefix sums and warp maps (RTW steps 3-6).
// See Warp.h for the exact definitions the GPU passes mirror.
#include "Warp.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace sl::rtw {

std::vector<float> gaussianWeights(int radius, float sigma) {
  int r = std::clamp(radius, 0, kMaxBlurRadius);
  if (!(sigma > 0.0f) || !std::isfinite(sigma)) r = 0;
  if (r == 0) return {1.0f};
  std::vector<float> w(static_cast<size_t>(2 * r + 1));
  float twoSigma2 = 2.0f * sigma * sigma;
  float sum = 0.0f;
  for (int k = -r; k <= r; ++k) {
    w[k + r] = std::exp(-static_cast<float>(k * k) / twoSigma2);
    sum += w[k + r];
  }
  for (float& x : w) x /= sum;
  return w;
}

std::vector<float> gaussianBlur1D(std::span<const float> in, int radius, float sigma) {
  std::vector<float> w = gaussianWeights(radius, sigma);
  int r = static_cast<int>(w.size() / 2);
  int n = static_cast<int>(in.size());
  std::vector<float> out(in.size());
  for (int i = 0; i < n; ++i) {
    float acc = 0.0f;
    for (int k = -r; k <= r; ++k) acc += w[k + r] * in[std::clamp(i + k, 0, n - 1)];
    out[i] = acc;
  }
  return out;
}

void applyImportanceFloor(std::span<float> values, float floorFraction) {
  float m = 0.0f;
  for (float v : values) m = std::max(m, v);
  if (!(m > 0.0f)) {
    std::fill(values.begin(), values.end(), 1.0f);
    return;
  }
  float f = std::isnan(floorFraction) ? 0.0f : std::clamp(floorFraction, 0.0f, 1.0f);
  float lo = f * m;
  for (float& v : values) v = std::max(v, lo);
}

std::vector<float> inclusiveScan(std::span<const float> in) {
  std::vector<float> out(in.size());
  float acc = 0.0f;
  for (size_t i = 0; i < in.size(); ++i) {
    acc = (i == 0) ? in[0] : acc + in[i];
    out[i] = acc;
  }
  return out;
}

std::vector<float> blellochScan(std::span<const float> in) {
  size_t n = in.size();
  size_t m = std::bit_ceil(std::max<size_t>(n, 1));
  std::vector<float> a(m, 0.0f);
  std::copy(in.begin(), in.end(), a.begin());
  for (size_t d = 1; d < m; d *= 2)  // up-sweep (reduce)
    for (size_t k = 0; k < m; k += 2 * d) a[k + 2 * d - 1] = a[k + d - 1] + a[k + 2 * d - 1];
  float total = a[m - 1];
  a[m - 1] = 0.0f;
  for (size_t d = m / 2; d >= 1; d /= 2) {  // down-sweep
    for (size_t k = 0; k < m; k += 2 * d) {
      float t = a[k + d - 1];
      a[k + d - 1] = a[k + 2 * d - 1];
      a[k + 2 * d - 1] = t + a[k + 2 * d - 1];
    }
  }
  std::vector<float> out(n);
  for (size_t i = 0; i < n; ++i) out[i] = (i + 1 < m) ? a[i + 1] : total;
  return out;
}

std::vector<float> warpFromImportance(std::span<const float> importance) {
  size_t n = importance.size();
  std::vector<float> warp(n + 1, 0.0f);
  if (n == 0) return warp;
  std::vector<float> s = blellochScan(importance);
  float total = s[n - 1];
  if (!(total > 0.0f) || !std::isfinite(total)) return warp;
  float nf = static_cast<float>(n);
  for (size_t e = 1; e < n; ++e) warp[e] = s[e - 1] / total - static_cast<float>(e) / nf;
  return warp;  // warp[0] = warp[n] = 0 by construction
}

float warpCoordinate(std::span<const float> warpEdges, float u) {
  int n = static_cast<int>(warpEdges.size()) - 1;
  if (n < 1 || !(u > 0.0f) || !(u < 1.0f)) return u;
  float x = u * static_cast<float>(n);
  int e = std::min(static_cast<int>(std::floor(x)), n - 1);
  float t = x - static_cast<float>(e);
  float a = warpEdges[e], b = warpEdges[e + 1];
  return u + (a + t * (b - a));
}

float unwarpCoordinate(std::span<const float> warpEdges, float uWarped) {
  int n = static_cast<int>(warpEdges.size()) - 1;
  if (n < 1 || !(uWarped > 0.0f) || !(uWarped < 1.0f)) return uWarped;
  float nf = static_cast<float>(n);
  auto edge = [&](int e) { return static_cast<float>(e) / nf + warpEdges[e]; };
  // Binary search for the last e in [0, n-1] with c_e <= uWarped (c_0 = 0 < uWarped).
  // A u' equal to a plateau's value (zero importance) maps to the plateau's first edge.
  int lo = 0, hi = n - 1;
  while (lo < hi) {
    int mid = (lo + hi + 1) / 2;
    if (edge(mid) <= uWarped)
      lo = mid;
    else
      hi = mid - 1;
  }
  int e = lo;
  float ce = edge(e), cn = edge(e + 1);
  if (uWarped == ce) {
    while (e > 0 && edge(e - 1) == ce) --e;
    return static_cast<float>(e) / nf;
  }
  float t = 0.0f;
  if (cn > ce) t = std::clamp((uWarped - ce) / (cn - ce), 0.0f, 1.0f);
  return (static_cast<float>(e) + t) / nf;
}

std::vector<float> buildWarpMap(std::span<const float> importance1d, const WarpSettings& s) {
  std::vector<float> v = gaussianBlur1D(importance1d, s.blurRadius, s.blurSigma);
  applyImportanceFloor(v, s.importanceFloor);
  return warpFromImportance(v);
}

WarpMaps buildWarpMaps(const ImportanceMap& map, const WarpSettings& s) {
  return {buildWarpMap(collapseColumnsMax(map), s), buildWarpMap(collapseRowsMax(map), s)};
}

glm::vec2 warpUv(const WarpMaps& maps, glm::vec2 lightUv) {
  return {warpCoordinate(maps.x, lightUv.x), warpCoordinate(maps.y, lightUv.y)};
}

glm::vec2 unwarpUv(const WarpMaps& maps, glm::vec2 warpedUv) {
  return {unwarpCoordinate(maps.x, warpedUv.x), unwarpCoordinate(maps.y, warpedUv.y)};
}

std::int64_t rtwTexels(int smRes, int imRes, int n1dMaps) {
  std::int64_t sm = std::max(smRes, 0), im = std::max(imRes, 0);
  return sm * sm + im * im + std::int64_t{std::max(n1dMaps, 0)} * im;
}

}  // namespace sl::rtw
