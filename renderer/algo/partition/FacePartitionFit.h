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

/// Map slots: a face that can face the light or away from it always has the same slot (the
/// far face never does: its normal is v, on the other side of the light from the near face's):
/// near 0, -x 1, +x 2, -y 3, +y 4. Unused slots stay empty, so memory, the publications'
/// cost and the partition overlay's colours do not depend on the light.
constexpr int kFaceSlots = 5;
/// The slot of frustum face `face` (StorageFactor's order), -1 for the far face.
int faceSlot(int face);

/// What the lookup needs to pick a pixel's partition. A point P of the frustum lies on one
/// light ray; that ray leaves the frustum through exactly one face on the light's side (front
/// faces, used when v . y < 0) and one on the other side (back faces, otherwise). P belongs
/// to the partition of the face through which the ray P + t rayDir, t >= 0, leaves: the
/// smallest t_f = (d_f - n_f . P) / (n_f . rayDir) over the partition faces (n_f . rayDir > 0
/// for every one of them). Points outside the frustum (a normal offset) get the same rule.
struct FaceSelection {
  std::array<glm::dvec4, 6> planes{};  ///< outward unit normal, d (inside: n . p <= d)
  glm::dvec3 rayDir{0.0, 1.0, 0.0};    ///< towards the light (front faces) or away (back)
  std::array<int, 6> partitionOfFace{-1, -1, -1, -1, -1, -1};  ///< its slot; -1: none
  bool frontFaces = true;
};
/// The slot serving world point `p` (see FaceSelection); 0 when no face has a partition
/// (FacePartitionFit then holds one uniform part in slot 0).
/// `secondGap`, when given, receives t_second - t_best (infinite with one candidate): how far
/// along the ray the choice is from changing (the GPU/CPU parity test's margin).
int selectFacePartition(const FaceSelection& sel, const glm::dvec3& p, double* secondGap = nullptr);

/// One face partition as rendered: its face, the region it covers and its warp.
struct FacePart {
  int face = 0;  ///< 0 near, 2 -x, 3 +x, 4 -y, 5 +y (StorageFactor's order); -1 the fallback
  int slot = 0;  ///< faceSlot(face): its layer of the map array
  std::vector<glm::dvec3> body;    ///< frustum ∩ the face's light prism ∩ the scene bounds
  warp::WarpFit fit;               ///< LiSPSM (or the given eta) along the bisector
  double nearM = 0.0, farM = 0.0;  ///< view-depth range of the body
};

struct FacePartitionFit {
  warp::ViewFrustum view;  ///< the camera's frustum, near/far clipped to frustum ∩ scene
  FaceSelection selection;
  std::vector<FacePart> parts;  ///< the used faces, in slot order
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
