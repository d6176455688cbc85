// Splitting long triangles for non-linear light passes (RTW's warped map; later the
// dual-paraboloid map). A warped pass bends each edge by tessellation, but the tessellator
// stops at a level cap (16 here: llvmpipe corrupts the map at 32-64); an edge that needs
// more than the cap would be clamped and its silhouette would miss by many texels (a 60 m
// wall under a strong warp). Triangles whose longest edge exceeds `maxEdgeM` are therefore
// cut, once at upload, into a regular grid of n^2 triangles (n = ceil(longest / maxEdgeM)),
// so every edge the tessellator sees is at most maxEdgeM long.
// Exact definitions (the tests check them):
//  - grid vertex (i, j), 0 <= i, j, i + j <= n: barycentrics (a, b, c) = ((n-i-j)/n, i/n, j/n)
//    of the corners (p0, p1, p2); attributes (position, normal, uv) interpolated with them.
//  - vertices on an original edge are computed from the edge's two corners ordered
//    canonically (lexicographically by position), p = lo + (hi - lo) * (k / n), so two
//    triangles sharing that edge with the same n produce bit-identical points (watertight).
//  - the sub-triangles keep the winding of the original; unsplit triangles keep their
//    original indices, and every original vertex is kept.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace sl {

struct TriangleMesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;  ///< empty or one per position
  std::vector<glm::vec2> uvs;      ///< empty or one per position
  std::vector<std::uint32_t> indices;
};

/// The split of `mesh` (see above). maxEdgeM not > 0: the mesh unchanged.
TriangleMesh splitLongTriangles(const TriangleMesh& mesh, float maxEdgeM);

}  // namespace sl
