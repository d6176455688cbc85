// Reading a bench CSV for `shadowlab-cli chart` within limits (issue 14): only a regular
// file, bounded in bytes, line length, rows and parameters, each refusal one line naming
// the file, the line and the limit. Separate from Bench.cpp (GL-free) so the fuzz target
// tests/fuzz/fuzz_chart_csv.cpp reads CSVs exactly as the command does.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "Chart.h"

namespace sl::cli {

/// Limits on a CSV read by `chart` (bench writes a few KiB).
inline constexpr std::uint64_t kMaxCsvBytes = std::uint64_t(64) << 20;
inline constexpr std::size_t kMaxCsvLineBytes = std::size_t(1) << 20;
inline constexpr std::size_t kMaxCsvRows = 100000;
inline constexpr std::size_t kMaxCsvParamsBytes = 4096;  ///< the params (and technique) cell
inline constexpr std::size_t kMaxCsvParams = 64;         ///< KEY=VALUE pairs in one params cell

/// One configuration's place on the chart (from a bench run or its CSV).
struct ChartRow {
  std::string technique;
  std::vector<std::pair<std::string, std::string>> params;
  double totalMs = 0, bytes = 0, errorPct = 0;
};

/// The rows of a bench CSV and the chart's titles (spec.x = `x`; title and subtitle from the
/// first row).
struct ChartCsv {
  std::vector<ChartRow> rows;  ///< never empty
  ChartSpec spec;
};

/// Fields of one CSV line (RFC 4180 quoting; no newlines inside fields).
std::vector<std::string> splitCsvLine(const std::string& line);

/// Reads `csvPath`, charting against `x`. Throws UsageError naming the file (and line) on
/// anything it cannot chart.
ChartCsv readChartCsv(const std::string& csvPath, sl::ChartX x);

}  // namespace sl::cli
