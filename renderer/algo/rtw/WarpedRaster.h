// Rectilinear Texture Warping, step 7 and the lookup: the warped shadow map with EXACT
// depth, and the warped lookup coordinate. CPU reference of the GPU "exact warped depth"
// pass (an inverse-table compute pass per axis and shaders/rtw/warped_exact.frag) and of
// shadowLookupCoord in shaders/rtw/lookup.glsl (with a zero normal offset).
//
// Why: an orthographic light's window depth z is AFFINE in the UNWARPED light uv over a
// triangle, not in the warped uv'. Rasterising warped vertices and letting the hardware
// interpolate z linearly in warped space (even on tessellated, bent edges) is wrong for
// long triangles; the exact map evaluates each triangle's plane at the unwarped position
// of each warped texel centre.
//
// Exact definitions the GPU mirrors (smRes = shadow-map width = height; warp edges and
// warpCoordinate / unwarpCoordinate as in Warp.h):
//  - Light space (Importance.h's conventions): for a world point P,
//      c = lightViewProj * vec4(P, 1)   (float; orthographic light, so c.w = 1)
//      (u, v, z) = c.xyz / c.w * 0.5 + 0.5
//    u, v: light uv in [0, 1] (v = 0 bottom), z: window depth in [0, 1] (glDepthRange 0..1,
//    z = 0.5 * z_ndc + 0.5). lightSpaceOf computes exactly this.
//  - Inverse tables, one per axis, smRes floats:
//      table[i] = unwarpCoordinate(warpEdges, (float(i) + 0.5f) / float(smRes))
//    (the division is exact for power-of-two smRes, so a GLSL x / y or x * (1 / y) gives
//    the same centre). Texel (i, j) of the warped map has its centre at warped
//    (s, t) = ((i + 0.5) / smRes, (j + 0.5) / smRes) and samples the unwarped light
//    position (u, v) = (tableX[i], tableY[j]).
//  - Warped depth map: smRes * smRes floats, row-major, row j = t (row 0 = v' = 0, the GL
//    texture layout of glTexImage2D / glGetTextureImage), cleared to 1.0 (far). Texel
//    (i, j) = min over the triangles that contain (u, v) of the triangle's plane at (u, v):
//      area = orient(a, b, c), orient(a, b, p) = (b.u-a.u)(p.v-a.v) - (b.v-a.v)(p.u-a.u)
//      (twice the signed area in uv^2); |area| < 1e-12: degenerate (edge-on to the light),
//      never covers anything. Else w0 = orient(b, c, p), w1 = orient(c, a, p),
//      w2 = orient(a, b, p), all multiplied by sign(area); p is covered when w0, w1, w2
//      >= 0 (edges inclusive) and then z = (w0 a.z + w1 b.z + w2 c.z) / |area|.
//      A z outside [0, 1] is not written (GL clips against the near and far planes).
//    Arithmetic in double from the float vertices and the float table values, so the
//    reference carries no rounding of its own beyond the final conversion to float.
//    Coverage is exact here (edges in UNWARPED space); the GPU's coverage is approximate
//    (tessellated straight edges in warped space), so GPU and CPU may disagree on
//    silhouette texels only; away from silhouettes they must agree on the depth.
//  - Identity warp (the unwarped map): empty WarpMaps (warpCoordinate / unwarpCoordinate
//    are the identity for n < 1), which gives table[i] = the texel centre exactly. All-zero
//    warp edges give the identity up to 1 ulp of the unwarp's arithmetic.
//  - Lookup (no bias): warpedLookup(P) = (warpUv(maps, (u, v)), z) with (u, v, z) =
//    lightSpaceOf(P); the map texel is floor(uv' * smRes), as depth_map_test.glsl does.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "Warp.h"

namespace sl::rtw {

/// One triangle in light space: per vertex (u, v, z) as lightSpaceOf returns.
struct LightTriangle {
  std::array<glm::vec3, 3> v;
};

/// (u, v, z) of a world point: c = lightViewProj * (P, 1), c.xyz / c.w * 0.5 + 0.5 (float).
glm::vec3 lightSpaceOf(const glm::mat4& lightViewProj, glm::vec3 worldP);

/// A world-space triangle in light space (lightSpaceOf of each vertex).
LightTriangle lightTriangle(const glm::mat4& lightViewProj, glm::vec3 a, glm::vec3 b, glm::vec3 c);

/// Appends the triangles of an indexed world-space triangle list (indices.size() / 3
/// triangles; a trailing partial triangle or an index past positions is ignored).
void appendLightTriangles(const glm::mat4& lightViewProj, std::span<const glm::vec3> positions,
                          std::span<const std::uint32_t> indices, std::vector<LightTriangle>& out);

/// smRes entries: entry i = unwarpCoordinate(warpEdges, (float(i) + 0.5f) / float(smRes)).
/// smRes < 1 gives {}.
std::vector<float> inverseWarpTable(std::span<const float> warpEdges, int smRes);

/// Twice the signed area of a light triangle in uv (orient(a, b, c) above), in double.
double lightTriangleArea2(const LightTriangle& tri);

/// The coverage test and plane of the definition above at unwarped light uv (u, v): true
/// and `depth` set when (u, v) is inside (edges inclusive) of a non-degenerate triangle.
/// Does not apply the [0, 1] depth clip.
bool lightTrianglePlaneAt(const LightTriangle& tri, double u, double v, double& depth);

/// The exact warped map with, per texel, which triangle wrote it.
struct WarpedRaster {
  int size = 0;
  std::vector<float> depth;   ///< size * size, row-major, row 0 = v' = 0, 1.0 = empty
  std::vector<int> triangle;  ///< index into tris of the nearest covering triangle, -1 = empty
  std::vector<float> tableX;  ///< inverseWarpTable(maps.x, size)
  std::vector<float> tableY;  ///< inverseWarpTable(maps.y, size)
};

/// The exact warped depth map (definition above). Ties between triangles keep the first.
/// smRes < 1 gives an empty raster.
WarpedRaster rasterizeWarped(const WarpMaps& maps, int smRes, std::span<const LightTriangle> tris);

/// rasterizeWarped(...).depth.
std::vector<float> rasterizeWarpedDepth(const WarpMaps& maps, int smRes,
                                        std::span<const LightTriangle> tris);

/// The warped map as seed 002 renders it (warp.depth = interpolated, shaders/rtw/
/// warped_vertex.*): each vertex moved by the warp, (u', v') = warpUv(maps, (u, v)) in float
/// as the vertex shader does, the triangle rasterised with straight edges in WARPED space
/// and z interpolated linearly there. Texel (i, j) is covered when its centre
/// ((i + 0.5) / smRes, (j + 0.5) / smRes) lies inside the warped triangle (edges inclusive,
/// orient as above on the warped uv, |area| < 1e-12 covers nothing); z = the barycentric mix
/// of the vertices' z at that centre; outside [0, 1] not written; the nearest wins (ties
/// keep the first). Double arithmetic from the float warped vertices. tableX / tableY are
/// left empty. Against rasterizeWarped, the depth is wrong by about |grad z| times how far
/// the warp bends the triangle, and silhouettes are the warped straight edges.
WarpedRaster rasterizeWarpedInterpolated(const WarpMaps& maps, int smRes,
                                         std::span<const LightTriangle> tris);

/// The lookup coordinate of a world point, without bias: (warpUv(maps, uv), z) with
/// (uv, z) = lightSpaceOf(lightViewProj, worldP). Mirrors lookup.glsl's shadowLookupCoord
/// for a zero normal offset.
glm::vec3 warpedLookup(const WarpMaps& maps, const glm::mat4& lightViewProj, glm::vec3 worldP);

}  // namespace sl::rtw
