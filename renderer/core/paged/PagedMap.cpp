// The GL side of a paged virtual shadow map (PagedMap.h).
#include "PagedMap.h"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <vector>

#include "algo/pages/PageViews.h"
#include "common/shared_constants.h"
#include "core/Publish.h"
#include "core/SceneGpu.h"
#include "gl/GpuTimer.h"

namespace sl {

namespace {

/// (Re)creates a DEPTH_COMPONENT32F texture of width x height and its depth-only framebuffer.
void createDepthTarget(gl::Texture& texture, gl::Framebuffer& fbo, int width, int height,
                       const std::string& what) {
  texture = gl::Texture::create2D(GL_DEPTH_COMPONENT32F, width, height);
  fbo = gl::Framebuffer::create();
  fbo.attach(GL_DEPTH_ATTACHMENT, texture);
  fbo.setDrawBuffers(0);
  fbo.checkComplete(what);
}
}  // namespace

std::vector<ParamDecl> pagedMapParamDecls() {
  std::vector<ParamDecl> p;
  for (ParamDecl& d : shadowMapParamDecls(2048))
    if (d.key != "resolution") p.push_back(std::move(d));
  p.push_back(
      intParam("virtual.resolution", "Virtual resolution", "Pages", 65536, {256, 262144, 256})
          .withHelp("Texels per side of the virtual shadow map (level 0, the finest pages); a "
                    "power of two. Its quadtree has log2(virtual.resolution / page.size) + 1 "
                    "levels, cut at 8 (the lookup's maps): deeper, the coarsest level has several "
                    "pages, all allocated every frame as the fallback of every lookup."));
  p.push_back(intParam("page.size", "Page size", "Pages", 128, {16, 1024, 16})
                  .withHelp("Texels per side of one page (a power of two): the unit of allocation "
                            "and rendering."));
  p.push_back(
      intParam("lod.bias", "LOD bias", "Pages", 1, {0, 6, 1})
          .withUniform("u_rmsmLodBias")
          .withHelp("Each pixel asks for the page this many levels finer than its footprint needs. "
                    "0 is the paper (l = log2 sqrt(A), resolution matching: one to four texels per "
                    "pixel, the level floored); 1 (the tool's default) 2 x 2 times that, 2 4 x "
                    "4...: it fills a pool that matching alone leaves mostly empty (the default "
                    "pool holds 4.5 texels per pixel of a 1280 x 720 view) and is the more "
                    "accurate at uniform 2048²'s bytes (docs/techniques/rmsm.md)."));
  p.push_back(
      intParam("pool.pages", "Pool pages", "Pages", 256, {1, 4096, 1})
          .withHelp("Pages the physical pool holds (256 pages of 128²: the bytes of one uniform "
                    "2048² map; the paper gives no size). When a frame asks for more, pages of the "
                    "finest requested level move to their parents, sibling group by sibling group, "
                    "until they fit (counted in pages.coarsened).")
          .asMemoryKnob());
  return p;
}

ParamDecl pagedRenderParamDecl(std::string key, std::string group, std::string help) {
  return choiceParam(std::move(key), "Render", std::move(group), {"superpages", "pages"},
                     kPagedRenderPages)
      .withHelp(std::move(help));
}

std::vector<PublicationDecl> pagedMapPublicationDecls() {
  return {
      {"pages.table.*",
       PublicationKind::ImageSet,
       "Page table level i (0 = finest), one cell per entry, a PageState (algo/pages/PageViews): "
       "rmsm 0 empty, 1 requested and allocated, 2 allocated unasked (top level, ancestor of "
       "coarsened requests), 3 requested but coarsened (pool ran out); asm 4 allocated this "
       "frame, 5 cached and used (hit), 6 cached unused, 7 evicted this frame, 8 requested, not "
       "allocated. CPU data, no readback.",
       "",
       {}},
      {"pages.served",
       PublicationKind::Image,
       "Per finest page: the level of the page serving it (its finest allocated ancestor).",
       "",
       {}},
      {"pages.requests.heat",
       PublicationKind::Image,
       "Per finest page: how many of this frame's compacted requests ask for a page holding it.",
       "",
       {}},
      {"pages.pool.levels",
       PublicationKind::Curve,
       "Per pool slot: the level of the page it holds (NaN: free).",
       "",
       {}},
      {"pages.pool.depth", PublicationKind::Image,
       "The physical pool's depth texture as rendered (0..1), pages side by side.",
       "4 B x pool texels (ceil(sqrt(pool.pages)) columns of page.size^2; nearest-sampled to "
       "at most 2048 per side)",
       [](const ParamSet& ps) {
         const int pages = ps.getInt("pool.pages");
         const int cols = poolColumnsFor(pages);
         const int rows = (pages + cols - 1) / cols;
         const int side = ps.getInt("page.size");
         return publishedImageBytes(cols * side, rows * side);
       }},
      {"pages.pool.columns", PublicationKind::Number, "Pages per row of the pool.", "", {}},
      {"pages.requests.compacted",
       PublicationKind::Number,
       "Requests left after dedup and compaction (the GPU list's length; asm: all iterations' "
       "requests, touches aside).",
       "",
       {}},
      {"pages.requested", PublicationKind::Number, "Unique pages requested this frame.", "", {}},
      {"pages.allocated",
       PublicationKind::Number,
       "Pool slots in use after the frame (the top level or coarse map included).",
       "",
       {}},
      {"pages.pool", PublicationKind::Number, "Pages the pool holds (pool.pages).", "", {}},
  };
}

void PagedMap::publish(FrameContext& ctx, const PageViewsFrame& f) const {
  publishNumber(ctx, "pages.requests.compacted", double(f.requests.size()));
  publishNumber(ctx, "pages.requested", f.requested);
  publishNumber(ctx, "pages.allocated", f.allocated);
  publishNumber(ctx, "pages.pool", poolPages_);
  publishNumber(ctx, "pages.pool.columns", poolColumns_);
  for (int l = 0; l < layout_.levels(); ++l) {
    const std::string key = "pages.table." + std::to_string(l);
    if (ctx.wants(key))
      publishImage(ctx, key, layout_.pagesPerSide(l), layout_.pagesPerSide(l), f.levelStates(l));
  }
  const int finest = layout_.finestPagesPerSide();
  if (ctx.wants("pages.served"))
    publishImage(ctx, "pages.served", finest, finest, pages::servedLevels(*f.table));
  if (ctx.wants("pages.requests.heat"))
    publishImage(ctx, "pages.requests.heat", finest, finest,
                 pages::requestHeat(layout_, f.requests));
  if (ctx.wants("pages.pool.levels")) publishValues(ctx, "pages.pool.levels", f.poolLevels());
  publishDepth(ctx, "pages.pool.depth", poolMap_);
}

std::vector<int> PagedMap::pageGrid() const {
  std::vector<int> n;
  for (int l = 0; l < layout_.levels(); ++l) n.push_back(layout_.pagesPerSide(l));
  return n;
}

int poolColumnsFor(int pages) {
  int c = 1;
  while (c * c < pages) ++c;
  return c;
}

glm::mat4 regionViewProj(const glm::mat4& viewProj, int level, int x, int y, int side,
                         const pages::VirtualLayout& layout) {
  const float n = float(layout.pagesPerSide(level)), s = float(side);
  glm::mat4 crop(1.0f);
  crop[0][0] = n / s;
  crop[1][1] = n / s;
  crop[3][0] = -(2.0f * float(x) + s - n) / s;
  crop[3][1] = -(2.0f * float(y) + s - n) / s;
  return crop * viewProj;
}

glm::mat4 pageViewProj(const glm::mat4& viewProj, const pages::PageId& p,
                       const pages::VirtualLayout& layout) {
  return regionViewProj(viewProj, p.level, p.x, p.y, 1, layout);
}

pages::VirtualLayout pagedLayoutOf(const ParamSet& params) {
  return {params.getInt("virtual.resolution"), params.getInt("page.size"), SL_PAGED_LOOKUP_LEVELS};
}

std::optional<std::string> checkPagedMapParams(const ParamSet& params) {
  if (auto e = checkPowerOfTwo(params, "page.size")) return e;
  if (auto e = checkPowerOfTwo(params, "virtual.resolution")) return e;
  const pages::VirtualLayout layout = pagedLayoutOf(params);
  const std::string values = "virtual.resolution = " + std::to_string(layout.virtualResolution) +
                             ", page.size = " + std::to_string(layout.pageSize);
  if (layout.virtualResolution < layout.pageSize)
    return "virtual.resolution must be at least page.size (" + values + ")";
  if (layout.virtualResolution / layout.pageSize > SL_PAGE_MAX_PER_SIDE)
    return "virtual.resolution / page.size must be at most " +
           std::to_string(SL_PAGE_MAX_PER_SIDE) + " pages per side (" + values + ": " +
           std::to_string(layout.virtualResolution / layout.pageSize) + ")";
  if (const std::string e = layout.validate(); !e.empty()) return e;
  const int poolPages = params.getInt("pool.pages");
  if (poolPages < layout.topPages())
    return "pool.pages = " + std::to_string(poolPages) + " cannot hold the " +
           std::to_string(layout.topPages()) + " pages of the coarsest level (" + values +
           ", the quadtree cut at " + std::to_string(SL_PAGED_LOOKUP_LEVELS) +
           " levels); raise pool.pages or page.size";
  const int columns = poolColumnsFor(poolPages);
  if (columns * layout.pageSize > kMaxPoolSideTexels)
    return "a pool of pool.pages = " + std::to_string(poolPages) +
           " pages of page.size = " + std::to_string(layout.pageSize) + " is " +
           std::to_string(columns * layout.pageSize) + " texels wide, more than " +
           std::to_string(kMaxPoolSideTexels) + "; lower pool.pages or page.size";
  return std::nullopt;
}

bool PagedMap::ensure(const pages::VirtualLayout& layout, int poolPages, int minPages,
                      const std::string& technique, int poolColumns) {
  const int columns = poolColumns > 0 ? poolColumns : poolColumnsFor(poolPages);
  const int rows = (poolPages + columns - 1) / columns;
  if (poolPages < minPages)
    throw std::runtime_error(
        technique + ": pool.pages = " + std::to_string(poolPages) + " cannot hold the " +
        std::to_string(minPages) + " pages of the coarsest level (the quadtree is cut at " +
        std::to_string(SL_PAGED_LOOKUP_LEVELS) + " levels); raise pool.pages or page.size");
  if (columns * layout.pageSize > kMaxPoolSideTexels)
    throw std::runtime_error(technique + ": a pool of " + std::to_string(poolPages) + " pages of " +
                             std::to_string(layout.pageSize) + "² is " +
                             std::to_string(columns * layout.pageSize) +
                             " texels wide, more than " + std::to_string(kMaxPoolSideTexels) +
                             "; lower pool.pages or page.size");
  bool changed = false;
  if (!pageTable_ || layout_.virtualResolution != layout.virtualResolution ||
      layout_.pageSize != layout.pageSize) {
    layout_ = layout;
    const int n = layout_.finestPagesPerSide();
    pageTable_ = gl::Texture::create2D(GL_R32UI, n, n, layout_.levels());
    changed = true;
  }
  if (!poolMap_ || poolPages_ != poolPages || poolMap_.width() != columns * layout_.pageSize ||
      poolMap_.height() != rows * layout_.pageSize) {
    poolPages_ = poolPages;
    poolColumns_ = columns;
    createDepthTarget(poolMap_, poolFbo_, columns * layout_.pageSize, rows * layout_.pageSize,
                      technique + " page pool");
    keptPool_ = {};
    kept_.clear();
    changed = true;
  }
  return changed;
}

namespace {
/// Copies slot `slot` of a pool of `columns` pages per row of `pageSize`² texels.
void copySlot(const gl::Texture& from, const gl::Texture& to, int slot, int columns, int pageSize) {
  const int x = (slot % columns) * pageSize, y = (slot / columns) * pageSize;
  glCopyImageSubData(from.id(), GL_TEXTURE_2D, 0, x, y, 0, to.id(), GL_TEXTURE_2D, 0, x, y, 0,
                     pageSize, pageSize, 1);
}
}  // namespace

void PagedMap::keepSlots(std::span<const int> slots) {
  if (!keptPool_)
    keptPool_ = gl::Texture::create2D(poolMap_.format(), poolMap_.width(), poolMap_.height());
  for (const int slot : slots) {
    if (std::find(kept_.begin(), kept_.end(), slot) != kept_.end()) continue;
    copySlot(poolMap_, keptPool_, slot, poolColumns_, layout_.pageSize);
    kept_.push_back(slot);
  }
}

void PagedMap::restoreKept() {
  for (const int slot : kept_) copySlot(keptPool_, poolMap_, slot, poolColumns_, layout_.pageSize);
  kept_.clear();
}

void PagedMap::uploadTable(const pages::PageTable& table) {
  const std::vector<std::uint32_t> entries = table.finalised();
  std::size_t at = 0;
  for (int l = 0; l < layout_.levels(); ++l) {
    const int n = layout_.pagesPerSide(l);
    glTextureSubImage2D(pageTable_.id(), l, 0, 0, n, n, GL_RED_INTEGER, GL_UNSIGNED_INT,
                        entries.data() + at);
    at += std::size_t(n) * n;
  }
}

void PagedMap::renderPages(const DepthProgram& depth, const SceneGpu& scene,
                           const glm::mat4& viewProj, std::span<const pages::PageId> pageIds,
                           std::span<const int> slots, bool clearPool) {
  // The whole pool cleared (rmsm renders every page every frame) or only the pages rendered
  // (asm keeps the others: they are its cache).
  beginDepthPass(poolFbo_.id(), poolMap_.width(), poolMap_.height(), clearPool);
  depth.use();
  const int ps = layout_.pageSize;
  glEnable(GL_SCISSOR_TEST);
  for (std::size_t i = 0; i < pageIds.size(); ++i) {
    const int x = (slots[i] % poolColumns_) * ps, y = (slots[i] / poolColumns_) * ps;
    glViewport(x, y, ps, ps);
    glScissor(x, y, ps, ps);
    if (!clearPool) {
      const float one = 1.0f;  // a reused slot must not keep its old page's depth
      glClearNamedFramebufferfv(poolFbo_.id(), GL_DEPTH, 0, &one);
    }
    depth.set("u_lightViewProj", pageViewProj(viewProj, pageIds[i], layout_));
    depth.draw(scene);
  }
  glDisable(GL_SCISSOR_TEST);
}

std::int64_t PagedMap::renderSuperpages(const DepthProgram& depth, const SceneGpu& scene,
                                        const glm::mat4& viewProj,
                                        std::span<const pages::Superpage> superpages,
                                        const pages::PageTable& table, int superpageSize,
                                        bool clearPool, gl::GpuTimer* timer,
                                        const std::string& renderPass,
                                        const std::string& copyPass) {
  const int ps = layout_.pageSize;
  const int side = std::min(superpageSize, layout_.virtualResolution);
  if (!superpage_ || superpage_.width() != side) {
    createDepthTarget(superpage_, superpageFbo_, side, side, "superpage target");
  }
  using Scope = std::optional<gl::GpuTimer::Scope>;  // empty: the caller times the step
  if (clearPool) {
    // Free slots hold 1 (far) as on the page-by-page path: the pools are then equal.
    Scope pass;
    if (timer) pass.emplace(*timer, renderPass);
    const float one = 1.0f;
    glClearNamedFramebufferfv(poolFbo_.id(), GL_DEPTH, 0, &one);
  }
  std::int64_t texels = 0;
  for (const pages::Superpage& s : superpages) {
    // The block's pages: perSide a side, or the whole level when it has fewer.
    const int blockPages = std::min(s.pagesPerSide, layout_.pagesPerSide(s.level));
    texels += std::int64_t(blockPages * ps) * (blockPages * ps);
    const int x0 = s.x * s.pagesPerSide, y0 = s.y * s.pagesPerSide;
    {
      Scope pass;
      if (timer) pass.emplace(*timer, renderPass);
      beginDepthPass(superpageFbo_.id(), blockPages * ps, blockPages * ps, true);
      depth.use();
      depth.set("u_lightViewProj", regionViewProj(viewProj, s.level, x0, y0, blockPages, layout_));
      depth.draw(scene);
    }
    Scope pass;
    if (timer) pass.emplace(*timer, copyPass);
    for (const pages::PageId& p : s.pages) {
      const int slot = table.slot(p);
      if (slot < 0) throw std::logic_error("renderSuperpages: a page without a slot");
      glCopyImageSubData(superpage_.id(), GL_TEXTURE_2D, 0, (p.x - x0) * ps, (p.y - y0) * ps, 0,
                         poolMap_.id(), GL_TEXTURE_2D, 0, (slot % poolColumns_) * ps,
                         (slot / poolColumns_) * ps, 0, ps, ps, 1);
    }
  }
  return texels;
}

void PagedMap::releaseSuperpageTarget() {
  superpageFbo_ = {};
  superpage_ = {};
}

void PagedMap::setLayoutUniforms(const gl::Program& p, const glm::mat4& viewProj) const {
  p.set("u_rmsmViewProj", viewProj);
  p.set("u_rmsmVirtualResolution", layout_.virtualResolution);
  p.set("u_rmsmPageSize", layout_.pageSize);
  p.set("u_rmsmLevels", layout_.levels());
}

void PagedMap::bindLookup(const gl::Program& p, int firstUnit, const DepthMapView& view) const {
  // Every level is one "map" of the shared bias model with the same light matrix; they
  // differ in texel size only (shadowMapTexels in common/paged/page_fetch.glsl).
  const std::vector<DepthMapView> views(std::size_t(layout_.levels()), view);
  bindDepthLookup(p, views);
  setLayoutUniforms(p, view.lightViewProj);
  glBindTextureUnit(GLuint(firstUnit), poolMap_.id());
  p.set("u_rmsmPool", firstUnit);
  glBindTextureUnit(GLuint(firstUnit + 1), pageTable_.id());
  p.set("u_rmsmPageTable", firstUnit + 1);
  p.set("u_rmsmPoolColumns", poolColumns_);
}

void PagedMap::addMemory(MemoryStats& m) const {
  if (poolMap_)
    m.add("page pool", gl::formatName(poolMap_.format()), poolMap_.width(), poolMap_.height(), 1,
          gl::bytesPerTexel(poolMap_.format()));
  if (keptPool_)
    m.add("page pool as the last complete frame left it", gl::formatName(keptPool_.format()),
          keptPool_.width(), keptPool_.height(), 1, gl::bytesPerTexel(keptPool_.format()));
  if (superpage_)
    m.add("superpage target", gl::formatName(superpage_.format()), superpage_.width(),
          superpage_.height(), 1, gl::bytesPerTexel(superpage_.format()));
  if (pageTable_)
    for (int l = 0; l < layout_.levels(); ++l)
      m.add("page table level " + std::to_string(l), "R32UI", layout_.pagesPerSide(l),
            layout_.pagesPerSide(l), 1, 4);
}

std::uint64_t PagedMap::poolBytes() const {
  return poolMap_ ? std::uint64_t(poolMap_.width()) * std::uint64_t(poolMap_.height()) *
                        std::uint64_t(gl::bytesPerTexel(poolMap_.format()))
                  : 0;
}

std::uint64_t PagedMap::superpageBytes() const {
  return superpage_ ? std::uint64_t(superpage_.width()) * std::uint64_t(superpage_.height()) *
                          std::uint64_t(gl::bytesPerTexel(superpage_.format()))
                    : 0;
}

}  // namespace sl
