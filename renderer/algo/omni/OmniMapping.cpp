// Cube and dual-paraboloid mappings of the sphere of directions (OmniMapping.h): face
// selection, uv and inverse, texels, densities, the faces a spot's cone reaches.
#include "OmniMapping.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace sl::omni {

namespace {

// forward, right (= forward x up, glm::lookAt's s), up (lookAt's u) per face.
const CubeFaceBasis kFaces[kCubeFaces] = {
    {{1, 0, 0}, {0, 0, 1}, {0, 1, 0}},    // +x
    {{-1, 0, 0}, {0, 0, -1}, {0, 1, 0}},  // -x
    {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},    // +y
    {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}},  // -y
    {{0, 0, 1}, {-1, 0, 0}, {0, 1, 0}},   // +z
    {{0, 0, -1}, {1, 0, 0}, {0, 1, 0}},   // -z
};

int checkedFace(int face) {
  return std::clamp(face, 0, kCubeFaces - 1);
}

}  // namespace

const char* cubeFaceName(int face) {
  static const char* const names[kCubeFaces] = {"+x", "-x", "+y", "-y", "+z", "-z"};
  return names[checkedFace(face)];
}

CubeFaceBasis cubeFaceBasis(int face) {
  return kFaces[checkedFace(face)];
}

glm::mat4 cubeFaceView(int face, const glm::vec3& lightPosM) {
  const CubeFaceBasis& b = kFaces[checkedFace(face)];
  return glm::lookAt(lightPosM, lightPosM + glm::vec3(b.forward), glm::vec3(b.up));
}

int selectCubeFace(const glm::dvec3& d) {
  const glm::dvec3 a = glm::abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0 ? 0 : 1;
  if (a.y >= a.z) return d.y >= 0.0 ? 2 : 3;
  return d.z >= 0.0 ? 4 : 5;
}

CubeCoord cubeFaceUv(const glm::dvec3& dir) {
  CubeCoord c;
  c.face = selectCubeFace(dir);
  const CubeFaceBasis& b = kFaces[c.face];
  const double f = glm::dot(dir, b.forward);
  c.uv = 0.5 + 0.5 * glm::dvec2(glm::dot(dir, b.right), glm::dot(dir, b.up)) / f;
  return c;
}

glm::dvec3 cubeDirection(int face, const glm::dvec2& uv) {
  const CubeFaceBasis& b = kFaces[checkedFace(face)];
  const glm::dvec2 p = 2.0 * uv - 1.0;
  return glm::normalize(b.forward + p.x * b.right + p.y * b.up);
}

CubeTexel cubeTexel(const glm::dvec3& dir, int resolution) {
  const CubeCoord c = cubeFaceUv(dir);
  const glm::ivec2 t = glm::ivec2(glm::floor(c.uv * double(resolution)));
  return {c.face, glm::clamp(t, glm::ivec2(0), glm::ivec2(resolution - 1))};
}

glm::dvec3 cubeTexelCentreDirection(const CubeTexel& t, int resolution) {
  return cubeDirection(t.face, (glm::dvec2(t.texel) + 0.5) / double(resolution));
}

double storedDistance(double distanceM, double nearM, double farM) {
  return (distanceM - nearM) / (farM - nearM);
}

double distanceFromStored(double stored, double nearM, double farM) {
  return nearM + stored * (farM - nearM);
}

double cubeTexelsPerSteradian(const glm::dvec3& dir, int resolution) {
  const int face = selectCubeFace(dir);
  const double r = glm::length(dir) / glm::dot(dir, kFaces[face].forward);
  const double half = 0.5 * double(resolution);
  return half * half * r * r * r;
}

double cubeFaceAngularDistance(int face, const glm::dvec3& dir) {
  const CubeFaceBasis& b = kFaces[checkedFace(face)];
  const glm::dvec3 d = glm::normalize(dir);
  // The pyramid: forward.d >= |right.d| and forward.d >= |up.d|: four half-spaces whose
  // planes pass through the light.
  const glm::dvec3 normals[4] = {b.forward - b.right, b.forward + b.right, b.forward - b.up,
                                 b.forward + b.up};
  auto inside = [&](const glm::dvec3& v) {
    for (const glm::dvec3& n : normals)
      if (glm::dot(v, n) < -1e-12) return false;
    return true;
  };
  if (inside(d)) return 0.0;
  // Outside: the nearest direction lies on a side plane (the projection of d onto it, if
  // that is inside) or is one of the four edge rays.
  double bestCos = -1.0;
  for (const glm::dvec3& n0 : normals) {
    const glm::dvec3 n = glm::normalize(n0);
    const glm::dvec3 p = d - glm::dot(d, n) * n;
    const double len = glm::length(p);
    if (len > 1e-12 && inside(p / len)) bestCos = std::max(bestCos, glm::dot(d, p / len));
  }
  for (double su : {-1.0, 1.0})
    for (double sv : {-1.0, 1.0})
      bestCos =
          std::max(bestCos, glm::dot(d, glm::normalize(b.forward + su * b.right + sv * b.up)));
  return std::acos(std::clamp(bestCos, -1.0, 1.0));
}

std::uint32_t cubeFacesInCone(const glm::dvec3& axis, double halfAngleRad) {
  std::uint32_t mask = 0;
  for (int f = 0; f < kCubeFaces; ++f)
    if (cubeFaceAngularDistance(f, axis) < halfAngleRad) mask |= 1u << f;
  return mask;
}

void completeFrame(const glm::dvec3& axis, glm::dvec3& x, glm::dvec3& y) {
  const glm::dvec3 a = glm::abs(axis);
  // The world axis least aligned with `axis` seeds x.
  const glm::dvec3 seed = a.x <= a.y && a.x <= a.z ? glm::dvec3(1, 0, 0)
                          : a.y <= a.z             ? glm::dvec3(0, 1, 0)
                                                   : glm::dvec3(0, 0, 1);
  y = glm::normalize(glm::cross(axis, seed));
  x = glm::cross(y, axis);
}

ParaboloidFrame paraboloidFrame(const glm::dvec3& axis) {
  ParaboloidFrame f;
  f.axis = glm::normalize(axis);
  completeFrame(f.axis, f.x, f.y);
  return f;
}

namespace {
/// dir in hemisphere `half`'s frame: half 0 (x, y, axis); half 1 rotated 180° about x.
glm::dvec3 inHalf(const ParaboloidFrame& f, int half, const glm::dvec3& d) {
  const glm::dvec3 local(glm::dot(d, f.x), glm::dot(d, f.y), glm::dot(d, f.axis));
  return half == 0 ? local : glm::dvec3(local.x, -local.y, -local.z);
}
}  // namespace

ParaboloidCoord paraboloidUv(const ParaboloidFrame& frame, const glm::dvec3& dir) {
  const glm::dvec3 d = glm::normalize(dir);
  ParaboloidCoord c;
  c.half = glm::dot(d, frame.axis) >= 0.0 ? 0 : 1;
  const glm::dvec3 l = inHalf(frame, c.half, d);
  c.uv = 0.5 + 0.5 * glm::dvec2(l.x, l.y) / (1.0 + l.z);
  return c;
}

glm::dvec3 paraboloidDirection(const ParaboloidFrame& frame, int half, const glm::dvec2& uv) {
  // p = (x, y) / (1 + z) on the unit sphere: z = (1 - |p|^2) / (1 + |p|^2), (x, y) = p (1 + z).
  const glm::dvec2 p = 2.0 * uv - 1.0;
  const double r2 = glm::dot(p, p);
  const double z = (1.0 - r2) / (1.0 + r2);
  const glm::dvec3 l(p * (1.0 + z), z);
  const glm::dvec3 h = half == 0 ? l : glm::dvec3(l.x, -l.y, -l.z);
  return glm::normalize(h.x * frame.x + h.y * frame.y + h.z * frame.axis);
}

double paraboloidTexelsPerSteradian(const ParaboloidFrame& frame, const glm::dvec3& dir,
                                    int resolution) {
  // Disc area per solid angle: rho = tan(theta / 2), rho drho / (sin theta dtheta)
  // = 1 / (1 + cos theta)^2.
  const double cosTheta = std::abs(glm::dot(glm::normalize(dir), frame.axis));
  const double half = 0.5 * double(resolution);
  return half * half / ((1.0 + cosTheta) * (1.0 + cosTheta));
}

}  // namespace sl::omni
