// The exact warped shadow map and the warped lookup (RTW step 7).
// See WarpedRaster.h for the exact definitions the GPU passes mirror.
#include "WarpedRaster.h"

#include <algorithm>
#include <cmath>

#include <glm/vec4.hpp>

namespace sl::rtw {

namespace {

double orient(const glm::vec3& a, const glm::vec3& b, double pu, double pv) {
  return (double(b.x) - double(a.x)) * (pv - double(a.y)) -
         (double(b.y) - double(a.y)) * (pu - double(a.x));
}

/// Indices i with lo <= table[i] <= hi (tables are monotone up to rounding; scanning keeps
/// the result exact whatever the order).
void indicesInRange(const std::vector<float>& table, double lo, double hi, std::vector<int>& out) {
  out.clear();
  for (int i = 0; i < int(table.size()); ++i)
    if (double(table[i]) >= lo && double(table[i]) <= hi) out.push_back(i);
}

/// Writes the plane of triangle k at light uv (u, v) into texel t of r when it covers the
/// point, lies within GL's near / far clip and is nearer than best[t] (ties keep the first).
void keepNearest(WarpedRaster& r, std::vector<double>& best, size_t t, const LightTriangle& tri,
                 size_t k, double u, double v) {
  double z;
  if (!lightTrianglePlaneAt(tri, u, v, z)) return;
  if (!(z >= 0.0 && z <= 1.0)) return;  // GL's near / far clipping
  if (z < best[t]) {
    best[t] = z;
    r.depth[t] = static_cast<float>(z);
    r.triangle[t] = static_cast<int>(k);
  }
}

/// A map of smRes^2 texels with nothing drawn: depth 1 (far), no triangle.
WarpedRaster clearedRaster(int smRes) {
  WarpedRaster r;
  r.size = smRes;
  r.depth.assign(size_t(smRes) * size_t(smRes), 1.0f);
  r.triangle.assign(size_t(smRes) * size_t(smRes), -1);
  return r;
}

/// A triangle's bounding box in light-space x (u) and y (v), in double.
struct UvBounds {
  double u0, u1, v0, v1;
};

UvBounds uvBounds(const LightTriangle& tri) {
  UvBounds b{tri.v[0].x, tri.v[0].x, tri.v[0].y, tri.v[0].y};
  for (const glm::vec3& p : tri.v) {
    b.u0 = std::min(b.u0, double(p.x));
    b.u1 = std::max(b.u1, double(p.x));
    b.v0 = std::min(b.v0, double(p.y));
    b.v1 = std::max(b.v1, double(p.y));
  }
  return b;
}

}  // namespace

glm::vec3 lightSpaceOf(const glm::mat4& lightViewProj, glm::vec3 worldP) {
  glm::vec4 c = lightViewProj * glm::vec4(worldP, 1.0f);
  return glm::vec3(c) / c.w * 0.5f + 0.5f;
}

LightTriangle lightTriangle(const glm::mat4& lightViewProj, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
  return {{lightSpaceOf(lightViewProj, a), lightSpaceOf(lightViewProj, b),
           lightSpaceOf(lightViewProj, c)}};
}

void appendLightTriangles(const glm::mat4& lightViewProj, std::span<const glm::vec3> positions,
                          std::span<const std::uint32_t> indices, std::vector<LightTriangle>& out) {
  for (size_t k = 0; k + 2 < indices.size(); k += 3) {
    std::uint32_t i0 = indices[k], i1 = indices[k + 1], i2 = indices[k + 2];
    if (i0 >= positions.size() || i1 >= positions.size() || i2 >= positions.size()) continue;
    out.push_back(lightTriangle(lightViewProj, positions[i0], positions[i1], positions[i2]));
  }
}

std::vector<float> inverseWarpTable(std::span<const float> warpEdges, int smRes) {
  if (smRes < 1) return {};
  std::vector<float> table(static_cast<size_t>(smRes));
  const float res = static_cast<float>(smRes);
  for (int i = 0; i < smRes; ++i)
    table[static_cast<size_t>(i)] =
        unwarpCoordinate(warpEdges, (static_cast<float>(i) + 0.5f) / res);
  return table;
}

double lightTriangleArea2(const LightTriangle& tri) {
  return orient(tri.v[0], tri.v[1], double(tri.v[2].x), double(tri.v[2].y));
}

bool lightTrianglePlaneAt(const LightTriangle& tri, double u, double v, double& depth) {
  const double area = lightTriangleArea2(tri);
  if (!(std::abs(area) >= 1e-12)) return false;  // degenerate (or NaN): covers nothing
  const double sign = area > 0.0 ? 1.0 : -1.0;
  const glm::vec3 &a = tri.v[0], &b = tri.v[1], &c = tri.v[2];
  const double w0 = sign * orient(b, c, u, v);
  const double w1 = sign * orient(c, a, u, v);
  const double w2 = sign * orient(a, b, u, v);
  if (w0 < 0.0 || w1 < 0.0 || w2 < 0.0) return false;
  depth = (w0 * double(a.z) + w1 * double(b.z) + w2 * double(c.z)) / std::abs(area);
  return true;
}

WarpedRaster rasterizeWarped(const WarpMaps& maps, int smRes, std::span<const LightTriangle> tris) {
  if (smRes < 1) return {};
  WarpedRaster r = clearedRaster(smRes);
  const size_t n = static_cast<size_t>(smRes);
  r.tableX = inverseWarpTable(maps.x, smRes);
  r.tableY = inverseWarpTable(maps.y, smRes);
  // Exact depth of the current winner per texel (double), so the minimum is taken before
  // rounding to float and ties keep the first triangle.
  std::vector<double> best(n * n, 2.0);
  std::vector<int> cols, rows;
  for (size_t k = 0; k < tris.size(); ++k) {
    const LightTriangle& tri = tris[k];
    const double area = lightTriangleArea2(tri);
    if (!(std::abs(area) >= 1e-12)) continue;
    const auto [u0, u1, v0, v1] = uvBounds(tri);
    indicesInRange(r.tableX, u0, u1, cols);
    if (cols.empty()) continue;
    indicesInRange(r.tableY, v0, v1, rows);
    for (int j : rows)
      for (int i : cols)
        keepNearest(r, best, size_t(j) * n + size_t(i), tri, k, r.tableX[size_t(i)],
                    r.tableY[size_t(j)]);
  }
  return r;
}

std::vector<float> rasterizeWarpedDepth(const WarpMaps& maps, int smRes,
                                        std::span<const LightTriangle> tris) {
  return rasterizeWarped(maps, smRes, tris).depth;
}

WarpedRaster rasterizeWarpedInterpolated(const WarpMaps& maps, int smRes,
                                         std::span<const LightTriangle> tris) {
  if (smRes < 1) return {};
  WarpedRaster r = clearedRaster(smRes);
  const size_t n = static_cast<size_t>(smRes);
  std::vector<double> best(n * n, 2.0);
  const double res = double(smRes);
  for (size_t k = 0; k < tris.size(); ++k) {
    LightTriangle warped = tris[k];
    for (glm::vec3& p : warped.v) {
      const glm::vec2 w = warpUv(maps, glm::vec2(p));
      p.x = w.x;
      p.y = w.y;
    }
    const double area = lightTriangleArea2(warped);
    if (!(std::abs(area) >= 1e-12)) continue;
    const auto [u0, u1, v0, v1] = uvBounds(warped);
    // Texel centres (i + 0.5) / smRes within the bounding box, clamped to the map.
    const int i0 = std::max(0, int(std::ceil(u0 * res - 0.5)));
    const int i1 = std::min(smRes - 1, int(std::floor(u1 * res - 0.5)));
    const int j0 = std::max(0, int(std::ceil(v0 * res - 0.5)));
    const int j1 = std::min(smRes - 1, int(std::floor(v1 * res - 0.5)));
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i)
        keepNearest(r, best, size_t(j) * n + size_t(i), warped, k, (double(i) + 0.5) / res,
                    (double(j) + 0.5) / res);
  }
  return r;
}

glm::vec3 warpedLookup(const WarpMaps& maps, const glm::mat4& lightViewProj, glm::vec3 worldP) {
  glm::vec3 uvz = lightSpaceOf(lightViewProj, worldP);
  glm::vec2 w = warpUv(maps, glm::vec2(uvz));
  return {w.x, w.y, uvz.z};
}

}  // namespace sl::rtw
