// Judging a claim from a measurement: see ClaimVerdict.h.
#include "algo/claims/ClaimVerdict.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <vector>

namespace sl::claims {

namespace {

std::string num(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

/// splitmix64: a small generator whose sequence is the same on every platform (the standard
/// distributions are not).
std::uint64_t nextRandom(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15u);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
  return z ^ (z >> 31);
}

/// The q-quantile of sorted values, interpolated between neighbours.
double quantile(const std::vector<double>& sorted, double q) {
  const double pos = q * double(sorted.size() - 1);
  const std::size_t i = std::size_t(std::floor(pos));
  if (i + 1 >= sorted.size()) return sorted.back();
  const double t = pos - double(i);
  if (t == 0.0) return sorted[i];
  return sorted[i] + t * (sorted[i + 1] - sorted[i]);
}

}  // namespace

bool Predicate::holds(double measured) const {
  return std::isfinite(measured) && side(measured) == 0;
}

int Predicate::side(double measured) const {
  if (op == "<=") return measured <= value ? 0 : 1;
  if (op == "<") return measured < value ? 0 : 1;
  if (op == ">=") return measured >= value ? 0 : -1;
  if (op == ">") return measured > value ? 0 : -1;
  double lo = value * (1.0 - tolerance), hi = value * (1.0 + tolerance);
  if (op == "within-factor") lo = value / tolerance, hi = value * tolerance;
  if (lo > hi) std::swap(lo, hi);
  return measured < lo ? -1 : measured > hi ? 1 : 0;
}

int Predicate::direction() const {
  if (op == "<=" || op == "<") return -1;
  if (op == ">=" || op == ">") return 1;
  return 0;
}

std::string Predicate::text() const {
  if (op == "within") return "within " + num(100.0 * tolerance) + " % of " + num(value);
  if (op == "within-factor") return "within " + num(tolerance) + "x of " + num(value);
  return op + " " + num(value);
}

const char* verdictName(Verdict v) {
  switch (v) {
    case Verdict::Reproduced:
      return "reproduced";
    case Verdict::Partly:
      return "partly";
    case Verdict::NotReproduced:
      return "not reproduced";
    case Verdict::Inconclusive:
      return "inconclusive";
    case Verdict::NotTestable:
      return "not testable here";
  }
  return "?";
}

Verdict judge(const Predicate& expect, const std::optional<Predicate>& partly,
              const Interval& interval) {
  if (std::isnan(interval.low) || std::isnan(interval.high)) return Verdict::NotTestable;
  const int low = expect.side(interval.low), high = expect.side(interval.high);
  if (low == 0 && high == 0) return Verdict::Reproduced;
  if (low != high) return Verdict::Inconclusive;  // a bound of expect inside the interval
  if (partly) {
    const int pLow = partly->side(interval.low), pHigh = partly->side(interval.high);
    if (pLow == 0 && pHigh == 0) return Verdict::Partly;
    if (pLow != pHigh) return Verdict::Inconclusive;
  }
  return Verdict::NotReproduced;
}

Interval pairedBootstrap(std::span<const double> a, std::span<const double> b, Combine combine,
                         int resamples, std::uint64_t seed) {
  const bool paired = combine != Combine::A;
  if (a.empty() || (paired && b.size() != a.size()) || resamples < 1)
    throw std::invalid_argument("pairedBootstrap: a and b need the same, non-zero length");
  const std::size_t n = a.size();
  auto combined = [&](const auto& index) {
    double sa = 0.0, sb = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      sa += a[index(k)];
      if (paired) sb += b[index(k)];
    }
    if (combine == Combine::Ratio) return sa / sb;
    if (combine == Combine::Difference) return (sa - sb) / double(n);
    return sa / double(n);
  };
  Interval out;
  out.pairs = int(n);
  out.value = combined([](std::size_t k) { return k; });
  std::vector<double> draws(static_cast<std::size_t>(resamples));
  std::vector<std::size_t> picks(n);
  std::uint64_t state = seed;
  for (double& d : draws) {
    for (std::size_t& p : picks) p = std::size_t(nextRandom(state) % n);
    d = combined([&](std::size_t k) { return picks[k]; });
  }
  // A draw of 0 / 0 (every picked b and a zero) says nothing about the ratio: left out.
  std::erase_if(draws, [](double d) { return std::isnan(d); });
  if (draws.empty()) {
    out.low = out.high = std::numeric_limits<double>::quiet_NaN();
    return out;
  }
  std::sort(draws.begin(), draws.end());
  const double tail = (1.0 - kBootstrapConfidence) / 2.0;
  out.low = quantile(draws, tail);
  out.high = quantile(draws, 1.0 - tail);
  return out;
}

}  // namespace sl::claims
