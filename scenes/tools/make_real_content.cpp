// Real-content scenes: shapes of the kind users load (a detailed helmet, a room lit through a
// window, a human figure, a car), built procedurally so that they can be committed and
// regenerated. Unlike the lesson scenes they are not built around one shadow effect: curved,
// finely tessellated surfaces, thin parts (visor slit, fingers, mirror stalks, axles) and
// small objects in a large ground, each with its own sun, camera bookmarks and camera path.
// docs/results/real-content.md measures the techniques on them.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "SceneBuilder.h"

namespace sl::gen {

namespace {
constexpr float kPi = 3.14159265358979f;

/// |c|^e with the sign of c (superquadric profiles).
float signedPow(float c, float e) {
  return std::copysign(std::pow(std::abs(c), e), c);
}

/// A point `distM` from `target` at azimuth/elevation (degrees, the sun's convention).
glm::vec3 orbit(const glm::vec3& target, float azimuthDeg, float elevationDeg, float distM) {
  return target + distM * towardsLightFromAngles(azimuthDeg, elevationDeg);
}

/// A right-handed frame (x, y = unit axis, z) around `axis`.
glm::mat3 frameAround(const glm::vec3& axis) {
  const glm::vec3 y = glm::normalize(axis);
  const glm::vec3 helper = std::abs(y.y) > 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  const glm::vec3 z = glm::normalize(glm::cross(helper, y));
  const glm::vec3 x = glm::cross(y, z);
  return glm::mat3(x, y, z);
}

/// A unit-sphere point at azimuth u (from +x towards -z) and height v (0 bottom, 1 top):
/// cross(d/du, d/dv) points outwards (addSurface's front side).
glm::vec3 spherePoint(float u, float v) {
  const float a = 2.0f * kPi * u, t = kPi * (1.0f - v);
  return {std::sin(t) * std::cos(a), std::cos(t), -std::sin(t) * std::sin(a)};
}

/// An ellipsoid with semi-axes `radii` along the columns of `axes` (a rotation).
void addEllipsoid(MeshData& m, const glm::vec3& c, const glm::vec3& radii, const glm::mat3& axes,
                  int nu, int nv) {
  addSurface(m, nu, nv, [&](float u, float v) { return c + axes * (radii * spherePoint(u, v)); });
}

/// A capsule (a cylinder with hemispherical ends) of radius r from a to b.
void addCapsule(MeshData& m, const glm::vec3& a, const glm::vec3& b, float r, int nu, int nv) {
  const glm::mat3 f = frameAround(b - a);
  const float len = glm::length(b - a);
  addSurface(m, nu, nv, [&](float u, float v) {
    // v: bottom cap [0, 1/4], side [1/4, 3/4], top cap [3/4, 1].
    glm::vec3 p;
    if (v < 0.25f) {
      p = r * spherePoint(u, 2.0f * v);
    } else if (v > 0.75f) {
      p = r * spherePoint(u, 2.0f * v - 1.0f) + glm::vec3(0.0f, len, 0.0f);
    } else {
      const float a0 = 2.0f * kPi * u;
      p = {r * std::cos(a0), len * (2.0f * v - 0.5f), -r * std::sin(a0)};
    }
    return a + f * p;
  });
}

/// A closed cylinder of radius r from a to b (side and two flat caps).
void addTube(MeshData& m, const glm::vec3& a, const glm::vec3& b, float r, int segments) {
  const glm::mat3 f = frameAround(b - a);
  const float len = glm::length(b - a);
  auto ring = [&](float u, float rad, float y) {
    const float t = 2.0f * kPi * u;
    return a + f * glm::vec3(rad * std::cos(t), y, -rad * std::sin(t));
  };
  addSurface(m, segments, 1, [&](float u, float v) { return ring(u, r, len * v); });
  const glm::vec3 up = f[1], down = -f[1];
  // Top cap seen from +axis: radius grows with v, azimuth with u; bottom cap mirrored.
  addSurface(
      m, segments, 1, [&](float u, float v) { return ring(u, r * (1.0f - v), len); }, &up);
  addSurface(
      m, segments, 1, [&](float u, float v) { return ring(u, r * v, 0.0f); }, &down);
}

/// A torus around the +y axis through `c`: ring radius R, tube radius r.
void addTorus(MeshData& m, const glm::vec3& c, float R, float r, int nu, int nv) {
  addSurface(m, nu, nv, [&](float u, float v) {
    const float a = 2.0f * kPi * u, b = 2.0f * kPi * v;
    const float rr = R + r * std::cos(b);
    return c + glm::vec3(rr * std::cos(a), r * std::sin(b), -rr * std::sin(a));
  });
}

/// A superquadric "rounded box" centred at c, semi-axes h, exponent e (1: ellipsoid, small:
/// box-like).
void addRoundedBox(MeshData& m, const glm::vec3& c, const glm::vec3& h, float e, int nu, int nv) {
  addSurface(m, nu, nv, [&](float u, float v) {
    const float a = 2.0f * kPi * u, t = kPi * (1.0f - v);
    return c + h * glm::vec3(signedPow(std::sin(t), e) * signedPow(std::cos(a), e),
                             signedPow(std::cos(t), e),
                             -signedPow(std::sin(t), e) * signedPow(std::sin(a), e));
  });
}

MeshData ground(float halfM) {
  MeshData g;
  g.addQuad({-halfM, 0.0f, halfM}, {halfM, 0.0f, halfM}, {halfM, 0.0f, -halfM},
            {-halfM, 0.0f, -halfM}, glm::vec2(2.0f * halfM));
  return g;
}

/// A 10 s, 11-key camera path orbiting `target` from azimuth az0 to az1, elevation el0 to
/// el1, distance d0 to d1 (the first key is also a bookmark of the same name).
void addOrbitPath(SceneBuilder& b, const std::string& name, const glm::vec3& target, float az0,
                  float az1, float el0, float el1, float d0, float d1, float fovDeg, float nearM,
                  float farM) {
  std::vector<CameraKeyframe> keys;
  for (int k = 0; k <= 10; ++k) {
    const float s = float(k) / 10.0f;
    keys.push_back({float(k),
                    orbit(target, az0 + (az1 - az0) * s, el0 + (el1 - el0) * s, d0 + (d1 - d0) * s),
                    target});
  }
  int node = b.addCamera(name, keys.front().eye, keys.front().target, fovDeg, nearM, farM);
  b.addCameraPath(name, node, keys);
}
}  // namespace

// ----------------------------------------------------------------------------------------
// helmet: a finely tessellated helmet (about 50 k triangles: a fluted shell with a crest, a
// visor with an eye slit, a neck ring, rivets) on a pedestal in a 40 m ground, seen from a
// few metres: a small, detailed object in a large scene.
SceneBuilder makeHelmet() {
  SceneBuilder b("helmet");
  int groundMat = b.addMaterial("ground", {0.66f, 0.64f, 0.60f, 1.0f});
  int steel = b.addMaterial("steel", {0.62f, 0.64f, 0.68f, 1.0f});
  int brass = b.addMaterial("brass", {0.78f, 0.62f, 0.30f, 1.0f});
  int stone = b.addMaterial("stone", {0.50f, 0.48f, 0.46f, 1.0f});
  b.addNode("ground", b.addMesh("ground", ground(20.0f), groundMat));
  MeshData pedestal;
  pedestal.addBox({0.0f, 0.11f, 0.0f}, {0.16f, 0.11f, 0.16f});
  b.addNode("pedestal", b.addMesh("pedestal", pedestal, stone));

  const glm::vec3 c(0.0f, 0.34f, 0.0f);         // the shell's centre
  const glm::vec3 radii(0.115f, 0.15f, 0.14f);  // x (ear to ear), y, z (front +z)
  const float vCut = 0.38f;                     // the shell ends 0.62 pi below the top
  MeshData shell;
  addSurface(shell, 192, 96, [&](float u, float v) {
    const float vv = vCut + (1.0f - vCut) * v;  // from the rim up to the top
    glm::vec3 d = spherePoint(u, vv);
    const float a = 2.0f * kPi * u;
    // A crest along the midline (x = 0) over the top, and 24 flutes around.
    const float side = std::cos(a);  // 0 on the midline
    const float top = std::max(0.0f, d.y);
    const float crest = 0.07f * std::exp(-side * side / 0.004f) * top;
    const float flutes = 0.012f * std::cos(24.0f * a) * top;
    return c + radii * d * (1.0f + crest + flutes);
  });
  // The visor: two bands of a slightly larger ellipsoid over the face (azimuth 270 +- 60
  // degrees from +x towards -z: the +z side), leaving a 1.5 cm eye slit between them.
  auto visorBand = [&](float v0, float v1) {
    addSurface(shell, 64, 12, [&, v0, v1](float u, float v) {
      const float uu = 0.75f - 60.0f / 360.0f + (120.0f / 360.0f) * u;
      return c + radii * 1.07f * spherePoint(uu, v0 + (v1 - v0) * v);
    });
  };
  visorBand(0.40f, 0.50f);
  visorBand(0.535f, 0.64f);
  addTorus(shell, c + glm::vec3(0.0f, radii.y * std::cos(kPi * (1.0f - vCut)), 0.0f), 0.125f,
           0.012f, 96, 12);
  b.addNode("helmet", b.addMesh("helmet", shell, steel));
  MeshData rivets;
  for (int i = 0; i < 36; ++i) {
    const float u = float(i) / 36.0f;
    const glm::vec3 d = spherePoint(u, vCut + 0.03f);
    rivets.addSphere(c + radii * d * 1.02f, 0.006f, 12, 6);
  }
  for (int i = 0; i < 9; ++i) {  // a row along each side of the crest
    const float v = 0.62f + 0.04f * float(i);
    for (float u : {0.23f, 0.27f, 0.73f, 0.77f})
      rivets.addSphere(c + radii * spherePoint(u, v) * 1.02f, 0.005f, 10, 5);
  }
  b.addNode("rivets", b.addMesh("rivets", rivets, brass));
  b.addSun(140.0f, 40.0f);
  const glm::vec3 look(0.0f, 0.25f, 0.1f);
  b.addCamera("near", orbit(look, 40.0f, 25.0f, 1.4f), look, 40.0f, 0.05f, 60.0f);
  addOrbitPath(b, "walk-round", look, 10.0f, 100.0f, 22.0f, 15.0f, 3.6f, 2.6f, 40.0f, 0.05f, 60.0f);
  return b;
}

// ----------------------------------------------------------------------------------------
// sunroom: a closed 6 x 2.8 x 5 m room with 0.2 m walls; the sun shines in through one window
// (with a cross of glazing bars) onto a table, a chair, a vase and a shelf. Everything else
// is in the walls' shadow: the light's view is mostly roof.
SceneBuilder makeSunroom() {
  SceneBuilder b("sunroom");
  int wallMat = b.addMaterial("wall", {0.84f, 0.82f, 0.78f, 1.0f});
  int floorMat = b.addMaterial("floor", {0.60f, 0.50f, 0.40f, 1.0f});
  int wood = b.addMaterial("wood", {0.52f, 0.36f, 0.22f, 1.0f});
  int blue = b.addMaterial("blue", {0.30f, 0.45f, 0.70f, 1.0f});
  const float X = 3.0f, Z = 2.5f, H = 2.8f, T = 0.1f;  // inner half sizes, wall half-thickness
  MeshData floorMesh;
  floorMesh.addBox({0.0f, -T, 0.0f}, {X + 2 * T, T, Z + 2 * T});
  b.addNode("floor", b.addMesh("floor", floorMesh, floorMat));
  MeshData walls;
  walls.addBox({0.0f, H + T, 0.0f}, {X + 2 * T, T, Z + 2 * T});      // ceiling
  walls.addBox({X + T, 0.5f * H, 0.0f}, {T, 0.5f * H, Z + 2 * T});   // +x
  walls.addBox({-X - T, 0.5f * H, 0.0f}, {T, 0.5f * H, Z + 2 * T});  // -x
  walls.addBox({0.0f, 0.5f * H, -Z - T}, {X, 0.5f * H, T});          // -z
  // +z: the window wall, an opening 1.4 m wide from 0.9 m to 2.1 m, centred on x = 0.
  const float wx = 0.7f, wy0 = 0.9f, wy1 = 2.1f;
  walls.addBox({0.5f * (X + wx), 0.5f * H, Z + T}, {0.5f * (X - wx), 0.5f * H, T});
  walls.addBox({-0.5f * (X + wx), 0.5f * H, Z + T}, {0.5f * (X - wx), 0.5f * H, T});
  walls.addBox({0.0f, 0.5f * wy0, Z + T}, {wx, 0.5f * wy0, T});
  walls.addBox({0.0f, 0.5f * (wy1 + H), Z + T}, {wx, 0.5f * (H - wy1), T});
  walls.addBox({0.0f, 0.5f * (wy0 + wy1), Z + T}, {0.02f, 0.5f * (wy1 - wy0), 0.02f});  // bars
  walls.addBox({0.0f, 0.5f * (wy0 + wy1), Z + T}, {wx, 0.02f, 0.02f});
  b.addNode("walls", b.addMesh("walls", walls, wallMat));
  MeshData furniture;
  const glm::vec3 table(0.2f, 0.0f, 0.9f);
  furniture.addBox(table + glm::vec3(0.0f, 0.74f, 0.0f), {0.55f, 0.02f, 0.4f});
  for (float sx : {-1.0f, 1.0f})
    for (float sz : {-1.0f, 1.0f})
      furniture.addBox(table + glm::vec3(0.5f * sx, 0.36f, 0.35f * sz), {0.025f, 0.36f, 0.025f});
  const glm::vec3 chair(-0.7f, 0.0f, 0.6f);  // seat, back of slats, legs
  furniture.addBox(chair + glm::vec3(0.0f, 0.45f, 0.0f), {0.21f, 0.02f, 0.21f}, 15.0f);
  for (int i = 0; i < 5; ++i)
    furniture.addBox(chair + glm::vec3(-0.18f + 0.09f * float(i), 0.75f, -0.2f),
                     {0.015f, 0.28f, 0.012f});
  for (float sx : {-1.0f, 1.0f})
    for (float sz : {-1.0f, 1.0f})
      furniture.addBox(chair + glm::vec3(0.18f * sx, 0.22f, 0.18f * sz), {0.018f, 0.22f, 0.018f});
  furniture.addBox({-2.8f, 1.0f, -1.0f}, {0.18f, 1.0f, 0.8f});  // a shelf against -x
  for (int i = 1; i < 5; ++i)
    furniture.addBox({-2.6f, 0.4f * float(i), -1.0f}, {0.02f, 0.015f, 0.8f});
  b.addNode("furniture", b.addMesh("furniture", furniture, wood));
  MeshData things;
  addEllipsoid(things, table + glm::vec3(0.15f, 0.9f, 0.05f), {0.07f, 0.14f, 0.07f},
               glm::mat3(1.0f), 32, 16);
  things.addSphere(table + glm::vec3(-0.3f, 0.8f, -0.15f), 0.05f, 24, 12);
  for (int i = 0; i < 4; ++i)  // books on the shelf
    things.addBox({-2.7f, 0.95f, -1.5f + 0.12f * float(i)}, {0.1f, 0.13f, 0.04f});
  b.addNode("things", b.addMesh("things", things, blue));
  b.addSun(15.0f, 35.0f);  // from +z, through the window
  const glm::vec3 look(0.1f, 0.5f, 0.7f);
  b.addCamera("doorway", {-2.6f, 1.7f, -2.1f}, look, 60.0f, 0.05f, 30.0f);
  std::vector<CameraKeyframe> keys;
  for (int k = 0; k <= 10; ++k) {  // along the back wall, looking at the sun patch
    const float s = float(k) / 10.0f;
    keys.push_back({float(k), {-2.6f + 4.6f * s, 1.7f - 0.3f * s, -2.1f}, look});
  }
  int node = b.addCamera("pan", keys.front().eye, look, 60.0f, 0.05f, 30.0f);
  b.addCameraPath("pan", node, keys);
  return b;
}

// ----------------------------------------------------------------------------------------
// figure: a 1.75 m human figure of capsules and ellipsoids (thin limbs, fingers 1.6 cm
// across) standing with arms lowered away from the body, on a 40 m ground.
SceneBuilder makeFigure() {
  SceneBuilder b("figure");
  int groundMat = b.addMaterial("ground", {0.64f, 0.68f, 0.56f, 1.0f});
  int skin = b.addMaterial("skin", {0.85f, 0.66f, 0.52f, 1.0f});
  int cloth = b.addMaterial("cloth", {0.28f, 0.35f, 0.55f, 1.0f});
  b.addNode("ground", b.addMesh("ground", ground(20.0f), groundMat));
  MeshData body, limbs;
  const int nu = 24, nv = 16;
  addEllipsoid(body, {0.0f, 1.28f, 0.0f}, {0.19f, 0.27f, 0.11f}, glm::mat3(1.0f), nu, nv);
  addEllipsoid(body, {0.0f, 0.95f, 0.0f}, {0.17f, 0.12f, 0.11f}, glm::mat3(1.0f), nu, nv);
  for (float s : {-1.0f, 1.0f}) {  // legs and feet
    const glm::vec3 hip(0.09f * s, 0.92f, 0.0f), knee(0.1f * s, 0.5f, 0.02f),
        ankle(0.1f * s, 0.08f, 0.0f);
    addCapsule(body, hip, knee, 0.07f, nu, nv);
    addCapsule(body, knee, ankle, 0.05f, nu, nv);
    body.addBox({0.1f * s, 0.035f, 0.06f}, {0.045f, 0.035f, 0.12f});
  }
  b.addNode("body", b.addMesh("body", body, cloth));
  addCapsule(limbs, {0.0f, 1.52f, 0.0f}, {0.0f, 1.6f, 0.0f}, 0.045f, nu, nv);  // neck
  addEllipsoid(limbs, {0.0f, 1.68f, 0.01f}, {0.08f, 0.11f, 0.095f}, glm::mat3(1.0f), nu, nv);
  for (float s : {-1.0f, 1.0f}) {  // arms angled 20 degrees out, hands with five fingers
    const glm::vec3 shoulder(0.2f * s, 1.45f, 0.0f), elbow(0.3f * s, 1.17f, 0.02f),
        wrist(0.38f * s, 0.92f, 0.06f);
    addCapsule(limbs, shoulder, elbow, 0.045f, nu, nv);
    addCapsule(limbs, elbow, wrist, 0.035f, nu, nv);
    const glm::vec3 dir = glm::normalize(wrist - elbow);
    const glm::vec3 palm = wrist + 0.05f * dir;
    const glm::mat3 f = frameAround(dir);
    addEllipsoid(limbs, palm, {0.04f, 0.05f, 0.015f}, f, 16, 8);
    for (int i = 0; i < 5; ++i) {
      const float spread = -0.032f + 0.016f * float(i);
      const glm::vec3 base = palm + 0.045f * dir + f[0] * spread;
      const float len = i == 0 ? 0.05f : 0.075f;
      const glm::vec3 tipDir = glm::normalize(dir + f[0] * (0.25f * spread / 0.032f));
      addCapsule(limbs, base, base + len * tipDir, 0.008f, 8, 8);
    }
  }
  b.addNode("limbs", b.addMesh("limbs", limbs, skin));
  b.addSun(230.0f, 45.0f);
  const glm::vec3 look(0.0f, 0.85f, -0.3f);
  b.addCamera("hands", orbit({0.38f, 0.9f, 0.0f}, 120.0f, 20.0f, 1.2f), {0.3f, 0.6f, -0.3f}, 45.0f,
              0.05f, 60.0f);
  addOrbitPath(b, "walk-round", look, 10.0f, 100.0f, 18.0f, 26.0f, 4.5f, 3.5f, 40.0f, 0.05f, 60.0f);
  return b;
}

// ----------------------------------------------------------------------------------------
// car: a 4.4 m car (a rounded body and cabin, four wheels, axles and an exhaust under the
// body, door mirrors on stalks) under a high sun on a 60 m ground.
SceneBuilder makeCar() {
  SceneBuilder b("car");
  int groundMat = b.addMaterial("asphalt", {0.42f, 0.42f, 0.44f, 1.0f});
  int paint = b.addMaterial("paint", {0.72f, 0.16f, 0.14f, 1.0f});
  int rubber = b.addMaterial("rubber", {0.12f, 0.12f, 0.13f, 1.0f});
  int metal = b.addMaterial("metal", {0.55f, 0.56f, 0.58f, 1.0f});
  b.addNode("ground", b.addMesh("ground", ground(30.0f), groundMat));
  MeshData shell;
  addRoundedBox(shell, {0.0f, 0.62f, 0.0f}, {0.9f, 0.32f, 2.2f}, 0.35f, 96, 48);
  addRoundedBox(shell, {0.0f, 1.05f, -0.25f}, {0.78f, 0.33f, 1.05f}, 0.45f, 96, 48);
  for (float s : {-1.0f, 1.0f}) {  // mirrors on thin stalks ahead of the cabin
    const glm::vec3 root(0.86f * s, 1.0f, 0.72f), head(1.02f * s, 1.05f, 0.68f);
    addTube(shell, root, head, 0.012f, 12);
    addRoundedBox(shell, head + glm::vec3(0.05f * s, 0.0f, 0.0f), {0.06f, 0.045f, 0.03f}, 0.5f, 24,
                  12);
  }
  b.addNode("body", b.addMesh("body", shell, paint));
  MeshData wheels, under;
  for (float z : {-1.35f, 1.35f}) {
    for (float s : {-1.0f, 1.0f}) {
      addTube(wheels, {0.7f * s, 0.33f, z}, {0.92f * s, 0.33f, z}, 0.33f, 48);
    }
    addTube(under, {-0.7f, 0.33f, z}, {0.7f, 0.33f, z}, 0.03f, 12);  // axle
  }
  addTube(under, {0.35f, 0.22f, -2.3f}, {0.35f, 0.22f, 0.6f}, 0.035f, 16);  // exhaust
  under.addBox({0.0f, 0.3f, 0.0f}, {0.1f, 0.04f, 1.1f});                    // tunnel
  b.addNode("wheels", b.addMesh("wheels", wheels, rubber));
  b.addNode("underbody", b.addMesh("underbody", under, metal));
  b.addSun(30.0f, 72.0f);
  const glm::vec3 look(0.0f, 0.6f, 0.0f);
  b.addCamera("low-side", orbit({0.0f, 0.3f, 0.0f}, 90.0f, 8.0f, 4.5f), {0.0f, 0.3f, 0.0f}, 45.0f,
              0.05f, 80.0f);
  addOrbitPath(b, "walk-round", look, 200.0f, 300.0f, 20.0f, 14.0f, 8.0f, 6.0f, 45.0f, 0.05f,
               80.0f);
  return b;
}

}  // namespace sl::gen
