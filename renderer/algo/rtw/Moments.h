// Directionality-aware RTW (seed 000, Tokuyoshi, da Silva, Kanai, SIGGRAPH 2014 poster):
// the importance map's weighted moments through a mip chain (after LEAN mapping, Olano &
// Baker 2010) and the PCA that gives the IM's principal axis. CPU reference of the GPU
// moment and reduction passes.
//
// Exact definitions the GPU mirrors:
//  - Centred texel-centre coordinates of a w x h IM, in [-1, 1]:
//      x_i = float(2*i + 1 - w) * invW,  invW = 1.0f / float(w) computed on the HOST and
//      uploaded (so both sides do one correctly rounded product: bit-exact);
//      y_j likewise with h (row j = 0 is v = 0, the bottom). Equal to (i + 0.5) / w * 2 - 1.
//  - Six channels per texel, in this order: I, x*I, y*I, (x*x)*I, (y*y)*I, (x*y)*I.
//  - A chain of SUMS (not averages, so non-power-of-two sizes are exact): level l+1 has
//    size (ceil(w_l / 2), ceil(h_l / 2)); texel (i, j) =
//      (a(2i, 2j) + a(2i+1, 2j)) + (a(2i, 2j+1) + a(2i+1, 2j+1))
//    per channel, a source texel outside level l counting as 0. Down to 1x1, which holds
//    the six sums over the whole IM. Do NOT use glGenerateMipmap: it averages, and for
//    non-power-of-two sizes uses floor(size / 2) and drops the odd row / column.
//  - GPU vs CPU: level 0 and every reduction are bit-exact when the shader uses the same
//    association (mark the sums `precise`); momentsFromTop runs in double on the CPU from
//    the six top floats (24 bytes read back). A float GLSL port of momentsFromTop agrees to
//    ~1e-5 relative on the covariance and 1e-4 on (e_x, e_y).
#pragma once

#include <array>
#include <vector>

#include <glm/vec2.hpp>

#include "Importance.h"

namespace sl::rtw {

/// Channel order of a moment texel.
enum MomentChannel : int { kMomI = 0, kMomXI, kMomYI, kMomX2I, kMomY2I, kMomXYI, kMomCount };
using MomentTexel = std::array<float, kMomCount>;

/// One level of the moment chain, row-major like ImportanceMap (row 0 = bottom).
struct MomentLevel {
  int width = 0;
  int height = 0;
  std::vector<MomentTexel> texels;

  const MomentTexel& at(int x, int y) const { return texels[static_cast<size_t>(y) * width + x]; }
};

/// x of texel centre i of an axis of `size` texels: float(2*i + 1 - size) * (1.0f /
/// float(size)). In [-1, 1].
float centredCoordinate(int i, int size);

/// Level 0: the six channels of every IM texel.
MomentLevel momentTextures(const ImportanceMap& map);

/// One reduction step (sums of up to 2x2 texels; see the header comment). A 1x1 level
/// reduces to itself.
MomentLevel reduceMomentLevel(const MomentLevel& level);

/// Level 0 .. 1x1. An empty IM gives one 1x1 level of zeros. back().texels[0] = the sums.
std::vector<MomentLevel> buildMomentChain(const ImportanceMap& map);

/// The six sums accumulated directly in double over all texels (same per-texel products
/// as momentTextures), rounded to float: the test reference for the chain's top.
MomentTexel momentSumsDirect(const ImportanceMap& map);

/// PCA of the importance distribution (seed 000). All derived in double, stored in float.
struct MomentStats {
  bool valid = false;  ///< sumI > 0 and finite, and Σ anisotropic (see momentsFromTop)
  float sumI = 0.0f;   ///< Σ I
  float meanX = 0.0f, meanY = 0.0f;                ///< x̄ = Σ xI / Σ I, ȳ = Σ yI / Σ I
  float alpha = 0.0f, beta = 0.0f;                 ///< α = Σ x²I / Σ I, β = Σ y²I / Σ I
  float gamma = 0.0f;                              ///< γ = Σ xyI / Σ I (poster's "Σ yI": typo)
  float covXX = 0.0f, covXY = 0.0f, covYY = 0.0f;  ///< Σ (scaled by axisScale, below)
  float lambda1 = 0.0f, lambda2 = 0.0f;            ///< eigenvalues of Σ, lambda1 >= lambda2
  float anisotropy = 0.0f;     ///< (λ1 − λ2) / (λ1 + λ2), 0 if λ1 + λ2 = 0
  float ex = 1.0f, ey = 0.0f;  ///< unit principal eigenvector; ex > 0, or ex = 0 and ey = 1
  float angleDeg = 0.0f;       ///< atan2(ey, ex) in degrees, (-90, 90] (-90 by float rounding)
};

/// Stats from the six top-level sums. Exactly (double):
///   S = top[I]; if !(S > 0) or S not finite: valid = false, everything 0, e = (1, 0).
///   x̄, ȳ, α, β, γ as above;
///   Σxx = max(α − x̄², 0) sx², Σxy = (γ − x̄ȳ) sx sy, Σyy = max(β − ȳ², 0) sy²,
///     (sx, sy) = axisScale: the light frustum's half-extents (metres per centred unit)
///     so that the angle is measured in metres when the frustum is not square (a
///     non-uniform scale skews angles, though not the axis-aligned fixed points);
///     (1, 1) = measure in IM units, the poster's choice. Non-finite or <= 0 -> 1.
///   m = (Σxx + Σyy) / 2, d = (Σxx − Σyy) / 2, r = hypot(d, Σxy), λ1,2 = m ± r.
///   eigenvector: Σxy == 0 ? (Σxx >= Σyy ? (1, 0) : (0, 1))
///              : normalise(d >= 0 ? (d + r, Σxy) : (Σxy, r − d));
///   then negate it if ex < 0 or (ex == 0 and ey < 0): ex > 0, or ex == 0 and ey = +1
///   (the principal axis is exactly the y axis: the rotation is then +90°).
///   valid = (λ1 − λ2) > eps (λ1 + λ2) (strict, so λ1 = λ2 = 0 is invalid), eps =
///   isotropyEps (default 1e-4; non-finite or < 0 -> 1e-4). When not valid, e = (1, 0)
///   and angleDeg = 0: no rotation, never NaN.
MomentStats momentsFromTop(const MomentTexel& top, glm::vec2 axisScale = glm::vec2(1.0f),
                           float isotropyEps = 1e-4f);

/// momentsFromTop(buildMomentChain(map).back().texels[0], axisScale, isotropyEps).
MomentStats momentsOf(const ImportanceMap& map, glm::vec2 axisScale = glm::vec2(1.0f),
                      float isotropyEps = 1e-4f);

}  // namespace sl::rtw
