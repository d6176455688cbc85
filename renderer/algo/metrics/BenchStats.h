// Statistics for benchmarks and stability runs (techniques.md, "Measuring"): medians and
// percentiles over frames, perspective-aliasing summaries over pixels, mask changes and
// false flicker between consecutive frames, the Pareto front of cost (time or memory)
// against error, and the axes of the charts that show it.
// Plain C++ on spans: no GL, no Qt; the CLI, the GUI and the tests share it.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/shared_constants.h"

namespace sl {

/// Mask encoding of the renderer's hard mask and the Embree reference (the same values as
/// metrics/ErrorMetrics.h): 1 lit, 0 shadowed, 255 not covered; any other value is lit.
inline constexpr std::uint8_t kStatsMaskShadowed = SL_MASK_SHADOWED;
inline constexpr std::uint8_t kStatsMaskUncovered = SL_MASK_EMPTY;

/// Percentile p in [0, 100] with linear interpolation between closest ranks (the
/// "type 7" rule of R and numpy's default): sorted v, rank h = (n - 1) * p / 100,
/// v[floor h] + (h - floor h) * (v[floor h + 1] - v[floor h]). Non-finite values are
/// ignored; no finite value: 0. p outside [0, 100] is clamped.
double percentile(std::span<const double> values, double p);
double percentile(std::span<const float> values, double p);
/// The 50th percentile (mean of the two middle values for an even count).
double median(std::span<const double> values);

/// Perspective aliasing m over the covered pixels of one frame (m: shadow-map texel
/// footprint over pixel footprint; m > 1 undersampled).
struct AliasingStats {
  std::size_t pixels = 0;     ///< covered pixels with a finite m > 0 (the ones summarised)
  std::size_t nonFinite = 0;  ///< covered pixels with m NaN or infinite (left out)
  double mean = 0.0;
  double p95 = 0.0;  ///< 95th percentile (percentile() rule)
  double max = 0.0;
};
/// `aliasing[i]` is m of pixel i; `hardMask[i] == kStatsMaskUncovered` marks pixels with no
/// surface (left out), as do covered pixels with m <= 0 (no shadow-map coordinate).
/// An empty `hardMask` means every pixel with m > 0 is covered. Throws
/// std::invalid_argument when a non-empty mask's size differs from aliasing's.
AliasingStats computeAliasingStats(std::span<const float> aliasing,
                                   std::span<const std::uint8_t> hardMask);

/// A histogram of log2 m (the renderer's GPU aliasing statistics, common/aliasing_stats.comp,
/// and its CPU mirror): `binsPerOctave` bins per octave from 2^log2Min up; values below or
/// above the range fall in the first or last bin.
struct Log2Histogram {
  double log2Min = SL_ALIASING_LOG2_MIN;
  int binsPerOctave = SL_ALIASING_BINS_PER_OCTAVE;
  std::vector<std::uint64_t> counts = std::vector<std::uint64_t>(SL_ALIASING_BINS, 0);

  std::uint64_t total() const;
  std::size_t binOf(double m) const;  ///< m > 0
  /// The geometric centre of a bin: 2^(log2Min + (bin + 1/2) / binsPerOctave).
  double binCentre(std::size_t bin) const;
  /// The bin width in octaves (the precision of a percentile: see histogramPercentile).
  double binOctaves() const { return 1.0 / binsPerOctave; }
};
/// The histogram of the finite m > 0 of `aliasing` where `hardMask` is covered (the pixels
/// computeAliasingStats summarises).
Log2Histogram aliasingHistogram(std::span<const float> aliasing,
                                std::span<const std::uint8_t> hardMask);
/// Percentile p in [0, 100] of the histogram's values by percentile()'s rank rule, each rank's
/// value taken as its bin's centre, at most `maxValue` (the exact maximum). Within half a bin
/// (a factor 2^(1/(2 binsPerOctave))) of percentile() over the values when they lie inside the
/// histogram's range. 0 for an empty histogram.
double histogramPercentile(const Log2Histogram& histogram, double p, double maxValue);

/// Change of a technique's hard mask between two consecutive frames.
struct MaskChange {
  std::size_t compared = 0;  ///< pixels covered in both frames
  std::size_t changed = 0;   ///< of which lit in one frame and shadowed in the other
  double pct = 0.0;          ///< 100 * changed / compared (0 when nothing compared)
};
/// Throws std::invalid_argument when the sizes differ.
MaskChange compareConsecutiveMasks(std::span<const std::uint8_t> previous,
                                   std::span<const std::uint8_t> current);

/// False flicker between consecutive frames: pixels whose technique state flips while
/// the reference's does not.
struct FlickerStats {
  std::size_t compared = 0;   ///< pixels covered in all four masks
  std::size_t flicker = 0;    ///< technique flips, reference does not
  std::size_t trueFlips = 0;  ///< technique and reference both flip (real motion)
  double pct = 0.0;           ///< 100 * flicker / compared (0 when nothing compared)
};
/// Throws std::invalid_argument when the four sizes differ.
FlickerStats computeFlicker(std::span<const std::uint8_t> previousMask,
                            std::span<const std::uint8_t> currentMask,
                            std::span<const std::uint8_t> previousReference,
                            std::span<const std::uint8_t> currentReference);

/// A configuration's place on the cost-accuracy plane (both: lower is better).
struct CostPoint {
  double cost = 0.0;      ///< x: time per frame (ms) or shadow memory (bytes), see ChartX
  double errorPct = 0.0;  ///< y: error
};
/// Indices of the Pareto-optimal points (lower-left front): no other point costs at most as
/// much and is at most as wrong and strictly better in one of the two. Sorted by cost, then
/// error, then index; exact duplicates are all on the front; non-finite points never are.
std::vector<std::size_t> paretoFront(std::span<const CostPoint> points);

/// Cost-against-accuracy charts (CLI PNG and the GUI's Charts dock) share these.
/// What x is: the whole frame's time, or the technique's shadow memory (MemoryStats::bytes).
enum class ChartX { TimeMs, Bytes };
/// "ms" or "bytes" (the CLI's `--x`); nullopt for anything else.
std::optional<ChartX> parseChartX(std::string_view text);
/// "Speed against accuracy" / "Memory against accuracy".
const char* chartHeadline(ChartX x);

/// Upper end of an axis that starts at 0, and its tick count: a round step (1, 2 or 5
/// times a power of ten) giving 4 to 10 intervals that reach v. {1, 5} when v <= 0.
std::pair<double, int> niceAxisRange(double v);

/// A readable binary unit for byte counts up to `maxBytes`: the largest of bytes, KiB, MiB,
/// GiB in which maxBytes is at least 1 ({"bytes", 1} for maxBytes < 1024 or not finite).
struct ByteUnit {
  const char* name = "bytes";
  double bytes = 1.0;  ///< bytes per unit
};
ByteUnit byteUnitFor(double maxBytes);

/// One chart axis, decided from the values it shows; the Qt code only applies it.
/// Positions on the axis are value / unitScale.
struct ChartAxis {
  bool log = false;
  double logBase = 10.0;        ///< labels at the powers of this base (log axes)
  int minorTicks = 8;           ///< minor ticks between labels (log axes: 2..9 x 10^k)
  double min = 0.0, max = 1.0;  ///< range, in axis units
  int ticks = 5;                ///< tick count (linear axes)
  double unitScale = 1.0;       ///< data units per axis unit (e.g. 1048576 for MiB)
  std::string title;            ///< axis title, ", log scale" added when log
};
enum class AxisScale { Auto, Linear, Log };
/// Axis over the finite `values` (already in axis units): linear from 0 to
/// niceAxisRange(max * (1 + margin)); log (base 10) from min / 1.6 to max * 1.6. Auto is log
/// when every finite value is above 0 and max / min exceeds `logAboveRatio`. Log with a
/// finite value <= 0 throws std::invalid_argument naming the smallest value.
ChartAxis planChartAxis(std::span<const double> values, AxisScale scale, double logAboveRatio,
                        double margin, std::string title);
/// The x axis for costs of kind `x` (ms or bytes, as measured): time linear from 0; memory
/// in byteUnitFor(largest), log base 2 when the values span more than 8x.
ChartAxis planCostAxis(ChartX x, std::span<const double> values);

/// Colour of the i-th technique (the Okabe-Ito palette and 3 more, repeating), 8-bit RGB.
std::array<std::uint8_t, 3> chartColorRgb(std::size_t i);

}  // namespace sl
