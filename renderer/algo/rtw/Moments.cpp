// Moment mip chain and PCA of the importance map (DA-RTW, seed 000).
// See Moments.h for the exact definitions the GPU passes mirror.
#include "Moments.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sl::rtw {

namespace {

MomentTexel texelMoments(float value, float x, float y) {
  return {value, x * value, y * value, (x * x) * value, (y * y) * value, (x * y) * value};
}

double positiveOr(double v, double fallback) {
  return (std::isfinite(v) && v > 0.0) ? v : fallback;
}

}  // namespace

float centredCoordinate(int i, int size) {
  float inv = 1.0f / static_cast<float>(size);  // the host-side reciprocal the GPU receives
  return static_cast<float>(2 * i + 1 - size) * inv;
}

MomentLevel momentTextures(const ImportanceMap& map) {
  MomentLevel level;
  level.width = map.width;
  level.height = map.height;
  level.texels.resize(map.values.size());
  for (int y = 0; y < map.height; ++y) {
    float cy = centredCoordinate(y, map.height);
    for (int x = 0; x < map.width; ++x)
      level.texels[static_cast<size_t>(y) * map.width + x] =
          texelMoments(map.at(x, y), centredCoordinate(x, map.width), cy);
  }
  return level;
}

MomentLevel reduceMomentLevel(const MomentLevel& src) {
  MomentLevel dst;
  dst.width = (src.width + 1) / 2;
  dst.height = (src.height + 1) / 2;
  dst.texels.resize(static_cast<size_t>(dst.width) * dst.height);
  auto fetch = [&](int x, int y) {
    return (x < src.width && y < src.height) ? src.at(x, y) : MomentTexel{};
  };
  for (int j = 0; j < dst.height; ++j) {
    for (int i = 0; i < dst.width; ++i) {
      MomentTexel a = fetch(2 * i, 2 * j), b = fetch(2 * i + 1, 2 * j);
      MomentTexel c = fetch(2 * i, 2 * j + 1), d = fetch(2 * i + 1, 2 * j + 1);
      MomentTexel& o = dst.texels[static_cast<size_t>(j) * dst.width + i];
      for (int k = 0; k < kMomCount; ++k) o[k] = (a[k] + b[k]) + (c[k] + d[k]);
    }
  }
  return dst;
}

std::vector<MomentLevel> buildMomentChain(const ImportanceMap& map) {
  std::vector<MomentLevel> chain;
  if (map.width < 1 || map.height < 1) {
    chain.push_back(MomentLevel{1, 1, {MomentTexel{}}});
    return chain;
  }
  chain.push_back(momentTextures(map));
  while (chain.back().width > 1 || chain.back().height > 1)
    chain.push_back(reduceMomentLevel(chain.back()));
  return chain;
}

MomentTexel momentSumsDirect(const ImportanceMap& map) {
  std::array<double, kMomCount> acc{};
  for (int y = 0; y < map.height; ++y) {
    float cy = centredCoordinate(y, map.height);
    for (int x = 0; x < map.width; ++x) {
      MomentTexel t = texelMoments(map.at(x, y), centredCoordinate(x, map.width), cy);
      for (int k = 0; k < kMomCount; ++k) acc[k] += t[k];
    }
  }
  MomentTexel out{};
  for (int k = 0; k < kMomCount; ++k) out[k] = static_cast<float>(acc[k]);
  return out;
}

MomentStats momentsFromTop(const MomentTexel& top, glm::vec2 axisScale, float isotropyEps) {
  MomentStats st;
  double s = top[kMomI];
  if (!(s > 0.0) || !std::isfinite(s)) return st;
  double sx = positiveOr(axisScale.x, 1.0), sy = positiveOr(axisScale.y, 1.0);
  double eps = (std::isfinite(isotropyEps) && isotropyEps >= 0.0f) ? isotropyEps : 1e-4;

  double mx = top[kMomXI] / s, my = top[kMomYI] / s;
  double alpha = top[kMomX2I] / s, beta = top[kMomY2I] / s, gamma = top[kMomXYI] / s;
  double cxx = std::max(alpha - mx * mx, 0.0) * sx * sx;
  double cxy = (gamma - mx * my) * sx * sy;
  double cyy = std::max(beta - my * my, 0.0) * sy * sy;

  double m = 0.5 * (cxx + cyy), d = 0.5 * (cxx - cyy), r = std::hypot(d, cxy);
  double l1 = m + r, l2 = m - r;

  double ex, ey;
  if (cxy == 0.0) {
    ex = cxx >= cyy ? 1.0 : 0.0;
    ey = 1.0 - ex;
  } else {
    if (d >= 0.0)
      ex = d + r, ey = cxy;
    else
      ex = cxy, ey = r - d;
    double len = std::hypot(ex, ey);
    ex /= len;
    ey /= len;
  }
  if (ex < 0.0 || (ex == 0.0 && ey < 0.0)) ex = -ex, ey = -ey;

  st.sumI = static_cast<float>(s);
  st.meanX = static_cast<float>(mx);
  st.meanY = static_cast<float>(my);
  st.alpha = static_cast<float>(alpha);
  st.beta = static_cast<float>(beta);
  st.gamma = static_cast<float>(gamma);
  st.covXX = static_cast<float>(cxx);
  st.covXY = static_cast<float>(cxy);
  st.covYY = static_cast<float>(cyy);
  st.lambda1 = static_cast<float>(l1);
  st.lambda2 = static_cast<float>(l2);
  st.anisotropy = (l1 + l2) > 0.0 ? static_cast<float>((l1 - l2) / (l1 + l2)) : 0.0f;
  st.valid = std::isfinite(l1) && std::isfinite(l2) && (l1 - l2) > eps * (l1 + l2);
  if (st.valid) {
    st.ex = static_cast<float>(ex);
    st.ey = static_cast<float>(ey);
    st.angleDeg = static_cast<float>(std::atan2(ey, ex) * 180.0 / std::numbers::pi);
  }
  return st;
}

MomentStats momentsOf(const ImportanceMap& map, glm::vec2 axisScale, float isotropyEps) {
  return momentsFromTop(buildMomentChain(map).back().texels[0], axisScale, isotropyEps);
}

}  // namespace sl::rtw
