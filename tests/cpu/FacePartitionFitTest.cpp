// Face partitioning as rendered (algo/partition/FacePartitionFit): the selection rule (the
// face a point's light ray leaves through), the slots, the bisector axes, the analysis'
// storage factor with the light behind / in front of the viewer (Lloyd et al. 2006 §5.1), the
// combined scheme (face.zsplits: slices at the log split, each face-partitioned) against the
// analysis' face+cascades, and the messages for bad input.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <set>

#include "algo/partition/FacePartitionFit.h"
#include "algo/partition/StorageFactor.h"

namespace sl::partition {
namespace {

Camera lookingDownMinusZ() {
  Camera c;
  c.position = {0.0f, 1.2f, 2.0f};
  c.target = {0.0f, 0.2f, -12.0f};
  c.fovYDeg = 50.0f;
  c.nearM = 0.1f;
  c.farM = 120.0f;
  return c;
}

Aabb groundBox() {
  Aabb b;
  b.extend(glm::vec3(-16.0f, 0.0f, -90.0f));
  b.extend(glm::vec3(16.0f, 4.0f, 4.0f));
  return b;
}

glm::dvec3 towards(double azimuthDeg, double elevationDeg) {
  const double az = glm::radians(azimuthDeg), el = glm::radians(elevationDeg);
  return {std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)};
}

constexpr double kAspect = 16.0 / 9.0;

// For random points of the clipped frustum, the selected slot's face is the one the ray
// p + t rayDir leaves through: the exit point lies inside every other face's plane, on the
// selected face's plane; and that face's partition exists (slot in use).
TEST(FacePartitionFit, SelectionIsTheFaceTheLightRayLeavesThrough) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0), w(0.0, 1.0);
  for (const glm::dvec3& l :
       {towards(180, 14), towards(0, 14), towards(120, 40), towards(90, 5), towards(0, 89)}) {
    FacePartitionFit fit;
    ASSERT_FALSE(fitFacePartitions(lookingDownMinusZ(), kAspect, groundBox(), l, 0.0, fit));
    ASSERT_FALSE(fit.parts.empty());
    const warp::ViewFrustum& v = fit.view;
    for (int i = 0; i < 500; ++i) {
      const double z = v.nearM + (v.farM - v.nearM) * w(rng);
      const glm::dvec3 p = v.eye + z * v.forward + u(rng) * z * v.tanHalfX() * v.right() +
                           u(rng) * z * v.tanHalfY() * v.up;
      double gap = 0.0;
      const int slot = selectFacePartition(fit.selection, p, &gap);
      int face = -1;
      for (int f = 0; f < 6; ++f)
        if (fit.selection.partitionOfFace[std::size_t(f)] == slot) face = f;
      ASSERT_GE(face, 0);
      const glm::dvec4 pl = fit.selection.planes[std::size_t(face)];
      const double t =
          (pl.w - glm::dot(glm::dvec3(pl), p)) / glm::dot(glm::dvec3(pl), fit.selection.rayDir);
      EXPECT_GE(t, -1e-9);  // p is inside: the exit lies ahead
      const glm::dvec3 q = p + t * fit.selection.rayDir;
      for (const glm::dvec4& o : fit.selection.planes)
        EXPECT_LE(glm::dot(glm::dvec3(o), q) - o.w, 1e-7 * v.farM);
      EXPECT_GE(gap, 0.0);
    }
  }
}

// Front faces when v . y < 0 (light behind), back faces otherwise; slots fixed per face; the
// side faces warp along the bisector of their projected side edges (perpendicular to the
// light, at equal angles to both projected edges).
TEST(FacePartitionFit, FacesSlotsAndBisectors) {
  int bisectors = 0;
  for (const glm::dvec3& l : {towards(180, 14), towards(0, 14), towards(120, 40)}) {
    FacePartitionFit fit;
    ASSERT_FALSE(fitFacePartitions(lookingDownMinusZ(), kAspect, groundBox(), l, 0.0, fit));
    const glm::dvec3 y = glm::normalize(l);
    EXPECT_EQ(fit.selection.frontFaces, glm::dot(fit.view.forward, y) < 0.0);
    EXPECT_EQ(fit.selection.rayDir, fit.selection.frontFaces ? y : -y);
    const auto c = fit.view.corners();
    // Side faces' near corners (ViewFrustum::corners): -x {0, 3}, +x {1, 2}, -y {0, 1}, +y {3, 2}.
    const int sideCorners[6][2] = {{0, 0}, {0, 0}, {0, 3}, {1, 2}, {0, 1}, {3, 2}};
    for (const FacePart& p : fit.parts) {
      EXPECT_EQ(p.slot, faceSlot(p.face));
      EXPECT_EQ(fit.selection.partitionOfFace[std::size_t(p.face)], p.slot);
      EXPECT_NEAR(glm::dot(p.fit.space.z, y), 0.0, 1e-12);
      if (p.face < 2 || p.fit.uniform) continue;
      glm::dvec3 e[2];
      for (int k = 0; k < 2; ++k) {
        const int i = sideCorners[p.face][k];
        const glm::dvec3 d = c[std::size_t(i + 4)] - c[std::size_t(i)];
        e[k] = glm::normalize(d - glm::dot(d, y) * y);
      }
      EXPECT_NEAR(glm::dot(p.fit.space.z, e[0]), glm::dot(p.fit.space.z, e[1]), 1e-9) << p.face;
      EXPECT_GT(glm::dot(p.fit.space.z, e[0]), 0.0) << p.face;
      ++bisectors;
    }
  }
  EXPECT_GE(bisectors, 6);  // the warped side faces of the three lights
  EXPECT_EQ(faceSlot(0), 0);
  EXPECT_EQ(faceSlot(1), -1);
  EXPECT_EQ(faceSlot(5), 4);
}

// The dueling case in the analysis: the camera's frustum (near 0.1, far 120, 50 degrees,
// 16:9) with the light 14 degrees up in front of it and behind it. LiSPSM reverts to
// uniform (the same S as uniform), face partitioning lowers S by more than 10x.
TEST(FacePartitionFit, AnalysisFacePartitioningLowersStorageWhenFrustaDuel) {
  const warp::ViewFrustum v = warp::ViewFrustum::fromCamera(lookingDownMinusZ(), kAspect);
  for (const glm::dvec3& l : {towards(180, 14), towards(0, 14)}) {
    auto eval = [&](Scheme s) {
      SchemeSettings st;
      st.scheme = s;
      StorageResult r;
      EXPECT_FALSE(evaluateScheme(v, l, st, r));
      return r;
    };
    const StorageResult uni = eval(Scheme::Uniform), lis = eval(Scheme::Lispsm),
                        face = eval(Scheme::Face);
    ASSERT_EQ(lis.parts.size(), 1u);
    EXPECT_TRUE(lis.parts[0].fit.fallback);
    EXPECT_DOUBLE_EQ(lis.s, uni.s);
    EXPECT_LT(face.s, 0.1 * lis.s) << "face " << face.s << " lispsm " << lis.s;
  }
}

// The combined scheme (face.zsplits = k), slices first: the clipped frustum cut at the log split
// z_i = n (f/n)^(i/k) exactly (Splits.h), every part inside its slice's depth range, in the
// slot of its (slice, face); with a scene box around the whole frustum (no clipping) the
// rendered parts are the analysis' Scheme::FaceCascades parts (the same bodies, the same
// storage factor S per part: what `shadowlab-cli storage --scheme face+cascades` predicts).
TEST(FacePartitionFit, ZSplitsAreTheAnalysedFaceCascades) {
  Aabb huge;
  huge.extend(glm::vec3(-500.0f, -500.0f, -500.0f));
  huge.extend(glm::vec3(500.0f, 500.0f, 500.0f));
  for (const glm::dvec3& l : {towards(180, 14), towards(0, 14), towards(120, 40)})
    for (int k : {2, 3, 4}) {
      SCOPED_TRACE(k);
      FacePartitionFit fit;
      ASSERT_FALSE(fitFacePartitions(lookingDownMinusZ(), kAspect, huge, l, 0.0, fit, k,
                                     FaceNesting::ZSplitsFirst));
      const warp::ViewFrustum& v = fit.view;
      EXPECT_EQ(fit.splits, splitDistances(SplitScheme::Log, v.nearM, v.farM, k));
      EXPECT_EQ(fit.slots(), 5 * k);
      ASSERT_EQ(fit.selection.planes.size(), 6u * std::size_t(k));
      std::set<int> slices;
      for (const FacePart& p : fit.parts) {
        EXPECT_EQ(p.slot, p.slice * kFaceSlots + faceSlot(p.face));
        EXPECT_EQ(fit.selection.partitionOfFace[6 * std::size_t(p.slice) + std::size_t(p.face)],
                  p.slot);
        EXPECT_GE(p.nearM, fit.splits[std::size_t(p.slice)] - 1e-9 * v.farM);
        EXPECT_LE(p.farM, fit.splits[std::size_t(p.slice) + 1] + 1e-9 * v.farM);
        slices.insert(p.slice);
      }
      EXPECT_EQ(int(slices.size()), k);
      SchemeSettings st;
      st.scheme = Scheme::FaceCascades;
      st.partitions = k;
      st.split = SplitScheme::Log;
      StorageResult analysed;
      ASSERT_FALSE(evaluateScheme(v, l, st, analysed));
      ASSERT_EQ(analysed.parts.size(), fit.parts.size());
      double renderedS = 0.0;
      for (std::size_t i = 0; i < fit.parts.size(); ++i) {
        const FacePart& p = fit.parts[i];
        const PartStorage& a = analysed.parts[i];
        EXPECT_EQ(a.label, "z " + std::to_string(p.slice + 1) + "/" + std::to_string(k) + " face " +
                               faceName(p.face));
        ASSERT_EQ(a.body.size(), p.body.size()) << a.label;
        for (const glm::dvec3& q : p.body) {  // the same vertices (in another order)
          double nearest = 1e30;
          for (const glm::dvec3& o : a.body) nearest = std::min(nearest, glm::length(o - q));
          EXPECT_LE(nearest, 1e-9 * v.farM) << a.label;
        }
        const Storage rendered = storageOfBody(v, p.fit, p.body);
        EXPECT_NEAR(rendered.s, a.storage.s, 1e-9 * a.storage.s) << a.label;
        renderedS += rendered.s;
      }
      EXPECT_NEAR(renderedS, analysed.s, 1e-9 * analysed.s);
    }
}

// With slices, a point takes the slice of its view depth (the first whose far split is not
// below it), then the face its light ray leaves THAT slice through; the gap is the smaller of
// the distance to a split and the second face's. Points inside the scene bounds (a slice's
// face whose light prism misses the scene has no map: points outside the bounds, where no
// geometry is, may take another face).
TEST(FacePartitionFit, ZSplitSelectionIsTheSliceThenTheExitFace) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(-1.0, 1.0), w(0.0, 1.0);
  const Aabb box = groundBox();
  for (const glm::dvec3& l : {towards(180, 14), towards(0, 14), towards(120, 40)}) {
    FacePartitionFit fit;
    ASSERT_FALSE(fitFacePartitions(lookingDownMinusZ(), kAspect, box, l, 0.0, fit, 3,
                                   FaceNesting::ZSplitsFirst));
    const warp::ViewFrustum& v = fit.view;
    std::set<int> used;
    int tested = 0;
    for (int i = 0; i < 2000; ++i) {
      const double z = v.nearM + (v.farM - v.nearM) * w(rng);
      const glm::dvec3 p = v.eye + z * v.forward + u(rng) * z * v.tanHalfX() * v.right() +
                           u(rng) * z * v.tanHalfY() * v.up;
      if (glm::any(glm::lessThan(p, glm::dvec3(box.min))) ||
          glm::any(glm::greaterThan(p, glm::dvec3(box.max))))
        continue;
      ++tested;
      double gap = 0.0;
      const int slot = selectFacePartition(fit.selection, p, &gap);
      const int slice = slot / kFaceSlots;
      used.insert(slot);
      EXPECT_GE(z, fit.splits[std::size_t(slice)] - 1e-9);
      EXPECT_LE(z, fit.splits[std::size_t(slice) + 1] + 1e-9);
      for (std::size_t s = 1; s + 1 < fit.splits.size(); ++s)
        EXPECT_LE(gap, std::abs(z - fit.splits[s]) + 1e-9);
      int face = -1;
      for (int f = 0; f < 6; ++f)
        if (fit.selection.partitionOfFace[6 * std::size_t(slice) + std::size_t(f)] == slot)
          face = f;
      ASSERT_GE(face, 0);
      const glm::dvec4 pl = fit.selection.planes[6 * std::size_t(slice) + std::size_t(face)];
      const double t =
          (pl.w - glm::dot(glm::dvec3(pl), p)) / glm::dot(glm::dvec3(pl), fit.selection.rayDir);
      EXPECT_GE(t, -1e-9);
      const glm::dvec3 q = p + t * fit.selection.rayDir;
      for (int f = 0; f < 6; ++f) {
        const glm::dvec4 o = fit.selection.planes[6 * std::size_t(slice) + std::size_t(f)];
        EXPECT_LE(glm::dot(glm::dvec3(o), q) - o.w, 1e-7 * v.farM);
      }
      EXPECT_GE(gap, 0.0);
    }
    EXPECT_GE(tested, 200);      // measured 271 to 287 of the 2000 per light
    EXPECT_GE(used.size(), 6u);  // several faces of several slices
  }
}

TEST(FacePartitionFit, BadInputIsNamed) {
  FacePartitionFit fit;
  auto e = fitFacePartitions(lookingDownMinusZ(), kAspect, Aabb{}, towards(0, 30), 0.0, fit);
  ASSERT_TRUE(e);
  EXPECT_NE(e->find("scene bounds are empty"), std::string::npos) << *e;
  e = fitFacePartitions(lookingDownMinusZ(), kAspect, groundBox(), towards(0, 30), 1.5, fit);
  ASSERT_TRUE(e);
  EXPECT_NE(e->find("warp.eta"), std::string::npos) << *e;
  e = fitFacePartitions(lookingDownMinusZ(), kAspect, groundBox(), glm::dvec3(0.0), 0.0, fit);
  ASSERT_TRUE(e);
  EXPECT_NE(e->find("light direction"), std::string::npos) << *e;
  for (int k : {0, 5}) {
    e = fitFacePartitions(lookingDownMinusZ(), kAspect, groundBox(), towards(0, 30), 0.0, fit, k);
    ASSERT_TRUE(e);
    EXPECT_NE(e->find("face.zsplits must be in 1..4 (got " + std::to_string(k) + ")"),
              std::string::npos)
        << *e;
  }
}

// Faces first (the paper's nesting): every slice selects with the whole frustum's faces, so
// a point takes the face of face partitioning alone (k = 1) and the slice of its view depth;
// every part lies inside its slice's depth range and inside its face's partition of the
// whole frustum.
TEST(FacePartitionFit, FacesFirstCutsEachFacePartitionAlongItsLength) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0), w(0.0, 1.0);
  const Aabb box = groundBox();
  for (const glm::dvec3& l : {towards(180, 14), towards(0, 14), towards(120, 40)}) {
    FacePartitionFit one, fit, zFirst;
    ASSERT_FALSE(fitFacePartitions(lookingDownMinusZ(), kAspect, box, l, 0.0, one, 1));
    ASSERT_FALSE(fitFacePartitions(lookingDownMinusZ(), kAspect, box, l, 0.0, fit, 3,
                                   FaceNesting::FacesFirst));
    ASSERT_FALSE(fitFacePartitions(lookingDownMinusZ(), kAspect, box, l, 0.0, zFirst, 3,
                                   FaceNesting::ZSplitsFirst));
    EXPECT_EQ(fit.splits, zFirst.splits);
    for (int s = 0; s < 3; ++s)
      for (int f = 0; f < 6; ++f)
        EXPECT_EQ(fit.selection.planes[std::size_t(6 * s + f)],
                  one.selection.planes[std::size_t(f)]);
    for (const FacePart& p : fit.parts) {
      EXPECT_GE(p.nearM, fit.splits[std::size_t(p.slice)] - 1e-9 * fit.view.farM);
      EXPECT_LE(p.farM, fit.splits[std::size_t(p.slice) + 1] + 1e-9 * fit.view.farM);
      if (p.face < 0) continue;
      for (const glm::dvec3& q : p.body) {  // inside its face's partition of the whole frustum
        double gap = 0.0;
        const int whole = selectFacePartition(one.selection, q, &gap);
        if (gap > 1e-6 * fit.view.farM) {
          EXPECT_EQ(whole, faceSlot(p.face));
        }
      }
    }
    const warp::ViewFrustum& v = fit.view;
    int tested = 0, differs = 0;
    for (int i = 0; i < 2000; ++i) {
      const double z = v.nearM + (v.farM - v.nearM) * w(rng);
      const glm::dvec3 p = v.eye + z * v.forward + u(rng) * z * v.tanHalfX() * v.right() +
                           u(rng) * z * v.tanHalfY() * v.up;
      if (glm::any(glm::lessThan(p, glm::dvec3(box.min))) ||
          glm::any(glm::greaterThan(p, glm::dvec3(box.max))))
        continue;
      double gap = 0.0, gapOne = 0.0;
      const int map = selectFacePartition(fit.selection, p, &gap);
      const int face = selectFacePartition(one.selection, p, &gapOne);
      if (gap < 1e-9 * v.farM || gapOne < 1e-9 * v.farM) continue;
      ++tested;
      int slice = 0;
      while (slice < 2 && z > fit.splits[std::size_t(slice) + 1]) ++slice;
      EXPECT_EQ(map / kFaceSlots, slice);
      EXPECT_EQ(map % kFaceSlots, face);
      differs += selectFacePartition(zFirst.selection, p) != map;
    }
    EXPECT_GT(tested, 100);
    std::printf("light (%.2f %.2f %.2f): %d points, %d served by another map slices-first\n", l.x,
                l.y, l.z, tested, differs);
  }
}

}  // namespace
}  // namespace sl::partition
