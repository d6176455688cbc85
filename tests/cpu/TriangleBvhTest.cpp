// algo/TriangleBvh: first-hit rays against indexed triangles, exact on small inputs, and the
// hierarchy's answer equal to a test of every triangle on a larger one.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "algo/TriangleBvh.h"

namespace sl {
namespace {

constexpr float kMiss = std::numeric_limits<float>::infinity();

/// The triangle (0,0,z) (2,0,z) (0,2,z): facing +z or -z, either side counts.
std::vector<glm::vec3> triangleAt(float z) {
  return {{0, 0, z}, {2, 0, z}, {0, 2, z}};
}

const std::vector<std::uint32_t> kOneTriangle = {0, 1, 2};

TEST(TriangleBvh, RayTriangleHitsAtTheKnownDistanceFromEitherSide) {
  const auto t = triangleAt(-3.0f);
  EXPECT_EQ(rayTriangle({0.5f, 0.5f, 0.0f}, {0, 0, -1}, t[0], t[1], t[2]), 3.0f);
  EXPECT_EQ(rayTriangle({0.5f, 0.5f, -7.0f}, {0, 0, 1}, t[0], t[1], t[2]), 4.0f);
  // In units of `dir`: a direction of length 2 halves the distance.
  EXPECT_EQ(rayTriangle({0.5f, 0.5f, 0.0f}, {0, 0, -2}, t[0], t[1], t[2]), 1.5f);
}

TEST(TriangleBvh, RayTriangleMissesBehindBesideAndParallel) {
  const auto t = triangleAt(-3.0f);
  EXPECT_EQ(rayTriangle({0.5f, 0.5f, 0.0f}, {0, 0, 1}, t[0], t[1], t[2]), kMiss);   // behind
  EXPECT_EQ(rayTriangle({1.5f, 1.5f, 0.0f}, {0, 0, -1}, t[0], t[1], t[2]), kMiss);  // beside
  EXPECT_EQ(rayTriangle({0.5f, 0.5f, -3.0f}, {1, 0, 0}, t[0], t[1], t[2]), kMiss);  // in plane
}

TEST(TriangleBvh, OneTriangleHitAtTheKnownDistance) {
  const auto positions = triangleAt(-3.0f);
  TriangleBvh bvh({{positions, kOneTriangle}});
  EXPECT_EQ(bvh.firstHit({0.5f, 0.5f, 0.0f}, {0, 0, -1}), 3.0f);
  EXPECT_EQ(bvh.firstHit({0.5f, 0.5f, 1.0f}, {0, 0, -1}), 4.0f);
}

TEST(TriangleBvh, RayBesideOrAwayMisses) {
  const auto positions = triangleAt(-3.0f);
  TriangleBvh bvh({{positions, kOneTriangle}});
  EXPECT_EQ(bvh.firstHit({5.0f, 5.0f, 0.0f}, {0, 0, -1}), kMiss);
  EXPECT_EQ(bvh.firstHit({0.5f, 0.5f, 0.0f}, {0, 0, 1}), kMiss);
}

TEST(TriangleBvh, NearestOfTwoMeshesInEitherOrder) {
  const auto near = triangleAt(-2.0f), far = triangleAt(-5.0f);
  for (bool nearFirst : {true, false}) {
    std::vector<TriangleMeshView> meshes{{near, kOneTriangle}, {far, kOneTriangle}};
    if (!nearFirst) std::swap(meshes[0], meshes[1]);
    TriangleBvh bvh(meshes);
    EXPECT_EQ(bvh.firstHit({0.5f, 0.5f, 0.0f}, {0, 0, -1}), 2.0f) << nearFirst;
    EXPECT_EQ(bvh.firstHit({0.5f, 0.5f, -10.0f}, {0, 0, 1}), 5.0f) << nearFirst;
  }
}

TEST(TriangleBvh, EmptyInputAndTrailingIndicesMissEverything) {
  EXPECT_EQ(TriangleBvh(std::vector<TriangleMeshView>{}).firstHit({0, 0, 0}, {0, 0, -1}), kMiss);
  const auto positions = triangleAt(-3.0f);
  const std::vector<std::uint32_t> twoIndices = {0, 1};  // not a triangle
  TriangleBvh bvh({{positions, twoIndices}, {positions, {}}});
  EXPECT_EQ(bvh.firstHit({0.5f, 0.5f, 0.0f}, {0, 0, -1}), kMiss);
}

TEST(TriangleBvh, ManyTrianglesAnswerAsATestOfEveryTriangle) {
  // A 16 x 16 grid of small triangles at depths that vary per cell: far more than a leaf, so
  // the rays walk inner nodes; each answer must equal the brute-force minimum.
  std::vector<glm::vec3> positions;
  std::vector<std::uint32_t> indices;
  for (int i = 0; i < 16; ++i)
    for (int j = 0; j < 16; ++j) {
      const float z = -1.0f - float((i * 7 + j * 3) % 11);
      const auto base = std::uint32_t(positions.size());
      positions.push_back({float(i), float(j), z});
      positions.push_back({float(i) + 1.5f, float(j), z});
      positions.push_back({float(i), float(j) + 1.5f, z});
      indices.insert(indices.end(), {base, base + 1, base + 2});
    }
  TriangleBvh bvh({{positions, indices}});
  int hits = 0;
  for (int k = 0; k < 40; ++k) {
    const glm::vec3 origin(0.37f * float(k) - 0.5f, 0.41f * float(k % 17), 2.0f);
    const glm::vec3 dir(0.01f * float(k % 5), -0.02f * float(k % 3), -1.0f);
    float expected = kMiss;
    for (std::size_t t = 0; t < indices.size(); t += 3)
      expected =
          std::min(expected, rayTriangle(origin, dir, positions[indices[t]],
                                         positions[indices[t + 1]], positions[indices[t + 2]]));
    EXPECT_EQ(bvh.firstHit(origin, dir), expected) << k;
    hits += expected < kMiss;
  }
  EXPECT_GT(hits, 20);
}

}  // namespace
}  // namespace sl
