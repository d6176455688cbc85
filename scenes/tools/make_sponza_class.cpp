// A generated Sponza-class atrium for timing measurements (`--sponza-class OUT.glb`): the
// triangle count (about 262 k by default, as the Crytek Sponza of the DA-RTW poster's Table 1,
// Tokuyoshi et al. 2014) and an atrium's depth complexity and occlusion, nothing more: a
// floor, two storeys of arcades (finely tessellated columns, arches), walls, hanging drapes,
// a roof open over the courtyard, a sun through it, a camera looking along the atrium.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>

#include "SceneBuilder.h"

namespace sl::gen {

namespace {
constexpr float kPi = 3.14159265358979f;

// The atrium: the courtyard |x| < kCourtHalfX, galleries out to the walls at |x| =
// kWallX, kBays arcade bays of kBayM along z. Ground storey: columns to kColumn1TopM, arches
// (radius kBayM / 2) under a band to kStorey2FloorM; upper storey the same up to kRoofM.
constexpr int kBays = 12;
constexpr float kBayM = 3.0f;
constexpr float kHalfLengthM = 0.5f * kBays * kBayM;  // 18 m
constexpr float kCourtHalfX = 5.0f, kWallX = 9.0f;
constexpr float kColumnRadiusM = 0.32f;
constexpr float kColumn1TopM = 3.6f, kStorey2FloorM = 5.6f;
constexpr float kColumn2TopM = 8.6f, kRoofM = 10.6f;
constexpr float kArcadeThicknessM = 0.7f;  ///< the arcade wall (spandrels, bands) in x

/// How finely the curved parts are tessellated; every count grows with one scale.
struct Tessellation {
  int columnSegments, columnRings;  ///< around and along every column
  int archSegments;                 ///< along every semicircular arch
  int drapeColumns, drapeRows;      ///< grid of every drape
};

Tessellation tessellationAt(float scale) {
  auto level = [scale](float base, int least) { return std::max(least, int(base * scale + 0.5f)); };
  return {level(32.0f, 6), level(16.0f, 1), level(48.0f, 4), level(24.0f, 2), level(40.0f, 2)};
}

/// A fluted column with entasis standing on `base`, `heightM` tall, with a square plinth and
/// capital.
void addColumn(MeshData& m, const glm::vec3& base, float heightM, const Tessellation& t) {
  addSurface(m, t.columnSegments, t.columnRings, [&](float u, float v) {
    const float a = 2.0f * kPi * u;  // from +x towards -z: outward faces
    const float r = kColumnRadiusM * (1.0f - 0.12f * v * v) * (1.0f + 0.03f * std::cos(16.0f * a));
    return base + glm::vec3(r * std::cos(a), heightM * v, -r * std::sin(a));
  });
  const float plinth = kColumnRadiusM + 0.08f;
  m.addBox(base + glm::vec3(0.0f, 0.1f, 0.0f), {plinth, 0.1f, plinth});
  m.addBox(base + glm::vec3(0.0f, heightM - 0.1f, 0.0f), {plinth, 0.1f, plinth});
}

/// One arch of an arcade running along z at x = `x`: a semicircle of radius kBayM / 2
/// springing at `springM` over the bay centred at `zc`, its spandrels up to `topM` on both
/// faces and its soffit (the curved underside).
void addArch(MeshData& m, float x, float zc, float springM, float topM, int segments) {
  const float r = 0.5f * kBayM, t = 0.5f * kArcadeThicknessM;
  // Angle from +z over the top to -z (u = 0 .. 1).
  auto intrados = [&](float u) {
    const float a = kPi * u;
    return glm::vec2(zc + r * std::cos(a), springM + r * std::sin(a));  // (z, y)
  };
  // Where the ray from the arch's centre through intrados(u) leaves the bay's rectangle.
  auto outer = [&](float u) {
    const float a = kPi * u;
    const glm::vec2 d(std::cos(a), std::sin(a));
    float s = std::abs(d.x) > 1e-6f ? r / std::abs(d.x) : 1e9f;
    s = std::min(s, (topM - springM) / std::max(d.y, 1e-6f));
    return glm::vec2(zc, springM) + s * d;
  };
  for (float side : {-1.0f, 1.0f}) {
    // Faces at x - t (facing -x) and x + t (facing +x); they vanish at the spring line.
    const glm::vec3 n(side, 0.0f, 0.0f);
    addSurface(
        m, segments, 1,
        [&](float u, float v) {
          const float uu = side > 0.0f ? u : 1.0f - u;
          const glm::vec2 p = glm::mix(intrados(uu), outer(uu), v);
          return glm::vec3(x + side * t, p.y, p.x);
        },
        &n);
  }
  addSurface(m, segments, 1, [&](float u, float v) {  // soffit, facing down and in
    const glm::vec2 p = intrados(u);
    return glm::vec3(x - t + 2.0f * t * v, p.y, p.x);
  });
}

/// A drape hanging from `topM` at x = `x` over the bay centred at `zc`, folded in x, facing
/// the courtyard (`side` -1: at negative x).
void addDrape(MeshData& m, float x, float zc, float topM, const Tessellation& t, float side) {
  const float halfWidth = 0.42f * kBayM, length = 4.2f;
  addSurface(m, t.drapeColumns, t.drapeRows, [&](float u, float v) {
    const float z = zc - side * halfWidth * (2.0f * u - 1.0f);
    const float fold = 0.12f * std::sin(2.0f * kPi * 4.0f * u) * (0.4f + 0.6f * v);
    const float sway = 0.25f * v * v;  // the hem blown towards the courtyard
    return glm::vec3(x - side * (fold + sway), topM - length * v, z);
  });
}

struct AtriumMeshes {
  MeshData floor, walls, arcades, columns, drapes;
  std::size_t triangleCount() const {
    return floor.triangleCount() + walls.triangleCount() + arcades.triangleCount() +
           columns.triangleCount() + drapes.triangleCount();
  }
};

AtriumMeshes buildAtrium(const Tessellation& t) {
  AtriumMeshes a;
  const float L = kHalfLengthM, W = kWallX;
  a.floor.addQuad({-W, 0.0f, L}, {W, 0.0f, L}, {W, 0.0f, -L}, {-W, 0.0f, -L},
                  glm::vec2(2.0f * W, 2.0f * L));
  // Outer walls, end walls (the courtyard closed at both ends) and the gallery floor and
  // roof slabs; the roof is open over the courtyard.
  for (float s : {-1.0f, 1.0f}) {
    a.walls.addBox({s * (W + 0.25f), 0.5f * kRoofM + 0.2f, 0.0f},
                   {0.25f, 0.5f * kRoofM + 0.2f, L + 0.5f});
    a.walls.addBox({0.0f, 0.5f * kRoofM + 0.2f, s * (L + 0.25f)}, {W, 0.5f * kRoofM + 0.2f, 0.25f});
    const float galleryX = 0.5f * (kCourtHalfX + W);
    const float galleryHalf = 0.5f * (W - kCourtHalfX) + 0.5f * kArcadeThicknessM;
    a.walls.addBox({s * galleryX, kStorey2FloorM - 0.15f, 0.0f}, {galleryHalf, 0.15f, L});
    a.walls.addBox({s * galleryX, kRoofM + 0.2f, 0.0f}, {galleryHalf, 0.2f, L});
    // A parapet round the roof opening.
    a.walls.addBox({s * kCourtHalfX, kRoofM + 0.8f, 0.0f}, {0.5f * kArcadeThicknessM, 0.4f, L});
  }
  for (float s : {-1.0f, 1.0f}) {
    const float x = s * kCourtHalfX;
    for (int k = 0; k <= kBays; ++k) {
      const float z = -L + kBayM * float(k);
      addColumn(a.columns, {x, 0.0f, z}, kColumn1TopM, t);
      addColumn(a.columns, {x, kStorey2FloorM, z}, kColumn2TopM - kStorey2FloorM, t);
    }
    for (int k = 0; k < kBays; ++k) {
      const float zc = -L + kBayM * (float(k) + 0.5f);
      addArch(a.arcades, x, zc, kColumn1TopM, kStorey2FloorM, t.archSegments);
      addArch(a.arcades, x, zc, kColumn2TopM, kRoofM, t.archSegments);
      // Drapes hang in front of the upper arcade, into the courtyard's light.
      addDrape(a.drapes, x - s * 0.6f, zc, kColumn2TopM + 0.4f, t, s);
    }
  }
  return a;
}
}  // namespace

/// The atrium with about `targetTriangles` triangles (the largest tessellation at or under
/// it, the coarsest when even that is over); deterministic.
SceneBuilder makeSponzaClass(std::size_t targetTriangles) {
  // The triangle count grows with the scale; bisect for the largest scale that fits.
  float lo = 0.0f, hi = 16.0f;
  for (int i = 0; i < 40; ++i) {
    const float mid = 0.5f * (lo + hi);
    (buildAtrium(tessellationAt(mid)).triangleCount() <= targetTriangles ? lo : hi) = mid;
  }
  const AtriumMeshes a = buildAtrium(tessellationAt(lo));

  SceneBuilder b("sponza-class");
  int stone = b.addMaterial("stone", {0.72f, 0.68f, 0.60f, 1.0f});
  int floorMat = b.addMaterial("floor", {0.55f, 0.50f, 0.44f, 1.0f});
  int cloth = b.addMaterial("cloth", {0.62f, 0.16f, 0.14f, 1.0f}, "OPAQUE", 0.5f, true);
  b.addNode("floor", b.addMesh("floor", a.floor, floorMat));
  b.addNode("walls", b.addMesh("walls", a.walls, stone));
  b.addNode("arcades", b.addMesh("arcades", a.arcades, stone));
  b.addNode("columns", b.addMesh("columns", a.columns, stone));
  b.addNode("drapes", b.addMesh("drapes", a.drapes, cloth));
  // The sun through the open roof, across and a little along the courtyard.
  b.addSun(60.0f, 62.0f);
  b.addCamera("atrium", {0.0f, 1.8f, kHalfLengthM - 1.0f}, {0.0f, 3.5f, -kHalfLengthM}, 60.0f, 0.1f,
              80.0f);
  return b;
}

}  // namespace sl::gen
