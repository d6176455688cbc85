// Face partitioning for rendering (Lloyd, Tuft, Yoon, Manocha, EGSR 2006 §5.1): the view
// frustum split along its faces as seen from a directional light, one LiSPSM warp per face
// aligned to the bisector of its projected side edges, and the per-pixel selection rule that
// shaders/face-partition/lookup.glsl mirrors (selectFacePartition).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "algo/Camera.h"
#include "algo/warp/PerspectiveWarp.h"

namespace sl::partition {

/// What the lookup needs to pick a pixel's partition. A point P of the frustum lies on one
/// light ray; that ray leaves the frustum through exactly one face on the light's side (front
/// faces, used when v . y < 0) and one on the other side (back faces, otherwise). P belongs
/// to the partition of the face through which the ray P + t rayDir, t >= 0, leaves: the
/// smallest t_f = (d_f - n_f . P) / (n_f . rayDir) over the partition faces (n_f . rayDir > 0
/// for every one of them). Points outside the frustum (a normal offset) get the same rule.
struct FaceSelection {
  std::array<glm::dvec4, 6> planes{};  ///< outward unit normal, d (inside: n . p <= d)
  glm::dvec3 rayDir{0.0, 1.0, 0.0};    ///< towards the light (front faces) or away (back)
  std::array<int, 6> partitionOfFace{-1, -1, -1, -1, -1, -1};  ///< -1: no partition
  bool frontFaces = true;
};
/// The partition index serving world point `p` (see FaceSelection); 0 when no face has a
/// partition (FacePartitionFit then holds one uniform part).
/// `secondGap`, when given, receives t_second - t_best (infinite with one candidate): how far
/// along the ray the choice is from changing (the GPU/CPU parity test's margin).
int selectFacePartition(const FaceSelection& sel, const glm::dvec3& p, double* secondGap = nullptr);

/// One face partition as rendered: its face, the region it covers and its warp.
struct FacePart {
  int face = 0;  ///< 0 near, 2 -x, 3 +x, 4 -y, 5 +y (StorageFactor's order); -1 the fallback
  std::vector<glm::dvec3> body;    ///< frustum ∩ the face's light prism ∩ the scene bounds
  warp::WarpFit fit;               ///< LiSPSM (or the given eta) along the bisector
  double nearM = 0.0, farM = 0.0;  ///< view-depth range of the body
};

struct FacePartitionFit {
  warp::ViewFrustum view;  ///< the camera's frustum, near/far clipped to frustum ∩ scene
  FaceSelection selection;
  std::vector<FacePart> parts;  ///< layer i of the map array = parts[i]
};

/// Fits the face partitions of the camera's frustum ∩ `sceneBounds` for the directional
/// light `towardsLight`, each warped with eq. 11's `eta` (0 = LiSPSM) along its bisector (the
/// near face, which has no side edges, along the view vector, uniform where that looks
/// square). Scene-bound corners widen every map's depth range (casters). An error names the
/// input (empty bounds, a bad camera, eta out of range).
std::optional<std::string> fitFacePartitions(const Camera& camera, double aspect,
                                             const Aabb& sceneBounds,
                                             const glm::dvec3& towardsLight, double eta,
                                             FacePartitionFit& out);

}  // namespace sl::partition
