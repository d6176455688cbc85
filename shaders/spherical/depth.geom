// Spherical (lat-long) depth pass, geometry stage, once per scene triangle and half: where
// its image lies in the map (CPU: omni::latLongTriangleBounds). Straight edges become curves
// in longitude-latitude (a great-circle arc bulges towards a pole), a triangle around a pole
// covers every longitude, and one across the seam (longitude ±180°) wraps; so by default
// (sph.exactCoverage) it is drawn as its image's bounding box, one texel wider, copied at
// ±360° where it reaches past the seam, and the fragment stage keeps a texel only where the
// texel's own direction hits the triangle. sph.exactCoverage off: the three vertices mapped
// and joined by straight lines in the map (copied across the seam the same way), the
// per-vertex mapping of a projection, whose shapes are wrong (and lost around a pole).
#include "spherical/latlong.glsl"
layout(triangles) in;
layout(triangle_strip, max_vertices = 12) out;
in vec3 vg_worldPos[];
in vec2 vg_uv[];
flat out vec3 g_a, g_b, g_c;       // the triangle (world), for the per-texel ray test
flat out vec2 g_uvA, g_uvB, g_uvC;  // its material uv
uniform int u_sphHalfIndex;  // 0: longitudes [-pi, 0), 1: [0, pi)
uniform int u_sphExact;      // sph.exactCoverage
uniform float u_mapTexels;   // H: each half is H x H

void emitAt(vec2 lonLat, float halfStart) {
  g_a = vg_worldPos[0];
  g_b = vg_worldPos[1];
  g_c = vg_worldPos[2];
  g_uvA = vg_uv[0];
  g_uvB = vg_uv[1];
  g_uvC = vg_uv[2];
  gl_Position = vec4((lonLat.x - halfStart) / kSphPi * 2.0 - 1.0, lonLat.y / (0.5 * kSphPi), 0.0, 1.0);
  EmitVertex();
}

float wrapped(float d) {
  if (d > kSphPi) d -= 2.0 * kSphPi;
  if (d <= -kSphPi) d += 2.0 * kSphPi;
  return d;
}

void main() {
  vec3 v0 = vg_worldPos[0] - u_omniLight, v1 = vg_worldPos[1] - u_omniLight,
       v2 = vg_worldPos[2] - u_omniLight;
  vec3 n = cross(v1 - v0, v2 - v0);
  // Degenerate, or edge-on to the light: no texel's ray meets its area.
  if (abs(dot(n, v0)) <= 1e-7 * length(n) * length(v0)) return;
  vec3 u[3] = vec3[3](normalize(v0), normalize(v1), normalize(v2));
  vec2 ll[3] = vec2[3](sphLatLong(u[0]), sphLatLong(u[1]), sphLatLong(u[2]));
  float lon0 = ll[0].x;
  float lon1 = lon0 + wrapped(ll[1].x - lon0);
  float lon2 = lon1 + wrapped(ll[2].x - lon1);
  float halfStart = u_sphHalfIndex == 0 ? -kSphPi : 0.0;
  float texel = kSphPi / u_mapTexels;

  if (u_sphExact == 0) {
    vec2 p[3] = vec2[3](vec2(lon0, ll[0].y), vec2(lon1, ll[1].y), vec2(lon2, ll[2].y));
    float lo = min(lon0, min(lon1, lon2)), hi = max(lon0, max(lon1, lon2));
    for (int k = -1; k <= 1; ++k) {
      float s = 2.0 * kSphPi * float(k);
      if (hi + s < halfStart - texel || lo + s > halfStart + kSphPi + texel) continue;
      for (int i = 0; i < 3; ++i) emitAt(p[i] + vec2(s, 0.0), halfStart);
      EndPrimitive();
    }
    return;
  }

  // Latitude: the vertices, each edge's highest / lowest point where it lies on the arc.
  float latMin = min(ll[0].y, min(ll[1].y, ll[2].y));
  float latMax = max(ll[0].y, max(ll[1].y, ll[2].y));
  for (int i = 0; i < 3; ++i) {
    vec3 p = u[i], q = u[(i + 1) % 3];
    vec3 arcN = cross(p, q);
    if (length(arcN) <= 1e-7) continue;
    vec3 nn = normalize(arcN);
    vec3 e = u_omniAxis - dot(u_omniAxis, nn) * nn;
    if (length(e) <= 1e-7) continue;
    e = normalize(e);
    for (int s = 0; s < 2; ++s) {
      vec3 x = s == 0 ? e : -e;
      if (dot(cross(p, x), nn) < 0.0 || dot(cross(x, q), nn) < 0.0) continue;
      float lat = asin(clamp(dot(x, u_omniAxis), -1.0, 1.0));
      latMin = min(latMin, lat);
      latMax = max(latMax, lat);
    }
  }
  float lo = min(lon0, min(lon1, lon2)), hi = max(lon0, max(lon1, lon2));
  // A pole inside: every longitude, up to the pole.
  const float eps = 1e-5;
  if (sphBaryInside(sphRayTriangle(u_omniAxis, vg_worldPos[0], vg_worldPos[1], vg_worldPos[2]), eps)) {
    latMax = 0.5 * kSphPi;
    lo = -kSphPi;
    hi = kSphPi;
  }
  if (sphBaryInside(sphRayTriangle(-u_omniAxis, vg_worldPos[0], vg_worldPos[1], vg_worldPos[2]), eps)) {
    latMin = -0.5 * kSphPi;
    lo = -kSphPi;
    hi = kSphPi;
  }
  latMin -= texel;
  latMax += texel;
  lo -= texel;
  hi += texel;
  for (int k = -1; k <= 1; ++k) {
    float s = 2.0 * kSphPi * float(k);
    if (hi + s < halfStart || lo + s > halfStart + kSphPi) continue;
    emitAt(vec2(lo + s, latMin), halfStart);
    emitAt(vec2(hi + s, latMin), halfStart);
    emitAt(vec2(lo + s, latMax), halfStart);
    emitAt(vec2(hi + s, latMax), halfStart);
    EndPrimitive();
  }
}
