// libFuzzer target: the bench CSV reader of `shadowlab-cli chart` (readChartCsv), charting
// against time and against memory. It must read or refuse with one bounded line naming the
// file; any other exception, a crash or a leak is a finding.
#include "ChartCsv.h"
#include "CliCommon.h"
#include "FuzzInput.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path path = sl::fuzz::writeInput(data, size, "bench.csv");
  for (sl::ChartX x : {sl::ChartX::TimeMs, sl::ChartX::Bytes}) {
    try {
      (void)sl::cli::readChartCsv(path.string(), x);
    } catch (const sl::cli::UsageError& e) {
      sl::fuzz::checkMessage(e.what(), path.string());
    }
  }
  return 0;
}
