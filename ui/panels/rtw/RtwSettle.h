// What a lesson waits for with a technique whose state carries over frames (DA-RTW's
// rotation): the RTW publication keys stay in ui/panels/rtw/ (tests/source/ui_names_no_rtw_key.sh);
// LessonController and the GUI tests ask here.
#pragma once

#include <algorithm>
#include <optional>
#include <set>
#include <string>
#include <utility>

#include "algo/rtw/Rotation.h"
#include "core/Renderer.h"

namespace sl::ui::rtwsettle {

/// The technique's rotation carries over frames and settles by a declared rule
/// (TechniqueInfo::temporalRotation and settled); not the wider TechniqueInfo::temporalState,
/// which cascades and the paged maps declare too.
inline bool settlesRotation(const sl::TechniqueInfo& info) {
  return info.temporalRotation && bool(info.settled);
}

/// DA-RTW's vibration threshold: the parameter (and the published number) of that name.
inline constexpr const char* kThresholdKey = sl::rtw::kHoldThresholdKey;

/// The principal axis' x component, as published and as the Covariance panel draws it.
inline constexpr const char* kExKey = "e_x";

/// The numbers to request while waiting: the technique's own (TechniqueInfo::settleKeys) and
/// the angle.
inline std::set<std::string> keys(const sl::TechniqueInfo& info) {
  std::set<std::string> k = info.settleKeys;
  k.insert("rotation.deg");
  return k;
}

/// After a frame: nothing when it could not tell yet, else whether the state stopped changing
/// (the technique's own rule, TechniqueInfo::settled: the same as shadowlab-cli's warm-up).
inline std::optional<bool> settled(const sl::TechniqueInfo& info, const sl::Publication& pub) {
  if (!info.settled) return true;
  return info.settled(pub);
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
