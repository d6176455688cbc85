// Resolution-matched shadow maps (Lefohn, Sengupta, Owens 2007; techniques.md §5): a virtual
// orthographic map of virtual.resolution² texels in pages of page.size², of which only the
// pages camera pixels ask for are rendered, at the LOD each pixel needs, into one physical
// pool behind a page table (a mip chain). Per frame: requests (compute) → dedup + compaction
// (compute) → read back → sort + unique + allocate (CPU, renderer/algo/pages) → page table →
// bin pages into 1024² superpages → render each superpage once → copy its pages into the pool
// (rmsm.render = superpages; pages: each page rendered into its slot). Directional only.
#pragma once

#include <vector>

#include "algo/pages/VirtualPages.h"
#include "core/paged/PageRequestList.h"
#include "core/paged/PagedMap.h"
#include "core/ShadowPass.h"
#include "core/Technique.h"

namespace sl {

class RmsmShadowMap : public Technique {
 public:
  static TechniqueInfo info();
  explicit RmsmShadowMap(const gl::ShaderLibrary& lib);

  void renderShadows(FrameContext& ctx) override;
  std::string lookupShader() const override { return "rmsm/lookup.glsl"; }
  void bindLookup(const gl::Program& resolve, int firstUnit) const override;
  std::vector<const gl::Program*> programs() const override {
    std::vector<const gl::Program*> p = depthProgram_.programs();
    p.insert(p.end(), {&requestProgram_, &requests_.program(), &sortProgram_, &uniqueProgram_});
    return p;
  }
  std::vector<int> pageGrid() const override { return map_.pageGrid(); }
  MemoryStats memory() const override;
  std::optional<std::string> reloadShaders(const gl::ShaderLibrary& lib) override;

  /// What the last frame did (tests, publications).
  struct FrameResult {
    std::vector<pages::PageKey> compacted;  ///< the GPU's list after dedup + compaction
    std::vector<pages::PageKey> unique;     ///< the GPU's sorted unique list (read back)
    pages::Allocation allocation;
    /// The allocated pages binned into SL_RMSM_SUPERPAGE² superpages.
    std::vector<pages::Superpage> superpages;
    int sceneDraws = 0;  ///< scene draws of the render step (superpages or pages)
    /// Texels the render step's viewports cover (cleared and rasterised): per superpage its
    /// block (min(superpage, level) side)², or per page page.size².
    std::int64_t renderTexels = 0;
  };
  /// rmsm.render's values.
  static constexpr int kRenderSuperpages = kPagedRenderSuperpages, kRenderPages = kPagedRenderPages;
  const FrameResult& lastFrame() const { return last_; }
  void commitFrame() override { budgetPool_.commit(); }
  void discardFrame() override { budgetPool_.discard(); }
  void resetTemporalState() override { budgetPool_.reset(); }
  /// The pool (pages side by side) after the last frame's render step.
  const gl::Texture& poolTexture() const { return map_.poolTexture(); }
  /// The per-pixel request keys of the last frame (r32ui, camera size) and the page table.
  const gl::Texture& requestImage() const { return requests_.image(); }
  const gl::Texture& pageTableTexture() const { return map_.pageTableTexture(); }
  const pages::PageTable* pageTable() const { return table_.get(); }
  const pages::VirtualLayout& layout() const { return layout_; }
  int poolColumns() const { return map_.poolColumns(); }
  const glm::mat4& lightViewProj() const { return view_.lightViewProj; }  ///< the virtual map's

 private:
  /// The pool of `poolPages` (`columns` per row, 0: the squarest) and its CPU side.
  void ensurePool(const pages::VirtualLayout& layout, int poolPages, int columns);
  /// pool.budget: the pool of the most pages that fit in `budget` bytes beside every other
  /// buffer memory() lists this frame (after the sort, whose buffers follow the list's length).
  void fitPoolToBudget(const pages::VirtualLayout& layout, std::uint64_t budget, int render);
  void requestPages(FrameContext& ctx);
  /// The compacted list sorted and made unique on the GPU (rmsm/sort.comp, rmsm/unique.comp;
  /// reference pages::sortUnique).
  void sortUnique(FrameContext& ctx);
  /// Bitonic sort of the first `count` (a power of two) keys of `keys`, ascending.
  void bitonicSort(const gl::Buffer& keys, std::uint32_t count) const;
  void allocate(FrameContext& ctx);
  void renderPages(FrameContext& ctx);

  DepthProgram depthProgram_;
  gl::Program requestProgram_, sortProgram_, uniqueProgram_;
  pages::VirtualLayout layout_;
  std::unique_ptr<pages::PageTable> table_;
  std::unique_ptr<pages::PagePool> pool_;
  PagedMap map_;              ///< the pool and the page table's textures
  PageRequestList requests_;  ///< per pixel, then compacted
  /// The sort's keys and the unique list: this frame's compacted length rounded up to a power
  /// of two (at least 2) each.
  gl::Buffer sortKeys_, uniqueKeys_;
  gl::Buffer uniqueCount_;            ///< the number of unique keys
  std::uint32_t compactedCount_ = 0;  ///< the compacted list's length (clamped), sortUnique
  DepthMapView view_;
  FrameResult last_;
  /// pool.budget's fit of the last frame (empty: none); carried across frames.
  FrameCarried<pages::PoolShape> budgetPool_;
};

}  // namespace sl
