// Reading a bench CSV within limits for `shadowlab-cli chart` (see ChartCsv.h).
#include "ChartCsv.h"

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <string_view>

#include "CliCommon.h"
#include "algo/InputFile.h"
#include "algo/metrics/BenchStats.h"

namespace sl::cli {

std::vector<std::string> splitCsvLine(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    char ch = line[i];
    if (quoted) {
      if (ch == '"' && i + 1 < line.size() && line[i + 1] == '"')
        out.back() += '"', ++i;
      else if (ch == '"')
        quoted = false;
      else
        out.back() += ch;
    } else if (ch == '"') {
      quoted = true;
    } else if (ch == ',') {
      out.emplace_back();
    } else if (ch != '\r') {
      out.back() += ch;
    }
  }
  return out;
}

ChartCsv readChartCsv(const std::string& csvPath, ChartX x) {
  // A bench CSV is a few KiB; everything past the limits below is refused, naming the file,
  // the line and the limit, before it can take unbounded time or memory.
  std::vector<unsigned char> bytes;
  try {
    bytes = readRegularFile(csvPath, kMaxCsvBytes, "kMaxCsvBytes");
  } catch (const InputFileError& e) {
    throw UsageError(csvPath + ": " + e.what());
  }
  const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  std::size_t pos = 0;
  int lineNo = 0;
  std::string line;
  auto at = [&] { return csvPath + ":" + std::to_string(lineNo) + ": "; };
  // The next line into `line` (without its '\n'); false at the end of the file.
  auto nextLine = [&] {
    if (pos >= text.size()) return false;
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    ++lineNo;
    if (end - pos > kMaxCsvLineBytes)
      throw UsageError(at() + "line of " + std::to_string(end - pos) +
                       " bytes, over the limit of " + byteLimitText(kMaxCsvLineBytes) +
                       " (kMaxCsvLineBytes)");
    line.assign(text.substr(pos, end - pos));
    pos = end + 1;
    return true;
  };
  if (!nextLine()) throw UsageError(csvPath + ": empty");
  const std::vector<std::string> header = splitCsvLine(line);
  auto column = [&](const std::string& name) {
    auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end())
      throw UsageError(csvPath + ": no column '" + name + "' (not a bench CSV?)");
    return std::size_t(it - header.begin());
  };
  const std::size_t cTech = column("technique"), cParams = column("params"),
                    cMs = column("total_ms"), cErr = column("error_pct"), cScene = column("scene"),
                    cCamera = column("camera"), cW = column("width"), cH = column("height"),
                    cFrames = column("frames"), cTiming = column("timing_method");
  // Memory is read only when charted (a CSV without it still charts against time).
  const std::size_t cBytes = x == ChartX::Bytes ? column("bytes") : cMs;
  auto gl = std::find(header.begin(), header.end(), "gl");
  // The spacing of the path's frames (bench's column; older CSVs have none: measured frames only).
  auto pathHz = std::find(header.begin(), header.end(), "path_hz");
  // A failed configuration (bench wrote its failure; older CSVs have no such column).
  auto failureColumn = std::find(header.begin(), header.end(), "failure");
  // The pixels the error is over (bench's column; older CSVs have none): 0 is no measurement.
  auto coveredColumn = std::find(header.begin(), header.end(), "covered_pixels");
  std::vector<ChartRow> rows;
  std::vector<std::string> first;
  std::size_t unmeasured = 0;  // rows with an empty error_pct (no covered pixel)
  std::size_t failed = 0;      // rows of a configuration with a failed frame
  std::string failedNames;     // "uniform resolution=512", listed apart (bounded)
  while (nextLine()) {
    if (line.empty() || line == "\r") continue;
    if (rows.size() >= kMaxCsvRows)
      throw UsageError(at() + "more than " + std::to_string(kMaxCsvRows) +
                       " rows: refused (kMaxCsvRows)");
    std::vector<std::string> f = splitCsvLine(line);
    if (f.size() != header.size())
      throw UsageError(at() + std::to_string(f.size()) + " fields, the header has " +
                       std::to_string(header.size()));
    // A configuration that failed frames is not charted: its numbers are not comparable
    // (or there are none: empty cells).
    if ((failureColumn != header.end() &&
         !f[std::size_t(failureColumn - header.begin())].empty()) ||
        f[cMs].empty()) {
      if (++failed <= 3)
        failedNames += (failedNames.empty() ? "" : ", ") + cutText(f[cTech], 40) +
                       (f[cParams].empty() ? "" : " " + cutText(f[cParams], 60));
      continue;
    }
    ChartRow r;
    r.technique = f[cTech];
    if (r.technique.size() > kMaxCsvParamsBytes)
      throw UsageError(at() + "technique of " + std::to_string(r.technique.size()) +
                       " bytes, over the limit of " + std::to_string(kMaxCsvParamsBytes) +
                       " (kMaxCsvParamsBytes)");
    if (f[cParams].size() > kMaxCsvParamsBytes)
      throw UsageError(at() + "params of " + std::to_string(f[cParams].size()) +
                       " bytes, over the limit of " + std::to_string(kMaxCsvParamsBytes) +
                       " (kMaxCsvParamsBytes)");
    std::istringstream ps(f[cParams]);
    for (std::string kv; ps >> kv;) {
      auto eq = kv.find('=');
      if (eq == std::string::npos) continue;
      if (r.params.size() >= kMaxCsvParams)
        throw UsageError(at() + "more than " + std::to_string(kMaxCsvParams) +
                         " parameters in params: refused (kMaxCsvParams)");
      r.params.push_back({kv.substr(0, eq), kv.substr(eq + 1)});
    }
    try {
      // A time, a size and a percentage: out of their ranges they are no measurement (a chart
      // drew them anyway, at a negative time or 150 % error).
      r.totalMs = parseDouble("total_ms", f[cMs], 0, 1e300);
      r.bytes = parseDouble("bytes", f[cBytes], 0, 1e300);
      // An empty error cell, or an error over no covered pixel: nothing was measured; not
      // plotted (never a perfect 0 on the Pareto front).
      const bool noPixel =
          coveredColumn != header.end() &&
          !f[std::size_t(coveredColumn - header.begin())].empty() &&
          parseDouble("covered_pixels", f[std::size_t(coveredColumn - header.begin())], 0, 1e300) ==
              0.0;
      if (f[cErr].empty() || noPixel) {
        ++unmeasured;
        continue;
      }
      r.errorPct = parseDouble("error_pct", f[cErr], 0, 100);
    } catch (const UsageError& e) {
      throw UsageError(at() + e.what());
    }
    if (first.empty()) first = f;  // the titles come from a charted row
    rows.push_back(std::move(r));
  }
  if (rows.empty()) {
    std::string why;
    if (unmeasured) why = std::to_string(unmeasured) + " without a covered pixel";
    if (failed) why += (why.empty() ? "" : ", ") + std::to_string(failed) + " failed";
    throw UsageError(csvPath + (why.empty() ? std::string(": no rows")
                                            : ": no row has a measured error_pct (" + why + ")"));
  }
  if (failed)
    std::fprintf(stderr, "note: %s: %zu failed configuration%s not charted: %s%s\n",
                 csvPath.c_str(), failed, failed == 1 ? "" : "s", failedNames.c_str(),
                 failed > 3 ? ", ..." : "");
  ChartSpec spec;
  spec.x = x;
  spec.title = std::string(chartHeadline(x)) + ": " + first[cScene] + ", " + first[cCamera];
  if (pathHz != header.end() && !first[std::size_t(pathHz - header.begin())].empty())
    spec.title += ", " + cutText(first[std::size_t(pathHz - header.begin())], 20) + " Hz";
  spec.subtitle = first[cW] + "x" + first[cH] + ", " + first[cFrames] +
                  " frames (medians), timing " + first[cTiming] +
                  (gl == header.end() ? "" : ", " + first[std::size_t(gl - header.begin())]);
  return {std::move(rows), std::move(spec)};
}

}  // namespace sl::cli
