#include "core/LiveText.h"

#include <string_view>

#include "core/Renderer.h"

namespace sl {
namespace {
/// The side's own number for a built-in key ({error_pct}, {frame_ms}, {memory_mb}); nullptr
/// when `p` names a publication instead.
const std::optional<double>* builtin(const TextPlaceholder& p, const LiveSide& side) {
  if (p.index >= 0) return nullptr;
  if (p.key == kLiveErrorKey) return &side.errorPct;
  if (p.key == kLiveFrameKey) return &side.frameMs;
  if (p.key == kLiveMemoryKey) return &side.memoryMB;
  return nullptr;
}
}  // namespace

std::optional<double> liveValue(const TextPlaceholder& p, const LiveSide& main,
                                const LiveSide* compare) {
  const LiveSide* side = p.compare ? compare : &main;
  if (!side) return std::nullopt;
  if (const std::optional<double>* own = builtin(p, *side)) return *own;
  if (!side->publication) return std::nullopt;
  const Publication& pub = *side->publication;
  if (p.index < 0) {
    const auto it = pub.numbers.find(p.key);
    if (it == pub.numbers.end()) return std::nullopt;
    return it->second;
  }
  const auto it = pub.curves.find(p.key);
  if (it == pub.curves.end() || static_cast<std::size_t>(p.index) >= it->second.size())
    return std::nullopt;
  return static_cast<double>(it->second[static_cast<std::size_t>(p.index)]);
}

std::set<std::string> livePublicationKeys(const std::string& text, bool compare) {
  std::set<std::string> keys;
  const auto t = TextTemplate::parse(text, nullptr);
  if (!t) return keys;
  for (const TextPlaceholder& p : t->placeholders()) {
    if (p.compare != compare) continue;
    if (builtin(p, LiveSide{})) continue;
    keys.insert(p.key);
  }
  return keys;
}

std::string fillLiveText(const std::string& text, const LiveSide& main, const LiveSide* compare) {
  const auto t = TextTemplate::parse(text, nullptr);
  if (!t) return text;
  return t->fill([&](const TextPlaceholder& p) { return liveValue(p, main, compare); });
}

}  // namespace sl
