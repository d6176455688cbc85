// One perspective warp along light-space z for a directional light: PSM, LiSPSM and TSM as
// values of one parameter (Lloyd, Tuft, Yoon, Manocha, "Warping and Partitioning for Low
// Error Shadow Maps", EGSR 2006, §4, Fig. 3 and eq. 11; Wimmer et al. 2004 for light space).
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "algo/Camera.h"
#include "algo/ShadowBias.h"

namespace sl::warp {

/// The camera as the analysis sees it: a symmetric view frustum, double precision.
struct ViewFrustum {
  glm::dvec3 eye{0.0};
  glm::dvec3 forward{0.0, 0.0, -1.0};  ///< unit view vector v
  glm::dvec3 up{0.0, 1.0, 0.0};        ///< unit, orthogonal to forward
  double nearM = 1.0;
  double farM = 100.0;
  double fovYRad = 1.0;  ///< full vertical angle (2 theta)
  double aspect = 1.0;   ///< width / height; the paper's analysis assumes 1 (square image)

  glm::dvec3 right() const { return glm::cross(forward, up); }
  double tanHalfY() const;
  double tanHalfX() const { return tanHalfY() * aspect; }
  /// Corners between `nearM` and `farM` (0-3 near, 4-7 far; each: -x-y, +x-y, +x+y, -x+y).
  std::array<glm::dvec3, 8> corners(double nearM, double farM) const;
  std::array<glm::dvec3, 8> corners() const { return corners(nearM, farM); }
  /// An error naming the bad value (near/far, angle, aspect, axes), or nothing.
  std::optional<std::string> validate() const;

  static ViewFrustum fromCamera(const Camera& camera, double aspect);
  /// This frustum with near and far clipped to the view-depth range of `body` (a warp
  /// fitted around view frustum ∩ scene: TSM's focus and LiSPSM's n, f lie within what the
  /// camera sees of the scene, not on the far plane's empty kilometres).
  ViewFrustum clippedToBody(std::span<const glm::dvec3> body) const;
};

/// Light space of the paper's Fig. 3: y towards the light, z the warp axis (perpendicular
/// to y: the view vector projected, or a face partition's bisector), x = z cross y.
struct LightSpace {
  glm::dvec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  glm::dvec3 toLight(const glm::dvec3& world) const {
    return {glm::dot(world, x), glm::dot(world, y), glm::dot(world, z)};
  }
};

/// Light space with z along `axis` projected perpendicular to `towardsLight`; nothing when
/// the axis is (nearly) parallel to the light (|sin| < 1e-9).
std::optional<LightSpace> makeLightSpace(const glm::dvec3& towardsLight, const glm::dvec3& axis);

enum class WarpKind {
  Uniform,  ///< n' = infinity: the orthographic shadow map
  Eta,      ///< eq. 11 with the given eta in [-1, 1]
  Lispsm,   ///< eta = 0: n' = n'_LiSPSM
  Psm,      ///< eta = 1: n' = n (overhead light), the projection centre at the eye
  Tsm,      ///< the focus point on the 80 % line (Martin and Tan 2004)
};

struct WarpSettings {
  WarpKind kind = WarpKind::Lispsm;
  double eta = 0.0;  ///< for WarpKind::Eta, in [-1, 1]
  /// TSM's focus point: on the view axis at near + this share of (far - near).
  double tsmFocusFraction = 0.5;
  /// TSM's line: the focus maps to this share of the map's t (0.8 in the TSM paper).
  double tsmFocusLine = 0.8;
  /// PSM's singularity (n' -> 0 as the near plane -> 0): n' is kept >= this share of the
  /// body's light-space depth (a virtual shift of the projection centre, after Kozlov).
  double minNearShare = 1e-3;
  /// The warp's axis in world space (3D, not yet projected): the view vector when unset;
  /// a face partition passes the central direction of its side edges (§5.1).
  std::optional<glm::dvec3> axis;
  /// Projected warp axis override (perpendicular to the light), e.g. the bisector of a face
  /// partition's projected side edges; `axis` still gives sin(gamma) and the near distance.
  std::optional<glm::dvec3> projectedAxis;
  /// Revert to uniform when the view frustum looks square from the light (the paper's §4.4).
  bool squareFallback = true;
  /// World points that only widen the map's depth range (light-space y), not its x/z
  /// extent or the warp: the scene's casters between the light and the body.
  std::vector<glm::dvec3> depthOnly;
};

/// Why a warp asked for fell back to uniform (WarpFit::fallbackReason says it in words).
enum class FallbackCause {
  None,
  SquareLightBehind,   ///< the light behind the viewer, inside the view cone (the paper's §4.4)
  SquareLightInFront,  ///< the light in front of the viewer, inside the view cone
  TsmFocusBeyondLine,  ///< TSM's focus point lies beyond its line along the depth
  Degenerate,          ///< light parallel to the axis, no depth, body at the eye, n' infinite
};
/// One line for a panel: "light behind the viewer: the frustum looks square from the light".
const char* fallbackCauseText(FallbackCause cause);

/// The fitted warp and what the UI shows about it.
struct WarpFit {
  LightSpace space;
  /// The body's light-space bounds (x, y, z), metres; y widened by WarpSettings::depthOnly.
  glm::dvec3 lo{0.0}, hi{0.0};
  double depthM = 0.0;     ///< L = hi.z - lo.z
  double sinGamma = 1.0;   ///< sin of the angle between the warp's 3D axis and the light
  double alpha = 1.0;      ///< eq. 11's alpha = z1 / z0 (f / n for an overhead light)
  double nearAxisM = 0.0;  ///< near distance along the warp's 3D axis (n for the frustum)
  double eta = -1.0;       ///< the eta of this warp (eq. 11 inverted for TSM)
  /// n': distance from the projection centre c to the body's near face along z. Infinite
  /// for uniform.
  double nPrime = 0.0;
  double nPrimeLispsm = 0.0;  ///< n'_LiSPSM of this body (eta = 0)
  double tanHalfX = 0.0;      ///< the warping frustum's half-angle tangent in x
  double cx = 0.0;            ///< the projection centre's light-space x
  bool uniform = false;       ///< orthographic (asked for, or the fallback)
  bool fallback = false;      ///< a warp was asked for but uniform was used
  std::string fallbackReason;
  FallbackCause fallbackCause = FallbackCause::None;
  bool lightBehindViewer = false;  ///< v . y < 0 (PSM would need its inverted projection)
  bool nearClamped = false;        ///< n' was raised to minNearShare * L (PSM singularity)
  std::string note;                ///< what was done about the light behind / the clamp
  glm::mat4 lightView{1.0f};       ///< world -> light space (x, z, y: looks along -y)
  glm::mat4 lightProj{1.0f};       ///< light space -> clip: s, t in x, y; depth along the light

  bool warped() const { return !uniform; }
  /// Shadow-map coordinates (s, t) in [0, 1] of a world point (eqs. 5-6).
  glm::dvec2 mapUv(const glm::dvec3& world) const;
  /// Light beam widths (w_lx, w_lz) at a world point for a 1x1 map (eqs. 3-4, res = 1).
  glm::dvec2 beamWidths(const glm::dvec3& world) const;
  /// The map as the lookup's bias model sees it (warped only; the uniform case is the
  /// technique's orthographic fit): lightProj * lightView, w = z'; metres per unit s =
  /// 2 tan(theta') w, per unit t = w^2 (f' - n') / (f' n') (eq. 6), window depth per metre
  /// n' / (2 yHalf w): extentWPower (1, 2), depthWPower 1.
  DepthMapFrame mapFrame() const;
};

/// n' from eta (eq. 11): n' = n (sqrt(a) + 1 - eta (a - 1)) / (eta + 1) for eta <= 0,
/// n (sqrt(a) + 1) / (eta sqrt(a) + 1) for eta >= 0, with a = f / n. Infinite at eta = -1.
double nPrimeFromEta(double eta, double nearM, double farM);
/// The inverse of eq. 11 (n' >= n): eta in [-1, 1].
double etaFromNPrime(double nPrime, double nearM, double farM);

/// Fits the warp around `body` (world points: the view frustum, or its intersection with
/// the scene bounds, or a partition of it) for the light `towardsLight`. Errors name the
/// problem (no points, non-finite values, eta out of range).
std::optional<std::string> fitWarp(const ViewFrustum& view, std::span<const glm::dvec3> body,
                                   const glm::dvec3& towardsLight, const WarpSettings& settings,
                                   WarpFit& out);

/// The body a focused warp is fitted around (LiSPSM's focusing, Wimmer et al. 2004; what
/// psm, lispsm and tsm fit): the camera's view frustum ∩ the scene's bounds (the whole box
/// when the camera sees none of it), the frustum clipped to the body's view-depth range, and
/// the box's corners as depth-only points (every caster between the light and the body).
struct FocusedBody {
  ViewFrustum view;
  std::vector<glm::dvec3> body;
  std::vector<glm::dvec3> depthOnly;
};
FocusedBody focusedBody(const Camera& camera, double aspect, const Aabb& sceneBounds);

/// fitWarp around focusedBody(camera, aspect, sceneBounds) with `settings` (its depthOnly
/// set to the body's): the warp psm, lispsm and tsm render, and the virtual map of fvsm and
/// virtual-tiled with their warp = lispsm (Giegl & Wimmer 2007 use LiSPSM with focusing).
std::optional<std::string> fitFocusedWarp(const Camera& camera, double aspect,
                                          const Aabb& sceneBounds, const glm::dvec3& towardsLight,
                                          WarpSettings settings, WarpFit& out);

/// The crop of a map's clip space onto its uv rectangle [uvMin, uvMax] (a tile of a virtual
/// map; uv may leave [0, 1] for an overlap): clip' = crop * clip scales and shifts x and y
/// (the shift times w, so that it holds for orthographic and perspective maps alike) so
/// that uv' = (uv − uvMin) / (uvMax − uvMin); z and w are kept. A tile of a LiSPSM-warped
/// virtual map is the warp's own frustum cropped, its matrix crop * the warp's.
glm::dmat4 uvRectCrop(const glm::dvec2& uvMin, const glm::dvec2& uvMax);

/// True when `towardsLight` or its opposite lies inside the view frustum's pyramid: seen
/// from the light, the near face projects inside the far face (a square, not a trapezoid).
bool frustumLooksSquare(const ViewFrustum& view, const glm::dvec3& towardsLight);

}  // namespace sl::warp
