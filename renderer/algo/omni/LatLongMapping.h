// The spherical (latitude-longitude) parameterisation of a point light's sphere of
// directions, the third one the omni-light lecture slides list beside the cube and the dual
// paraboloid (Romanick's VGP353 notes, after Brabec, Annen, Seidel 2002): a direction's
// longitude and latitude about a pole axis are the map's u and v. Plain C++: the CPU
// reference of the `spherical` technique (shaders/spherical/latlong.glsl): mapping and
// inverse, texels, halves, sampling density, and the bounds of a triangle's image (seam,
// poles) that its depth pass rasterises.
#pragma once

#include <glm/glm.hpp>

namespace sl::omni {

/// The map's frame: latitude +90° along `pole`, longitude 0 along `x`, +90° along `y`
/// (x × y = pole). The seam (longitude ±180°) is the half-plane through -x.
struct LatLongFrame {
  glm::dvec3 pole{0.0, 1.0, 0.0};                  ///< unit
  glm::dvec3 x{1.0, 0.0, 0.0}, y{0.0, 0.0, -1.0};  ///< unit, x × y = pole
};
/// A frame about unit `pole` (x chosen stably, as omni::paraboloidFrame: the world axis
/// least aligned with the pole seeds it).
LatLongFrame latLongFrame(const glm::dvec3& pole);

/// The map is `2 * height` texels wide (longitude, 360°) and `height` high (latitude,
/// 180°): texels are square in angle on the equator. It is looked up as two halves of
/// height^2 texels (half 0: longitudes [-180°, 0°), half 1: [0°, 180°)), so that each
/// half's uv continues across its edges (the seam included) for the resolve's finite
/// differences.
inline constexpr int kLatLongHalves = 2;

/// Longitude in (-pi, pi] (atan2 of the frame's y and x parts) and latitude in
/// [-pi/2, pi/2] (asin of the pole part) of `dir` (any length > 0). At a pole the
/// longitude is that of atan2(0, 0) = 0.
struct LatLong {
  double longitudeRad = 0.0, latitudeRad = 0.0;
};
LatLong latLong(const LatLongFrame& frame, const glm::dvec3& dir);
/// The unit direction of a longitude and latitude.
glm::dvec3 latLongDirection(const LatLongFrame& frame, const LatLong& ll);

/// The whole map's uv in [0, 1]^2: u = (longitude + pi) / 2 pi (0 and 1 are the seam),
/// v = latitude / pi + 1/2 (0: the south pole -pole, 1: the north pole).
glm::dvec2 latLongUv(const LatLongFrame& frame, const glm::dvec3& dir);
/// The inverse (u wraps: any real u is a longitude).
glm::dvec3 latLongUvDirection(const LatLongFrame& frame, const glm::dvec2& uv);

/// The texel of a map `height` texels high (2 height wide) holding `dir`: column floor(u W)
/// modulo W (longitude pi, u = 1, is column 0 again: the seam wraps), row floor(v H)
/// clamped to [0, H - 1] (the north pole lies on the top edge).
glm::ivec2 latLongTexel(const LatLongFrame& frame, const glm::dvec3& dir, int height);
/// The unit direction through a texel's centre.
glm::dvec3 latLongTexelCentreDirection(const LatLongFrame& frame, const glm::ivec2& texel,
                                       int height);
/// A texel beyond the map's edges brought back onto it: columns wrap (the seam); a row
/// beyond a pole is mirrored and its column moved half way round (the texel on the other
/// side of the pole). PCF taps go through it.
glm::ivec2 latLongWrapTexel(glm::ivec2 texel, int height);

/// A direction on the two halves: the half (longitude < 0: 0, else 1) and the uv in it.
struct LatLongHalfCoord {
  int half = 0;
  glm::dvec2 uv{0.0};
};
LatLongHalfCoord latLongHalfUv(const LatLongFrame& frame, const glm::dvec3& dir);
/// `dir`'s uv in half `half`, beyond its edges too: the longitude taken within pi of the
/// half's centre (-pi/2 or pi/2), so u is continuous everywhere but the meridian opposite
/// that centre (u in [-1/2, 3/2]).
glm::dvec2 latLongUvInHalf(const LatLongFrame& frame, int half, const glm::dvec3& dir);

/// Texels per steradian in direction `dir` of a map `height` texels high: the map covers
/// 2 pi x pi radians of longitude x latitude with 2 H^2 texels and a solid angle element
/// is cos(latitude) dlon dlat, so H^2 / (pi^2 cos latitude): H^2 / pi^2 on the equator,
/// infinite at the poles (every texel of the top and bottom rows meets there).
double latLongTexelsPerSteradian(const LatLongFrame& frame, const glm::dvec3& dir, int height);
/// The exact solid angle (sr) of one texel of row `row` (all texels of a row are equal):
/// (2 pi / W) (sin lat1 - sin lat0) with the row's latitude bounds.
double latLongTexelSolidAngle(int row, int height);

/// The bounds of a world triangle's image in the map, for a light at `lightM`: which pole
/// its image holds (a ray from the light along the pole or -pole hits it: then every
/// longitude is in), its longitude range unwrapped from vertex a's longitude (may leave
/// [-pi, pi]: the image crosses the seam and is drawn twice, shifted by 2 pi), and its
/// latitude range, including the edges' bulges towards a pole (an edge is a great-circle arc
/// whose highest or lowest point may lie between its ends).
struct LatLongBounds {
  int pole = 0;  ///< 0: none, +1: holds the north pole (along frame.pole), -1: the south pole
  double lonMinRad = 0.0, lonMaxRad = 0.0;
  double latMinRad = 0.0, latMaxRad = 0.0;
  bool valid = false;  ///< false: a vertex at the light or a triangle edge-on to it
};
LatLongBounds latLongTriangleBounds(const LatLongFrame& frame, const glm::dvec3& lightM,
                                    const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

/// Distance along unit `dir` from `origin` to triangle (a, b, c), or -1 when the ray misses
/// it (Moeller-Trumbore; barycentrics within [-edgeEps, 1 + edgeEps] count as a hit, so
/// that a direction on an edge shared by two triangles hits at least one of them).
double rayTriangleDistance(const glm::dvec3& origin, const glm::dvec3& dir, const glm::dvec3& a,
                           const glm::dvec3& b, const glm::dvec3& c, double edgeEps = 0.0);

}  // namespace sl::omni
