// Statistics for benchmarks and stability runs; see BenchStats.h.
#include "BenchStats.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <tuple>

namespace sl {
namespace {

template <typename T>
double percentileOf(std::span<const T> values, double p) {
  std::vector<double> v;
  v.reserve(values.size());
  for (T x : values)
    if (std::isfinite(double(x))) v.push_back(double(x));
  if (v.empty()) return 0.0;
  if (!(p > 0.0)) p = 0.0;  // also NaN
  p = std::min(p, 100.0);
  const double h = double(v.size() - 1) * p / 100.0;
  const std::size_t lo = std::size_t(std::floor(h));
  const double frac = h - double(lo);
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(lo), v.end());
  const double a = v[lo];
  if (frac == 0.0 || lo + 1 >= v.size()) return a;
  // The next rank is the smallest value above position lo.
  const double b = *std::min_element(v.begin() + std::ptrdiff_t(lo) + 1, v.end());
  return a + frac * (b - a);
}

bool covered(std::uint8_t m) {
  return m != kStatsMaskUncovered;
}
bool lit(std::uint8_t m) {
  return m != kStatsMaskShadowed;
}

void requireSameSize(std::size_t a, std::size_t b, const char* what) {
  if (a != b) throw std::invalid_argument(std::string(what) + ": sizes differ");
}

}  // namespace

double percentile(std::span<const double> values, double p) {
  return percentileOf(values, p);
}
double percentile(std::span<const float> values, double p) {
  return percentileOf(values, p);
}
double median(std::span<const double> values) {
  return percentileOf(values, 50.0);
}

AliasingStats computeAliasingStats(std::span<const float> aliasing,
                                   std::span<const std::uint8_t> hardMask) {
  if (!hardMask.empty()) requireSameSize(aliasing.size(), hardMask.size(), "aliasing stats");
  AliasingStats s;
  std::vector<float> kept;
  kept.reserve(aliasing.size());
  double sum = 0.0;
  for (std::size_t i = 0; i < aliasing.size(); ++i) {
    if (!hardMask.empty() && !covered(hardMask[i])) continue;
    const float m = aliasing[i];
    if (!std::isfinite(m)) {
      ++s.nonFinite;
      continue;
    }
    if (m <= 0.0f) continue;
    kept.push_back(m);
    sum += m;
    s.max = std::max(s.max, double(m));
  }
  s.pixels = kept.size();
  if (kept.empty()) return s;
  s.mean = sum / double(kept.size());
  s.p95 = percentile(std::span<const float>(kept), 95.0);
  return s;
}

std::uint64_t Log2Histogram::total() const {
  return std::accumulate(counts.begin(), counts.end(), std::uint64_t(0));
}

std::size_t Log2Histogram::binOf(double m) const {
  const double t = std::floor((std::log2(m) - log2Min) * binsPerOctave);
  if (!(t > 0.0)) return 0;  // also NaN
  return std::min(counts.size() - 1, std::size_t(std::min(t, 1e15)));
}

double Log2Histogram::binCentre(std::size_t bin) const {
  return std::exp2(log2Min + (double(bin) + 0.5) / binsPerOctave);
}

Log2Histogram aliasingHistogram(std::span<const float> aliasing,
                                std::span<const std::uint8_t> hardMask) {
  if (!hardMask.empty()) requireSameSize(aliasing.size(), hardMask.size(), "aliasing histogram");
  Log2Histogram h;
  for (std::size_t i = 0; i < aliasing.size(); ++i) {
    if (!hardMask.empty() && !covered(hardMask[i])) continue;
    const float m = aliasing[i];
    if (std::isfinite(m) && m > 0.0f) ++h.counts[h.binOf(m)];
  }
  return h;
}

double histogramPercentile(const Log2Histogram& h, double p, double maxValue) {
  const std::uint64_t n = h.total();
  if (n == 0) return 0.0;
  if (!(p > 0.0)) p = 0.0;
  p = std::min(p, 100.0);
  const double rank = double(n - 1) * p / 100.0;
  const std::uint64_t lo = std::uint64_t(std::floor(rank));
  const double frac = rank - double(lo);
  // The value of the rank-th smallest (0-based): the centre of the bin holding it.
  auto valueAt = [&](std::uint64_t r) {
    std::uint64_t seen = 0;
    for (std::size_t b = 0; b < h.counts.size(); ++b) {
      seen += h.counts[b];
      if (seen > r) return h.binCentre(b);
    }
    return h.binCentre(h.counts.size() - 1);
  };
  const double a = valueAt(lo);
  const double v = frac == 0.0 || lo + 1 >= n ? a : a + frac * (valueAt(lo + 1) - a);
  return maxValue > 0.0 ? std::min(v, maxValue) : v;
}

MaskChange compareConsecutiveMasks(std::span<const std::uint8_t> previous,
                                   std::span<const std::uint8_t> current) {
  requireSameSize(previous.size(), current.size(), "mask change");
  MaskChange c;
  for (std::size_t i = 0; i < current.size(); ++i) {
    if (!covered(previous[i]) || !covered(current[i])) continue;
    ++c.compared;
    if (lit(previous[i]) != lit(current[i])) ++c.changed;
  }
  c.pct = c.compared ? 100.0 * double(c.changed) / double(c.compared) : 0.0;
  return c;
}

FlickerStats computeFlicker(std::span<const std::uint8_t> previousMask,
                            std::span<const std::uint8_t> currentMask,
                            std::span<const std::uint8_t> previousReference,
                            std::span<const std::uint8_t> currentReference) {
  requireSameSize(previousMask.size(), currentMask.size(), "flicker");
  requireSameSize(previousMask.size(), previousReference.size(), "flicker");
  requireSameSize(previousMask.size(), currentReference.size(), "flicker");
  FlickerStats f;
  for (std::size_t i = 0; i < currentMask.size(); ++i) {
    if (!covered(previousMask[i]) || !covered(currentMask[i]) || !covered(previousReference[i]) ||
        !covered(currentReference[i]))
      continue;
    ++f.compared;
    const bool techniqueFlips = lit(previousMask[i]) != lit(currentMask[i]);
    const bool referenceFlips = lit(previousReference[i]) != lit(currentReference[i]);
    if (techniqueFlips && !referenceFlips) ++f.flicker;
    if (techniqueFlips && referenceFlips) ++f.trueFlips;
  }
  f.pct = f.compared ? 100.0 * double(f.flicker) / double(f.compared) : 0.0;
  return f;
}

std::vector<std::size_t> paretoFront(std::span<const CostPoint> points) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (std::isfinite(points[i].cost) && std::isfinite(points[i].errorPct)) order.push_back(i);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (points[a].cost != points[b].cost) return points[a].cost < points[b].cost;
    if (points[a].errorPct != points[b].errorPct) return points[a].errorPct < points[b].errorPct;
    return a < b;
  });
  // Sweep by cost: a point is on the front when its error is below every error seen so
  // far, or equal to the last front point's (exact duplicate).
  std::vector<std::size_t> front;
  for (std::size_t i : order) {
    if (front.empty()) {
      front.push_back(i);
      continue;
    }
    const CostPoint& last = points[front.back()];
    const CostPoint& p = points[i];
    if (p.errorPct < last.errorPct || (p.errorPct == last.errorPct && p.cost == last.cost))
      front.push_back(i);
  }
  return front;
}

std::optional<ChartX> parseChartX(std::string_view text) {
  if (text == "ms") return ChartX::TimeMs;
  if (text == "bytes") return ChartX::Bytes;
  return std::nullopt;
}

const char* chartHeadline(ChartX x) {
  return x == ChartX::Bytes ? "Memory against accuracy" : "Speed against accuracy";
}

std::pair<double, int> niceAxisRange(double v) {
  if (!(v > 0.0)) return {1.0, 5};
  const double p = std::pow(10.0, std::floor(std::log10(v)));
  for (double step : {0.1 * p, 0.2 * p, 0.5 * p, p, 2.0 * p, 5.0 * p}) {
    const int n = int(std::ceil(v / step - 1e-9));
    if (n <= 10) return {n * step, n + 1};
  }
  return {10.0 * p, 11};
}

ByteUnit byteUnitFor(double maxBytes) {
  ByteUnit unit;
  for (const char* name : {"KiB", "MiB", "GiB"}) {
    if (!(maxBytes >= unit.bytes * 1024.0)) break;
    unit = {name, unit.bytes * 1024.0};
  }
  return unit;
}

ChartAxis planChartAxis(std::span<const double> values, AxisScale scale, double logAboveRatio,
                        double margin, std::string title) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (double v : values)
    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  ChartAxis axis;
  const bool any = lo <= hi;  // a finite value
  axis.log = any && (scale == AxisScale::Log ||
                     (scale == AxisScale::Auto && lo > 0.0 && hi / lo > logAboveRatio));
  if (axis.log && !(lo > 0.0))
    throw std::invalid_argument("a log axis needs every value above 0 (the smallest is " +
                                std::to_string(lo) + ")");
  axis.title = std::move(title);
  if (axis.log) {
    axis.min = lo / 1.6;
    axis.max = hi * 1.6;
    axis.title += ", log scale";
  } else {
    std::tie(axis.max, axis.ticks) = niceAxisRange(hi * (1.0 + margin));
  }
  return axis;
}

ChartAxis planCostAxis(ChartX x, std::span<const double> values) {
  if (x == ChartX::TimeMs)
    return planChartAxis(values, AxisScale::Linear, 0.0, 0.08,
                         "frame time, all passes (ms, median)");
  double hi = 0.0;
  for (double v : values)
    if (std::isfinite(v)) hi = std::max(hi, v);
  const ByteUnit unit = byteUnitFor(hi);
  std::vector<double> scaled;
  for (double v : values) scaled.push_back(v / unit.bytes);
  ChartAxis axis = planChartAxis(scaled, AxisScale::Auto, 8.0, 0.08,
                                 std::string("shadow memory (") + unit.name + ")");
  axis.unitScale = unit.bytes;
  axis.logBase = 2.0;
  axis.minorTicks = 0;
  return axis;
}

std::array<std::uint8_t, 3> chartColorRgb(std::size_t i) {
  static constexpr std::array<std::uint8_t, 3> kPalette[] = {
      {0, 114, 178},
      {213, 94, 0},
      {0, 158, 115},
      {204, 121, 167},
      {230, 159, 0},
      {86, 180, 233},
      {120, 120, 120},
      {240, 228, 66},
      // Beyond Okabe-Ito's 8: psm/lispsm/tsm and cascades made more than 8 techniques.
      {120, 70, 180},
      {165, 42, 42},
      {100, 130, 20}};
  return kPalette[i % (sizeof kPalette / sizeof kPalette[0])];
}

}  // namespace sl
