// First-hit rays against triangle meshes: a bounding volume hierarchy (median splits) over
// indexed triangles and the ray-triangle test it answers with (Moeller and Trumbore 1997).
// The glTF loader uses it to place a camera bookmark's focus at the surface it looks at.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace sl {

/// Distance along a ray to triangle (a, b, c), either side (Moeller-Trumbore), or +inf.
/// `dir` need not be unit length: the distance is in units of `dir`.
float rayTriangle(const glm::vec3& origin, const glm::vec3& dir, const glm::vec3& a,
                  const glm::vec3& b, const glm::vec3& c);

/// One mesh's triangles: every three `indices` name a triangle's corners in `positions`.
/// A trailing one or two indices are ignored.
struct TriangleMeshView {
  std::span<const glm::vec3> positions;
  std::span<const std::uint32_t> indices;
};

/// A bounding volume hierarchy over the triangles of several meshes, for first-hit rays:
/// O(n log n) to build (median splits), about O(log n) a ray. Built and walked with explicit
/// stacks (no recursion). The hit is the one a test of every triangle finds. The meshes'
/// data must outlive the hierarchy and stay unchanged.
class TriangleBvh {
 public:
  explicit TriangleBvh(std::vector<TriangleMeshView> meshes);

  /// Distance along the ray to the nearest triangle (either side), or +inf; in units of
  /// `dir`.
  float firstHit(const glm::vec3& origin, const glm::vec3& dir) const;

 private:
  static constexpr std::size_t kLeafSize = 4;
  struct Ref {
    std::uint32_t mesh, index;  ///< mesh, offset of the triangle's first index
  };
  struct Node {
    glm::vec3 lo{0.0f}, hi{0.0f};
    std::uint32_t first = 0;  ///< leaf: first ref; inner: left child (right = first + 1)
    std::uint32_t count = 0;  ///< refs in a leaf, 0 for an inner node
  };
  struct Corners {
    glm::vec3 a, b, c;
  };

  Corners corners(Ref r) const;
  /// Whether the ray can meet the node's box at a distance in [0, maxDist].
  static bool mayHit(const Node& n, const glm::vec3& o, const glm::vec3& d, float maxDist);

  std::vector<TriangleMeshView> meshes_;
  std::vector<Ref> refs_;
  std::vector<Node> nodes_;
};

}  // namespace sl
