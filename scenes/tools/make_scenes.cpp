// shadowlab-make-scenes: writes the built-in scenes (scenes/*.gltf) and, optionally, the loader
// test fixtures (tests/data) and CPU ray-cast previews of every camera bookmark.
// Each scene models only what its lesson needs; see scenes/README.md for what each teaches.
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <glm/gtc/constants.hpp>

#include "SceneBuilder.h"
#include "Textures.h"
#include "scene/GltfLoader.h"
#include "scene/PlaneBoxAnalytic.h"

namespace sl::gen {

// Defined in make_fixtures.cpp, Preview.cpp and make_sponza_class.cpp.
int writeFixtures(const std::filesystem::path& dir);
int writePreviews(const Scene& scene, const std::filesystem::path& dir);
SceneBuilder makeSponzaClass(std::size_t targetTriangles);
// Defined in make_real_content.cpp.
SceneBuilder makeHelmet();
SceneBuilder makeSunroom();
SceneBuilder makeFigure();
SceneBuilder makeCar();

namespace {

/// A point `distM` from `target` seen at azimuth/elevation (degrees, Light::directional's
/// convention), for placing cameras.
glm::vec3 orbitEye(const glm::vec3& target, float azimuthDeg, float elevationDeg, float distM) {
  return target + distM * towardsLightFromAngles(azimuthDeg, elevationDeg);
}

/// A flat ground quad over [x0, x1] x [z0, z1] at y = 0, facing up, uvs in metres.
MeshData groundQuad(float x0, float x1, float z0, float z1) {
  MeshData m;
  m.addQuad({x0, 0.0f, z1}, {x1, 0.0f, z1}, {x1, 0.0f, z0}, {x0, 0.0f, z0},
            glm::vec2(x1 - x0, z1 - z0));
  return m;
}

/// A camera (a bookmark at the path's first keyframe) animated through `keys`.
void addPath(SceneBuilder& b, const std::string& name, float yfovDeg, float nearM, float farM,
             const std::vector<CameraKeyframe>& keys) {
  int node = b.addCamera(name, keys.front().eye, keys.front().target, yfovDeg, nearM, farM);
  b.addCameraPath(name, node, keys);
}

// ----------------------------------------------------------------------------------------
// plane-box: one square occluder over a plane; the analytic reference of every technique.
SceneBuilder makePlaneBox() {
  namespace pb = planebox;
  SceneBuilder b("plane-box");
  int ground = b.addMaterial("ground", {0.80f, 0.80f, 0.78f, 1.0f});
  int occluder = b.addMaterial("occluder", {0.85f, 0.36f, 0.24f, 1.0f});
  const float g = pb::kGroundHalfSizeM;
  b.addNode("ground", b.addMesh("ground", groundQuad(-g, g, -g, g), ground));
  MeshData box;
  box.addBox({0.0f, pb::kOccluderCenterHeightM, 0.0f},
             {pb::kOccluderHalfSizeM, 0.5f * pb::kOccluderThicknessM, pb::kOccluderHalfSizeM});
  b.addNode("occluder", b.addMesh("occluder", box, occluder));
  b.addSun(pb::kSunAzimuthDeg, pb::kSunElevationDeg);

  // The shadow's centre; cameras look at it from the side away from the sun (azimuth 210),
  // low enough that the occluder hides little of it.
  glm::vec2 s = pb::shadowOffsetXZ(pb::kOccluderCenterHeightM, pb::sunTowardsLight());
  glm::vec3 shadow(s.x, 0.0f, s.y);
  b.addCamera("overview", orbitEye(shadow, 215.0f, 38.0f, 8.0f), shadow, 45.0f, 0.1f, 60.0f);
  glm::vec3 corner(s.x - pb::kOccluderHalfSizeM, 0.0f, s.y - pb::kOccluderHalfSizeM);
  b.addCamera("edge-closeup", orbitEye(corner, 200.0f, 45.0f, 1.5f), corner, 45.0f, 0.02f, 40.0f);
  b.addCamera("grazing", orbitEye(shadow, 230.0f, 6.0f, 7.0f) + glm::vec3(0.0f, 0.1f, 0.0f), shadow,
              45.0f, 0.05f, 60.0f);
  std::vector<CameraKeyframe> keys;
  for (int k = 0; k <= 10; ++k) {
    float u = float(k) / 10.0f;
    // Swing round the shadow from azimuth 170 to 260 while closing in from 8 m to 2.5 m.
    float az = 170.0f + 90.0f * u, el = 40.0f - 12.0f * u, dist = 8.0f - 5.5f * u;
    keys.push_back({float(k), orbitEye(shadow, az, el, dist), shadow});
  }
  addPath(b, "orbit-in", 45.0f, 0.05f, 60.0f, keys);
  return b;
}

// ----------------------------------------------------------------------------------------
// spot-box and point-box: a square occluder and two boxes on a ground plane under a
// positional light (KHR_lights_punctual spot / point): perspective shadows whose size grows
// with the occluder's height (side s H / (H - h) under a light at height H).
constexpr float kPunctualGroundHalfM = 6.0f;
constexpr float kPunctualOccluderHalfM = 0.75f, kPunctualOccluderHeightM = 1.5f;

SceneBuilder makePunctualBox(const std::string& name, bool spot) {
  SceneBuilder b(name);
  int ground = b.addMaterial("ground", {0.80f, 0.80f, 0.78f, 1.0f});
  int occluder = b.addMaterial("occluder", {0.85f, 0.36f, 0.24f, 1.0f});
  int boxMat = b.addMaterial("box", {0.30f, 0.45f, 0.70f, 1.0f});
  const float g = kPunctualGroundHalfM;
  b.addNode("ground", b.addMesh("ground", groundQuad(-g, g, -g, g), ground));
  MeshData plate;
  plate.addBox({0.0f, kPunctualOccluderHeightM, 0.0f},
               {kPunctualOccluderHalfM, 0.01f, kPunctualOccluderHalfM});
  b.addNode("occluder", b.addMesh("occluder", plate, occluder));
  MeshData boxes;
  boxes.addBox({2.2f, 0.5f, -1.4f}, {0.5f, 0.5f, 0.5f});
  boxes.addBox({-2.0f, 0.35f, 1.6f}, {0.35f, 0.35f, 0.6f});
  b.addNode("boxes", b.addMesh("boxes", boxes, boxMat));
  if (spot)  // from above and to one side, the ground's far corners outside the cone
    b.addSpotLight("spot", {1.5f, 5.0f, 2.0f}, glm::vec3(-0.25f, -5.0f, -2.0f), 40.0f, 30.0f,
                   20.0f);
  else
    b.addPointLight("bulb", {0.2f, 4.0f, 0.3f}, 15.0f);
  const glm::vec3 centre(0.0f, 0.0f, 0.0f);
  b.addCamera("overview", orbitEye(centre, 210.0f, 40.0f, 11.0f), centre, 45.0f, 0.1f, 60.0f);
  glm::vec3 corner(-1.2f, 0.0f, -1.2f);
  b.addCamera("edge-closeup", orbitEye(corner, 200.0f, 45.0f, 2.0f), corner, 45.0f, 0.02f, 40.0f);
  return b;
}

// ----------------------------------------------------------------------------------------
// omni-room: a point light in the middle of a closed room, with casters on every side of it
// (a table below, a hanging plate above, a pillar, a crate and a ball around): shadows fall
// on the floor, the ceiling and all four walls, so no single frustum can hold them (cube and
// dual-paraboloid shadow maps, seed 001).
constexpr float kRoomHalfXM = 4.0f, kRoomHalfZM = 3.0f, kRoomHeightM = 3.0f;

/// A quad centred at `c` facing along unit `n`, spanning u (half-extent hu) and v (hv),
/// cross(u, v) = n; uvs in metres.
void addFacingQuad(MeshData& m, const glm::vec3& c, const glm::vec3& u, const glm::vec3& v,
                   float hu, float hv) {
  m.addQuad(c - u * hu - v * hv, c + u * hu - v * hv, c + u * hu + v * hv, c - u * hu + v * hv,
            glm::vec2(2.0f * hu, 2.0f * hv));
}

SceneBuilder makeOmniRoom() {
  SceneBuilder b("omni-room");
  int wall = b.addMaterial("wall", {0.82f, 0.80f, 0.76f, 1.0f});
  int floorMat = b.addMaterial("floor", {0.62f, 0.55f, 0.46f, 1.0f});
  int wood = b.addMaterial("wood", {0.55f, 0.36f, 0.22f, 1.0f});
  int blue = b.addMaterial("blue", {0.30f, 0.45f, 0.70f, 1.0f});
  const float X = kRoomHalfXM, Z = kRoomHalfZM, H = kRoomHeightM;
  // Six inward-facing sides: floor, ceiling, walls at x = +-X and z = +-Z.
  MeshData room;
  addFacingQuad(room, {0, H, 0}, {1, 0, 0}, {0, 0, 1}, X, Z);            // ceiling, facing down
  addFacingQuad(room, {X, H / 2, 0}, {0, 0, 1}, {0, 1, 0}, Z, H / 2);    // facing -x
  addFacingQuad(room, {-X, H / 2, 0}, {0, 0, -1}, {0, 1, 0}, Z, H / 2);  // facing +x
  addFacingQuad(room, {0, H / 2, Z}, {-1, 0, 0}, {0, 1, 0}, X, H / 2);   // facing -z
  addFacingQuad(room, {0, H / 2, -Z}, {1, 0, 0}, {0, 1, 0}, X, H / 2);   // facing +z
  b.addNode("floor", b.addMesh("floor", groundQuad(-X, X, -Z, Z), floorMat));
  b.addNode("walls", b.addMesh("walls", room, wall));
  MeshData table;  // below the light: its shadow falls straight down
  table.addBox({0.1f, 0.78f, -0.1f}, {0.6f, 0.03f, 0.45f});
  for (float sx : {-1.0f, 1.0f})
    for (float sz : {-1.0f, 1.0f})
      table.addBox({0.1f + 0.52f * sx, 0.375f, -0.1f + 0.37f * sz}, {0.04f, 0.375f, 0.04f});
  table.addBox({0.0f, 2.45f, 0.15f}, {0.35f, 0.01f, 0.25f});  // hanging plate: straight up
  table.addBox({2.6f, 1.5f, 1.2f}, {0.15f, 1.5f, 0.15f});     // pillar: shadow on +x, +z walls
  b.addNode("furniture", b.addMesh("furniture", table, wood));
  MeshData things;
  things.addBox({-2.2f, 0.4f, -1.6f}, {0.4f, 0.4f, 0.4f}, 25.0f);  // crate: -x, -z walls
  things.addSphere({-2.4f, 1.2f, -0.1f}, 0.3f, 16, 10);            // ball in the air: -x wall
  b.addNode("things", b.addMesh("things", things, blue));
  b.addPointLight("bulb", {0.2f, 1.7f, 0.1f}, 0.0f);
  b.addCamera("overview", {-3.6f, 2.7f, 2.6f}, {0.6f, 0.6f, -0.9f}, 70.0f, 0.05f, 20.0f);
  b.addCamera("floor", {-2.0f, 2.4f, 2.0f}, {0.2f, 0.0f, -0.2f}, 60.0f, 0.05f, 20.0f);
  b.addCamera("ceiling", {-2.5f, 0.4f, 2.2f}, {0.2f, 3.0f, -0.2f}, 70.0f, 0.05f, 20.0f);
  b.addCamera("corner", {3.5f, 1.6f, -2.5f}, {-1.0f, 1.0f, 1.0f}, 75.0f, 0.05f, 20.0f);
  return b;
}

// ----------------------------------------------------------------------------------------
// spot-yard: a wide spot on a mast over a yard of crates and posts; its cone reaches three
// of the cube's faces (the `cube` technique renders only those).
SceneBuilder makeSpotYard() {
  SceneBuilder b("spot-yard");
  int ground = b.addMaterial("ground", {0.62f, 0.60f, 0.55f, 1.0f});
  int crate = b.addMaterial("crate", {0.70f, 0.52f, 0.30f, 1.0f});
  int stone = b.addMaterial("stone", {0.55f, 0.55f, 0.60f, 1.0f});
  b.addNode("ground", b.addMesh("ground", groundQuad(-10.0f, 10.0f, -10.0f, 10.0f), ground));
  MeshData crates, posts;
  crates.addBox({0.5f, 0.5f, 0.0f}, {0.5f, 0.5f, 0.5f}, 20.0f);
  crates.addBox({2.5f, 0.35f, 2.0f}, {0.35f, 0.35f, 0.7f}, -10.0f);
  crates.addBox({-1.5f, 0.6f, 2.5f}, {0.6f, 0.6f, 0.4f}, 40.0f);
  for (int i = 0; i < 6; ++i)  // a row of thin posts
    posts.addBox({-3.0f + 1.2f * float(i), 1.0f, -2.0f}, {0.05f, 1.0f, 0.05f});
  posts.addBox({-4.0f, 3.0f, -4.0f}, {0.08f, 3.0f, 0.08f});  // the mast
  b.addNode("crates", b.addMesh("crates", crates, crate));
  b.addNode("posts", b.addMesh("posts", posts, stone));
  b.addSpotLight("flood", {-3.7f, 5.5f, -3.7f}, glm::vec3(4.2f, -5.5f, 4.7f), 55.0f, 45.0f, 30.0f);
  const glm::vec3 centre(0.5f, 0.0f, 0.5f);
  b.addCamera("overview", orbitEye(centre, 30.0f, 40.0f, 12.0f), centre, 50.0f, 0.1f, 60.0f);
  glm::vec3 posts0(-1.5f, 0.0f, -0.5f);
  b.addCamera("posts", orbitEye(posts0, 60.0f, 35.0f, 4.0f), posts0, 50.0f, 0.05f, 40.0f);
  return b;
}

// ----------------------------------------------------------------------------------------
// diagonal: a row of thin posts at 45 degrees to the light's image axes.
constexpr float kDiagonalSunAzimuthDeg = 55.0f, kDiagonalSunElevationDeg = 45.0f;

SceneBuilder makeDiagonal() {
  SceneBuilder b("diagonal");
  int ground = b.addMaterial("ground", {0.74f, 0.70f, 0.58f, 1.0f});
  int post = b.addMaterial("post", {0.42f, 0.30f, 0.22f, 1.0f});
  b.addNode("ground", b.addMesh("ground", groundQuad(-12.0f, 72.0f, -16.0f, 16.0f), ground));
  MeshData posts;
  const int kPosts = 40;
  const float spacing = 1.5f;
  for (int i = 0; i < kPosts; ++i)
    posts.addBox({float(i) * spacing, 0.9f, 0.0f}, {0.04f, 0.9f, 0.04f});
  b.addNode("posts", b.addMesh("posts", posts, post));
  b.addSun(kDiagonalSunAzimuthDeg, kDiagonalSunElevationDeg);

  const float rowEnd = float(kPosts - 1) * spacing;
  // The posts' shadows fall towards -x and -z: the cameras stand on that side of the row.
  b.addCamera("row-end", {-4.0f, 1.6f, -1.2f}, {20.0f, 0.0f, -0.8f}, 50.0f, 0.1f, 120.0f);
  b.addCamera("row-end-low", {-2.0f, 0.5f, -0.6f}, {12.0f, 0.2f, -0.6f}, 50.0f, 0.05f, 120.0f);
  b.addCamera("overview", {0.4f * rowEnd, 12.0f, -15.0f}, {0.4f * rowEnd, 0.0f, 0.0f}, 50.0f, 0.2f,
              150.0f);
  std::vector<CameraKeyframe> keys;
  for (int k = 0; k <= 10; ++k) {
    float x = -4.0f + 4.5f * float(k);  // walk along the row, 4.5 m/s
    float sway = 0.4f * std::sin(float(k) * 0.9f);
    keys.push_back({float(k), {x, 1.6f, -1.2f + sway}, {x + 24.0f, 0.0f, -0.8f}});
  }
  addPath(b, "walk-along-row", 50.0f, 0.1f, 120.0f, keys);
  return b;
}

// ----------------------------------------------------------------------------------------
// band-diagonal, band-aligned, blob: where DA-RTW's rotation must win, and where it must not.
// The only receivers are a thin strip (or a disc) about 35 m from the camera, with a fence on
// it (posts and two rails along the strip; posts on the disc); nothing else is in view, so the
// importance is exactly the strip's footprint in the light's image. The sun stands at
// azimuth 0: the light's image x axis is world +x, its y axis world z foreshortened by
// sin(el). The strip runs at 45° to the image x axis (band-diagonal), along it
// (band-aligned); the blob is a disc of the same area (isotropic importance). The camera
// stands in the same place relative to the receiver in all three.
constexpr float kBandSunAzimuthDeg = 0.0f, kBandSunElevationDeg = 65.0f;
constexpr float kBandLengthM = 40.0f, kBandWidthM = 2.0f;

SceneBuilder makeBand(const std::string& name, float imageDeg, bool blob) {
  SceneBuilder b(name);
  int ground = b.addMaterial("ground", {0.74f, 0.70f, 0.58f, 1.0f});
  int post = b.addMaterial("post", {0.42f, 0.30f, 0.22f, 1.0f});
  // A ground direction whose image lies at imageDeg: image y = world z * sin(el), so
  // tan(world angle) = tan(imageDeg) / sin(el); towards -z for a positive image angle
  // (the image y axis points away from the sun, towards world -z).
  const float sinEl = std::sin(glm::radians(kBandSunElevationDeg));
  const float a = std::atan(std::tan(glm::radians(imageDeg)) / sinEl);
  const glm::vec3 along(std::cos(a), 0.0f, -std::sin(a));
  const glm::vec3 across(-along.z, 0.0f, along.x);  // horizontal, perpendicular
  const glm::vec3 centre(0.0f, 0.0f, 0.0f);
  MeshData strip, posts;
  if (blob) {
    // A disc of the strip's area, as a fan of 48 triangles.
    const float r = std::sqrt(kBandLengthM * kBandWidthM / glm::pi<float>());
    const int n = 48;
    for (int i = 0; i < n; ++i) {
      float t0 = glm::two_pi<float>() * float(i) / float(n);
      float t1 = glm::two_pi<float>() * float(i + 1) / float(n);
      glm::vec3 p0 = centre + r * glm::vec3(std::cos(t0), 0.0f, -std::sin(t0));
      glm::vec3 p1 = centre + r * glm::vec3(std::cos(t1), 0.0f, -std::sin(t1));
      const auto base = std::uint32_t(strip.positions.size());
      for (const glm::vec3& q : {centre, p0, p1}) {
        strip.positions.push_back(q);
        strip.normals.push_back({0.0f, 1.0f, 0.0f});
        strip.uvs.push_back({q.x, q.z});
      }
      for (std::uint32_t k = 0; k < 3; ++k) strip.indices.push_back(base + k);  // up-facing
    }
    for (int i = -4; i <= 4; ++i)
      for (int j = -4; j <= 4; ++j)
        if (1.44f * float(i * i + j * j) < (r - 0.5f) * (r - 0.5f))
          posts.addBox(centre + glm::vec3(1.2f * float(i), 0.3f, 1.2f * float(j)),
                       {0.03f, 0.3f, 0.03f});
  } else {
    const glm::vec3 h = 0.5f * kBandLengthM * along, w = 0.5f * kBandWidthM * across;
    strip.addQuad(centre - h + w, centre + h + w, centre + h - w, centre - h - w,
                  glm::vec2(kBandLengthM, kBandWidthM));
    // A fence on the sunward half (+z side): posts, and two rails along the strip whose
    // shadows are edges along it (they need texels across the strip, which only a rotation
    // that lays the strip along a map axis can concentrate).
    const glm::vec3 sunward = 0.25f * kBandWidthM * (across.z > 0 ? across : -across);
    for (int i = 0; i < 33; ++i) {
      float t = -0.5f * kBandLengthM + 1.0f + 1.2f * float(i);
      posts.addBox(centre + t * along + sunward + glm::vec3(0.0f, 0.5f, 0.0f),
                   {0.03f, 0.5f, 0.03f});
    }
    const float yawDeg = glm::degrees(a);
    for (float railM : {0.45f, 0.95f})
      posts.addBox(centre + sunward + glm::vec3(0.0f, railM, 0.0f),
                   {0.5f * kBandLengthM - 0.5f, 0.04f, 0.04f}, yawDeg);
  }
  b.addNode("receiver", b.addMesh("receiver", strip, ground));
  b.addNode("posts", b.addMesh("posts", posts, post));
  b.addSun(kBandSunAzimuthDeg, kBandSunElevationDeg);
  // The camera stands in the same place relative to the receiver in every variant: 30 m
  // from its middle across the strip, 18 m up (the scene turns with the strip; only the
  // light meets it at another angle), drifting slowly along it.
  std::vector<CameraKeyframe> keys;
  for (int k = 0; k <= 10; ++k) {
    float s = 0.3f * float(k) - 1.5f;  // 0.3 m/s along the strip
    glm::vec3 eye = centre - 30.0f * across + s * along + glm::vec3(0.0f, 18.0f, 0.0f);
    keys.push_back({float(k), eye, centre + s * along});
  }
  addPath(b, "far-look", 35.0f, 0.5f, 150.0f, keys);
  return b;
}

// ----------------------------------------------------------------------------------------
// thin-pole: a 6 mm pole on a 6 x 6 m ground. Seen from the light it is a line narrower than a
// texel of adaptive shadow maps' coarse map over the scene (asm.coarse.resolution 512: 1.6 cm;
// the pole spans texels 255.75 to 256.25 across, between two texel centres): the coarse map
// does not hold it, has no shadow edge there, and ASM never refines it (Fernando et al. 2001's
// missed fine shadow); at 2048 it covers two centres. RMSM asks for pages by footprint.
constexpr float kThinPoleSunAzimuthDeg = 30.0f, kThinPoleSunElevationDeg = 55.0f;
constexpr float kThinPoleHalfWidthM = 0.003f, kThinPoleHeightM = 1.5f;
constexpr float kThinPoleXM = 0.0f;

SceneBuilder makeThinPole() {
  SceneBuilder b("thin-pole");
  int ground = b.addMaterial("ground", {0.80f, 0.80f, 0.78f, 1.0f});
  int pole = b.addMaterial("pole", {0.30f, 0.32f, 0.36f, 1.0f});
  b.addNode("ground", b.addMesh("ground", groundQuad(-3.0f, 3.0f, -3.0f, 3.0f), ground));
  MeshData m;
  m.addBox({kThinPoleXM, 0.5f * kThinPoleHeightM, 0.0f},
           {kThinPoleHalfWidthM, 0.5f * kThinPoleHeightM, kThinPoleHalfWidthM});
  b.addNode("pole", b.addMesh("pole", m, pole));
  b.addSun(kThinPoleSunAzimuthDeg, kThinPoleSunElevationDeg);
  // The cameras look along the shadow, away from the sun, with the pole behind them: only the
  // shadow is in view (the pole's own lit and unlit sides would be shadow edges ASM refines,
  // and in the light's view they lie exactly over the shadow).
  const glm::vec3 l = towardsLightFromAngles(kThinPoleSunAzimuthDeg, kThinPoleSunElevationDeg);
  const float length = kThinPoleHeightM * std::sqrt(l.x * l.x + l.z * l.z) / l.y;
  const glm::vec3 along = -glm::normalize(glm::vec3(l.x, 0.0f, l.z));
  const glm::vec3 foot(kThinPoleXM, 0.0f, 0.0f);
  const glm::vec3 tip = foot + length * along;
  b.addCamera("shadow", foot + 0.2f * along + glm::vec3(0.0f, 0.6f, 0.0f), tip, 45.0f, 0.05f,
              30.0f);
  std::vector<CameraKeyframe> keys;
  for (int k = 0; k <= 10; ++k) {
    const float u = float(k) / 10.0f;  // from above the foot back to 0.5 m along, rising
    keys.push_back(
        {float(k), foot + (0.2f + 0.3f * u) * along + glm::vec3(0.0f, 0.6f + 0.3f * u, 0.0f), tip});
  }
  addPath(b, "orbit", 45.0f, 0.05f, 30.0f, keys);
  return b;
}

// ----------------------------------------------------------------------------------------
// corridor: occluders log-spaced from 0.1 m to 1 km along a 1 km receiver.
constexpr float kCorridorSunAzimuthDeg = 30.0f, kCorridorSunElevationDeg = 50.0f;

SceneBuilder makeCorridor() {
  SceneBuilder b("corridor");
  int floorMat = b.addMaterial("floor", {0.72f, 0.72f, 0.70f, 1.0f});
  int frameMat = b.addMaterial("frame", {0.25f, 0.35f, 0.55f, 1.0f});
  b.addNode("floor", b.addMesh("floor", groundQuad(-2.0f, 2.0f, -1010.0f, 2.0f), floorMat));
  // Frames (two pillars and a lintel, members 0.08 m thick) at distances 0.1 m .. 1 km ahead
  // of the camera (which stands at z = 0 looking down -z), 30 of them, ratio 10^(4/29).
  MeshData frames;
  const int kFrames = 30;
  for (int i = 0; i < kFrames; ++i) {
    float d = 0.1f * std::pow(10.0f, 4.0f * float(i) / float(kFrames - 1));
    float z = -d;
    frames.addBox({-1.5f, 1.25f, z}, {0.04f, 1.25f, 0.04f});
    frames.addBox({1.5f, 1.25f, z}, {0.04f, 1.25f, 0.04f});
    frames.addBox({0.0f, 2.54f, z}, {1.54f, 0.04f, 0.04f});
  }
  b.addNode("frames", b.addMesh("frames", frames, frameMat));
  b.addSun(kCorridorSunAzimuthDeg, kCorridorSunElevationDeg);

  b.addCamera("start", {0.0f, 1.0f, 0.0f}, {0.0f, -1.2f, -10.0f}, 50.0f, 0.05f, 1200.0f);
  b.addCamera("start-level", {0.0f, 1.0f, 0.0f}, {0.0f, 0.8f, -100.0f}, 50.0f, 0.05f, 1200.0f);
  b.addCamera("midway", {0.5f, 1.8f, -20.0f}, {0.0f, 0.0f, -50.0f}, 50.0f, 0.05f, 1200.0f);
  std::vector<CameraKeyframe> keys;
  for (int k = 0; k <= 10; ++k) {
    // Accelerating down the corridor: 0 -> 60 m in 10 s, looking ahead and slightly down.
    float z = -0.6f * float(k * k);
    float look = 0.3f * std::sin(float(k) * 0.7f);
    keys.push_back({float(k), {0.0f, 1.0f, z}, {look * 10.0f, -1.0f, z - 12.0f}});
  }
  addPath(b, "fly-down-corridor", 50.0f, 0.05f, 1200.0f, keys);
  return b;
}

// ----------------------------------------------------------------------------------------
// dueling: the camera looks towards a low sun behind the far end (Lloyd et al. 2006 §4.4,
// §5.1: "dueling frusta"). Seen from the light the view frustum is square, so one warp
// cannot help; shadows of posts, rails and blocks run back towards the camera.
constexpr float kDuelingSunAzimuthDeg = 180.0f, kDuelingSunElevationDeg = 14.0f;

SceneBuilder makeDueling() {
  SceneBuilder b("dueling");
  int ground = b.addMaterial("ground", {0.76f, 0.72f, 0.62f, 1.0f});
  int post = b.addMaterial("post", {0.36f, 0.30f, 0.26f, 1.0f});
  int block = b.addMaterial("block", {0.30f, 0.45f, 0.70f, 1.0f});
  b.addNode("ground", b.addMesh("ground", groundQuad(-16.0f, 16.0f, -90.0f, 4.0f), ground));
  MeshData posts;
  for (int i = 0; i < 24; ++i) {  // two rows of posts, 3 m apart, 2 m high, along the view
    const float z = -1.5f - 3.0f * float(i);
    posts.addBox({-3.0f, 1.0f, z}, {0.06f, 1.0f, 0.06f});
    posts.addBox({3.0f, 1.0f, z}, {0.06f, 1.0f, 0.06f});
  }
  // A picket fence across the view 4 m ahead (0.05 m pickets every 0.15 m, 0.5 m high): its
  // striped shadow runs 2 m back towards the camera.
  for (int i = 0; i < 27; ++i)
    posts.addBox({-2.0f + 0.15f * float(i), 0.25f, -2.0f}, {0.025f, 0.25f, 0.025f});
  b.addNode("posts", b.addMesh("posts", posts, post));
  MeshData blocks;  // small blocks scattered 1 m to 10 m ahead, a few large ones further out
  Rng rng(20261123u);
  for (int i = 0; i < 30; ++i) {
    const float z = 0.5f - 9.0f * rng.uniform(), x = -2.4f + 4.8f * rng.uniform();
    const float h = 0.04f + 0.1f * rng.uniform();
    blocks.addBox({x, h, z}, glm::vec3(h), 90.0f * rng.uniform());
  }
  blocks.addBox({1.5f, 1.0f, -30.0f}, {1.0f, 1.0f, 1.0f});
  blocks.addBox({-6.0f, 1.5f, -12.0f}, {0.8f, 1.5f, 0.8f}, 35.0f);
  blocks.addBox({7.0f, 2.0f, -26.0f}, {1.2f, 2.0f, 1.2f}, -20.0f);
  b.addNode("blocks", b.addMesh("blocks", blocks, block));
  b.addSun(kDuelingSunAzimuthDeg, kDuelingSunElevationDeg);

  // Looking down -z into the sun: the light lies inside the view cone (square frustum).
  b.addCamera("into-sun", {0.0f, 1.2f, 2.0f}, {0.0f, 0.2f, -12.0f}, 50.0f, 0.1f, 120.0f);
  // The same spot looking back along +z: the sun behind the viewer.
  b.addCamera("sun-behind", {0.0f, 1.7f, -48.0f}, {0.0f, 0.6f, -26.0f}, 50.0f, 0.1f, 120.0f);
  return b;
}

// ----------------------------------------------------------------------------------------
// default: a small pleasant scene, near and far, fine and large shadows, alpha-masked leaves.
constexpr float kDefaultSunAzimuthDeg = 240.0f, kDefaultSunElevationDeg = 35.0f;

SceneBuilder makeDefault() {
  SceneBuilder b("default");
  Rng rng(20260601u);
  int meadow = b.addMaterial("meadow", {0.58f, 0.66f, 0.46f, 1.0f});
  int terracotta = b.addMaterial("terracotta", {0.80f, 0.40f, 0.27f, 1.0f});
  int slate = b.addMaterial("slate", {0.31f, 0.43f, 0.63f, 1.0f});
  int mustard = b.addMaterial("mustard", {0.91f, 0.71f, 0.26f, 1.0f});
  int porcelain = b.addMaterial("porcelain", {0.93f, 0.91f, 0.86f, 1.0f});
  int stone = b.addMaterial("stone", {0.80f, 0.77f, 0.71f, 1.0f});
  int lavender = b.addMaterial("tower", {0.63f, 0.57f, 0.72f, 1.0f});
  int wood = b.addMaterial("wood", {0.52f, 0.39f, 0.27f, 1.0f});
  int bark = b.addMaterial("bark", {0.42f, 0.31f, 0.21f, 1.0f});
  std::vector<std::uint8_t> picketsRgba = makePicketTexture(kPicketTextureSize);
  std::vector<std::uint8_t> leavesRgba = makeLeafTexture(kLeafTextureSize, rng);
  int picketTex = b.addTexture("pickets", kPicketTextureSize, kPicketTextureSize, picketsRgba);
  int leafTex = b.addTexture("leaves", kLeafTextureSize, kLeafTextureSize, leavesRgba);
  int pickets = b.addMaterial("pickets", glm::vec4(1.0f), "MASK", 0.5f, true, picketTex);
  int leaves = b.addMaterial("leaves", glm::vec4(1.0f), "MASK", 0.5f, true, leafTex);

  b.addNode("meadow", b.addMesh("meadow", groundQuad(-40.0f, 40.0f, -40.0f, 40.0f), meadow));
  MeshData m;
  m.addSphere({0.0f, 1.0f, -1.0f}, 1.0f, 48, 24);
  b.addNode("sphere", b.addMesh("sphere", m, porcelain));
  m = {};
  m.addBox({-2.6f, 0.8f, -0.2f}, glm::vec3(0.8f), 25.0f);
  b.addNode("terracotta-box", b.addMesh("terracotta-box", m, terracotta));
  m = {};
  m.addBox({3.5f, 1.6f, -4.0f}, {0.5f, 1.6f, 0.5f}, -15.0f);
  b.addNode("slate-box", b.addMesh("slate-box", m, slate));
  m = {};
  m.addBox({1.8f, 0.25f, 1.8f}, glm::vec3(0.25f), 40.0f);
  b.addNode("mustard-box", b.addMesh("mustard-box", m, mustard));
  m = {};
  for (float x : {-9.0f, -5.0f, -1.0f, 3.0f}) m.addCylinder({x, 0.0f, -14.0f}, 0.3f, 5.0f, 32);
  m.addBox({-3.0f, 5.15f, -14.0f}, {6.4f, 0.15f, 0.45f});  // an architrave on the columns
  b.addNode("colonnade", b.addMesh("colonnade", m, stone));
  m = {};
  m.addBox({12.0f, 5.0f, -22.0f}, {1.25f, 5.0f, 1.25f}, 10.0f);
  b.addNode("tower", b.addMesh("tower", m, lavender));

  // A picket fence along z at x = -6: one alpha-masked quad (1 texture tile per metre) and
  // five posts. Its striped shadow falls towards +x.
  m = {};
  const float fx = -6.0f, fz0 = -1.0f, fz1 = 7.0f, fh = 1.2f;
  m.addQuad({fx, 0.0f, fz1}, {fx, 0.0f, fz0}, {fx, fh, fz0}, {fx, fh, fz1}, {fz1 - fz0, 1.0f});
  b.addNode("fence", b.addMesh("fence", m, pickets));
  m = {};
  for (float z = fz0; z <= fz1 + 0.01f; z += 2.0f)
    m.addBox({fx - 0.08f, 0.65f, z}, {0.05f, 0.65f, 0.05f});
  b.addNode("fence-posts", b.addMesh("fence-posts", m, wood));

  // A tree: a trunk and a crown of alpha-masked leaf cards.
  const glm::vec3 treeBase(-9.0f, 0.0f, -7.0f);
  m = {};
  m.addCylinder(treeBase, 0.22f, 3.4f, 16);
  b.addNode("trunk", b.addMesh("trunk", m, bark));
  m = {};
  const glm::vec3 crown = treeBase + glm::vec3(0.0f, 3.9f, 0.0f);
  for (int i = 0; i < 44; ++i) {
    glm::vec3 c = crown + rng.inBall() * glm::vec3(1.7f, 1.3f, 1.7f);
    glm::vec3 n = rng.onSphere();
    glm::vec3 u = glm::normalize(
        glm::cross(std::abs(n.y) > 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0), n));
    glm::vec3 v = glm::cross(n, u);
    float h = 0.65f + 0.25f * rng.uniform();
    m.addQuad(c - h * u - h * v, c + h * u - h * v, c + h * u + h * v, c - h * u + h * v);
  }
  b.addNode("crown", b.addMesh("crown", m, leaves));

  b.addSun(kDefaultSunAzimuthDeg, kDefaultSunElevationDeg);
  b.addCamera("overview", {9.0f, 8.0f, 17.0f}, {-0.5f, 1.0f, -5.0f}, 50.0f, 0.1f, 150.0f);
  b.addCamera("fence", {-2.6f, 1.7f, 8.0f}, {-5.2f, 0.3f, 3.0f}, 50.0f, 0.05f, 150.0f);
  b.addCamera("tree", {2.0f, 2.4f, -3.0f}, {-5.0f, 0.8f, -5.5f}, 50.0f, 0.05f, 150.0f);
  b.addCamera("far", {2.0f, 1.7f, 12.0f}, {5.0f, 2.5f, -20.0f}, 50.0f, 0.1f, 200.0f);
  std::vector<CameraKeyframe> keys;
  const glm::vec3 center(-1.5f, 0.8f, -3.5f);
  for (int k = 0; k <= 10; ++k) {
    float az = 40.0f - 10.0f * float(k);  // from front-right round to the left
    float dist = 17.0f - 0.6f * float(k);
    keys.push_back({float(k),
                    center + glm::vec3(dist * std::sin(glm::radians(az)), 5.5f,
                                       dist * std::cos(glm::radians(az))),
                    center});
  }
  addPath(b, "orbit", 50.0f, 0.1f, 150.0f, keys);
  return b;
}

// ----------------------------------------------------------------------------------------
// yard (a test fixture, tests/data/yard.gltf): what a user's glTF looks like to the warp —
// a 160 m ground of two triangles, crates, posts and a wall from 2 m to 70 m ahead of a
// walking camera. RTW must get better with every texel here too (issue 8).
SceneBuilder makeYard() {
  SceneBuilder b("yard");
  int ground = b.addMaterial("ground", {0.62f, 0.60f, 0.55f, 1.0f});
  int crate = b.addMaterial("crate", {0.70f, 0.52f, 0.30f, 1.0f});
  int stone = b.addMaterial("stone", {0.55f, 0.55f, 0.60f, 1.0f});
  b.addNode("ground", b.addMesh("ground", groundQuad(-80.0f, 80.0f, -80.0f, 80.0f), ground));
  MeshData crates, stones;
  for (int i = 0; i < 14; ++i) {  // crates along the walk, every 5 m, alternating sides
    float z = -3.0f - 5.0f * float(i), x = (i % 2 ? 2.6f : -2.4f) + 0.3f * float(i % 3);
    float h = 0.4f + 0.15f * float(i % 4);
    crates.addBox({x, h, z}, {0.5f + 0.1f * float(i % 3), h, 0.5f}, 12.0f * float(i % 5));
  }
  for (int i = 0; i < 10; ++i)  // thin posts further out
    stones.addBox({-7.0f + 1.5f * float(i % 3), 1.5f, -8.0f - 7.0f * float(i)},
                  {0.06f, 1.5f, 0.06f});
  stones.addBox({6.0f, 1.0f, -40.0f}, {0.2f, 1.0f, 30.0f});  // a 60 m wall on the right
  b.addNode("crates", b.addMesh("crates", crates, crate));
  b.addNode("stones", b.addMesh("stones", stones, stone));
  b.addSun(140.0f, 35.0f);
  std::vector<CameraKeyframe> keys;
  for (int k = 0; k <= 10; ++k) {
    float z = 4.0f - 4.0f * float(k);  // walk 40 m down the yard at 4 m/s
    keys.push_back({float(k), {0.3f * std::sin(float(k)), 1.7f, z}, {0.0f, 0.8f, z - 20.0f}});
  }
  addPath(b, "walk", 55.0f, 0.1f, 150.0f, keys);
  return b;
}

/// Writes `builder` to `path` (.gltf or .glb), reads it back through the real loader and
/// prints what scenes/README.md lists (first line: "PATH: N triangles, ...").
int writeSceneFile(SceneBuilder builder, const std::filesystem::path& path,
                   const std::filesystem::path& previewDir) {
  if (std::string err = builder.write(path.string()); !err.empty()) {
    std::fprintf(stderr, "%s\n", err.c_str());
    return 1;
  }
  // Read it back through the real loader and report the facts scenes/README.md lists.
  SceneLoadResult loaded = loadGltf(path);
  if (!loaded) {
    std::fprintf(stderr, "%s\n", loaded.error.c_str());
    return 1;
  }
  const Scene& s = *loaded.scene;
  std::error_code ec;
  auto bytes = std::filesystem::file_size(path, ec);
  std::printf("%s: %zu triangles, %.0f KiB, bounds (%.2f %.2f %.2f)..(%.2f %.2f %.2f)\n",
              path.string().c_str(), s.triangleCount(), double(bytes) / 1024.0,
              double(s.bounds.min.x), double(s.bounds.min.y), double(s.bounds.min.z),
              double(s.bounds.max.x), double(s.bounds.max.y), double(s.bounds.max.z));
  if (s.light) std::printf("  light: %s\n", s.light->describe().c_str());
  for (const CameraBookmark& c : s.cameras)
    std::printf(
        "  camera %-14s eye (%.2f %.2f %.2f) target (%.2f %.2f %.2f) fov %.0f near %.2f far %.0f\n",
        c.name.c_str(), double(c.camera.position.x), double(c.camera.position.y),
        double(c.camera.position.z), double(c.camera.target.x), double(c.camera.target.y),
        double(c.camera.target.z), double(c.camera.fovYDeg), double(c.camera.nearM),
        double(c.camera.farM));
  for (const CameraPath& p : s.paths)
    std::printf("  path %s: %zu keys, %.1f s\n", p.name.c_str(), p.keys.size(),
                double(p.durationS()));
  for (const std::string& w : s.warnings) std::printf("  warning: %s\n", w.c_str());
  if (!previewDir.empty()) return writePreviews(s, previewDir);
  return 0;
}

int writeScene(SceneBuilder builder, const std::string& name, const std::filesystem::path& dir,
               const std::filesystem::path& previewDir) {
  return writeSceneFile(std::move(builder), dir / (name + ".gltf"), previewDir);
}

}  // namespace
}  // namespace sl::gen

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  fs::path scenesDir, fixturesDir, previewDir, sponzaFile;
  constexpr long kSponzaDefaultTriangles = 262000;  // Crytek Sponza: 262 k (DA-RTW poster)
  long sponzaTriangles = kSponzaDefaultTriangles;
  bool trianglesGiven = false;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    auto value = [&]() -> fs::path { return i + 1 < argc ? fs::path(argv[++i]) : fs::path(); };
    if (arg == "--sponza-class") {
      sponzaFile = value();
      if (sponzaFile.empty()) {
        std::fprintf(stderr, "--sponza-class: missing the file to write (OUT.glb or OUT.gltf)\n");
        return 2;
      }
    } else if (arg == "--triangles") {
      const std::string text = value().string();
      char* end = nullptr;
      sponzaTriangles = std::strtol(text.c_str(), &end, 10);
      trianglesGiven = true;
      if (text.empty() || *end != '\0' || sponzaTriangles < 5000 || sponzaTriangles > 20000000) {
        std::fprintf(stderr, "--triangles: expected a whole number 5000..20000000, got '%s'\n",
                     text.c_str());
        return 2;
      }
    } else if (arg == "--scenes") {
      scenesDir = value();
    } else if (arg == "--fixtures") {
      fixturesDir = value();
    } else if (arg == "--preview") {
      previewDir = value();
    } else {
      std::fprintf(
          stderr,
          "usage: %s [--scenes DIR] [--fixtures DIR] [--preview DIR]\n"
          "       %s --sponza-class OUT.glb [--triangles N]\n"
          "  --scenes DIR    write the built-in scenes (plane-box, diagonal, corridor, "
          "default, dueling, spot-box, point-box, omni-room, spot-yard, thin-pole, band-diagonal, "
          "band-aligned, blob; real content: helmet, sunroom, figure, car) as "
          "DIR/<name>.gltf\n"
          "  --fixtures DIR  write the loader's test fixtures into DIR\n"
          "  --preview DIR   also ray-trace a PNG of every camera bookmark into DIR\n"
          "  --sponza-class OUT.glb  write a generated atrium for timings (floor, two "
          "storeys of arcades, walls, drapes, an open roof, a sun, camera 'atrium') with "
          "at most --triangles N triangles (default %ld, as the Crytek Sponza of the "
          "DA-RTW poster); .gltf writes JSON\n",
          argv[0], argv[0], kSponzaDefaultTriangles);
      return 2;
    }
  }
  if (!sponzaFile.empty()) {
    if (!scenesDir.empty() || !fixturesDir.empty() || !previewDir.empty()) {
      std::fprintf(stderr, "--sponza-class: give it alone (with --triangles N)\n");
      return 2;
    }
    if (sponzaFile.has_parent_path()) fs::create_directories(sponzaFile.parent_path());
    return sl::gen::writeSceneFile(sl::gen::makeSponzaClass(std::size_t(sponzaTriangles)),
                                   sponzaFile, {});
  }
  if (trianglesGiven) {
    std::fprintf(stderr, "--triangles: only with --sponza-class OUT.glb\n");
    return 2;
  }
  if (scenesDir.empty() && fixturesDir.empty()) {
    std::fprintf(stderr, "nothing to do: give --scenes DIR and/or --fixtures DIR (see --help)\n");
    return 2;
  }
  int rc = 0;
  if (!scenesDir.empty()) {
    fs::create_directories(scenesDir);
    if (!previewDir.empty()) fs::create_directories(previewDir);
    rc |= sl::gen::writeScene(sl::gen::makePlaneBox(), "plane-box", scenesDir, previewDir);
    rc |= sl::gen::writeScene(sl::gen::makeDiagonal(), "diagonal", scenesDir, previewDir);
    rc |= sl::gen::writeScene(sl::gen::makeCorridor(), "corridor", scenesDir, previewDir);
    rc |= sl::gen::writeScene(sl::gen::makeDefault(), "default", scenesDir, previewDir);
    rc |= sl::gen::writeScene(sl::gen::makeDueling(), "dueling", scenesDir, previewDir);
    rc |= sl::gen::writeScene(sl::gen::makePunctualBox("spot-box", true), "spot-box", scenesDir,
                              previewDir);
    rc |= sl::gen::writeScene(sl::gen::makePunctualBox("point-box", false), "point-box", scenesDir,
                              previewDir);
    rc |= sl::gen::writeScene(sl::gen::makeOmniRoom(), "omni-room", scenesDir, previewDir);
    rc |= sl::gen::writeScene(sl::gen::makeSpotYard(), "spot-yard", scenesDir, previewDir);
    rc |= sl::gen::writeScene(sl::gen::makeThinPole(), "thin-pole", scenesDir, previewDir);
    rc |= sl::gen::writeScene(sl::gen::makeBand("band-diagonal", 45.0f, false), "band-diagonal",
                              scenesDir, previewDir);
    rc |= sl::gen::writeScene(sl::gen::makeBand("band-aligned", 0.0f, false), "band-aligned",
                              scenesDir, previewDir);
    rc |= sl::gen::writeScene(sl::gen::makeBand("blob", 0.0f, true), "blob", scenesDir, previewDir);
    rc |= sl::gen::writeScene(sl::gen::makeHelmet(), "helmet", scenesDir, previewDir);
    rc |= sl::gen::writeScene(sl::gen::makeSunroom(), "sunroom", scenesDir, previewDir);
    rc |= sl::gen::writeScene(sl::gen::makeFigure(), "figure", scenesDir, previewDir);
    rc |= sl::gen::writeScene(sl::gen::makeCar(), "car", scenesDir, previewDir);
  }
  if (!fixturesDir.empty()) {
    fs::create_directories(fixturesDir);
    rc |= sl::gen::writeFixtures(fixturesDir);
    rc |= sl::gen::writeScene(sl::gen::makeYard(), "yard", fixturesDir, {});
  }
  return rc;
}
