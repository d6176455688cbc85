// Face partitioning for rendering (Lloyd, Tuft, Yoon, Manocha, EGSR 2006 §5.1): the view
// frustum split along its faces as seen from a directional light, one LiSPSM warp per face
// aligned to the bisector of its projected side edges, and the per-pixel selection rule that
// shaders/facepartition/lookup.glsl mirrors (selectFacePartition). Optionally z-partitioned
// too (their combined scheme): the frustum first cut in depth by the log split
// (Splits.h), then each slice cut along its own faces, one warped map per (slice, face).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "algo/Camera.h"
#include "algo/warp/PerspectiveWarp.h"
#include "common/shared_constants.h"

namespace sl::partition {

/// Map slots per depth slice: a face that can face the light or away from it always has the
/// same slot (the far face never does: its normal is v, on the other side of the light from
/// the near face's): near 0, -x 1, +x 2, -y 3, +y 4. Slice s's face slot f is map
/// s * kFaceSlots + f. Unused slots stay empty, so memory, the publications' cost and the
/// partition overlay's colours do not depend on the light.
constexpr int kFaceSlots = SL_FACE_SLOTS;
/// The most depth slices (face.zsplits); kFaceSlots * kMaxFaceZSplits maps fit the lookup.
constexpr int kMaxFaceZSplits = SL_FACE_MAX_ZSPLITS;
static_assert(kFaceSlots * kMaxFaceZSplits <= SL_MAX_DEPTH_MAPS);
/// The slot of frustum face `face` (StorageFactor's order) within its slice, -1 for the far face.
int faceSlot(int face);

/// What the lookup needs to pick a pixel's partition. With several depth slices, P first
/// takes the slice of its view depth d = (P - eye) . forward: the first slice s whose far
/// distance splitFarM[s] is not below d (the last one beyond), as cascades do. A point P of
/// the slice lies on one light ray; that ray leaves the slice through exactly one face on the
/// light's side (front faces, used when v . y < 0) and one on the other side (back faces,
/// otherwise). P belongs to the partition of the face through which the ray P + t rayDir,
/// t >= 0, leaves: the smallest t_f = (d_f - n_f . P) / (n_f . rayDir) over the slice's
/// partition faces (n_f . rayDir > 0 for every one of them). Points outside the frustum (a
/// normal offset) get the same rule.
struct FaceSelection {
  /// Slice s's faces are planes[6 s + f] (outward unit normal, d; inside: n . p <= d), f in
  /// StorageFactor's face order; one slice: 6 planes.
  std::vector<glm::dvec4> planes = std::vector<glm::dvec4>(6);
  glm::dvec3 rayDir{0.0, 1.0, 0.0};  ///< towards the light (front faces) or away (back)
  /// partitionOfFace[6 s + f]: the map of slice s's face f; -1: none.
  std::vector<int> partitionOfFace = std::vector<int>(6, -1);
  bool frontFaces = true;
  glm::dvec3 eye{0.0}, forward{0.0, 0.0, -1.0};  ///< the view depth of a point
  std::vector<double> splitFarM;                 ///< far view depth of each slice (m)
  int slices() const { return int(splitFarM.size()); }
};
/// The map serving world point `p` (see FaceSelection); slice s * kFaceSlots when no face of
/// its slice has a partition (FacePartitionFit then holds one uniform part in that slot).
/// `secondGap`, when given, receives how far the choice is from changing: the smaller of
/// t_second - t_best along the ray (infinite with one candidate) and, with several slices,
/// |d - split| for the nearest split (the GPU/CPU parity test's margin, metres).
int selectFacePartition(const FaceSelection& sel, const glm::dvec3& p, double* secondGap = nullptr);

/// One face partition as rendered: its face, the region it covers and its warp.
struct FacePart {
  int face = 0;   ///< 0 near, 2 -x, 3 +x, 4 -y, 5 +y (StorageFactor's order); -1 the fallback
  int slice = 0;  ///< its depth slice, 0 nearest
  int slot = 0;   ///< slice * kFaceSlots + faceSlot(face): its layer of the map array
  std::vector<glm::dvec3> body;    ///< frustum ∩ the face's light prism ∩ the scene bounds
  warp::WarpFit fit;               ///< LiSPSM (or the given eta) along the bisector
  double nearM = 0.0, farM = 0.0;  ///< view-depth range of the body
};

struct FacePartitionFit {
  warp::ViewFrustum view;  ///< the camera's frustum, near/far clipped to frustum ∩ scene
  FaceSelection selection;
  std::vector<FacePart> parts;  ///< the used faces, in slot order
  std::vector<double> splits;   ///< the slices' k + 1 view depths, view.nearM .. view.farM
  int slots() const { return kFaceSlots * int(selection.splitFarM.size()); }
};

/// Fits the face partitions of the camera's frustum ∩ `sceneBounds` for the directional
/// light `towardsLight`, each warped with eq. 11's `eta` (0 = LiSPSM) along its bisector (the
/// near face, which has no side edges, along the view vector, uniform where that looks
/// square). `zSplits` = k > 1 first cuts the clipped frustum into k slices at the log split
/// z_i = n (f/n)^(i/k) (splitDistances) and partitions each slice along its own faces (their
/// combined scheme; StorageFactor's Scheme::FaceCascades is its analysis), or (`nesting`
/// FacesFirst, the paper's order) partitions the whole frustum along its faces and cuts each
/// face partition at the same split depths; k = 1 is face
/// partitioning alone. Scene-bound corners widen every map's depth range (casters). An error
/// names the input (empty bounds, a bad camera, eta or zSplits out of range).
/// How face partitions and depth slices nest when zSplits > 1.
enum class FaceNesting {
  /// The faces of the whole (clipped) frustum, then each face partition cut along its length
  /// at the log split: Lloyd et al.'s "the view frustum or its face partitions along their
  /// length". Every slice selects with the whole frustum's planes.
  FacesFirst,
  /// The frustum cut into depth slices first, then each slice face-partitioned along its
  /// own faces (each slice has its own near face partition).
  ZSplitsFirst,
};
std::optional<std::string> fitFacePartitions(const Camera& camera, double aspect,
                                             const Aabb& sceneBounds,
                                             const glm::dvec3& towardsLight, double eta,
                                             FacePartitionFit& out, int zSplits = 1,
                                             FaceNesting nesting = FaceNesting::FacesFirst);

}  // namespace sl::partition
