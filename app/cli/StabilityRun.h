// What both stability runs share (one technique, or a suite of cases): running
// configurations frame by frame and writing their records and summaries (the records, the
// summary and its metric names: measure/Stability.h). See Stability.cpp and Suite.cpp.
#pragma once

#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "CliCommon.h"
#include "measure/Measure.h"
#include "measure/Stability.h"

namespace sl::cli {

/// The largest orbit a frame (degrees, either way): `stability --orbit` and a suite's
/// `orbit_deg_per_frame`. A larger step is the same view as a smaller one the other way.
inline constexpr double kMaxOrbitDegPerFrame = 180.0;

/// "%.6g".
std::string fmt(double v);

nlohmann::json summaryJson(const StabilitySummary& s);
nlohmann::json frameJson(std::size_t k, const StabilityFrame& fr);

/// Runs `runners` over `cameras`, interleaved frame by frame; right before its frame f each
/// renders `between[f]` unmeasured (a path's in-between frames, MeasureCameras; none when
/// `between` is shorter).
std::vector<std::vector<StabilityFrame>> runFrames(
    std::vector<std::unique_ptr<ConfigRunner>>& runners, const std::vector<Camera>& cameras,
    const MeasureOptions& opts, ReferenceCache* reference, ProgressBar& progress,
    const std::vector<std::vector<Camera>>& between = {});

/// `stability --suite`: runs the suite file's cases, prints the tables and expectations,
/// writes `jsonPath` (when not empty); 1 when an expectation fails. Suite.cpp.
int runSuite(const std::string& file, double framesScale,
             const std::optional<std::pair<int, int>>& sizeOverride,
             const std::vector<std::string>& onlyCases,
             const std::vector<std::string>& onlyTechniques, const std::string& jsonPath);

/// Reads and checks a suite file as runSuite does before any case runs (keys, techniques,
/// parameters, expectations, scene names; not the frame sizes, which need a GL context).
/// Returns the number of cases; throws UsageError naming the file and the JSON path. Needs
/// no GL: the fuzz target tests/fuzz/fuzz_json.cpp calls it. Suite.cpp.
std::size_t checkSuiteFile(const std::string& file);

}  // namespace sl::cli
