// Golden-image comparison for tests, with a stated tolerance (as Filament's maxAbsDiff and
// maxFailingPixelsFraction): on failure the candidate and a diff image are written next
// to the test output so the difference can be seen, and a new golden can be blessed with
// SHADOWLAB_UPDATE_GOLDEN=1.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "metrics/Image.h"

namespace sl {

struct GoldenTolerance {
  int maxChannelDiff = 0;           ///< a pixel fails when any channel (RGBA) differs by more
  double maxFailingFraction = 0.0;  ///< the image passes when failing pixels / all <= this
};

struct GoldenResult {
  bool pass = false;
  double failingFraction = 0.0;  ///< failing pixels / candidate pixels (1 when no golden)
  int maxDiff = 0;               ///< largest channel difference over the compared pixels
  std::string message;           ///< one paragraph for the test log
};

/// Compares `candidate` with the image at `golden`.
/// - Pass: the golden exists, has the same size and at most maxFailingFraction of the
///   pixels differ by more than maxChannelDiff in some channel.
/// - Fail (missing or unreadable golden, size mismatch, too many failing pixels): writes
///   `outDir/name.candidate.png` and `outDir/name.diff.png` (failing pixels bright red over
///   a dim grey copy of the candidate; pixels outside the golden count as failing) and the
///   message says where they are and how to bless the candidate as the new golden.
/// - With `update` (empty: environment variable SHADOWLAB_UPDATE_GOLDEN=1), a comparison
///   that would fail writes the candidate to `golden` instead (creating directories) and
///   passes, the message saying so; a golden that already passes is left untouched (no churn).
GoldenResult compareToGolden(const ImageRGBA8& candidate, const std::filesystem::path& golden,
                             GoldenTolerance tolerance, const std::filesystem::path& outDir,
                             const std::string& name, std::optional<bool> update = std::nullopt);

/// Whether SHADOWLAB_UPDATE_GOLDEN's value (null: unset) asks to bless goldens: exactly "1".
bool goldenUpdateRequested(const char* environmentValue);

/// The diff image used above: a dim grey copy of `candidate` with every pixel that
/// differs from `golden` by more than maxChannelDiff (or lies outside it) in bright red.
/// `failing` and `maxDiff` (optional) receive the failing pixel count and largest diff.
ImageRGBA8 makeGoldenDiffImage(const ImageRGBA8& candidate, const ImageRGBA8& golden,
                               int maxChannelDiff, std::size_t* failing = nullptr,
                               int* maxDiff = nullptr);

}  // namespace sl
