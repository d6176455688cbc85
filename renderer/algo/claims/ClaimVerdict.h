// Judging a paper's claim from a measurement (`shadowlab-cli reproduce`, docs/papers/): the
// claim's threshold as a predicate, a paired bootstrap interval of a comparison measured frame
// by frame, and the verdict the interval gives. Plain C++: no GL, no Qt.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace sl::claims {

/// The largest relative tolerance of "within" (exclusive): within 100 % of a value admits 0 and
/// twice the value, which no claim means ("within-factor" says "within k times").
inline constexpr double kMaxWithinTolerance = 1.0;

/// A claim's predicate on the measured value: "<=", ">=", "<", ">" against `value`;
/// "within": |measured / value − 1| <= tolerance; "within-factor": value / factor <= measured
/// <= value · factor (two-sided: "within 2x" of the paper's number).
struct Predicate {
  std::string op;
  double value = 0.0;
  double tolerance = 0.0;  ///< within: relative; within-factor: the factor k > 1
  bool holds(double measured) const;
  /// Where `measured` lies: 0 inside the accepted set, −1 below it, +1 above it.
  int side(double measured) const;
  /// The direction the predicate asks for: −1 for "<", "<=", +1 for ">", ">=", 0 two-sided.
  int direction() const;
  std::string text() const;  ///< "<= 1", "within 0.1 % of 85.74", "within 2x of 1"
};

/// The five verdicts: the interval inside the accepted set, partly (an effect in the paper's
/// direction smaller than the paper's), outside on the other side, straddling a bound, and a
/// value this machine could not measure.
enum class Verdict { Reproduced, Partly, NotReproduced, Inconclusive, NotTestable };
const char* verdictName(Verdict v);  ///< "reproduced", ..., "not testable here"

/// A value with its 95 % interval (low == high == value for an exact measurement).
struct Interval {
  double value = 0.0, low = 0.0, high = 0.0;
  int pairs = 0;  ///< the frames (pairs) it was computed over; 0 for an exact value
};

/// The verdict an interval gives: reproduced when it lies inside `expect`, inconclusive when it
/// straddles a bound of it; outside it, partly when it lies inside `partly` (and inconclusive
/// when it straddles partly's bound), else not reproduced. Not testable when a bound is NaN.
Verdict judge(const Predicate& expect, const std::optional<Predicate>& partly,
              const Interval& interval);

/// How two paired series combine into one value.
enum class Combine {
  Ratio,       ///< Σa / Σb (the ratio of the means)
  Difference,  ///< mean(a) − mean(b)
  A,           ///< mean(a) alone (b is ignored)
};

inline constexpr int kBootstrapResamples = 2000;
inline constexpr std::uint64_t kBootstrapSeed = 0x5eed2014u;
inline constexpr double kBootstrapConfidence = 0.95;

/// The combined value of a[i], b[i] (frame i of both configurations) and its percentile
/// bootstrap interval: `resamples` draws of the frame indices with replacement, the same
/// indices for a and b (paired), from a fixed seed (deterministic on every platform).
/// a and b have the same size (b may be empty for Combine::A); at least one pair.
Interval pairedBootstrap(std::span<const double> a, std::span<const double> b, Combine combine,
                         int resamples = kBootstrapResamples, std::uint64_t seed = kBootstrapSeed);

}  // namespace sl::claims
