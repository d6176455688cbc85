// JSON presets (and lessons, and the GUI's saved sessions): scene, technique, parameters,
// camera and light in one file; a session adds the split view's compare technique and the
// window layout (optional: older lessons stay valid). The same parameter declarations
// validate them as the UI and the command line.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "algo/Camera.h"
#include "algo/Light.h"

namespace sl {

/// Limits on a session's layout (the window has ~20 docks; Qt's saved state is ~2 KiB).
inline constexpr std::size_t kMaxPresetLayoutDocks = 64;
inline constexpr std::size_t kMaxPresetLayoutStateBytes = 64 * 1024;  ///< base64 text
/// At most this many parameters in a lesson's strip ("layout": {"strip": [...]}).
inline constexpr std::size_t kMaxPresetStripKeys = 3;
/// At most this many cases in one lesson ("cases").
inline constexpr std::size_t kMaxPresetCases = 8;
/// Limits on a lesson's text: the title reaches the window's menus and banner (the 300-byte
/// rule of every text that reaches a title, kMaxMessageBytes); the explanation is laid out in
/// the Lesson dock (the longest lesson's is ~2 KiB; one of 1 MB blocked the window 140 s).
inline constexpr std::size_t kMaxPresetTitleBytes = 300;
inline constexpr std::size_t kMaxPresetExplanationBytes = 16 * 1024;

/// The split view's right half: its technique ("": the split view is off) and that
/// technique's own parameter values (the shared view/shading ones are the main side's).
struct PresetCompare {
  std::string technique;
  std::map<std::string, std::string> params;
  bool operator==(const PresetCompare&) const = default;
};

/// The window's layout: the object names of the visible docks, and QMainWindow::saveState
/// as base64 (either may be empty), and the one dock a lesson shows large ("": none). Dock
/// names are checked by the window, not here. `strip`: the 1..kMaxPresetStripKeys parameters
/// a lesson's steps change, shown as a compact strip with the lesson; each key is checked at
/// load against the technique of every case (or the shared view parameters).
struct PresetLayout {
  std::vector<std::string> docks;
  std::string state;
  std::string large;               ///< a dock of `docks` given most of its side of the window
  std::vector<std::string> strip;  ///< parameter keys, in the strip's order
  bool operator==(const PresetLayout&) const = default;
};

struct Preset {
  std::string title;
  std::string explanation;  ///< what to look at (lessons)
  std::string scene;        ///< built-in name or path
  std::string technique;
  std::map<std::string, std::string> params;  ///< key -> value text (validated on apply)
  std::optional<Camera> camera;
  std::optional<Light> light;            ///< core/LightJson: {"type", ...}
  std::optional<PresetCompare> compare;  ///< "compare": {"technique", "params"} (sessions)
  std::optional<PresetLayout> layout;    ///< "layout": {"docks", "state", "large", "strip"}
  /// A lesson told in cases ("cases": 2..kMaxPresetCases objects with "title" and
  /// "explanation" and any of scene, technique, params, camera, light, compare): each a
  /// complete preset, this one's fields with the case's on top ("params" replaces, it does
  /// not merge; a case naming a technique gives its params; a case naming another scene
  /// starts from that scene's camera and light). Empty: one case, this preset.
  /// The command line renders the preset itself (the first case should need no overrides).
  std::vector<Preset> cases;
};

/// Reads a preset; the error names the file and the problem.
std::optional<Preset> loadPreset(const std::filesystem::path& path, std::string* error);
std::string presetToJson(const Preset& preset);

}  // namespace sl
