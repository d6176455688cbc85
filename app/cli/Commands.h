// The shadowlab-cli commands that live in their own files (main.cpp dispatches).
#pragma once

#include <vector>

#include "CliCommon.h"
#include "algo/partition/StorageFactor.h"

namespace sl::cli {

/// `bench`: sweeps configurations along a camera path -> CSV (+ chart). Bench.cpp.
int cmdBench(Args& args);
/// `stability`: one technique frame by frame (JSON), or a suite of cases with
/// expectations (exit 1 when one fails). Stability.cpp.
int cmdStability(Args& args);
/// `chart`: the chart again from a bench CSV, x = time or memory (`--x`). Bench.cpp.
int cmdChart(Args& args);

/// `storage`: the storage factor of warped and partitioned shadow maps (Lloyd et al. 2006):
/// S, M_x, M_z for one light, the paper's Figs. 6 and 7 as PNG and CSV. Storage.cpp.
int cmdStorage(Args& args);

/// The numbers `storage ARGS` prints, for the same arguments (no --csv, --out): the scheme's
/// storage and its k + 1 split distances (--split over --near..--far, k = --partitions).
/// UsageError as `storage` gives it. Storage.cpp.
struct StorageQuery {
  partition::StorageResult result;
  std::vector<double> splits;
};
StorageQuery storageQuery(const std::vector<std::string>& args);

/// `reproduce`: every claim of the papers (scenes/claims/*.json) measured, one verdict each,
/// DIR/REPORT.md with figures. Reproduce.cpp.
int cmdReproduce(Args& args);

extern const char* const kBenchUsage;
extern const char* const kReproduceUsage;
extern const char* const kStorageUsage;
extern const char* const kStabilityUsage;
extern const char* const kChartUsage;

}  // namespace sl::cli
