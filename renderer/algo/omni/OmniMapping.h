// The two parameterisations of an omni-directional light's sphere of directions (seed 001;
// docs/techniques.md §7): the cube (six 90° perspective faces) and the dual paraboloid
// (Brabec, Annen, Seidel 2002), with their inverses and sampling densities. Plain C++: the
// CPU reference of the `cube` technique's face selection and lookup (shaders/cube/lookup.glsl).
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

namespace sl::omni {

/// The cube's faces, in the order of the `cube` technique's layers (and SL_CUBE_FACE_*).
enum class CubeFace : int { PosX = 0, NegX = 1, PosY = 2, NegY = 3, PosZ = 4, NegZ = 5 };
inline constexpr int kCubeFaces = 6;
/// "+x", "-x", "+y", "-y", "+z", "-z".
const char* cubeFaceName(int face);

/// The frame of one face: it looks along `forward`; its light uv grows along `right` (u)
/// and `up` (v). right = forward x up, as glm::lookAt(eye, eye + forward, up) builds it,
/// so a 90° glm::perspective over cubeFaceView gives exactly cubeFaceUv.
struct CubeFaceBasis {
  glm::dvec3 forward, right, up;
};
CubeFaceBasis cubeFaceBasis(int face);
/// World -> the face's view space for a light at `lightPosM` (glm::lookAt).
glm::mat4 cubeFaceView(int face, const glm::vec3& lightPosM);

/// The face serving direction `dir` (any length > 0): its largest |component|; ties go to
/// x before y before z, positive before negative (shaders/cube/lookup.glsl does the same).
int selectCubeFace(const glm::dvec3& dir);

/// A direction's place on the cube: its face and the uv in [0, 1]^2 on that face.
struct CubeCoord {
  int face = 0;
  glm::dvec2 uv{0.0};
};
/// `dir` (any length > 0) on its face (selectCubeFace): uv = 0.5 + 0.5 (dir.right, dir.up)
/// / dir.forward.
CubeCoord cubeFaceUv(const glm::dvec3& dir);
/// The unit direction through uv of `face` (uv may leave [0, 1]: the face's plane).
glm::dvec3 cubeDirection(int face, const glm::dvec2& uv);
/// The texel of a face of `resolution`^2 texels holding `dir`, and the centre of a texel.
struct CubeTexel {
  int face = 0;
  glm::ivec2 texel{0};
};
CubeTexel cubeTexel(const glm::dvec3& dir, int resolution);
glm::dvec3 cubeTexelCentreDirection(const CubeTexel& t, int resolution);

/// What an omni map stores per texel for a surface `distanceM` from the light (the cube's
/// faces and the paraboloid's discs alike): (distance - near) / (far - near), 1 = the far
/// distance (nothing nearer: the cleared value). GLSL: storedLightDistance
/// (common/light_distance.glsl), written by cube/distance.frag and dual-paraboloid/depth.frag.
double storedDistance(double distanceM, double nearM, double farM);
/// The inverse: the distance (m) a stored value stands for.
double distanceFromStored(double stored, double nearM, double farM);

/// Texels per steradian of a cube map of `resolution`^2 texels per face, in direction `dir`:
/// (resolution / 2)^2 r^3 with r = |dir| / dir.forward (the face's plane at distance 1,
/// dOmega = dA / r^3). Face centre: (res/2)^2; corner: 3√3 times that.
double cubeTexelsPerSteradian(const glm::dvec3& dir, int resolution);

/// The cube faces a cone (unit axis, half-angle in radians, < pi/2) reaches: bit f set for
/// face f. Exact: a face is in when the smallest angle between `axis` and any direction of
/// the face's 90° pyramid is below `halfAngleRad` (cubeFaceAngularDistance).
std::uint32_t cubeFacesInCone(const glm::dvec3& axis, double halfAngleRad);
/// The smallest angle (radians) between unit `dir` and the directions `face` serves: 0
/// inside, else to the nearest side plane or edge ray of its pyramid.
double cubeFaceAngularDistance(int face, const glm::dvec3& dir);

/// The dual paraboloid's frame: hemisphere 0 looks along `axis`, hemisphere 1 along -axis
/// (rotated 180° about the frame's x, so both are right-handed).
struct ParaboloidFrame {
  glm::dvec3 axis{0.0, 1.0, 0.0};                  ///< unit
  glm::dvec3 x{1.0, 0.0, 0.0}, y{0.0, 0.0, -1.0};  ///< unit, x × y = axis
};
/// A frame about unit `axis` (x chosen stably: the world axis least aligned with it).
ParaboloidFrame paraboloidFrame(const glm::dvec3& axis);
/// Unit x and y completing unit `axis` to a right-handed frame (x × y = axis), x chosen stably:
/// the world axis least aligned with `axis` seeds it (paraboloidFrame, latLongFrame).
void completeFrame(const glm::dvec3& axis, glm::dvec3& x, glm::dvec3& y);

/// A direction on the dual paraboloid: its hemisphere and uv in [0, 1]^2 (the disc of
/// radius 0.5 around (0.5, 0.5) holds the hemisphere; the rim is the split plane).
struct ParaboloidCoord {
  int half = 0;
  glm::dvec2 uv{0.5};
};
/// Brabec et al.'s mapping: in the hemisphere's frame d = (x, y, z) unit, z >= 0 (ties at
/// z = 0 to hemisphere 0); p = (x, y) / (1 + z); uv = 0.5 + 0.5 p.
ParaboloidCoord paraboloidUv(const ParaboloidFrame& frame, const glm::dvec3& dir);
/// The inverse: the unit direction of uv on hemisphere `half` (|p| <= 1).
glm::dvec3 paraboloidDirection(const ParaboloidFrame& frame, int half, const glm::dvec2& uv);
/// Texels per steradian of a paraboloid map of `resolution`^2 texels per hemisphere:
/// (resolution / 2)^2 / (1 + cos theta)^2, theta from the hemisphere's axis. Centre:
/// res^2 / 16; rim: res^2 / 4, 4 times the centre.
double paraboloidTexelsPerSteradian(const ParaboloidFrame& frame, const glm::dvec3& dir,
                                    int resolution);

}  // namespace sl::omni
