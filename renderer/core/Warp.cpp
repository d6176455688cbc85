// The perspective warp's shared parameter and outlines (Warp.h).
#include "Warp.h"

#include <array>

namespace sl {

ParamDecl warpEtaDecl(double defaultEta) {
  return floatParam("warp.eta", "Warp eta", "Warp", defaultEta, {-1.0, 1.0, 0.05})
      .withHelp(
          "Lloyd et al.'s eq. 11: -1 uniform (n' infinite), 0 LiSPSM (n' = n + sqrt(f n)), 1 their "
          "light-space PSM (n' = n). Shared by psm with psm.method = lispsm-eta1, lispsm (which "
          "differ only in the default) and cascades with partition.warp (per partition: n and f of "
          "its slice) and face-partition (one warp per face); tsm derives it from warp.focus and "
          "publishes it (warp.eta).");
}

void addWarpOutlines(const warp::WarpFit& fit, FrameOutlines& out, int map) {
  // Light space (algo/warp): x across, y along the light (depth), z the warp's axis. The box
  // the warp was fitted in is the light's (unwarped) frustum; the warping frustum is the
  // wedge |x - cx| <= tanHalfX z' for z' = z - lo.z + n' in [n', n' + L], its side edges
  // meeting at the apex line z' = 0 (paper's Fig. 3).
  const glm::dvec3 X = fit.space.x, Y = fit.space.y, Z = fit.space.z;
  auto world = [&](double x, double y, double z) { return glm::vec3(x * X + y * Y + z * Z); };
  FrustumOutline box, warp;
  box.role = OutlineRole::LightMap;
  warp.role = OutlineRole::Warp;
  box.map = warp.map = map;
  std::array<glm::vec3, 4> apex;
  for (int i = 0; i < 8; ++i) {
    const int face = i & 3;
    const double sx = (face == 1 || face == 2) ? 1.0 : -1.0;
    const double y = face >= 2 ? fit.hi.y : fit.lo.y;
    const double z = i < 4 ? fit.lo.z : fit.hi.z;
    box.corners[size_t(i)] = world(sx > 0 ? fit.hi.x : fit.lo.x, y, z);
    const double zPrime = z - fit.lo.z + fit.nPrime;
    warp.corners[size_t(i)] = world(fit.cx + sx * fit.tanHalfX * zPrime, y, z);
    if (i < 4) apex[size_t(i)] = world(fit.cx, y, fit.lo.z - fit.nPrime);
  }
  warp.apex = apex;
  out.frusta.push_back(box);
  out.frusta.push_back(warp);
}

}  // namespace sl
