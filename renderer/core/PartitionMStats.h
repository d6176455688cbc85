// Per-map perspective aliasing m of the previous frame's resolve, for every multi-map
// technique (cascades, face-partition): a 1/8-octave histogram of m per selected map
// (shaders/common/partition_m.comp), published as partition.<i>.m.p95 / .max / .pixels for
// the Partitions panel, measured only while one of those keys is requested.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "core/Technique.h"
#include "gl/Gl.h"
#include "gl/ShaderLibrary.h"

namespace sl {

class PartitionMStats {
 public:
  explicit PartitionMStats(const gl::ShaderLibrary& lib);

  /// When a partition.<i>.m.* key of maps 0..maps-1 is requested: the pass "partition m"
  /// (timed) bins the previous frame's m by its selected map and publishes the three numbers
  /// of each map; otherwise frees its buffer (memory() then names nothing).
  void update(FrameContext& ctx, int maps);
  /// The pass's declaration (id "partition m"), for the technique's TechniqueInfo::passes.
  static PassDecl passDecl();
  /// The "partition.*.m.*" declaration; `maps` gives the number of maps for the params.
  static PublicationDecl publicationDecl(std::function<int(const ParamSet&)> maps);

  const gl::Program& program() const { return program_; }
  void addMemory(MemoryStats& m) const;
  std::optional<std::string> reloadShaders(const gl::ShaderLibrary& lib) {
    return program_.rebuild(lib);
  }

 private:
  gl::Program program_;
  gl::Buffer stats_;  ///< per map: SL_CASCADE_M_BINS bins, count, max (only while requested)
};

}  // namespace sl
