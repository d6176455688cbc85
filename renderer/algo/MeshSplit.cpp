#include "MeshSplit.h"

#include <algorithm>
#include <cmath>

namespace sl {

namespace {

bool lexLess(const glm::vec3& a, const glm::vec3& b) {
  if (a.x != b.x) return a.x < b.x;
  if (a.y != b.y) return a.y < b.y;
  return a.z < b.z;
}

template <typename T>
T along(const T& lo, const T& hi, float t) {
  return lo + (hi - lo) * t;
}

}  // namespace

TriangleMesh splitLongTriangles(const TriangleMesh& mesh, float maxEdgeM) {
  TriangleMesh out = mesh;
  if (!(maxEdgeM > 0.0f)) return out;
  out.indices.clear();
  const bool hasN = mesh.normals.size() == mesh.positions.size();
  const bool hasUv = mesh.uvs.size() == mesh.positions.size();
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t c[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
    if (c[0] >= mesh.positions.size() || c[1] >= mesh.positions.size() ||
        c[2] >= mesh.positions.size())
      continue;
    const glm::vec3 p[3] = {mesh.positions[c[0]], mesh.positions[c[1]], mesh.positions[c[2]]};
    const float longest =
        std::max({glm::distance(p[0], p[1]), glm::distance(p[1], p[2]), glm::distance(p[2], p[0])});
    const int n = std::isfinite(longest) ? int(std::ceil(longest / maxEdgeM)) : 1;
    if (n <= 1) {
      out.indices.insert(out.indices.end(), c, c + 3);
      continue;
    }
    // Grid vertex (i, j): index in `grid`, (n+1)(n+2)/2 of them.
    std::vector<std::uint32_t> grid;
    grid.reserve(size_t(n + 1) * size_t(n + 2) / 2);
    auto cornerOf = [&](int i, int j) -> int {
      if (i == 0 && j == 0) return 0;
      if (i == n && j == 0) return 1;
      if (i == 0 && j == n) return 2;
      return -1;
    };
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i + j <= n; ++i) {
        if (int corner = cornerOf(i, j); corner >= 0) {
          grid.push_back(c[corner]);
          continue;
        }
        // On an original edge? (a = 0: edge p1-p2; j = 0: edge p0-p1; i = 0: edge p2-p0)
        int e0 = -1, e1 = -1, k = 0;  // k of n steps from corner e0 towards e1
        if (i + j == n) {
          e0 = 1, e1 = 2, k = j;
        } else if (j == 0) {
          e0 = 0, e1 = 1, k = i;
        } else if (i == 0) {
          e0 = 2, e1 = 0, k = n - j;
        }
        auto mixAttr = [&](auto get) {
          using V = decltype(get(0));
          if (e0 >= 0) {
            bool swap = lexLess(p[e1], p[e0]);
            int lo = swap ? e1 : e0, hi = swap ? e0 : e1;
            return along<V>(get(lo), get(hi), float(swap ? n - k : k) / float(n));
          }
          const float b1 = float(i) / float(n), b2 = float(j) / float(n), b0 = 1.0f - b1 - b2;
          return V(get(0) * b0 + get(1) * b1 + get(2) * b2);
        };
        out.positions.push_back(mixAttr([&](int q) { return p[q]; }));
        if (hasN)
          out.normals.push_back(glm::normalize(mixAttr([&](int q) { return mesh.normals[c[q]]; })));
        if (hasUv) out.uvs.push_back(mixAttr([&](int q) { return mesh.uvs[c[q]]; }));
        grid.push_back(std::uint32_t(out.positions.size() - 1));
      }
    auto at = [&](int i, int j) {  // rows j = 0..n hold n - j + 1 vertices
      size_t row = size_t(j) * size_t(n + 1) - size_t(j) * size_t(j - 1) / 2;
      return grid[row + size_t(i)];
    };
    for (int j = 0; j < n; ++j)
      for (int i = 0; i + j < n; ++i) {
        out.indices.insert(out.indices.end(), {at(i, j), at(i + 1, j), at(i, j + 1)});
        if (i + j + 1 < n)
          out.indices.insert(out.indices.end(), {at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
  }
  return out;
}

}  // namespace sl
