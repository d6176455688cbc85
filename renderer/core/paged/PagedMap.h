// The GL side of a paged virtual shadow map, shared by `rmsm` (Lefohn et al. 2007) and `asm`
// (Fernando et al. 2001): the physical pool (one depth texture, pages side by side) with its
// framebuffer, the page table's mip chain (R32UI, one level per quadtree level), rendering
// pages into their pool slots and binding both for the paged lookup (common/paged/page_fetch.glsl).
// The CPU side (layout, page table, pool allocator) is algo/pages.
#pragma once

#include <functional>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "algo/pages/VirtualPages.h"
#include "core/ShadowPass.h"
#include "core/Technique.h"

namespace sl {

class SceneGpu;
namespace gl {
class GpuTimer;
}

/// The parameters of a paged map, declared once for rmsm and asm: the shared shadow-map ones
/// (bias, PCF; no `resolution`), virtual.resolution, page.size, lod.bias, pool.pages (rmsm's
/// help texts; a technique replaces a help text with setParamHelp).
std::vector<ParamDecl> pagedMapParamDecls();
/// The values of a paged technique's render step (rmsm.render, asm.render, in this order): the
/// pages binned into superpages, each rendered once and its pages copied into the pool
/// (PagedMap::renderSuperpages), or each page rendered straight into its slot (renderPages).
inline constexpr int kPagedRenderSuperpages = 0, kPagedRenderPages = 1;
/// The declaration of a paged technique's render step `key` (pages by default; `help` says
/// what the technique does with each value).
ParamDecl pagedRenderParamDecl(std::string key, std::string group, std::string help);

/// The Pages panel's publications, declared once for rmsm and asm (pages.table.*, pages.served,
/// pages.requests.heat, pages.pool.levels, pages.pool.depth, pages.pool.columns,
/// pages.requests.compacted, pages.requested, pages.allocated, pages.pool).
std::vector<PublicationDecl> pagedMapPublicationDecls();

/// A paged technique's frame as the Pages panel shows it (CPU data; published by
/// PagedMap::publish only where requested).
struct PageViewsFrame {
  const pages::PageTable* table = nullptr;
  /// Per level: a pages::PageState per entry (pages::levelStates, adaptive::cacheLevelStates).
  std::function<std::vector<float>(int level)> levelStates;
  std::span<const pages::PageKey> requests;        ///< this frame's compacted requests (heat map)
  std::function<std::vector<float>()> poolLevels;  ///< per slot: its page's level, NaN free
  int requested = 0;                               ///< unique pages requested this frame
  int allocated = 0;                               ///< pool slots in use after the frame
};

/// The largest pool texture side ShadowLab asks for (GL 4.5 guarantees 16384 on llvmpipe).
inline constexpr int kMaxPoolSideTexels = 16384;

/// Columns of a pool's page grid: the smallest square holding `pages`.
int poolColumnsFor(int pages);

/// The virtual layout of pagedMapParamDecls' values (the quadtree cut at
/// SL_PAGED_LOOKUP_LEVELS levels).
pages::VirtualLayout pagedLayoutOf(const ParamSet& params);
/// What PagedMap::ensure and the layout need of pagedMapParamDecls' values together (a
/// technique's TechniqueInfo::checkParams): page.size and virtual.resolution powers of two,
/// at most SL_PAGE_MAX_PER_SIDE pages per side, a pool that holds the quadtree's top level and
/// fits the largest texture. Each error names the parameters with their values.
std::optional<std::string> checkPagedMapParams(const ParamSet& params);

class PagedMap {
 public:
  /// (Re)creates the textures for `layout` and a pool of `poolPages` when either changed;
  /// true when it did (the CPU side starts over too). Throws std::runtime_error, prefixed with
  /// `technique`, for a pool smaller than `minPages` (what the technique must always hold) or
  /// wider than the largest texture ShadowLab asks for.
  /// `columns` > 0 gives the pool's pages per row (pool.budget: pages::fitPoolToBytes), else
  /// poolColumnsFor(poolPages).
  bool ensure(const pages::VirtualLayout& layout, int poolPages, int minPages,
              const std::string& technique, int columns = 0);
  const pages::VirtualLayout& layout() const { return layout_; }
  int poolColumns() const { return poolColumns_; }
  const gl::Texture& poolTexture() const { return poolMap_; }
  const gl::Texture& pageTableTexture() const { return pageTable_; }

  /// Uploads the CPU page table's finalised mip chain.
  void uploadTable(const pages::PageTable& table);
  /// One depth pass per page into its slot: `viewProj` cropped to the page (pageViewProj);
  /// the whole pool cleared first, or (clearPool false: the other slots are a cache) each
  /// rendered slot only.
  void renderPages(const DepthProgram& depth, const SceneGpu& scene, const glm::mat4& viewProj,
                   std::span<const pages::PageId> pageIds, std::span<const int> slots,
                   bool clearPool);
  /// The lecture's render step (Lefohn et al.; the same steps in its ASM loop): the pool
  /// cleared when `clearPool` (rmsm renders every page every frame; asm keeps its cached
  /// pages, and each copied page overwrites its whole slot), then per superpage (its level's
  /// block of `superpageSize`² texels, or the whole level when smaller) one depth pass of
  /// `viewProj` cropped to the block (regionViewProj) into the superpage target (timed as
  /// `renderPass`), then each of its pages copied (glCopyImageSubData) to its slot in `table`
  /// (`copyPass`). With `timer` null the caller times the whole step. Creates the target of
  /// min(superpageSize, virtual.resolution)² texels on first use. Returns the texels the
  /// superpages' viewports cover (each cleared and rasterised).
  std::int64_t renderSuperpages(const DepthProgram& depth, const SceneGpu& scene,
                                const glm::mat4& viewProj,
                                std::span<const pages::Superpage> superpages,
                                const pages::PageTable& table, int superpageSize, bool clearPool,
                                gl::GpuTimer* timer, const std::string& renderPass,
                                const std::string& copyPass);
  /// Transactional frames (Technique::commitFrame) for a pool kept as a cache (asm): before a
  /// frame renders into `slots`, the texels of those not kept yet this frame are copied into a
  /// second pool (created on first use, listed by addMemory); restoreKept() copies them back
  /// (the frame is discarded), forgetKept() forgets them (committed). A new pool forgets them.
  void keepSlots(std::span<const int> slots);
  void restoreKept();
  void forgetKept() { kept_.clear(); }
  /// Frees the superpage target (the page-by-page path does not need it).
  void releaseSuperpageTarget();
  const gl::Texture& superpageTexture() const { return superpage_; }
  /// The layout's uniforms of common/paged/request.glsl.
  void setLayoutUniforms(const gl::Program& p, const glm::mat4& viewProj) const;
  /// The paged lookup's bindings: every level a map of the shared bias model with `view`'s
  /// matrix, the pool at unit firstUnit, the page table at firstUnit + 1.
  void bindLookup(const gl::Program& p, int firstUnit, const DepthMapView& view) const;
  /// The Pages panel's publications of `frame` (pagedMapPublicationDecls), each only while
  /// requested; the pool's depth is the only readback.
  void publish(FrameContext& ctx, const PageViewsFrame& frame) const;
  /// Pages per side of every level (Technique::pageGrid: the page-border overlay).
  std::vector<int> pageGrid() const;
  /// The pool's, the page table's and the superpage target's bytes.
  void addMemory(MemoryStats& m) const;
  /// The pool texture's bytes (0 before ensure).
  std::uint64_t poolBytes() const;
  /// The superpage target's bytes while it exists (0 otherwise).
  std::uint64_t superpageBytes() const;

 private:
  pages::VirtualLayout layout_;
  int poolPages_ = 0;
  int poolColumns_ = 1;
  gl::Texture poolMap_;  ///< DEPTH_COMPONENT32F, poolColumns x rows pages
  gl::Framebuffer poolFbo_;
  gl::Texture pageTable_;  ///< R32UI, finest pages per side, one mip level per quadtree level
  gl::Texture superpage_;  ///< DEPTH_COMPONENT32F, one superpage (renderSuperpages only)
  gl::Texture keptPool_;   ///< the pool's size: slots as the last complete frame left them
  std::vector<int> kept_;  ///< the slots keptPool_ holds for the frame in progress
  gl::Framebuffer superpageFbo_;
};

/// World -> clip of one page: the map's matrix followed by the crop of the page's square of
/// light uv onto the whole clip square (depth unchanged: the page stores the map's depth).
glm::mat4 pageViewProj(const glm::mat4& viewProj, const pages::PageId& p,
                       const pages::VirtualLayout& layout);
/// World -> clip of a square block of `side` x `side` pages of `level` whose lower-left page
/// is (x, y): the crop of that block of light uv onto the whole clip square (side 1: one page).
glm::mat4 regionViewProj(const glm::mat4& viewProj, int level, int x, int y, int side,
                         const pages::VirtualLayout& layout);

}  // namespace sl
