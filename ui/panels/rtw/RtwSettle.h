// What a lesson waits for with a technique whose state carries over frames (DA-RTW's
// rotation): the RTW publication keys stay in ui/panels/rtw/ (tests/source/ui_names_no_rtw_key.sh);
// LessonController and the GUI tests ask here.
#pragma once

#include <algorithm>
#include <optional>
#include <set>
#include <string>
#include <utility>

#include "core/Renderer.h"

namespace sl::ui::rtwsettle {

/// The technique's state carries over frames: it declares the rotation's hold.
inline bool hasTemporalState(const sl::TechniqueInfo& info) {
  return std::any_of(info.publications.begin(), info.publications.end(),
                     [](const sl::PublicationDecl& d) { return d.key == "rotation.held"; });
}

/// DA-RTW's vibration threshold: the parameter (and the published number) of that name.
inline constexpr const char* kThresholdKey = "pca.threshold";

/// The principal axis' x component, as published and as the Covariance panel draws it.
inline constexpr const char* kExKey = "e_x";

/// The numbers to request while waiting.
inline std::set<std::string> keys() {
  return {"pca.valid", "rotation.held", "rotation.step_deg", "rotation.deg"};
}

/// After a frame: nothing when it made no estimate (the first frame has no last frame), else
/// whether the estimate left R unchanged (no principal axis, held, or a zero step) — the
/// same test as shadowlab-cli's warm-up.
inline std::optional<bool> settled(const sl::Publication& pub) {
  const auto& n = pub.numbers;
  auto number = [&n](const char* key) {
    auto it = n.find(key);
    return it == n.end() ? std::optional<double>() : std::optional<double>(it->second);
  };
  const std::optional<double> valid = number("pca.valid");
  if (!valid) return std::nullopt;
  return *valid == 0 || number("rotation.held").value_or(0) != 0 ||
         number("rotation.step_deg").value_or(1) == 0;
}

/// The rotation's angle in the frame's publication (degrees), if published.
inline std::optional<double> angleDeg(const sl::Publication& pub) {
  auto it = pub.numbers.find("rotation.deg");
  return it == pub.numbers.end() ? std::nullopt : std::optional<double>(it->second);
}

/// The share of the light's texels the frame's importance map (before the collapse) gives any
/// importance (I > 0), and the map's texel count; nothing when the frame did not publish it.
inline std::optional<std::pair<double, std::size_t>> importanceCoverage(
    const sl::Publication& pub) {
  auto it = pub.images.find("importance");
  if (it == pub.images.end() || it->second.values.empty()) return std::nullopt;
  const sl::FloatImage& im = it->second;
  std::size_t any = 0, texels = 0;
  for (std::size_t i = 0; i < im.values.size(); i += std::size_t(std::max(1, im.channels))) {
    ++texels;
    any += im.values[i] > 0.0f ? 1 : 0;
  }
  return std::pair{double(any) / double(texels), texels};
}

}  // namespace sl::ui::rtwsettle
