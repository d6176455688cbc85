// Warp maps shared by the warped rendering and the warped lookup: n+1 edge offsets per
// axis, x map first. Mirrors sl::rtw::warpCoordinate (algo/rtw/Warp.h): edges fetched and
// interpolated in float, no hardware filtering. Read through buffer textures over the
// scan pass's storage buffers (C++: RtwShadowMap::bindWarpTextures): llvmpipe serves
// texelFetch several times faster than SSBO loads (measured: the warped resolve pass).
uniform samplerBuffer u_warpEdges;
float warpEdge(int i) { return texelFetch(u_warpEdges, i).r; }
uniform int u_warpN;   // 1D map size n (= im.resolution)
uniform int u_warpOn;  // 0: identity (the unwarped map drawn for contrast)

float warpAxis(int axis, float u) {
  if (u_warpOn == 0 || !(u > 0.0 && u < 1.0)) return u;
  int n = u_warpN;
  int base = axis * (n + 1);
  float x = u * float(n);
  int e = min(int(floor(x)), n - 1);
  float t = x - float(e);
  float a = warpEdge(base + e), b = warpEdge(base + e + 1);
  return u + (a + t * (b - a));
}

// du'/du: how many times denser than uniform the map samples at u.
float warpSlope(int axis, float u) {
  if (u_warpOn == 0) return 1.0;
  int n = u_warpN;
  int e = clamp(int(floor(u * float(n))), 0, n - 1);
  int base = axis * (n + 1);
  return 1.0 + float(n) * (warpEdge(base + e + 1) - warpEdge(base + e));
}

vec2 warpUv(vec2 uv) { return vec2(warpAxis(0, uv.x), warpAxis(1, uv.y)); }

// Inverse tables (rtw/inverse_warp.comp; C++: sl::rtw::inverseWarpTable): per axis, the
// unwarped light coordinate of each warped texel centre, x table first (size entries each).
uniform samplerBuffer u_inverseWarp;
vec2 inverseWarpCentre(ivec2 texel, int size) {
  if (u_warpOn == 0) return (vec2(texel) + 0.5) / float(size);
  ivec2 t = clamp(texel, ivec2(0), ivec2(size - 1));  // helper lanes may sit outside
  return vec2(texelFetch(u_inverseWarp, t.x).r, texelFetch(u_inverseWarp, size + t.y).r);
}

// Light clip space (orthographic, w = 1) -> warped clip space.
vec4 warpClip(vec4 clip) {
  vec2 uv = warpUv(clip.xy / clip.w * 0.5 + 0.5);
  return vec4((uv * 2.0 - 1.0) * clip.w, clip.z, clip.w);
}
