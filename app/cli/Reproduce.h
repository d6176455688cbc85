// `shadowlab-cli reproduce`: the papers' claims as data (scenes/claims/*.json, one file per
// source document), each measured by one of a few kinds implemented here once, on the
// measuring code that `bench` uses (Measure.h), and judged against its threshold. The report
// (REPORT.md) quotes the paper, gives the measurement, the verdict and the commands that
// re-run it.
#pragma once

#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "Measure.h"

namespace sl::cli {

/// The measurement kinds a claim may use.
inline constexpr const char* kMeasurementKinds[] = {"error-compare", "time-ratio", "memory-ratio",
                                                    "publication", "cpu"};

/// The largest relative tolerance of "within" (exclusive): within 100 % of a value admits 0 and
/// twice the value, which no claim means.
inline constexpr double kMaxWithinTolerance = 1.0;

/// A claim's predicate on the measured value: "<=", ">=", "<", ">" against `value`, or
/// "within": |measured / value − 1| <= tolerance.
struct Predicate {
  std::string op;
  double value = 0.0;
  double tolerance = 0.0;
  bool holds(double measured) const;
  std::string text() const;  ///< "<= 1", "within 0.1 % of 85.74"
};

/// Frame size and frames of one run (a claim has one for the full run and one for --quick).
struct RunSize {
  int width = 640, height = 360;
  int frames = 4;
  int warmup = 2;
};

/// How a claim is measured.
///  - error-compare, time-ratio, memory-ratio: the configurations (a, optionally b) render
///    the same frames in one interleaved run; `metric` of each (medians over the frames),
///    combined: a / b (ratio), a − b (difference) or a alone.
///  - publication: one configuration; a number it publishes, over the frames: median, min,
///    max, final, or changes (frames whose value differs from the previous frame's).
///  - cpu: a computation of the CPU reference, no GL: `storage` with storageA's arguments
///    (as `shadowlab-cli storage` takes them), `value` of it (s, mx, mz, imbalance =
///    max(M_x, M_z) / min(M_x, M_z), parts, part_s_spread = largest / smallest part's S, split:I =
///    the I-th split distance), divided by the same value for storageB when given.
struct Measurement {
  std::string kind;
  std::string scene, camera, path, lightText;
  std::optional<Light> light;
  std::vector<ConfigSpec> configs;
  std::string metric, combine;
  std::string number, statistic;
  std::vector<std::string> storageA, storageB;
  std::string value;
  bool figure = false;  ///< cpu: also draw storage's Figs. 6 and 7
  RunSize full, quick;
};

struct Claim {
  std::string file;  ///< the claims file it came from
  std::string id, seed, source;
  std::string words;        ///< the paper's words, quoted
  std::string paperNumber;  ///< the paper's number, as the paper gives it
  std::string note;         ///< which reading of the paper the measurement takes
  Measurement measurement;
  Predicate expect;
  std::optional<Predicate> partly;  ///< holds (and expect does not): "partly"
  /// For a claim not reproduced: the suspected cause changed alone (measured whenever the
  /// verdict is not "reproduced"), and what it is meant to show.
  std::optional<Measurement> mechanism;
  std::string mechanismText;
};

/// Reads one claims file: {"seed", "source", "sizes"?, "claims": [...]}. Bad input throws
/// UsageError naming the file and the JSON path ("000.json: /claims/3/expect/op: ...").
std::vector<Claim> loadClaims(const std::filesystem::path& file);
/// Every *.json in `folder`, in name order; an id used twice is an error.
std::vector<Claim> loadClaimFolder(const std::filesystem::path& folder);

struct MeasuredValue {
  bool measured = false;
  double value = std::numeric_limits<double>::quiet_NaN();
  std::string text;  ///< what was measured, with the parts of the value
  std::string why;   ///< not measured: why (a failed frame, a number never published)
  std::vector<std::string> figures;  ///< PNGs, relative to the output folder
};

struct ClaimOutcome {
  std::string verdict;  ///< "reproduced", "partly", "not reproduced" or "not measured"
  MeasuredValue main;
  std::optional<MeasuredValue> mechanism;
  std::vector<std::string> commands;  ///< the commands that re-run it
  double seconds = 0.0;
};

/// The verdict the value gives: not measured, else reproduced when expect holds, partly when
/// only `partly` holds, else not reproduced.
std::string verdictFor(const Claim& claim, const MeasuredValue& value);
/// The commands that re-run the claim: `bench`, `render` or `storage` with the claim's
/// configurations, and `reproduce --claim ID`.
std::vector<std::string> rerunCommands(const Claim& claim, bool quick);
/// Measures a claim; the rendered kinds need a current GL context. Figures go to
/// outDir/figures/.
ClaimOutcome runClaim(const Claim& claim, bool quick, const std::filesystem::path& outDir);
/// REPORT.md: a summary table, then per claim the words, number, measurement, verdict and
/// commands.
std::string reportMarkdown(const std::vector<Claim>& claims,
                           const std::vector<ClaimOutcome>& outcomes, bool quick,
                           const std::string& glDescription, double seconds);

}  // namespace sl::cli
