// First-hit rays against triangle meshes (TriangleBvh.h).
#include "TriangleBvh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "Camera.h"

namespace sl {

float rayTriangle(const glm::vec3& origin, const glm::vec3& dir, const glm::vec3& a,
                  const glm::vec3& b, const glm::vec3& c) {
  constexpr float miss = std::numeric_limits<float>::infinity();
  glm::vec3 e1 = b - a;
  glm::vec3 e2 = c - a;
  glm::vec3 pv = glm::cross(dir, e2);
  float det = glm::dot(e1, pv);
  if (std::abs(det) < 1e-12f) return miss;
  float inv = 1.0f / det;
  glm::vec3 tv = origin - a;
  float u = glm::dot(tv, pv) * inv;
  if (u < 0.0f || u > 1.0f) return miss;
  glm::vec3 qv = glm::cross(tv, e1);
  float v = glm::dot(dir, qv) * inv;
  if (v < 0.0f || u + v > 1.0f) return miss;
  float dist = glm::dot(e2, qv) * inv;
  return dist > 0.0f ? dist : miss;
}

TriangleBvh::TriangleBvh(std::vector<TriangleMeshView> meshes) : meshes_(std::move(meshes)) {
  struct Build {
    Ref ref;
    glm::vec3 centroid;
  };
  std::vector<Build> items;
  for (std::size_t m = 0; m < meshes_.size(); ++m)
    for (std::size_t t = 0; t + 2 < meshes_[m].indices.size(); t += 3) {
      auto [a, b, c] = corners({std::uint32_t(m), std::uint32_t(t)});
      items.push_back({{std::uint32_t(m), std::uint32_t(t)}, (a + b + c) / 3.0f});
    }
  if (items.empty()) return;
  struct Range {
    std::size_t node, begin, end;
  };
  nodes_.push_back({});
  std::vector<Range> todo{{0, 0, items.size()}};
  while (!todo.empty()) {
    const Range r = todo.back();
    todo.pop_back();
    Aabb box, centroids;
    for (std::size_t i = r.begin; i < r.end; ++i) {
      auto [a, b, c] = corners(items[i].ref);
      box.extend(a), box.extend(b), box.extend(c);
      centroids.extend(items[i].centroid);
    }
    // Padded, so that a hit a rounding error outside its triangle is not culled.
    const glm::vec3 mag = glm::max(glm::abs(box.min), glm::abs(box.max)) + box.size();
    const float pad = 1e-5f * std::max({mag.x, mag.y, mag.z});
    Node& node = nodes_[r.node];
    node.lo = box.min - pad;
    node.hi = box.max + pad;
    const glm::vec3 spread = centroids.size();
    const int axis = spread.x >= spread.y && spread.x >= spread.z ? 0
                     : spread.y >= spread.z                       ? 1
                                                                  : 2;
    if (r.end - r.begin <= kLeafSize || !(spread[axis] > 0.0f)) {
      node.first = std::uint32_t(r.begin);
      node.count = std::uint32_t(r.end - r.begin);
      continue;
    }
    const std::size_t mid = r.begin + (r.end - r.begin) / 2;
    std::nth_element(items.begin() + std::ptrdiff_t(r.begin), items.begin() + std::ptrdiff_t(mid),
                     items.begin() + std::ptrdiff_t(r.end), [axis](const Build& x, const Build& y) {
                       return x.centroid[axis] < y.centroid[axis];
                     });
    const std::size_t left = nodes_.size();
    nodes_[r.node].first = std::uint32_t(left);  // `node` is invalidated by the push_back
    nodes_.push_back({});
    nodes_.push_back({});
    todo.push_back({left, r.begin, mid});
    todo.push_back({left + 1, mid, r.end});
  }
  refs_.reserve(items.size());
  for (const Build& item : items) refs_.push_back(item.ref);
}

float TriangleBvh::firstHit(const glm::vec3& origin, const glm::vec3& dir) const {
  float best = std::numeric_limits<float>::infinity();
  if (nodes_.empty()) return best;
  std::vector<std::uint32_t> stack{0};
  while (!stack.empty()) {
    const Node& node = nodes_[stack.back()];
    stack.pop_back();
    if (!mayHit(node, origin, dir, best)) continue;
    if (node.count == 0) {
      stack.push_back(node.first);
      stack.push_back(node.first + 1);
      continue;
    }
    for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
      auto [a, b, c] = corners(refs_[i]);
      best = std::min(best, rayTriangle(origin, dir, a, b, c));
    }
  }
  return best;
}

TriangleBvh::Corners TriangleBvh::corners(Ref r) const {
  const TriangleMeshView& mesh = meshes_[r.mesh];
  return {mesh.positions[mesh.indices[r.index]], mesh.positions[mesh.indices[r.index + 1]],
          mesh.positions[mesh.indices[r.index + 2]]};
}

bool TriangleBvh::mayHit(const Node& n, const glm::vec3& o, const glm::vec3& d, float maxDist) {
  float tNear = 0.0f, tFar = maxDist;
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0.0f) {
      if (o[a] < n.lo[a] || o[a] > n.hi[a]) return false;
      continue;
    }
    float t0 = (n.lo[a] - o[a]) / d[a], t1 = (n.hi[a] - o[a]) / d[a];
    if (t0 > t1) std::swap(t0, t1);
    tNear = std::max(tNear, t0);
    tFar = std::min(tFar, t1);
    if (tNear > tFar) return false;
  }
  return true;
}

}  // namespace sl
