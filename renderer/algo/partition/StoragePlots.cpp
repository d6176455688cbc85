// The data of the storage-factor plots; see StoragePlots.h.
#include "StoragePlots.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sl::partition {

std::optional<std::string> etaCurve(const warp::ViewFrustum& view, const glm::dvec3& towardsLight,
                                    int points, EtaCurve& out) {
  if (points < 2) return "eta curve: need at least 2 points, got " + std::to_string(points);
  out.eta.clear(), out.mx.clear(), out.mz.clear(), out.s.clear();
  for (int i = 0; i < points; ++i) {
    SchemeSettings s;
    s.scheme = Scheme::Eta;
    s.eta = i + 1 == points ? 1.0 : -1.0 + 2.0 * i / (points - 1);
    StorageResult r;
    if (auto e = evaluateScheme(view, towardsLight, s, r)) return e;
    out.eta.push_back(s.eta), out.mx.push_back(r.mx), out.mz.push_back(r.mz);
    out.s.push_back(r.s);
  }
  return std::nullopt;
}

HemisphereFrame HemisphereFrame::forView(const warp::ViewFrustum& view, const glm::dvec3& worldUp) {
  HemisphereFrame f;
  f.up = glm::normalize(worldUp);
  glm::dvec3 front = view.forward - glm::dot(view.forward, f.up) * f.up;
  if (glm::length(front) < 1e-6) {  // looking straight down (or up): the image's up is "front"
    const double sign = glm::dot(view.forward, f.up) < 0.0 ? 1.0 : -1.0;
    front = sign * (view.up - glm::dot(view.up, f.up) * f.up);
  }
  f.front = glm::normalize(front);
  f.right = glm::cross(f.front, f.up);
  return f;
}

std::optional<glm::dvec3> HemisphereFrame::direction(double u, double v) const {
  const double rad = std::hypot(u, v);
  if (!(rad <= 1.0)) return std::nullopt;
  const double z = rad * 0.5 * M_PI;  // zenith angle
  if (rad == 0.0) return up;
  return std::cos(z) * up + std::sin(z) * (u / rad * front + v / rad * right);
}

glm::dvec2 HemisphereFrame::disk(const glm::dvec3& towardsLight) const {
  const glm::dvec3 l = glm::normalize(towardsLight);
  const double zenith = std::acos(std::clamp(glm::dot(l, up), -1.0, 1.0));
  const glm::dvec2 h(glm::dot(l, front), glm::dot(l, right));
  const double len = glm::length(h);
  if (len < 1e-12) return {0.0, 0.0};
  return h / len * (zenith / (0.5 * M_PI));
}

glm::dvec2 HemispherePanel::cellCentre(int row, int col) const {
  return {-1.0 + (2.0 * col + 1.0) / grid, 1.0 - (2.0 * row + 1.0) / grid};
}

std::optional<std::string> hemispherePanel(const warp::ViewFrustum& view,
                                           const HemisphereFrame& frame,
                                           const SchemeSettings& settings, int grid,
                                           HemispherePanel& out) {
  if (grid < 1 || grid > 4096)
    return "hemisphere: grid " + std::to_string(grid) + " not in 1..4096";
  out.grid = grid;
  const std::size_t n = std::size_t(grid) * std::size_t(grid);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  out.s.assign(n, nan), out.mx.assign(n, nan), out.mz.assign(n, nan);
  for (int r = 0; r < grid; ++r)
    for (int c = 0; c < grid; ++c) {
      const glm::dvec2 uv = out.cellCentre(r, c);
      const std::optional<glm::dvec3> l = frame.direction(uv.x, uv.y);
      if (!l) continue;
      StorageResult sr;
      if (auto e = evaluateScheme(view, *l, settings, sr)) return e;
      const std::size_t i = std::size_t(r) * std::size_t(grid) + std::size_t(c);
      out.s[i] = sr.s, out.mx[i] = sr.mx, out.mz[i] = sr.mz;
    }
  return std::nullopt;
}

}  // namespace sl::partition
