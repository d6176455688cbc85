// The publication keys the Storage factor panel observes (the renderer's own numbers,
// core/Renderer.h rendererPublicationDecls), plain C++ so that tests can request exactly
// what the panel draws.
#pragma once

#include <set>
#include <string>

namespace sl::ui::analysis {

/// The frame's camera and light (the analysis' view frustum and the marked light), the
/// technique's parameter values (its scheme: warp.eta, partitions, ...), the eta a warp
/// published when it is not a parameter (tsm: StorageScheme.h) and the measured m.
inline std::set<std::string> storagePanelKeys() {
  return {"camera.*",     "light.type",      "light.azimuth_deg",   "light.elevation_deg",
          "param.*",      "warp.eta",        "aliasing.p50",        "aliasing.p95",
          "aliasing.max", "aliasing.pixels", "aliasing.bin_octaves"};
}

}  // namespace sl::ui::analysis
