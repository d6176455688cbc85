// Golden-image comparison: tolerance check, candidate + diff files on failure, blessing.
#include "metrics/GoldenImage.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string_view>

namespace sl {

namespace {

std::string percent(double fraction) {
  std::ostringstream s;
  s.precision(4);
  s << 100.0 * fraction << "%";
  return s.str();
}

}  // namespace

bool goldenUpdateRequested(const char* environmentValue) {
  return environmentValue && std::string_view(environmentValue) == "1";
}

ImageRGBA8 makeGoldenDiffImage(const ImageRGBA8& candidate, const ImageRGBA8& golden,
                               int maxChannelDiff, std::size_t* failing, int* maxDiff) {
  ImageRGBA8 diff = makeImage(candidate.width, candidate.height);
  std::size_t failCount = 0;
  int worst = 0;
  const bool goldenValid = golden.valid();
  for (int y = 0; y < candidate.height; ++y) {
    for (int x = 0; x < candidate.width; ++x) {
      const std::uint8_t* c = candidate.pixel(x, y);
      bool fails = true;
      if (goldenValid && x < golden.width && y < golden.height) {
        const std::uint8_t* g = golden.pixel(x, y);
        int d = 0;
        for (int i = 0; i < 4; ++i) d = std::max(d, std::abs(int(c[i]) - int(g[i])));
        worst = std::max(worst, d);
        fails = d > maxChannelDiff;
      }
      std::uint8_t* o = diff.pixel(x, y);
      if (fails) {
        ++failCount;
        o[0] = 255, o[1] = 0, o[2] = 0, o[3] = 255;
      } else {
        const float luma = 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2];
        const auto grey = static_cast<std::uint8_t>(std::lround(0.3f * luma));
        o[0] = o[1] = o[2] = grey, o[3] = 255;
      }
    }
  }
  if (failing) *failing = failCount;
  if (maxDiff) *maxDiff = worst;
  return diff;
}

GoldenResult compareToGolden(const ImageRGBA8& candidate, const std::filesystem::path& golden,
                             GoldenTolerance tolerance, const std::filesystem::path& outDir,
                             const std::string& name, std::optional<bool> update) {
  GoldenResult r;
  if (!candidate.valid()) {
    r.failingFraction = 1.0;
    r.message = name + ": the candidate image is empty or invalid (" +
                std::to_string(candidate.width) + "x" + std::to_string(candidate.height) + ")";
    return r;
  }

  // Compare (when there is a golden to compare with).
  std::string readError;
  std::optional<ImageRGBA8> gold;
  std::error_code ec;
  const bool goldenExists = std::filesystem::exists(golden, ec);
  if (goldenExists) gold = readImage(golden, &readError);
  std::string problem;
  std::size_t failing = candidate.pixelCount();
  ImageRGBA8 diff;
  if (!goldenExists) {
    problem = "no golden image at " + golden.string();
  } else if (!gold) {
    problem = readError;
  } else {
    diff = makeGoldenDiffImage(candidate, *gold, tolerance.maxChannelDiff, &failing, &r.maxDiff);
    if (gold->width != candidate.width || gold->height != candidate.height)
      problem = "size mismatch: candidate " + std::to_string(candidate.width) + "x" +
                std::to_string(candidate.height) + ", golden " + std::to_string(gold->width) + "x" +
                std::to_string(gold->height) + " (" + golden.string() + ")";
  }
  r.failingFraction = double(failing) / double(candidate.pixelCount());
  const std::string counts = percent(r.failingFraction) + " of pixels differ by more than " +
                             std::to_string(tolerance.maxChannelDiff) + " (allowed " +
                             percent(tolerance.maxFailingFraction) + "), max channel diff " +
                             std::to_string(r.maxDiff);
  if (problem.empty() && r.failingFraction <= tolerance.maxFailingFraction) {
    r.pass = true;
    r.message = name + ": matches " + golden.string() + " (" + counts + ")";
    return r;
  }
  if (problem.empty()) problem = counts + "; golden " + golden.string();

  // Bless: replace the golden with the candidate.
  if (update.value_or(goldenUpdateRequested(std::getenv("SHADOWLAB_UPDATE_GOLDEN")))) {
    if (auto err = writeImage(golden, candidate)) {
      r.message = name + ": SHADOWLAB_UPDATE_GOLDEN=1 but " + *err + " (" + problem + ")";
      return r;
    }
    r.pass = true;
    r.message = name + ": golden updated (SHADOWLAB_UPDATE_GOLDEN=1): wrote the candidate to " +
                golden.string() + " (was: " + problem + ")";
    return r;
  }

  // Fail: leave the evidence next to the test output.
  if (!diff.valid()) diff = makeGoldenDiffImage(candidate, ImageRGBA8{}, tolerance.maxChannelDiff);
  const std::filesystem::path candidatePath = outDir / (name + ".candidate.png");
  const std::filesystem::path diffPath = outDir / (name + ".diff.png");
  std::string files;
  if (auto err = writeImage(candidatePath, candidate))
    files += " " + *err + ".";
  else
    files += " Candidate: " + candidatePath.string() + ".";
  if (auto err = writeImage(diffPath, diff))
    files += " " + *err + ".";
  else
    files += " Diff (failing pixels red): " + diffPath.string() + ".";
  r.message = name + ": FAILED: " + problem + "." + files +
              " If the candidate is right, bless it by rerunning with SHADOWLAB_UPDATE_GOLDEN=1"
              " (or copy the candidate to " +
              golden.string() + ").";
  return r;
}

}  // namespace sl
