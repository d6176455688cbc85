// Rectilinear Texture Warping, steps 3-6: blur and floor of the 1D importance maps,
// prefix sums, and the warp maps that move shadow-map coordinates. CPU reference of the
// GPU blur / scan / warp compute passes and of the warped vertex and lookup shaders.
// Follows seed 002 (collapse -> blur -> warp formula, prefix sum) and docs/techniques.md §2
// (importance floor, after Rosen, I3D 2012); the scan is Blelloch's work-efficient scan
// (GPU Gems 3, ch. 39).
//
// Exact definitions the GPU mirrors (n = number of texels of a 1D map):
//  - Texel k of a 1D map covers u in [k/n, (k+1)/n); its EDGES are at u = e/n, e = 0..n.
//  - A warp map has n + 1 values, one per edge: warp[e] = S_e / T - e/n with
//    S_e = sum_{i<e} I(i) (so S_0 = 0, S_n = T), T = sum_{i<n} I(i), and warp[0] =
//    warp[n] = 0 written explicitly (not computed). This is seed 002's
//    warp(k) = sum_{i<=k} I(i) / sum I - k/n read at the RIGHT edge of texel k (edge k+1)
//    with k/n replaced by (k+1)/n, which is what makes it start and end at 0.
//  - The warped coordinate is u' = u + warp(u), warp(u) linearly interpolated between
//    edges (see warpCoordinate): u' is the piecewise-linear normalised CDF of importance.
//  - Never use hardware linear filtering for the warp (its weights have 8 fractional bits):
//    store the n + 1 floats in an r32f buffer / 1D texture and texelFetch both edges.
//  - Tolerances GPU vs CPU: blur 1e-6 relative (fma contraction), Blelloch scan bit-exact
//    when done in the order below (float + is correctly rounded in GLSL), warp values 1e-6
//    absolute (GLSL division is not correctly rounded: 2.5 ulp).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec2.hpp>

#include "Importance.h"
#include "common/shared_constants.h"

namespace sl::rtw {

/// Largest blur radius; the shader's weight array has 2 * kMaxBlurRadius + 1 entries.
inline constexpr int kMaxBlurRadius = SL_BLUR_MAX_RADIUS;

// ---------------------------------------------------------------------------------------
// Step 3: Gaussian blur (1D, clamp-to-edge).

/// Normalised weights for offsets k = -r..r (index k + r), r = clamp(radius, 0,
/// kMaxBlurRadius). In float: raw_k = exp(-float(k*k) / (2 * sigma * sigma)),
/// W = raw_{-r} + ... + raw_r (ascending k), w_k = raw_k / W. sigma not > 0 (or NaN, or
/// not finite) gives the identity {1}. The host uploads THESE weights to the shader (GLSL
/// exp is not correctly rounded), so the blur itself is the only thing the GPU computes.
std::vector<float> gaussianWeights(int radius, float sigma);

/// out[i] = sum_{k=-r..r, ascending} w_k * in[clamp(i + k, 0, n - 1)], accumulated in
/// float from 0, w = gaussianWeights(radius, sigma). Same size as in; identity for r = 0.
std::vector<float> gaussianBlur1D(std::span<const float> in, int radius, float sigma);

// ---------------------------------------------------------------------------------------
// Step 4: importance floor.

/// In place: m = max(values); if !(m > 0) every value becomes 1 (uniform: the identity
/// warp, never NaN); else v = max(v, f * m) with f = clamp(floorFraction, 0, 1) (NaN -> 0).
/// Chosen over an additive floor because it leaves the important region's shape untouched
/// and guarantees every texel at least f * m / T of the warped axis (T = sum after the
/// floor), i.e. no region collapses to zero texels when f > 0.
void applyImportanceFloor(std::span<float> values, float floorFraction);

// ---------------------------------------------------------------------------------------
// Step 5: prefix sums.

/// Sequential inclusive scan in float: out[0] = in[0], out[k] = out[k-1] + in[k].
std::vector<float> inclusiveScan(std::span<const float> in);

/// Inclusive scan computed exactly as a one-work-group compute shader does Blelloch's
/// work-efficient scan (GPU Gems 3, ch. 39), in float:
///   m = smallest power of two >= max(n, 1); a[i] = in[i] for i < n, 0 for n <= i < m.
///   up-sweep:   for d = 1, 2, 4, .., m/2: for every k = 0, 2d, 4d, .. < m:
///                 a[k + 2d - 1] = a[k + d - 1] + a[k + 2d - 1]
///   total = a[m - 1]; a[m - 1] = 0
///   down-sweep: for d = m/2, .., 2, 1: for every k = 0, 2d, 4d, .. < m:
///                 t = a[k + d - 1]; a[k + d - 1] = a[k + 2d - 1];
///                 a[k + 2d - 1] = t + a[k + 2d - 1]
///   (a is now the exclusive scan) out[i] = (i + 1 < m) ? a[i + 1] : total, for i < n.
/// The iterations of one level are independent (barrier between levels), so any thread
/// order gives the same bits. Versus inclusiveScan: only the association of the additions
/// differs; for non-negative input both are within ~(log2 m + k) * 6e-8 relative of the
/// exact prefix, the tests hold them to 1e-5 relative.
std::vector<float> blellochScan(std::span<const float> in);

// ---------------------------------------------------------------------------------------
// Step 6: warp maps.

/// n + 1 edge offsets from a 1D importance (n = importance.size(), values >= 0):
/// S = blellochScan(importance), T = S[n-1], and for 0 < e < n
///   warp[e] = S[e-1] / T - float(e) / float(n)        (float divisions)
/// with warp[0] = warp[n] = 0. T not > 0 or not finite: all zeros (identity warp).
/// n = 0 gives {0}.
std::vector<float> warpFromImportance(std::span<const float> importance);

/// u' = u + warp(u). For u in (0, 1), exactly:
///   n = warpEdges.size() - 1; x = u * float(n); e = min(int(floor(x)), n - 1);
///   t = x - float(e); u' = u + (warpEdges[e] + t * (warpEdges[e+1] - warpEdges[e]))
/// Outside (0, 1) (and for n < 1) u' = u: continuous, since warp is 0 at both ends, so
/// vertices outside the light frustum move consistently. Non-decreasing in u for any
/// non-negative importance up to float rounding (measured: decreases of at most 2 ulp of
/// 1.0; the tests allow 1e-6); in real arithmetic exactly the piecewise-linear CDF.
/// Vertex shader: u = 0.5 * x_ndc + 0.5 (before the divide for ortho, w = 1),
/// x'_ndc = 2 * u' - 1; same for v with the y map.
float warpCoordinate(std::span<const float> warpEdges, float u);

/// Inverse of warpCoordinate (used by the warp-grid overlay: where does warped texel
/// line u' come from). Edge coordinates c_e = float(e) / float(n) + warpEdges[e]; e = the
/// last edge in [0, n-1] with c_e <= uWarped (binary search); if uWarped == c_e, step
/// back over equal c's (a flat run = zero importance) and return e / n; else return
/// (e + t) / n with t = (uWarped - c_e) / (c_{e+1} - c_e) clamped to [0, 1] (t = 0 if
/// c_{e+1} <= c_e). Identity outside (0, 1). warpCoordinate(unwarpCoordinate(u')) = u'
/// to 1e-6.
float unwarpCoordinate(std::span<const float> warpEdges, float uWarped);

/// Parameters of steps 3-4. Defaults are starting points for the parameter declarations.
struct WarpSettings {
  int blurRadius = 4;             ///< texels, [0, kMaxBlurRadius]
  float blurSigma = 2.0f;         ///< texels, > 0
  float importanceFloor = 0.05f;  ///< fraction of the max importance, [0, 1]
  bool operator==(const WarpSettings&) const = default;
};

/// Steps 3-6 for one axis: blur, floor, warpFromImportance. Returns n + 1 edges.
std::vector<float> buildWarpMap(std::span<const float> importance1d, const WarpSettings& s);

/// Both axes of an IM: x from collapseColumnsMax (width + 1 edges), y from
/// collapseRowsMax (height + 1 edges).
struct WarpMaps {
  std::vector<float> x;
  std::vector<float> y;
};
WarpMaps buildWarpMaps(const ImportanceMap& map, const WarpSettings& s);

/// (warpCoordinate(maps.x, uv.x), warpCoordinate(maps.y, uv.y)).
glm::vec2 warpUv(const WarpMaps& maps, glm::vec2 lightUv);
/// (unwarpCoordinate(maps.x, uv.x), unwarpCoordinate(maps.y, uv.y)).
glm::vec2 unwarpUv(const WarpMaps& maps, glm::vec2 warpedUv);

// ---------------------------------------------------------------------------------------
// Memory accounting (seed 002).

/// Texels an RTW shadow map uses: smRes^2 (SM) + imRes^2 (IM) + n1dMaps * imRes (1D maps,
/// counted with n texels each as seed 002 does; our warp maps hold n + 1 edges).
/// Seed 002: rtwTexels(512, 512, 3) = 525,824 versus 1,048,576 for a uniform 1024^2.
std::int64_t rtwTexels(int smRes, int imRes, int n1dMaps);

}  // namespace sl::rtw
