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

#include "CliCommon.h"
#include "measure/Measure.h"
#include "algo/claims/ClaimVerdict.h"

namespace sl::cli {

/// The measurement kinds a claim may use.
inline constexpr const char* kMeasurementKinds[] = {"error-compare", "time-ratio", "memory-ratio",
                                                    "publication", "cpu"};

/// A claim's predicate on the measured value (algo/claims/ClaimVerdict.h).
using Predicate = claims::Predicate;

/// Who makes a claim: "seed" (a source document says it; quoted verbatim), "tool"
/// (ShadowLab's own reading or design) or "check" (an implementation check that holds by
/// construction or arithmetic). The report's headline counts seed claims only.
inline constexpr const char* kClaimKinds[] = {"seed", "tool", "check"};

/// The fewest frames a full run compares errors over (paired frame by frame), and the fewest
/// interleaved repetitions a full run compares timings over; --quick may use fewer, and its
/// verdicts are then indicative only.
inline constexpr int kMinErrorFrames = 20;
inline constexpr int kMinTimingRepetitions = 3;

/// Along a camera path a full run renders bench's frames in between (kDefaultPathHz); a
/// --quick run the measured frames only (0), or its ~300 frames a configuration would make
/// the quick run of every claim take many times the few minutes it is for.
inline constexpr double kQuickPathHz = 0.0;

/// Frame size and frames of one run (a claim has one for the full run and one for --quick).
struct RunSize {
  int width = 640, height = 360;
  int frames = kMinErrorFrames;
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
  std::string kind;         ///< seed, tool or check (kClaimKinds)
  std::string quote;        ///< the seed's own words, verbatim ("[...]" marks a gap)
  std::string translation;  ///< the quote in English, when the seed is not
  std::string statement;    ///< a tool or check claim in ShadowLab's words
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
  /// The value's 95 % paired bootstrap interval over the frames (low == high == value for an
  /// exact measurement: cpu, memory, a published count).
  claims::Interval interval;
  std::string text;  ///< what was measured, with the parts of the value
  std::string why;   ///< not measured: why (a failed frame, a number never published)
  std::vector<std::string> figures;  ///< PNGs, relative to the output folder
};

struct ClaimOutcome {
  std::string verdict;      ///< claims::verdictName: reproduced, ..., not testable here
  bool indicative = false;  ///< measured by --quick: fewer frames than a verdict needs
  MeasuredValue main;
  std::optional<MeasuredValue> mechanism;
  std::vector<std::string> commands;  ///< the commands that re-run it
  double seconds = 0.0;
};

/// The verdict the value's interval gives (claims::judge): not testable here when nothing
/// was measured.
std::string verdictFor(const Claim& claim, const MeasuredValue& value);
/// The commands that re-run the claim: `bench`, `render` or `storage` with the claim's
/// configurations, and `reproduce --claim ID`.
std::vector<std::string> rerunCommands(const Claim& claim, bool quick);
/// Measures a claim; the rendered kinds need a current GL context. Figures go to
/// outDir/figures/.
ClaimOutcome runClaim(const Claim& claim, bool quick, const std::filesystem::path& outDir);
/// REPORT.md: the seed claims' verdicts per seed, a table each for the seed, tool and check
/// claims, then per claim the quote (or statement), number, measurement with its interval,
/// verdict and commands, and the threats to validity.
std::string reportMarkdown(const std::vector<Claim>& claims,
                           const std::vector<ClaimOutcome>& outcomes, bool quick,
                           const std::string& glDescription, double seconds);

}  // namespace sl::cli
