// The numbers a lesson text quotes ("{error_pct}", "{pca.anisotropy}", "{compare.error_pct}",
// algo/TextTemplate.h), looked up in what one frame measured and published: the same numbers
// the view's caption and the panels show, so a text is right at any window size and after any
// interaction.
#pragma once

#include <optional>
#include <set>
#include <string>

#include "algo/TextTemplate.h"

namespace sl {

struct Publication;

/// One side of the view (the main view, or the split view's right half) after a frame.
struct LiveSide {
  /// The error measured against the reference for this frame, in % of covered pixels;
  /// nothing when it was not measured (failed frame, no covered pixel, not yet traced).
  std::optional<double> errorPct;
  std::optional<double> frameMs;             ///< the frame's time; nothing for a failed frame
  std::optional<double> memoryMB;            ///< the technique's memory() in MiB
  const Publication* publication = nullptr;  ///< the frame's publication (null: none)
};

/// Keys every side has without asking the technique (the rest are publications).
inline constexpr const char* kLiveErrorKey = "error_pct";
inline constexpr const char* kLiveFrameKey = "frame_ms";
inline constexpr const char* kLiveMemoryKey = "memory_mb";

/// The value of `p` on `main` or, for "{compare.…}", on `compare` (null: no right half):
/// the three keys above, else the publication's number `key`, or element `index` of its curve
/// `key`. Nothing when the frame has no such value.
std::optional<double> liveValue(const TextPlaceholder& p, const LiveSide& main,
                                const LiveSide* compare);

/// The publication keys the placeholders of `text` need from one side (compare: the right
/// half's), to request them from the renderer; the built-in keys are left out. A text that
/// does not parse needs nothing (presets are checked at load).
std::set<std::string> livePublicationKeys(const std::string& text, bool compare);

/// `text` with its placeholders filled (a text that does not parse is returned as it is).
std::string fillLiveText(const std::string& text, const LiveSide& main, const LiveSide* compare);

}  // namespace sl
