// libFuzzer target: the JSON readers of user files, a preset (loadPreset, as the GUI and
// `render --preset` read it) and a suite (checkSuiteFile: everything `stability --suite`
// checks before it runs a case), both on the same bytes. Each must accept or refuse with one
// bounded line naming the file; any other exception, a crash or a leak is a finding.
#include "FuzzInput.h"
#include "StabilityRun.h"
#include "core/Preset.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path path = sl::fuzz::writeInput(data, size, "input.json");
  std::string error;
  if (!sl::loadPreset(path, &error)) sl::fuzz::checkMessage(error, path.string() + ": ");
  try {
    (void)sl::cli::checkSuiteFile(path.string());
  } catch (const sl::cli::UsageError& e) {
    sl::fuzz::checkMessage(e.what(), path.string() + ": ");
  }
  return 0;
}
