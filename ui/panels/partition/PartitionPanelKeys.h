// The publication keys the Partitions panel observes (core/Renderer.h, Publication): plain
// C++ so that tests/gl can request exactly what the panel draws. Any multi-map technique
// that publishes "partition.<i>.*" (cascades, face-partition) fills it.
#pragma once

#include <set>
#include <string>

namespace sl::ui::partition {

inline std::set<std::string> partitionsPanelKeys() {
  return {"partition.count",
          "partition.*.map",
          "partition.*.near",
          "partition.*.far",
          "partition.*.texels_per_m",
          "partition.*.texels",
          "partition.*.extent_m",
          "partition.*.warped",
          "partition.*.warp.fallback_cause",
          "partition.*.warp.n_prime",
          "partition.*.warp.eta",
          "partition.*.slice_uv",
          "depth.near",
          "depth.far",
          "depth.fitted",
          "partition.*.m.p95",
          "partition.*.m.max",
          "partition.*.m.pixels"};
}

}  // namespace sl::ui::partition
