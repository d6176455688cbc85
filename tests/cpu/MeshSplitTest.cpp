// algo/MeshSplit: long triangles cut into a regular grid for the warped light passes.
#include <gtest/gtest.h>

#include <map>
#include <tuple>

#include "algo/MeshSplit.h"

namespace sl {
namespace {

TriangleMesh quad(float size) {  // two triangles sharing the diagonal 0-2, facing +y
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {0, 0, -size}, {size, 0, -size}, {size, 0, 0}};
  m.normals.assign(4, glm::vec3(0, 1, 0));
  m.uvs = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
  m.indices = {0, 3, 2, 0, 2, 1};
  return m;
}

double signedAreaY(const TriangleMesh& m, size_t t) {  // area of triangle t seen from +y
  const glm::vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]],
                  c = m.positions[m.indices[t + 2]];
  return 0.5 * double(glm::cross(b - a, c - a).y);
}

TEST(MeshSplit, ShortTrianglesAndNonPositiveLimitsAreUnchanged) {
  TriangleMesh q = quad(2.0f);
  TriangleMesh same = splitLongTriangles(q, 10.0f);
  EXPECT_EQ(same.indices, q.indices);
  EXPECT_EQ(same.positions, q.positions);
  EXPECT_EQ(splitLongTriangles(q, 0.0f).indices, q.indices);
  EXPECT_EQ(splitLongTriangles(q, -1.0f).indices, q.indices);
}

TEST(MeshSplit, GridOfNSquaredKeepsAreaWindingAndAttributes) {
  TriangleMesh q = quad(100.0f);
  // Longest edge: the 141.42 m diagonal -> n = ceil(141.42 / 10) = 15 per triangle.
  TriangleMesh s = splitLongTriangles(q, 10.0f);
  ASSERT_EQ(s.indices.size(), size_t(2 * 15 * 15 * 3));
  double area = 0.0;
  for (size_t t = 0; t < s.indices.size(); t += 3) {
    double a = signedAreaY(s, t);
    EXPECT_GT(a, 0.0) << "winding flipped in triangle " << t / 3;
    area += a;
  }
  EXPECT_NEAR(area, 100.0 * 100.0, 1e-2);
  for (size_t i = 0; i < 4; ++i) EXPECT_EQ(s.positions[i], q.positions[i]);  // kept
  for (size_t i = 0; i < s.positions.size(); ++i) {
    const glm::vec3 p = s.positions[i];
    // uv = (x, -z) / 100 on this quad, normal +y: interpolated exactly (to float).
    EXPECT_NEAR(s.uvs[i].x, p.x / 100.0f, 1e-5f);
    EXPECT_NEAR(s.uvs[i].y, -p.z / 100.0f, 1e-5f);
    EXPECT_EQ(s.normals[i], glm::vec3(0, 1, 0));
  }
  // Every edge is at most 10 m (the grid's legs are 100/15; its diagonals 141.42/15).
  for (size_t t = 0; t < s.indices.size(); t += 3)
    for (int k = 0; k < 3; ++k)
      EXPECT_LE(
          glm::distance(s.positions[s.indices[t + k]], s.positions[s.indices[t + (k + 1) % 3]]),
          10.0f);
}

// The shared diagonal is cut into the same points, bit for bit, by both triangles (which
// walk it in opposite directions): no T-junction, no crack.
TEST(MeshSplit, SharedEdgePointsAreBitIdentical) {
  TriangleMesh s = splitLongTriangles(quad(37.3f), 3.1f);
  std::map<std::tuple<float, float, float>, int> onDiagonal;
  for (const glm::vec3& p : s.positions) {
    // On the diagonal from (0,0,0) to (37.3,0,-37.3): x == -z up to rounding.
    if (std::abs(p.x + p.z) < 1e-3f) ++onDiagonal[{p.x, p.y, p.z}];
  }
  const int n = int(std::ceil(glm::length(glm::vec2(37.3f, 37.3f)) / 3.1f));
  // n - 1 inner points, each made twice (once per triangle) with identical bits.
  int inner = 0;
  for (const auto& [p, count] : onDiagonal) {
    bool corner = std::get<0>(p) == 0.0f || std::get<0>(p) == 37.3f;
    if (corner) continue;
    ++inner;
    EXPECT_EQ(count, 2) << std::get<0>(p) << "," << std::get<2>(p);
  }
  EXPECT_EQ(inner, n - 1);
}

}  // namespace
}  // namespace sl
