// Rectilinear Texture Warping, step 1-2: the importance map (IM) and its collapse to
// two 1D maps. CPU reference of the GPU importance and collapse passes.
// Follows seed 002 (Hlavová, backward RTW) and Rosen, "Rectilinear Texture Warping for
// Fast Adaptive Shadow Mapping", I3D 2012; the importance terms follow the aliasing
// decomposition of Stamminger & Drettakis 2002 as restated by Lloyd et al. (seed 004, Eq. 1).
//
// Conventions the GPU passes mirror exactly:
//  - Light-space uv in [0,1]^2: u along the light view's x axis, v along its y axis
//    (glm::ortho, no flip). v = 0 is the bottom.
//  - ImportanceMap is row-major: values[y * width + x]; row 0 is v = 0 (bottom), x is u.
//    Texel (x, y) covers u in [x/width, (x+1)/width), v in [y/height, (y+1)/height).
//    Same layout as a GL texture uploaded with glTexImage2D (row 0 = t = 0).
//  - Importance values are finite and >= 0. An IM starts as all zeros.
#pragma once

#include <span>
#include <vector>

#include <glm/vec2.hpp>

namespace sl::rtw {

/// A light-space importance map. Row-major, row 0 = v = 0 (bottom), x = u.
struct ImportanceMap {
  int width = 0;
  int height = 0;
  std::vector<float> values;  ///< width * height entries, >= 0

  ImportanceMap() = default;
  /// An all-zero map (sizes below 1 become 0, i.e. an empty map).
  ImportanceMap(int w, int h);

  float& at(int x, int y) { return values[static_cast<size_t>(y) * width + x]; }
  float at(int x, int y) const { return values[static_cast<size_t>(y) * width + x]; }
  bool operator==(const ImportanceMap&) const = default;
};

// ---------------------------------------------------------------------------------------
// Importance terms (per camera sample in backward analysis, per light texel in forward).
// Each term is a pure float function; the shader's copy must use the same expressions.
// The aliasing error of a shadow-map sample is (Lloyd Eq. 1)
//     m = (w_l / w_i) * (cos θ_i / cos θ_l),
// w_i = image-beam width (∝ eye depth z, Lloyd Eq. 2), θ_i / θ_l the angles between the
// surface normal and the eye / light beams. Importance is the shadow-map density a sample
// needs for m <= 1, i.e. ∝ 1/z (perspective aliasing) × cos θ_i / cos θ_l (projection
// aliasing). The terms are therefore combined by MULTIPLICATION; a term that is off is 1.
// The exact forms are ShadowLab's choice: seed 002 computes importance "from the distance
// to the camera" without a formula, and Rosen's normal / shadow-edge terms are restated in
// docs/techniques.md §2 without one.

/// Perspective-aliasing term, nearM / max(eyeDepthM, nearM), in [0, 1]. Exactly:
///   (!(nearM > 0) || !(eyeDepthM > nearM)) ? 1 : nearM / eyeDepthM
/// eyeDepthM is the view-space depth of the sample (Lloyd's z = p·v, metres; the radial
/// eye distance is an acceptable variant). The term is 1 up to the near plane and falls as
/// 1/z. NaN depth -> 1, +inf -> 0, never NaN. GPU division: tolerance 1e-6 relative.
float eyeDepthTerm(float eyeDepthM, float nearM);

/// Projection-aliasing term: min(max(nDotV, 0), 1) / max(|nDotL|, minCosL), in
/// [0, 1/minCosL]. Exactly: v = nDotV > 0 ? min(nDotV, 1) : 0; l = |nDotL|;
/// l = l > minCosL ? l : minCosL; return v / l  (NaN inputs count as 0 resp. grazing).
/// nDotV = dot(n, towards eye), nDotL = dot(n, towards light), both unit vectors.
/// |nDotL| because a surface lit from behind (self-shadowed) also has its terminator at
/// grazing light. minCosL (clamped to [0.01, 1], NaN -> 0.1) bounds the term.
float orientationTerm(float nDotL, float nDotV, float minCosL);

/// Shadow-edge term input: clamp(edge, 0, 1). `edge` is 1 on (or near) a shadow edge of
/// the previous frame (from its shadow mask or a depth discontinuity in its SM) and 0
/// elsewhere; how it is detected is the caller's business. NaN -> 0.
float shadowEdgeTerm(float edge);

/// Weights and switches of the importance terms. Defaults: seed 002 (eye distance only).
struct ImportanceSettings {
  bool eyeOn = true;
  float eyeWeight = 1.0f;  ///< [0,1]: 0 = neutral (1), 1 = full 1/z term
  bool orientationOn = false;
  float orientationWeight = 1.0f;  ///< [0,1]: 0 = neutral, 1 = full cos θ_i / cos θ_l
  float minCosL = 0.1f;            ///< [0.01,1]: lower bound of |n·L| in orientationTerm
  bool edgeOn = false;
  float edgeWeight = 4.0f;  ///< [0,16]: a texel on a shadow edge gets (1 + edgeWeight)×
  float nearM = 0.1f;       ///< camera near plane (metres), > 0, for eyeDepthTerm
  bool operator==(const ImportanceSettings&) const = default;
};

/// Combined importance, exactly:
///   e = eyeOn         ? 1 + eyeWeight         * (eyeDepthTerm(eyeDepthM, nearM) - 1)    : 1
///   o = orientationOn ? 1 + orientationWeight * (orientationTerm(nDotL, nDotV, minCosL) - 1) : 1
///   s = edgeOn        ? 1 + edgeWeight        * shadowEdgeTerm(edge)                    : 1
///   I = (e * o) * s
/// Weights are clamped to their ranges first, so I >= 0 and finite. The GPU may contract
/// the `1 + w * (t - 1)` into an fma: parity tolerance 1e-6 relative.
float combineImportance(const ImportanceSettings& settings, float eyeDepthM, float nDotL,
                        float nDotV, float edge);

// ---------------------------------------------------------------------------------------
// Backward analysis scatter.

/// Texel of a light-space uv: (floor(u * width), floor(v * height)) computed in float
/// (one correctly rounded product, then floor: bit-exact on the GPU). Returns false (and
/// leaves texel untouched) when the texel is outside [0,width) x [0,height) or uv is NaN.
/// u = 1.0 exactly is outside.
bool texelOfLightUv(int width, int height, glm::vec2 lightUv, glm::ivec2& texel);

/// values[texel] = max(values[texel], value). Values that are not > 0 (0, -0, negative,
/// NaN) or are infinite are dropped, so the map stays finite and >= 0.
/// GPU: imageAtomicMax on an r32ui image with floatBitsToUint(value). Valid because for
/// finite floats >= +0 the IEEE-754 bit patterns, read as unsigned ints, are ordered like
/// the floats. -0.0 (0x80000000) and negatives would break the order: the shader must do
/// the same `if (!(value > 0.0) || isinf(value)) return;` before the atomic.
void scatterMax(ImportanceMap& map, glm::vec2 lightUv, float value);

// ---------------------------------------------------------------------------------------
// Collapse (seed 002's first compute pass; Rosen's "1D importance maps").

/// x map: out[x] = max over y of map.at(x, y). Size width. An empty map gives {}.
std::vector<float> collapseColumnsMax(const ImportanceMap& map);
/// y map: out[y] = max over x of map.at(x, y). Size height.
std::vector<float> collapseRowsMax(const ImportanceMap& map);

/// Half-mass width of a 1D importance map (a collapsed x or y map) as a share of its length:
/// the length of the shortest run of whole texels whose importance sums to at least half of
/// the map's, divided by values.size(). In (0, 1]; 0 for an empty or all-zero map (values
/// that are not > 0 or are infinite count as 0). A narrow peak gives a small width: the warp
/// can give it many texels. This is how "sharp" an importance distribution is along one
/// shadow-map axis (seed 000's "sharper importance distribution ... for the vertical axis").
float halfMassWidth(const std::vector<float>& values);

}  // namespace sl::rtw
