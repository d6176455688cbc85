// Face partitioning for rendering (FacePartitionFit.h): clip the frustum to the scene, cut it
// along its faces (StorageFactor's facePartitions), warp every part along its bisector.
#include "FacePartitionFit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "Splits.h"
#include "StorageFactor.h"
#include "algo/Focus.h"

namespace sl::partition {

int faceSlot(int face) {
  constexpr std::array<int, 6> slots{0, -1, 1, 2, 3, 4};
  return face >= 0 && face < 6 ? slots[std::size_t(face)] : -1;
}

int selectFacePartition(const FaceSelection& sel, const glm::dvec3& p, double* secondGap) {
  // The slice by view depth (cascades' rule), then the face the light ray leaves it through.
  std::size_t s = 0;
  double splitGap = std::numeric_limits<double>::infinity();
  if (sel.splitFarM.size() > 1) {
    const double d = glm::dot(p - sel.eye, sel.forward);
    while (s + 1 < sel.splitFarM.size() && d > sel.splitFarM[s]) ++s;
    for (std::size_t i = 0; i + 1 < sel.splitFarM.size(); ++i)
      splitGap = std::min(splitGap, std::abs(d - sel.splitFarM[i]));
  }
  int best = -1;
  double bestT = std::numeric_limits<double>::infinity();
  double secondT = bestT;
  for (std::size_t f = 6 * s; f < 6 * s + 6; ++f) {
    if (sel.partitionOfFace[f] < 0) continue;
    const glm::dvec3 n(sel.planes[f]);
    const double nd = glm::dot(n, sel.rayDir);
    if (!(nd > 0.0)) continue;
    const double t = (sel.planes[f].w - glm::dot(n, p)) / nd;
    if (t < bestT) {
      secondT = bestT;
      bestT = t;
      best = sel.partitionOfFace[f];
    } else if (t < secondT) {
      secondT = t;
    }
  }
  if (secondGap) *secondGap = std::min(secondT - bestT, splitGap);
  return best < 0 ? int(s) * kFaceSlots : best;
}

std::optional<std::string> fitFacePartitions(const Camera& camera, double aspect,
                                             const Aabb& sceneBounds,
                                             const glm::dvec3& towardsLight, double eta,
                                             FacePartitionFit& out, int zSplits,
                                             FaceNesting nesting) {
  if (!sceneBounds.valid()) return "face partitions: the scene bounds are empty";
  if (!(eta >= -1.0 && eta <= 1.0)) return "face partitions: warp.eta must be in [-1, 1]";
  if (zSplits < 1 || zSplits > kMaxFaceZSplits)
    return "face partitions: face.zsplits must be in 1.." + std::to_string(kMaxFaceZSplits) +
           " (got " + std::to_string(zSplits) + ")";
  if (!(glm::length(towardsLight) > 1e-12) || !std::isfinite(glm::length(towardsLight)))
    return "face partitions: the light direction is zero or not finite";
  FacePartitionFit fit;
  fit.view = warp::ViewFrustum::fromCamera(camera, aspect);
  if (auto e = fit.view.validate()) return "face partitions: " + *e;
  const glm::dvec3 y = glm::normalize(towardsLight);

  // The frustum's depth range clipped to what it sees of the scene (as the perspective
  // warps do); the whole frustum when it sees none of it.
  const std::vector<glm::vec3> seen = intersectFrustumWithBox(
      camera.frustumCorners(float(aspect), camera.nearM, camera.farM), sceneBounds);
  std::optional<glm::dvec3> clipMin, clipMax;
  if (!seen.empty()) {
    double lo = fit.view.farM, hi = fit.view.nearM;
    for (const glm::vec3& p : seen) {
      const double d = glm::dot(glm::dvec3(p) - fit.view.eye, fit.view.forward);
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
    fit.view.nearM = std::clamp(lo, fit.view.nearM, fit.view.farM);
    fit.view.farM = std::max(std::min(hi, fit.view.farM), fit.view.nearM * (1.0 + 1e-6));
    clipMin = glm::dvec3(sceneBounds.min);
    clipMax = glm::dvec3(sceneBounds.max);
  }

  const auto box = sceneBounds.corners();
  warp::WarpSettings base;
  base.kind = warp::WarpKind::Eta;
  base.eta = eta;
  base.depthOnly.assign(box.begin(), box.end());  // every caster toward the light

  // The slices: the log split of the clipped depth range (k = 1: the whole of it).
  try {
    fit.splits = splitDistances(SplitScheme::Log, fit.view.nearM, fit.view.farM, zSplits);
  } catch (const std::invalid_argument& e) {
    return std::string("face partitions: ") + e.what();
  }
  fit.selection.frontFaces = glm::dot(fit.view.forward, y) < 0.0;
  fit.selection.rayDir = fit.selection.frontFaces ? y : -y;
  fit.selection.eye = fit.view.eye;
  fit.selection.forward = fit.view.forward;
  fit.selection.splitFarM.assign(fit.splits.begin() + 1, fit.splits.end());
  fit.selection.planes.assign(6 * std::size_t(zSplits), glm::dvec4(0.0));
  fit.selection.partitionOfFace.assign(6 * std::size_t(zSplits), -1);
  for (int s = 0; s < zSplits; ++s) {
    const double a = fit.splits[std::size_t(s)], b = fit.splits[std::size_t(s) + 1];
    // Faces first: the whole frustum's faces (and selection planes), bodies cut to the slice.
    const bool facesFirst = nesting == FaceNesting::FacesFirst && zSplits > 1;
    const double fa = facesFirst ? fit.view.nearM : a, fb = facesFirst ? fit.view.farM : b;
    const std::array<glm::dvec4, 6> planes = frustumFacePlanes(fit.view, fa, fb);
    std::copy(planes.begin(), planes.end(), fit.selection.planes.begin() + 6 * s);
    const std::size_t first = fit.parts.size();
    const std::optional<glm::dvec2> slab =
        facesFirst ? std::optional<glm::dvec2>(glm::dvec2(a, b)) : std::nullopt;
    for (FacePartition& f : facePartitions(fit.view, fa, fb, y, clipMin, clipMax, slab)) {
      FacePart part;
      part.face = f.face;
      part.slice = s;
      if (faceSlot(f.face) < 0) continue;  // the far face: never towards or away from the light
      part.slot = s * kFaceSlots + faceSlot(f.face);
      part.body = std::move(f.body);
      warp::WarpSettings ws = base;
      ws.axis = f.axis;
      if (f.axis) ws.projectedAxis = f.bisector;
      if (auto e = warp::fitWarp(fit.view, part.body, y, ws, part.fit))
        return "face partitions: " + *e;
      part.nearM = std::numeric_limits<double>::max();
      part.farM = -part.nearM;
      for (const glm::dvec3& p : part.body) {
        const double d = glm::dot(p - fit.view.eye, fit.view.forward);
        part.nearM = std::min(part.nearM, d);
        part.farM = std::max(part.farM, d);
      }
      fit.selection.partitionOfFace[6 * std::size_t(s) + std::size_t(f.face)] = part.slot;
      fit.parts.push_back(std::move(part));
    }
    if (fit.parts.size() > first) continue;
    // No face region with volume in this slice (the frustum sees a flat sliver of the
    // scene): one uniform map over what the slice sees, selected everywhere in the slice
    // (its first slot).
    FacePart part;
    part.face = -1;
    part.slice = s;
    part.slot = s * kFaceSlots;
    const std::vector<glm::vec3> sliceSeen =
        zSplits == 1 ? seen
                     : intersectFrustumWithBox(
                           camera.frustumCorners(float(aspect), float(a), float(b)), sceneBounds);
    if (sliceSeen.empty()) {
      const auto c = fit.view.corners(a, b);
      part.body.assign(c.begin(), c.end());
    } else {
      part.body.assign(sliceSeen.begin(), sliceSeen.end());
    }
    warp::WarpSettings ws = base;
    ws.kind = warp::WarpKind::Uniform;
    if (auto e = warp::fitWarp(fit.view, part.body, y, ws, part.fit))
      return "face partitions: " + *e;
    part.nearM = a;
    part.farM = b;
    fit.parts.push_back(std::move(part));
  }
  out = std::move(fit);
  return std::nullopt;
}

}  // namespace sl::partition
