// Per-map aliasing m statistics (PartitionMStats.h): clear, bin on the GPU, read back the
// histograms, publish p95 / max / pixel count per map.
#include "PartitionMStats.h"

#include <cstring>
#include <vector>

#include "algo/partition/CascadeFit.h"
#include "common/shared_constants.h"
#include "core/Publish.h"

namespace sl {

namespace {
constexpr std::size_t kStride = SL_CASCADE_M_BINS + 2;  ///< uints per map
const char* const kKeys[] = {"m.p95", "m.max", "m.pixels"};
}  // namespace

PartitionMStats::PartitionMStats(const gl::ShaderLibrary& lib)
    : program_(lib,
               {"common/partition_m", {{GL_COMPUTE_SHADER, "common/partition_m.comp"}}, {}, {}}) {}

PassDecl PartitionMStats::passDecl() {
  return {"partition m", "Aliasing per partition",
          "Only while the Partitions panel (or a partition.<i>.m.* key) is shown: the previous "
          "frame's texels per pixel m, binned per selected map (1/8-octave histogram): p95 and "
          "max of every partition.",
          "partitions"};
}

PublicationDecl PartitionMStats::publicationDecl(std::function<int(const ParamSet&)> maps) {
  return {"partition.*.m.*", PublicationKind::Number,
          "Partition i's perspective aliasing m over the previous frame's pixels that selected "
          "it: m.p95 (upper edge of its 1/8-octave histogram bin), m.max, m.pixels.",
          "4 B x (" + std::to_string(SL_CASCADE_M_BINS) + " + 2) x maps",
          [maps = std::move(maps)](const ParamSet& ps) {
            return std::uint64_t(4 * kStride) * std::uint64_t(maps(ps));
          }};
}

void PartitionMStats::update(FrameContext& ctx, int maps) {
  bool wanted = false;
  for (int i = 0; i < maps && !wanted; ++i)
    for (const char* m : kKeys)
      wanted = wanted || ctx.wants("partition." + std::to_string(i) + "." + m);
  if (!wanted) {
    stats_ = {};  // held only while requested (memory())
    return;
  }
  auto pass = ctx.timer.scope("partition m");
  const GLsizeiptr bytes = GLsizeiptr(4 * kStride * std::size_t(maps));
  if (!stats_ || stats_.size() != bytes) stats_ = gl::Buffer::create(bytes, nullptr);
  const std::uint32_t zero = 0;
  glClearNamedBufferData(stats_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  program_.use();
  program_.set("u_size", glm::ivec2(ctx.width, ctx.height));
  program_.set("u_maps", maps);
  glBindTextureUnit(SL_UNIT_ALIASING, ctx.previous.aliasing.id());
  glBindTextureUnit(SL_UNIT_MAP_INDEX, ctx.previous.mapIndex.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SL_CASCADE_BUFFER_M_STATS, stats_.id());
  glDispatchCompute(GLuint((ctx.width + SL_CASCADE_GROUP - 1) / SL_CASCADE_GROUP),
                    GLuint((ctx.height + SL_CASCADE_GROUP - 1) / SL_CASCADE_GROUP), 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  // Read as floats by the counting helper; the words are uint counts and float bits.
  const std::vector<float> words = readPublishedFloats(ctx, stats_, 0, kStride * std::size_t(maps));
  for (int i = 0; i < maps; ++i) {
    const float* w = words.data() + kStride * std::size_t(i);
    std::vector<std::uint32_t> bins(SL_CASCADE_M_BINS);
    std::memcpy(bins.data(), w, bins.size() * 4);
    std::uint32_t count = 0, maxBits = 0;
    std::memcpy(&count, w + SL_CASCADE_M_BINS, 4);
    std::memcpy(&maxBits, w + SL_CASCADE_M_BINS + 1, 4);
    float maxM = 0.0f;
    std::memcpy(&maxM, &maxBits, 4);
    const std::string key = "partition." + std::to_string(i) + ".";
    publishNumber(
        ctx, key + "m.p95",
        partition::histogramQuantileLog2(bins, 0.95, SL_CASCADE_M_LOG2_MIN, SL_CASCADE_M_LOG2_MAX));
    publishNumber(ctx, key + "m.max", count > 0 ? double(maxM) : 0.0);
    publishNumber(ctx, key + "m.pixels", double(count));
  }
}

void PartitionMStats::addMemory(MemoryStats& m) const {
  if (stats_)
    m.add("m histograms (per partition, while requested)", "R32UI", int(stats_.size() / 4), 1, 1,
          4);
}

}  // namespace sl
