// The latitude-longitude mapping in GLSL (CPU: algo/omni/LatLongMapping.h; the spherical
// parameterisation of the omni-light slides, beside the cube and the dual paraboloid):
// longitude about the pole u_omniAxis from u_omniX is u, latitude is v; the map is 2H x H
// texels, kept as two halves of H x H (layer 0: longitudes [-pi, 0), layer 1: [0, pi)). The
// light, frame (x × y = pole) and depth range: common/omni/frame.glsl.
#include "common/omni/frame.glsl"

const float kSphPi = 3.14159265358979;

// (longitude in (-pi, pi], latitude in [-pi/2, pi/2]) of d (omni::latLong); the latitude
// through atan, well conditioned near the poles.
vec2 sphLatLong(vec3 d) {
  vec3 l = omniLocal(d);
  float lon = atan(l.y, l.x);
  if (lon <= -kSphPi) lon = kSphPi;
  return vec2(lon, atan(l.z, length(l.xy)));
}

// The unit world direction of a longitude and latitude (omni::latLongDirection).
vec3 sphDirection(vec2 lonLat) {
  float c = cos(lonLat.y);
  return normalize(c * cos(lonLat.x) * u_omniX + c * sin(lonLat.x) * u_omniY +
                   sin(lonLat.y) * u_omniAxis);
}

// d's uv in half `map`, beyond its edges too (omni::latLongUvInHalf): the longitude within
// pi of the half's centre.
vec2 sphUvInHalf(int map, vec3 d) {
  vec2 ll = sphLatLong(d);
  float centre = map == 0 ? -0.5 * kSphPi : 0.5 * kSphPi;
  float dl = ll.x - centre;
  if (dl > kSphPi) dl -= 2.0 * kSphPi;
  if (dl <= -kSphPi) dl += 2.0 * kSphPi;
  return vec2((dl + 0.5 * kSphPi) / kSphPi, ll.y / kSphPi + 0.5);
}
int sphHalf(vec3 d) { return sphLatLong(d).x < 0.0 ? 0 : 1; }

// The unit direction through the centre of texel t of the whole 2H x H map
// (omni::latLongTexelCentreDirection).
vec3 sphTexelDirection(ivec2 t, int H) {
  vec2 uv = (vec2(t) + 0.5) / vec2(2 * H, H);
  return sphDirection(vec2(uv.x * 2.0 * kSphPi - kSphPi, (uv.y - 0.5) * kSphPi));
}

// A texel beyond the map's edges brought back (omni::latLongWrapTexel): columns wrap at the
// seam, a row beyond a pole is mirrored half way round.
ivec2 sphWrapTexel(ivec2 t, int H) {
  if (t.y >= H) {
    t = ivec2(t.x + H, 2 * H - 1 - t.y);
  } else if (t.y < 0) {
    t = ivec2(t.x + H, -1 - t.y);
  }
  t.y = clamp(t.y, 0, H - 1);
  t.x = ((t.x % (2 * H)) + 2 * H) % (2 * H);
  return t;
}

// Moeller-Trumbore from the light along unit `dir` against triangle (a, b, c): (t, u, v),
// t the distance (-1 behind or parallel), u and v the barycentrics of b and c, NOT range
// checked (omni::rayTriangleDistance checks them).
vec3 sphRayTriangle(vec3 dir, vec3 a, vec3 b, vec3 c) {
  vec3 e1 = b - a, e2 = c - a;
  vec3 p = cross(dir, e2);
  float det = dot(e1, p);
  if (abs(det) < 1e-12 * length(e1) * length(e2)) return vec3(-1.0, 0.0, 0.0);
  vec3 s = u_omniLight - a;
  vec3 q = cross(s, e1);
  float t = dot(e2, q) / det;
  return vec3(t > 0.0 ? t : -1.0, dot(s, p) / det, dot(dir, q) / det);
}
bool sphBaryInside(vec3 tuv, float eps) {
  return tuv.x > 0.0 && tuv.y >= -eps && tuv.z >= -eps && tuv.y + tuv.z <= 1.0 + eps;
}
