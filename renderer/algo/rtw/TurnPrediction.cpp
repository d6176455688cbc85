// DA-RTW's predicted warp per candidate turn (TurnPrediction.h).
#include "TurnPrediction.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

namespace sl::rtw {

namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

/// floor and ceil of finite values within int range, without a library call (they run per
/// texel per candidate).
int floorInt(double x) {
  const int i = int(x);
  return i - (x < double(i) ? 1 : 0);
}
int ceilInt(double x) {
  const int i = int(x);
  return i + (x > double(i) ? 1 : 0);
}

/// Texel of coordinate c of an n-texel axis, clamped to [0, n - 1].
int texelOf(double c, int n) {
  return std::clamp(floorInt(std::clamp(c, -1.0, 2.0) * n), 0, n - 1);
}

bool insideFrame(glm::dvec2 uv) {
  return uv.x >= 0.0 && uv.x < 1.0 && uv.y >= 0.0 && uv.y < 1.0;
}

/// The n-texels of one axis whose centres lie in [c - h, c + h]; c's own texel when none.
struct BinRange {
  int first, last;
};
BinRange binRange(double c, double h, int n) {
  // c - h and c + h lie within [-1, 2] for texels inside the frame (h < 1).
  const int first = std::max(0, ceilInt(std::clamp(c - h, -1.0, 2.0) * n - 0.5));
  const int last = std::min(n - 1, floorInt(std::clamp(c + h, -1.0, 2.0) * n - 0.5));
  if (first > last) {
    const int own = texelOf(c, n);
    return {own, own};
  }
  return {first, last};
}

/// Fills a snapshot texel's bins (binRange) with max.
void fillMax(std::vector<float>& axis, double c, double h, float value) {
  const BinRange r = binRange(c, h, int(axis.size()));
  for (int k = r.first; k <= r.last; ++k) axis[size_t(k)] = std::max(axis[size_t(k)], value);
}

/// A snapshot texel's footprint along the frame's u and v: half-widths of the parallelogram a
/// square of side 1/M becomes, |A00| + |A01| (resp. |A10| + |A11|) times half its side.
glm::dvec2 footprintHalfWidths(const CandidateFrame& frame, int snapshotSize) {
  const glm::dmat2& a = frame.fromSnapshot.linear;  // column-major: a[col][row]
  const double half = 0.5 / double(snapshotSize);
  return {half * (std::abs(a[0][0]) + std::abs(a[1][0])),
          half * (std::abs(a[0][1]) + std::abs(a[1][1]))};
}

double pixelsOf(const ImportanceSnapshot& s, size_t i) {
  return s.pixels.size() == s.importance.size() ? double(s.pixels[i]) : 1.0;
}

/// What texel i's pixels ask for on average: the mean importance when known, else the max.
double askedOf(const ImportanceSnapshot& s, size_t i) {
  return s.meanImportance.size() == s.importance.size() && s.meanImportance[i] > 0.0f
             ? double(s.meanImportance[i])
             : double(s.importance[i]);
}

/// The blurred and floored 1D map of one axis, as the renderer's blur and scan passes make it,
/// and its sum.
struct Density {
  std::vector<float> b;
  double total = 0.0;
};
Density blurAndFloor(const std::vector<float>& collapsed, const WarpSettings& w) {
  Density d{gaussianBlur1D(collapsed, w.blurRadius, w.blurSigma), 0.0};
  applyImportanceFloor(d.b, w.importanceFloor);
  for (float v : d.b) d.total += double(v);
  return d;
}

/// One axis of the warped map: prefix sums of 1 / B, so the mean texel width over any run of
/// texels is one difference.
struct AxisWidths {
  std::vector<double> invPrefix;  ///< invPrefix[k] = sum_{j < k} 1 / B[j]
  double scale = 0.0;             ///< T E / (S n): width (m) of a warped texel = scale / B
  AxisWidths(const Density& d, double extentM, double sn) : invPrefix(d.b.size() + 1, 0.0) {
    for (size_t k = 0; k < d.b.size(); ++k) invPrefix[k + 1] = invPrefix[k] + 1.0 / double(d.b[k]);
    scale = d.total * extentM / sn;
  }
  /// Mean width (m) of the warped texels over the bins a footprint [c - h, c + h] covers.
  double width(double c, double h) const {
    const BinRange r = binRange(c, h, int(invPrefix.size()) - 1);
    return scale * (invPrefix[size_t(r.last) + 1] - invPrefix[size_t(r.first)]) /
           double(r.last - r.first + 1);
  }
};

/// The error band of an edge whose normal has direction cs = (|cos|, |sin|) in the frame, for
/// texel widths m = (m_x, m_y) in pixel footprints: sqrt((cos m_x)^2 + (sin m_y)^2) (a
/// quarter of it is the mean band; TurnPrediction.h).
double acrossEdge(glm::dvec2 cs, glm::dvec2 m) {
  return std::hypot(cs.x * m.x, cs.y * m.y);  // 4 edgeBandWidth
}

/// Per-axis aliasing of a snapshot texel landing at uv with asked-for density kI: its texel
/// widths along x and y in pixel footprints, (kI w_x, kI w_y), averaged over its footprint.
struct AxisDensity {
  AxisWidths x, y;
  glm::dvec2 half;  ///< footprintHalfWidths
  glm::dvec2 m(glm::dvec2 uv, double askedDensity) const {
    return {askedDensity * x.width(uv.x, half.x), askedDensity * y.width(uv.y, half.y)};
  }
};

}  // namespace

namespace {
/// The snapshot's own frame: the identity map (the camera did not move, the turn is 0).
bool isSnapshotFrame(const CandidateFrame& frame) {
  const glm::dmat2& a = frame.fromSnapshot.linear;
  const glm::dvec2& o = frame.fromSnapshot.offset;
  constexpr double eps = 1e-9;
  return std::abs(a[0][0] - 1.0) < eps && std::abs(a[1][1] - 1.0) < eps &&
         std::abs(a[0][1]) < eps && std::abs(a[1][0]) < eps && std::abs(o.x) < eps &&
         std::abs(o.y) < eps;
}

bool validFrame(const CandidateFrame& frame) {
  return frame.extentM.x > 0.0 && frame.extentM.y > 0.0 && std::isfinite(frame.extentM.x) &&
         std::isfinite(frame.extentM.y);
}
}  // namespace

TurnPredictor::TurnPredictor(const ImportanceSnapshot& snapshot, const PredictionSettings& settings)
    : snapshot_(snapshot), settings_(settings) {
  texels_.reserve(snapshot.importance.size());
  const ImportanceSnapshot& s = snapshot;
  const int m = s.size;
  valid_ = m > 0 && s.importance.size() == size_t(m) * size_t(m) && settings.warpResolution > 0 &&
           settings.mapResolution > 0 && settings.densityPerImportance > 0.0 &&
           std::isfinite(settings.densityPerImportance);
  if (!valid_) return;
  const size_t plane = size_t(m) * size_t(m);
  const bool counted = s.pixels.size() == plane;
  const bool binned = s.edgeBins.size() == kEdgeBins * plane;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const size_t idx = size_t(j) * size_t(m) + size_t(i);
      const float value = s.importance[idx];
      if (!(value > 0.0f) || !std::isfinite(value) || (counted && s.pixels[idx] == 0)) continue;
      Texel t{{(i + 0.5) / m, (j + 0.5) / m}, value, askedOf(s, idx), pixelsOf(s, idx), 0.0, {}};
      if (binned)
        for (int b = 0; b < kEdgeBins; ++b) {
          t.bins[size_t(b)] = float(double(s.edgeBins[size_t(b) * plane + idx]) / double(kEdgeOne));
          t.edges += double(t.bins[size_t(b)]);
        }
      texels_.push_back(t);
    }
}

Collapsed TurnPredictor::collapsed(const CandidateFrame& frame) const {
  const int n = std::max(settings_.warpResolution, 0);
  if (isSnapshotFrame(frame) && snapshot_.collapsedX.size() == size_t(n) &&
      snapshot_.collapsedY.size() == size_t(n))
    return {snapshot_.collapsedX, snapshot_.collapsedY};
  Collapsed c{std::vector<float>(size_t(n), 0.0f), std::vector<float>(size_t(n), 0.0f)};
  if (n <= 0 || snapshot_.size <= 0) return c;
  const glm::dvec2 h = footprintHalfWidths(frame, snapshot_.size);
  for (const Texel& t : texels_) {
    const glm::dvec2 uv = frame.fromSnapshot.apply(t.uv);
    if (!insideFrame(uv)) continue;
    fillMax(c.x, uv.x, h.x, t.maxImportance);
    fillMax(c.y, uv.y, h.y, t.maxImportance);
  }
  return c;
}

WarpPrediction TurnPredictor::predict(const CandidateFrame& frame) const {
  WarpPrediction out;
  out.angleDeg = frame.angleDeg;
  if (!valid_ || !validFrame(frame)) return out;
  const int n = settings_.warpResolution;
  const Collapsed c = collapsed(frame);
  const Density dx = blurAndFloor(c.x, settings_.warp), dy = blurAndFloor(c.y, settings_.warp);
  if (!(dx.total > 0.0) || !(dy.total > 0.0)) return out;
  const double sn = double(settings_.mapResolution) * double(n);
  const AxisDensity g{AxisWidths(dx, frame.extentM.x, sn), AxisWidths(dy, frame.extentM.y, sn),
                      footprintHalfWidths(frame, snapshot_.size)};
  // The edge bins' directions in this frame: bin b's normal at b kEdgeBinDeg - turnDeg; and
  // the same directions unturned, for edges of every direction alike.
  std::array<glm::dvec2, kEdgeBins> binCosSin, uniformCosSin;
  for (int b = 0; b < kEdgeBins; ++b) {
    const double u = b * kEdgeBinDeg * kDegToRad, r = (b * kEdgeBinDeg - frame.turnDeg) * kDegToRad;
    uniformCosSin[size_t(b)] = {std::abs(std::cos(u)), std::abs(std::sin(u))};
    binCosSin[size_t(b)] = {std::abs(std::cos(r)), std::abs(std::sin(r))};
  }
  const bool edges = settings_.weight == PredictionWeight::EdgePixels;
  double sum = 0.0, weight = 0.0, under = 0.0, outside = 0.0;
  for (const Texel& t : texels_) {
    const double w = edges ? t.edges : t.pixels;
    if (!(w > 0.0)) continue;
    const glm::dvec2 uv = frame.fromSnapshot.apply(t.uv);
    if (!insideFrame(uv)) {
      outside += w;
      continue;
    }
    // Texel widths in pixel footprints along the frame's axes: k I / g.
    const glm::dvec2 m = g.m(uv, settings_.densityPerImportance * t.asked);
    if (edges) {
      for (int b = 0; b < kEdgeBins; ++b)
        if (t.bins[size_t(b)] > 0.0f)
          sum += double(t.bins[size_t(b)]) * acrossEdge(binCosSin[size_t(b)], m);
    } else {
      double mean = 0.0;
      for (const glm::dvec2& cs : uniformCosSin) mean += acrossEdge(cs, m);
      sum += w * mean / double(uniformCosSin.size());
    }
    weight += w;
    if (m.x * m.y > 1.0) under += w;
  }
  if (!(weight > 0.0)) return out;
  out.valid = true;
  out.weight = weight;
  out.score = sum / weight;
  out.undersampled = under / weight;
  out.outside = outside / (weight + outside);
  return out;
}

std::vector<double> TurnPredictor::aliasingQuantiles(const CandidateFrame& frame,
                                                     std::span<const double> q) const {
  if (!valid_ || !validFrame(frame)) return {};
  const int n = settings_.warpResolution;
  const Collapsed c = collapsed(frame);
  const Density dx = blurAndFloor(c.x, settings_.warp), dy = blurAndFloor(c.y, settings_.warp);
  if (!(dx.total > 0.0) || !(dy.total > 0.0)) return {};
  const double sn = double(settings_.mapResolution) * double(n);
  const AxisDensity g{AxisWidths(dx, frame.extentM.x, sn), AxisWidths(dy, frame.extentM.y, sn),
                      footprintHalfWidths(frame, snapshot_.size)};
  std::vector<std::pair<double, double>> mw;  // (m, pixels)
  double total = 0.0;
  for (const Texel& t : texels_) {
    const glm::dvec2 uv = frame.fromSnapshot.apply(t.uv);
    if (!(t.pixels > 0.0) || !insideFrame(uv)) continue;
    const glm::dvec2 m = g.m(uv, settings_.densityPerImportance * t.asked);
    mw.emplace_back(std::sqrt(m.x * m.y), t.pixels);
    total += t.pixels;
  }
  if (mw.empty()) return {};
  std::sort(mw.begin(), mw.end());
  std::vector<double> out;
  for (double qi : q) {
    // The smallest m whose cumulative weight reaches q of the total (a weighted lower quantile).
    const double target = std::clamp(qi, 0.0, 1.0) * total;
    double acc = 0.0;
    double value = mw.back().first;
    for (const auto& [m, w] : mw) {
      acc += w;
      if (acc >= target) {
        value = m;
        break;
      }
    }
    out.push_back(value);
  }
  return out;
}

Collapsed resampleCollapsed(const ImportanceSnapshot& snapshot, const CandidateFrame& frame,
                            int n) {
  PredictionSettings s;
  s.warpResolution = n;
  CandidateFrame moved = frame;  // never the snapshot's own maps: the resampling itself
  if (isSnapshotFrame(moved)) moved.fromSnapshot.offset.x += 1e-12;
  return TurnPredictor(snapshot, s).collapsed(moved);
}

WarpPrediction predictWarp(const ImportanceSnapshot& snapshot, const CandidateFrame& frame,
                           const PredictionSettings& settings) {
  return TurnPredictor(snapshot, settings).predict(frame);
}

std::vector<double> predictedAliasingQuantiles(const ImportanceSnapshot& snapshot,
                                               const CandidateFrame& frame,
                                               const PredictionSettings& settings,
                                               std::span<const double> q) {
  return TurnPredictor(snapshot, settings).aliasingQuantiles(frame, q);
}

double ImportanceSnapshot::edgePixels(size_t i) const {
  const size_t plane = size_t(size) * size_t(size);
  if (edgeBins.size() != kEdgeBins * plane) return 0.0;
  std::uint64_t parts = 0;
  for (int b = 0; b < kEdgeBins; ++b) parts += edgeBins[size_t(b) * plane + i];
  return double(parts) / double(kEdgeOne);
}

ImportanceSnapshot reduceSnapshot(const ImportanceSnapshot& s, int maxSize) {
  if (s.size <= maxSize || maxSize <= 0) return s;
  const int f = (s.size + maxSize - 1) / maxSize, r = (s.size + f - 1) / f;
  const size_t plane = size_t(s.size) * size_t(s.size), rplane = size_t(r) * size_t(r);
  const bool pixels = s.pixels.size() == plane, edges = s.edgeBins.size() == kEdgeBins * plane;
  const bool mean = pixels && s.meanImportance.size() == plane;
  ImportanceSnapshot out;
  out.size = r;
  out.collapsedX = s.collapsedX;
  out.collapsedY = s.collapsedY;
  out.importance.assign(rplane, 0.0f);
  std::vector<double> sums(mean ? rplane : 0, 0.0);
  if (pixels) out.pixels.assign(rplane, 0u);
  if (edges) out.edgeBins.assign(kEdgeBins * rplane, 0u);
  for (int j = 0; j < s.size; ++j)
    for (int i = 0; i < s.size; ++i) {
      const size_t from = size_t(j) * size_t(s.size) + size_t(i);
      const size_t to = size_t(j / f) * size_t(r) + size_t(i / f);
      out.importance[to] = std::max(out.importance[to], s.importance[from]);
      if (pixels) out.pixels[to] += s.pixels[from];
      if (mean) sums[to] += double(s.meanImportance[from]) * double(s.pixels[from]);
      if (edges)
        for (int b = 0; b < kEdgeBins; ++b)
          out.edgeBins[size_t(b) * rplane + to] += s.edgeBins[size_t(b) * plane + from];
    }
  if (mean) {
    out.meanImportance.assign(rplane, 0.0f);
    for (size_t i = 0; i < rplane; ++i)
      if (out.pixels[i] > 0) out.meanImportance[i] = float(sums[i] / double(out.pixels[i]));
  }
  return out;
}

EdgeBinParts edgeBinParts(double betaDeg) {
  double a = std::isfinite(betaDeg) ? std::fmod(betaDeg, 180.0) : 0.0;
  if (a < 0.0) a += 180.0;
  const double x = std::min(a / kEdgeBinDeg, double(kEdgeBins) - 1e-4);  // as the shader
  EdgeBinParts p;
  p.lo = int(std::floor(x));
  p.hi = (p.lo + 1) % kEdgeBins;
  p.hiPart = std::uint32_t(std::lround((x - p.lo) * double(kEdgeOne)));
  p.loPart = kEdgeOne - p.hiPart;
  return p;
}

double edgeBandWidth(double normalDeg, double wX, double wY) {
  const double r = normalDeg * kDegToRad;
  return 0.25 * std::hypot(std::cos(r) * wX, std::sin(r) * wY);
}

double foldQuarterTurn(double angleDeg) {
  if (!std::isfinite(angleDeg)) return 0.0;
  double a = std::fmod(angleDeg, 90.0);  // (-90, 90)
  if (a > 45.0) a -= 90.0;
  if (a <= -45.0) a += 90.0;
  return a;
}

TurnSearch searchTurn(double currentDeg, std::optional<double> pcaAxisDeg,
                      const std::function<WarpPrediction(double angleDeg)>& predict,
                      double refineAbove) {
  TurnSearch s;
  std::map<long long, int> seen;  // folded angle in micro-degrees -> index
  auto eval = [&](double angleDeg) {
    const double a = foldQuarterTurn(angleDeg);
    const long long key = std::llround(a * 1e6);
    if (auto it = seen.find(key); it != seen.end()) return it->second;
    WarpPrediction p = predict(a);
    p.angleDeg = a;
    s.scored.push_back(p);
    const int index = int(s.scored.size()) - 1;
    seen[key] = index;
    return index;
  };
  const double current = foldQuarterTurn(currentDeg);
  auto better = [&](int a, int b) {  // a strictly preferred to b
    const WarpPrediction &pa = s.scored[size_t(a)], &pb = s.scored[size_t(b)];
    if (pa.valid != pb.valid) return pa.valid;
    if (pa.score != pb.score) return pa.score < pb.score;
    if (b == s.current) return false;
    if (a == s.current) return true;
    return std::abs(foldQuarterTurn(pa.angleDeg - current)) <
           std::abs(foldQuarterTurn(pb.angleDeg - current));
  };
  auto updateBest = [&] {
    for (int i = 0; i < int(s.scored.size()); ++i)
      if (s.best < 0 || better(i, s.best)) s.best = i;
  };
  s.current = eval(current);
  if (pcaAxisDeg && std::isfinite(*pcaAxisDeg)) eval(*pcaAxisDeg);
  for (double a = -45.0 + kTurnSearchStepDeg; a <= 45.0 + 1e-9; a += kTurnSearchStepDeg) eval(a);
  updateBest();
  const WarpPrediction& cur = s.scored[size_t(s.current)];
  const WarpPrediction& coarse = s.scored[size_t(s.best)];
  const bool inSight =
      cur.valid && coarse.valid && cur.score > 0.0 && 1.0 - coarse.score / cur.score >= refineAbove;
  double step = kTurnSearchStepDeg;
  for (int r = 0; r < kTurnSearchRefinements && inSight; ++r) {
    step *= 0.5;
    const double centre = s.scored[size_t(s.best)].angleDeg;
    eval(centre - step);
    eval(centre + step);
    updateBest();
  }
  return s;
}

TurnDecision decideTurn(const TurnSearch& search, double margin, double holdDeg) {
  TurnDecision d;
  if (search.current < 0 || search.best < 0) return d;
  const WarpPrediction& cur = search.scored[size_t(search.current)];
  const WarpPrediction& best = search.scored[size_t(search.best)];
  d.toDeg = cur.angleDeg;
  d.bestDeg = best.angleDeg;
  if (!cur.valid || !best.valid) return d;  // NoPrediction
  d.gain = cur.score > 0.0 ? 1.0 - best.score / cur.score : 0.0;
  if (cur.outside > margin) {
    d.reason = TurnReason::ViewMoved;
    return d;
  }
  if (search.best == search.current || !(d.gain > 0.0)) {
    d.reason = TurnReason::CurrentIsBest;
    return d;
  }
  if (!(d.gain > margin)) {
    d.reason = TurnReason::WithinMargin;
    return d;
  }
  if (std::abs(foldQuarterTurn(best.angleDeg - cur.angleDeg)) < holdDeg) {
    d.reason = TurnReason::WithinVibration;
    return d;
  }
  d.reason = TurnReason::Turned;
  d.toDeg = best.angleDeg;
  return d;
}

glm::mat2 rotationOfAngle(double angleDeg) {
  const double r = angleDeg * kDegToRad;
  const float c = float(std::cos(r)), s = float(std::sin(r));
  return glm::mat2(c, s, -s, c);
}

UvAffine uvAffineBetween(const glm::mat4& fromViewProj, const glm::mat4& toViewProj) {
  const glm::dmat4 inv = glm::inverse(glm::dmat4(fromViewProj));
  const glm::dmat4 to(toViewProj);
  auto image = [&](glm::dvec2 uv) {
    glm::dvec4 x = inv * glm::dvec4(2.0 * uv - 1.0, 0.0, 1.0);
    x /= x.w;
    const glm::dvec4 c = to * x;
    return 0.5 * glm::dvec2(c.x, c.y) / c.w + 0.5;
  };
  const glm::dvec2 o = image({0.0, 0.0});
  UvAffine a;
  a.offset = o;
  a.linear = glm::dmat2(image({1.0, 0.0}) - o, image({0.0, 1.0}) - o);
  return a;
}

}  // namespace sl::rtw
