// One side of the GUI's view — the main technique, or the split view's right half — as the
// UI thread holds it. No GL and no Qt: the render service's renderer of that side is
// configured from the SideRequest this side hands out with each frame request, and what
// that renderer's last complete frame measured comes back here.
//
// Parameters are edited HERE (panels, presets, lessons, the CLI-like `--set`): the side is
// the document, the render thread's renderer a copy brought up to date with every request.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>

#include "algo/Params.h"
#include "core/FrameStats.h"
#include "core/Renderer.h"

namespace sl {

/// What the render thread applies to a side's renderer before it renders a frame.
struct SideRequest {
  std::string techniqueId;
  ParamSet params;             ///< the technique's own parameters, every value
  bool resetTemporal = false;  ///< forget kept state (DA-RTW's rotation, a progressive resolve)
  std::set<std::string> publications;  ///< patterns to publish (Renderer::requestPublications)
};

/// Brings `dst` to the values of `src` (same declarations), setting only the values that
/// differ, so that `dst`'s revision moves only when something changed. Returns how many
/// values were set.
int syncParams(ParamSet& dst, const ParamSet& src);

class ViewSide {
 public:
  explicit ViewSide(std::string_view techniqueId = Renderer::baselineTechniqueId());

  /// Switches technique (its parameters are kept per technique, as the renderer keeps them).
  /// Unknown id: the error naming the known ones, no change.
  std::optional<std::string> setTechnique(std::string_view id);
  const std::string& techniqueId() const { return techniqueId_; }
  const TechniqueInfo& info() const { return *info_; }

  ParamSet& params() { return paramsOf(techniqueId_); }
  const ParamSet& params() const;
  ParamSet& paramsOf(std::string_view techniqueId);
  /// The shared view and shading parameters this side renders with (the view's, one set for
  /// both halves); set by the view before use.
  void setSharedParams(ParamSet* shared) { shared_ = shared; }
  ParamSet& rendererParams() { return *shared_; }
  const ParamSet& rendererParams() const { return *shared_; }

  /// The next frame starts the technique's kept state afresh.
  void resetTemporalState() {
    resetPending_ = true;
    ++changes_;
  }
  void requestPublications(std::set<std::string> patterns) { publications_ = std::move(patterns); }
  const std::set<std::string>& requestedPublications() const { return publications_; }

  /// Changes with every edit that changes the image: a parameter, the technique, a reset.
  /// Monotonic: a technique switch or reset moves the high half, a parameter edit the low.
  std::uint64_t revision() const { return (changes_ << 32) + params().revision(); }
  /// The request for the next frame (takes a pending reset).
  SideRequest takeRequest();

  /// The last complete frame this side's renderer drew (none yet: hasFrame() false).
  void setFrame(FrameStats stats, Publication publication);
  bool hasFrame() const { return hasFrame_; }
  const FrameStats& stats() const { return stats_; }
  const Publication& publication() const { return publication_; }

  /// The error of the view revision it was measured for: a number, or why it is n/a (never
  /// 0 for "not measured").
  struct Error {
    std::optional<double> pct;
    std::string unmeasured;  ///< why pct is not a number; empty when measured
    std::uint64_t viewRevision = 0;
  };
  void setError(std::optional<double> pct, std::string unmeasured, std::uint64_t viewRevision);
  void clearError() { error_ = {}; }
  /// The error if it was measured for `viewRevision`, else nothing (out of date).
  std::optional<Error> errorFor(std::uint64_t viewRevision) const;

  /// The values that differ from the technique's defaults, as "key=value" (figures, labels).
  std::string nonDefaultParams() const;

 private:
  std::string techniqueId_;
  const TechniqueInfo* info_ = nullptr;
  std::map<std::string, ParamSet, std::less<>> params_;
  ParamSet* shared_ = nullptr;
  std::set<std::string> publications_;
  bool resetPending_ = false;
  std::uint64_t changes_ = 0;
  bool hasFrame_ = false;
  FrameStats stats_;
  Publication publication_;
  std::optional<Error> error_;
};

/// The caption of a side: "Name · error 0.420 % · [note ·] 3.1 ms" — the error first (a
/// narrow half wraps the end), "error —" before it was computed, "error n/a (why)" when it is
/// not a number (never 0); `note` (a live reference's age) right after it.
std::string sideCaption(std::string_view techniqueId, const FrameStats& stats,
                        std::optional<double> errorPct, std::string_view note = {},
                        std::string_view unmeasured = {});

}  // namespace sl
