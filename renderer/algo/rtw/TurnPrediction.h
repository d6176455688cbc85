// DA-RTW's turn chosen by the warp it will give. RTW's warp is a function of the importance
// map, so the warp a turn of the light's image plane WILL give can be computed before it is
// used: the last frame's importance is resampled into the candidate frame, collapsed, blurred
// and floored exactly as the renderer does (Warp.h), and every important texel reads off the
// shadow-map texels it will get per texel it asks for, a predicted aliasing m. Seed 000 gives
// the direction of the turn (PCA's principal axis) but no test of whether turning pays; this
// is that test. Chong (2003, "Real-time perspective optimal shadow maps") chooses a light's
// film plane by predicted aliasing in the same way; here the free parameter is the in-plane
// turn. No GL: the CPU work of the renderer's "rotation estimate" pass, and its reference.
//
// Conventions:
//  - Angles are the turn of the shadow map's x axis in the unturned light image plane (the
//    frame rtw-backward uses, sl::lightBaseView), in degrees, counter-clockwise: the angle
//    of RotationState::R. A separable warp of a square map is the same after a quarter turn
//    (x and y swap roles, the tight frustum swaps its sides), so every score has period 90°
//    and candidates are taken in (-45, 45].
//  - Asked-for density: importance I is the shadow-map density a sample needs, up to one
//    constant (Importance.h: near/z times the orientation term). With k = H / (2 tan(fovY/2)
//    near) (H: viewport height in pixels), k I is texels per metre of the light plane that
//    make one texel per pixel: k I = 1 / (pixel footprint) for the eye term.
//  - Given density: the warped map gives texel x of its n-texel 1D map a slope of
//    n B_x / T_x (B: blurred and floored 1D importance, T its sum), so g_x = S n B_x / (T_x E_x)
//    texels per metre (S: shadow-map side, E_x: frustum width in metres), same for y.
//  - Predicted m of a texel: m = k I / sqrt(g_x g_y), the renderer's measured aliasing m
//    (texel footprint over pixel footprint, 1 / sqrt(texels per pixel): common/resolve.frag)
//    read off the importance instead of the screen.
//  - Score: the expected wrong pixels per pixel that can be wrong. A hard shadow test is wrong
//    only near a shadow edge (in the light plane: the caster's silhouette), where a point and
//    the centre of the texel it falls in lie on opposite sides of the edge. For texels of
//    widths (w_x, w_y) and an edge whose normal makes angle b with the frame's x axis, the
//    wrong band beside the edge is on average sqrt((w_x cos b)^2 + (w_y sin b)^2) / 4 wide
//    (the edge's offset against the grid uniform; for square texels a quarter texel at every
//    angle): measured by sampling points at random offsets and checked in
//    TurnPrediction.EdgeBandIsAQuarterOfTheTexelsNormWidth. In pixel footprints (w k I), every
//    edge pixel adds m_edge = sqrt((m_x cos b)^2 + (m_y sin b)^2), m_x = k I / g_x, and
//    score = sum(w m_edge) / sum(w): linear in the texel width below and above m = 1.
//    PredictionWeight::EdgePixels: w and b are the last frame's shadow-edge pixels and their
//    normals (ImportanceSnapshot::edgeBins), turned into the candidate frame: a turn that lays
//    the map's fine axis across the edges the view has is the one that pays.
//    PredictionWeight::Pixels: every scattering pixel, edges in the bins' directions alike.
//    The constant k cancels in every ratio of scores, so the choice does not depend on it;
//    the m quantiles and the undersampled share do.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include <glm/mat2x2.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include "Warp.h"
#include "common/shared_constants.h"

namespace sl::rtw {

/// Bins of the edge pixels' normal angle, and the fixed-point parts a pixel is split into.
inline constexpr int kEdgeBins = SL_RTW_EDGE_BINS;
inline constexpr std::uint32_t kEdgeOne = SL_RTW_EDGE_ONE;
inline constexpr double kEdgeBinDeg = 180.0 / kEdgeBins;

/// Last frame's importance as the prediction reads it: an M x M map over that frame's light
/// frustum (row-major, row 0 = v = 0, x = u; the IM or its block maxima, DA-RTW's moment IM),
/// with, per texel, how many camera pixels scattered into it, their mean importance, and, of
/// those on a shadow edge of
/// the frame before, the direction of the edge: kEdgeBins planes of M x M counts, bin b the
/// edges whose normal in the snapshot's light plane (metres) lies at b kEdgeBinDeg degrees,
/// in units of 1 / kEdgeOne pixel (edgeBinParts).
struct ImportanceSnapshot {
  int size = 0;
  std::vector<float> importance;  ///< max importance per texel, finite, >= 0
  /// Mean importance of the texel's scattering pixels (empty: the max stands for it). The max
  /// builds the 1D maps (the renderer's collapse keeps maxima); the mean is what the texel's
  /// pixels ask for on average: a texel's m and its share of the score.
  std::vector<float> meanImportance;
  std::vector<std::uint32_t> pixels;    ///< scattering camera pixels (empty: 1 per texel)
  std::vector<std::uint32_t> edgeBins;  ///< kEdgeBins * M * M (empty: no edge known)
  /// The renderer's own 1D maps of the snapshot's frame (max over each column and row of the
  /// full IM, n texels each; empty: not known). The snapshot's frame itself is predicted from
  /// these, every other frame from the M x M texels resampled: a coarser picture, so that the
  /// comparison leans towards the frame in use (a turn must pay against the warp as it is).
  std::vector<float> collapsedX, collapsedY;
  bool empty() const { return size <= 0; }
  /// Edge pixels of texel i (the sum of its bins, in pixels).
  double edgePixels(size_t i) const;
};

/// How an edge pixel whose light-plane normal lies at betaDeg (any angle: an edge normal has
/// no sign, so modulo 180) is split between its two nearest bins, exactly as the backward
/// scatter does it (shaders/rtw/importance_backward.frag): x = fold(betaDeg) / kEdgeBinDeg in
/// [0, kEdgeBins - 1e-4], lo = floor(x), hi = (lo + 1) mod kEdgeBins, parts[hi] = round((x - lo)
/// kEdgeOne), parts[lo] = kEdgeOne - parts[hi].
struct EdgeBinParts {
  int lo = 0, hi = 1;
  std::uint32_t loPart = kEdgeOne, hiPart = 0;
};
EdgeBinParts edgeBinParts(double betaDeg);

/// The snapshot at most maxSize texels a side: blocks of f = ceil(size / maxSize) texels a side
/// become one texel of ceil(size / f), its importance the block's max, its counts the block's
/// sums, its mean importance the pixel-weighted mean (the block maxima DA-RTW's moment IM
/// holds). Returned as is when already small enough.
ImportanceSnapshot reduceSnapshot(const ImportanceSnapshot& snapshot, int maxSize);

/// uv' = linear * uv + offset: where a point of the snapshot's light frame lies in another
/// frame of the same directional light (orthographic frames: an affine map of the plane).
struct UvAffine {
  glm::dmat2 linear{1.0};
  glm::dvec2 offset{0.0};
  glm::dvec2 apply(glm::dvec2 uv) const { return linear * uv + offset; }
};

/// A candidate frame: the turn, where the snapshot's uv lands in it, and its size.
struct CandidateFrame {
  double angleDeg = 0.0;    ///< angle of R in this frame (see the conventions)
  double turnDeg = 0.0;     ///< its axes' turn from the snapshot's: angleDeg - snapshot's
  UvAffine fromSnapshot;    ///< snapshot uv -> this frame's uv
  glm::dvec2 extentM{1.0};  ///< frustum width and height, metres (> 0)
};

enum class PredictionWeight { Pixels, EdgePixels };

struct PredictionSettings {
  WarpSettings warp;                  ///< blur radius and sigma, importance floor: the renderer's
  int warpResolution = 512;           ///< n: im.resolution, length of the 1D maps
  int mapResolution = 1024;           ///< S: the shadow map's side
  double densityPerImportance = 1.0;  ///< k (texels per metre per unit of importance), > 0
  PredictionWeight weight = PredictionWeight::Pixels;
};

/// What one candidate frame's warp is predicted to give.
struct WarpPrediction {
  double angleDeg = 0.0;
  bool valid = false;         ///< some weighted importance landed in the frame
  double score = 0.0;         ///< sum(w m_edge) / sum(w): ~4x the expected wrong pixels per w
  double undersampled = 0.0;  ///< share of the weight with m > 1
  double weight = 0.0;        ///< sum(w)
  double outside = 0.0;       ///< share of the weight whose texel centre left the frame
};

/// The two 1D importance maps (x: max over each column, y: over each row, n texels each) of
/// the snapshot resampled into `frame`: each snapshot texel with importance > 0 and at least
/// one scattering pixel fills the n-texels whose centres its footprint (a parallelogram)
/// covers along each axis, with max, and always the texel holding its centre; centres outside
/// [0, 1) are dropped. Before the blur: what the renderer's backward scatter would collapse.
struct Collapsed {
  std::vector<float> x, y;
};
Collapsed resampleCollapsed(const ImportanceSnapshot& snapshot, const CandidateFrame& frame, int n);

/// The prediction of one snapshot for any number of frames: the snapshot's important texels
/// are gathered once (a frame scores a dozen candidates, the panel's curve 37), each
/// candidate then walks only them.
class TurnPredictor {
 public:
  TurnPredictor(const ImportanceSnapshot& snapshot, const PredictionSettings& settings);
  /// predictWarp (below) for `frame`.
  WarpPrediction predict(const CandidateFrame& frame) const;
  /// predictedAliasingQuantiles (below) for `frame`.
  std::vector<double> aliasingQuantiles(const CandidateFrame& frame,
                                        std::span<const double> q) const;
  /// resampleCollapsed, or the snapshot's own 1D maps for its own frame.
  Collapsed collapsed(const CandidateFrame& frame) const;

 private:
  struct Texel {
    glm::dvec2 uv;                      ///< its centre in the snapshot's frame
    float maxImportance;                ///< what the collapse keeps
    double asked;                       ///< mean importance of its pixels (the max when not known)
    double pixels;                      ///< scattering pixels (1 when not counted)
    double edges;                       ///< edge pixels, all bins
    std::array<float, kEdgeBins> bins;  ///< edge pixels per normal bin
  };
  const ImportanceSnapshot& snapshot_;
  PredictionSettings settings_;
  std::vector<Texel> texels_;
  bool valid_ = false;
};

/// Predicts the warp `frame` would give: resampleCollapsed (or, for the snapshot's own frame,
/// an identity map, its collapsedX / collapsedY when they have n texels), then blur and floor
/// (Warp.h's gaussianBlur1D and applyImportanceFloor with settings.warp, as the renderer's passes),
/// and per weighted texel m and m_edge at its centre. Not valid (score 0) when no weight lands.
WarpPrediction predictWarp(const ImportanceSnapshot& snapshot, const CandidateFrame& frame,
                           const PredictionSettings& settings);

/// Weighted quantiles of the predicted m (geometric, as the renderer measures m) of `frame`,
/// weighted by scattering pixels whatever settings.weight says: what the renderer's
/// "aliasing.p50" / "aliasing.p95" should read in a frame rendered in `frame`. q in [0, 1].
/// Empty when nothing lands.
std::vector<double> predictedAliasingQuantiles(const ImportanceSnapshot& snapshot,
                                               const CandidateFrame& frame,
                                               const PredictionSettings& settings,
                                               std::span<const double> q);

/// The mean width of the band beside a straight edge in which a point and the centre of its
/// texel lie on opposite sides of the edge (a point-sampled hard shadow test is wrong there),
/// for texels of widths wX, wY and an edge whose normal makes angle normalDeg with x, averaged
/// over the edge's offset against the grid: sqrt((wX cos)^2 + (wY sin)^2) / 4.
double edgeBandWidth(double normalDeg, double wX, double wY);

/// Folds an angle into (-45, 45] (the quarter-turn symmetry).
double foldQuarterTurn(double angleDeg);

/// Candidate step of the coarse search, and the refinements around its best.
inline constexpr double kTurnSearchStepDeg = 15.0;
inline constexpr int kTurnSearchRefinements = 2;  ///< halving: 7.5°, then 3.75°
/// Step of the score curve the panels plot over -90..90 (37 angles).
inline constexpr double kTurnCurveStepDeg = 5.0;

/// Default of rotation.margin: a predicted gain must exceed this share of the current score.
/// It is the prediction's own error: measured against the true error of fixed turns (every
/// 15°, every still view of the built-in and real-content scenes, 1024² and 512², 270 turns),
/// log(predicted ratio / measured ratio) has a robust standard deviation s = 0.264 (1.4826 x
/// its median absolute value, 0.178), which holds the re-gridding spread a turn adds by
/// itself; a gain beyond 1 - exp(-1.645 s) = 0.352 is a gain with 95 % confidence
/// (one-sided). Re-derived by scripts/rtw-turns-table.py.
inline constexpr double kDefaultTurnMargin = 0.35;
/// Why (the parameter's help and the docs say it).
inline constexpr const char* kTurnMarginWhy =
    "The default is the prediction's own measured error: a predicted gain beyond it is a true "
    "gain with 95 % confidence (docs/results/rtw-rotation.md).";

/// Every prediction a frame made, and the current frame's and the best one's index.
struct TurnSearch {
  std::vector<WarpPrediction> scored;
  int current = -1;  ///< the frame in use (angle = currentDeg)
  int best = -1;     ///< lowest valid score; ties keep the current frame, then the smaller turn
};

/// Scores the current angle, PCA's axis (when given, absolute), every kTurnSearchStepDeg in
/// (-45, 45], then, when the best so far is predicted better than the current frame by at
/// least `refineAbove` (a share of the current score; a turn is in sight), twice around it at
/// half the last step: at most 6 + 2 + 4 = 12 predictions. `predict(angleDeg)` is called once
/// per distinct folded angle.
TurnSearch searchTurn(double currentDeg, std::optional<double> pcaAxisDeg,
                      const std::function<WarpPrediction(double angleDeg)>& predict,
                      double refineAbove = 0.0);

enum class TurnReason {
  NoPrediction,     ///< no importance landed (first frame, empty view): R kept
  Turned,           ///< the best frame beats the current one by more than the margin
  WithinMargin,     ///< a better frame exists, by less than the margin: R kept
  CurrentIsBest,    ///< nothing scores lower than the current frame: R kept
  WithinVibration,  ///< the best frame is a turn of less than acos(threshold): R kept
  ViewMoved         ///< more than the margin's share of the snapshot lies outside the current frame
};

struct TurnDecision {
  TurnReason reason = TurnReason::NoPrediction;
  double toDeg = 0.0;    ///< the angle R takes (the current one unless Turned)
  double bestDeg = 0.0;  ///< the best candidate's angle
  double gain = 0.0;     ///< 1 - score(best) / score(current): the predicted share saved
};

/// Turn to the best frame when gain > margin and the turn (folded) is at least holdDeg. A
/// snapshot whose weight lies outside the current frame by more than the margin's share
/// describes another view (the camera moved since): no turn is taken on its word.
TurnDecision decideTurn(const TurnSearch& search, double margin, double holdDeg);

/// The rotation for an absolute angle: R = [[c, -s], [s, c]] (rows), as RotationState::R.
glm::mat2 rotationOfAngle(double angleDeg);

/// The affine map from one orthographic light frame's uv to another's, both given as
/// view-projection matrices of the same directional light (uv = 0.5 (viewProj X).xy / w + 0.5):
/// the images of uv (0, 0), (1, 0), (0, 1), computed in double.
UvAffine uvAffineBetween(const glm::mat4& fromViewProj, const glm::mat4& toViewProj);

}  // namespace sl::rtw
