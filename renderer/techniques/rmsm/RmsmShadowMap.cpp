// Resolution-matched shadow maps (RmsmShadowMap.h): requests, compaction, sort and unique in
// compute, the CPU reference allocator (algo/pages), the pages rendered into the pool.
#include "RmsmShadowMap.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>

#include "algo/Focus.h"
#include "algo/pages/PageRequests.h"
#include "algo/pages/PageViews.h"
#include "common/shared_constants.h"
#include "core/Publish.h"
#include "core/SceneGpu.h"

namespace sl {

static_assert(SL_PAGED_LOOKUP_LEVELS <= SL_MAX_DEPTH_MAPS);  // one lookup map per level

namespace {

gl::ProgramDesc requestProgramDesc() {
  return {"rmsm/requests", {{GL_COMPUTE_SHADER, "rmsm/requests.comp"}}, {}, {}};
}
gl::ProgramDesc sortProgramDesc() {
  return {"rmsm/sort", {{GL_COMPUTE_SHADER, "rmsm/sort.comp"}}, {}, {}};
}
gl::ProgramDesc uniqueProgramDesc() {
  return {"rmsm/unique", {{GL_COMPUTE_SHADER, "rmsm/unique.comp"}}, {}, {}};
}

}  // namespace

TechniqueInfo RmsmShadowMap::info() {
  std::vector<ParamDecl> p = pagedMapParamDecls();
  p.push_back(pagedRenderParamDecl(
      "rmsm.render", "Pages",
      "superpages (Lefohn et al.): the allocated pages are binned into " +
          std::to_string(SL_RMSM_SUPERPAGE) +
          "² blocks of one level; each block is "
          "rendered once into a superpage target, then its pages are copied into their "
          "pool slots (one scene draw per superpage): the paper's pipeline. pages (the "
          "tool's default): one scene draw per allocated page, straight into its slot, no "
          "superpage target (its 4 MiB count in memory() and so in pool.budget; on "
          "llvmpipe superpages made the frame 1.4-2.1x slower: docs/techniques/rmsm.md)."));
  p.push_back(
      choiceParam("lod.derivatives", "LOD derivatives", "Pages", {"neighbour", "same-surface"},
                  SL_RMSM_DERIVATIVES_NEIGHBOUR)
          .withUniform("u_rmsmDerivatives")
          .withHelp("Where dX and dY of the LOD come from (G-buffer finite differences). neighbour "
                    "(the tool's default): the right / upper pixel, else the left / lower one, on "
                    "whatever surface it lies: at a silhouette the step jumps to another surface "
                    "and asks for a far coarser page. same-surface (the paper's reading: the "
                    "derivatives of the rasterised (s, t), taken within the pixel's own triangle): "
                    "the first of the two that lies on the pixel's surface (its offset within 0.1 "
                    "of the tangent plane, normals within 25.8 degrees), else as neighbour."));

  p.push_back(
      intParam("pool.budget", "Memory budget (bytes)", "Pages", 0, {0, 1073741824, 1048576})
          .withHelp("0: the pool holds pool.pages. Otherwise the technique's whole memory in bytes "
                    "(memory(): the pool, the page table, the per-pixel request image, the request "
                    "list, the sort's buffers, the superpage target): each frame, after the sort, "
                    "the pool gets the most pages that fit in what the rest leaves, and pool.pages "
                    "is ignored (16777216: uniform 2048²'s DEPTH_COMPONENT32F map). The paper "
                    "gives no pool size; this compares it at another technique's bytes."));

  TechniqueInfo info{"rmsm", "Resolution-matched shadow map",
                     "Lefohn, Sengupta, Owens 2007: every camera pixel asks for the page of a "
                     "virtual quadtree of shadow-map pages at the resolution its footprint needs; "
                     "only those pages are rendered, into one physical pool behind a page table. "
                     "Directional light only.",
                     std::move(p)};
  info.temporalState = true;  // pool.budget: the pool is the last frame's fit
  info.passes = {
      {"rmsm requests", "Page requests, dedup, compaction",
       "Per camera pixel (compute): light uv (s, t) and LOD l = floor(log2(sqrt(|dX x dY|))) in "
       "virtual texels, the key of the page serving it; a request stays only when its left and "
       "lower neighbours ask for a different page; the survivors are appended to one list.",
       "pages"},
      {"rmsm sort", "Sort, unique",
       "The compacted list (compute): a bitonic sort of the keys (padded to a power of two), "
       "then each key equal to its predecessor is dropped and a second sort moves the kept "
       "ones, in order, to the front: the sorted unique page list.",
       "pages"},
      {"rmsm allocate", "Read back, allocate",
       "The sorted unique list is read back; the top level (one root page "
       "unless the tree is cut) and then the requests, coarse to fine, take pool slots from the "
       "free list (while they do not fit, pages of the finest level move to their parents, "
       "sibling group by group); the page table's mip chain is finalised (each entry: its "
       "finest allocated ancestor) and uploaded.",
       "pages"},
      {"rmsm superpages", "Render superpages",
       "The allocated pages binned into " + std::to_string(SL_RMSM_SUPERPAGE) +
           "² superpages (blocks of one level; a coarser level smaller than that is one "
           "block): each is one scene draw, the exact depth through the map's matrix cropped "
           "to the block, into the superpage target (rmsm.render = superpages).",
       "pages", false, "rmsm.render", kRenderSuperpages},
      {"rmsm copy", "Copy pages into the pool",
       "After each superpage, its allocated pages' texel blocks are copied "
       "(glCopyImageSubData) into their pool slots; the Pages panel shows the pool "
       "(rmsm.render = superpages).",
       "pages", false, "rmsm.render", kRenderSuperpages},
      {"rmsm pages", "Render pages",
       "Every allocated page: the scene's exact depth through the map's matrix cropped to the "
       "page, into its slot of the pool (a viewport of page.size² texels; rmsm.render = "
       "pages).",
       "pages", false, "rmsm.render", kRenderPages},
  };
  info.publications = pagedMapPublicationDecls();
  info.publications.insert(
      info.publications.end(),
      {
          {"pages.coarsened",
           PublicationKind::Number,
           "Requests that got a coarser page because the pool ran out.",
           "",
           {}},
          {"pages.superpages",
           PublicationKind::Number,
           std::to_string(SL_RMSM_SUPERPAGE) +
               "² superpages the allocated pages fall into (Lefohn et al.'s render unit).",
           "",
           {}},
          {"pages.scene_draws",
           PublicationKind::Number,
           "Scene draws of the render step this frame: one per superpage (rmsm.render = "
           "superpages) or one per allocated page (pages).",
           "",
           {}},
          {"pages.render_texels",
           PublicationKind::Number,
           "Texels the render step's viewports cover this frame (each cleared and rasterised): "
           "the superpages' blocks, or page.size² per allocated page.",
           "",
           {}},
      });
  info.checkParams = checkPagedMapParams;
  return info;
}

RmsmShadowMap::RmsmShadowMap(const gl::ShaderLibrary& lib)
    : depthProgram_(lib),
      requestProgram_(lib, requestProgramDesc()),
      sortProgram_(lib, sortProgramDesc()),
      uniqueProgram_(lib, uniqueProgramDesc()),
      requests_(lib, "rmsm/compact") {}

void RmsmShadowMap::renderShadows(FrameContext& ctx) {
  // One lookup "map" per level (rmsm/lookup.glsl): a deeper tree is cut below its root.
  if (auto e = checkPagedMapParams(ctx.params)) throw std::runtime_error("rmsm: " + *e);
  const pages::VirtualLayout layout = pagedLayoutOf(ctx.params);
  const auto budget = std::uint64_t(ctx.params.get("pool.budget"));
  if (budget == 0) {
    *budgetPool_ = {};
    ensurePool(layout, ctx.params.getInt("pool.pages"), 0);
  } else if (budgetPool_->pages() > 0) {
    ensurePool(layout, budgetPool_->pages(), budgetPool_->columns);  // last frame's fit
  } else {
    ensurePool(layout, layout.topPages(), 0);  // refitted below, once the sort's size is known
  }

  LightFit fit;
  if (auto err = fitDirectionalLight(ctx.camera, ctx.aspect, ctx.scene.bounds,
                                     ctx.light.directionalTowards(), FocusSettings{}, fit))
    throw std::runtime_error(*err);
  view_ = depthMapView(fit);
  ctx.addOutline(view_.lightViewProj, OutlineRole::LightMap);

  requestPages(ctx);
  sortUnique(ctx);
  if (budget > 0) fitPoolToBudget(layout, budget, ctx.params.getInt("rmsm.render"));
  allocate(ctx);
  renderPages(ctx);

  publishNumber(ctx, "pages.coarsened", last_.allocation.coarsened);
  publishNumber(ctx, "pages.superpages", double(last_.superpages.size()));
  publishNumber(ctx, "pages.scene_draws", last_.sceneDraws);
  publishNumber(ctx, "pages.render_texels", double(last_.renderTexels));
  map_.publish(
      ctx, {.table = table_.get(),
            .levelStates = [&](int l) { return pages::levelStates(*table_, last_.unique, l); },
            .requests = last_.compacted,
            .poolLevels = [&] { return pages::poolLevels(last_.allocation, pool_->capacity()); },
            .requested = last_.allocation.requested,
            .allocated = int(last_.allocation.pages.size())});
}

void RmsmShadowMap::ensurePool(const pages::VirtualLayout& layout, int poolPages, int columns) {
  if (map_.ensure(layout, poolPages, layout.topPages(), "rmsm", columns) || !table_ ||
      pool_->capacity() != poolPages) {
    layout_ = layout;
    table_ = std::make_unique<pages::PageTable>(layout_);
    pool_ = std::make_unique<pages::PagePool>(poolPages);
  }
}

void RmsmShadowMap::fitPoolToBudget(const pages::VirtualLayout& layout, std::uint64_t budget,
                                    int render) {
  // Everything but the pool, as memory() will list it after the render step: the superpage
  // target exists exactly while rmsm.render = superpages.
  const std::uint64_t side = std::uint64_t(std::min(SL_RMSM_SUPERPAGE, layout.virtualResolution));
  const std::uint64_t superpage = render == kRenderSuperpages ? 4 * side * side : 0;
  const std::uint64_t rest =
      memory().bytes() - map_.poolBytes() - map_.superpageBytes() + superpage;
  const std::uint64_t pageBytes = 4ull * std::uint64_t(layout.pageSize) * layout.pageSize;
  const std::optional<pages::PoolShape> shape =
      budget > rest ? pages::fitPoolToBytes(budget - rest, pageBytes,
                                            kMaxPoolSideTexels / layout.pageSize, layout.topPages())
                    : std::nullopt;
  if (!shape)
    throw std::runtime_error(
        "rmsm: pool.budget = " + std::to_string(budget) + " bytes cannot hold the " +
        std::to_string(layout.topPages()) + " pages of the coarsest level (" +
        std::to_string(std::uint64_t(layout.topPages()) * pageBytes) + " bytes) beside the " +
        std::to_string(rest) +
        " bytes of the page table, request and sort buffers and superpage target; raise "
        "pool.budget");
  *budgetPool_ = *shape;
  ensurePool(layout, shape->pages(), shape->columns);
}

void RmsmShadowMap::requestPages(FrameContext& ctx) {
  auto pass = ctx.timer.scope("rmsm requests");
  const int w = ctx.width, h = ctx.height;
  requests_.ensure(w, h);
  const GLuint gx = GLuint((w + SL_RMSM_GROUP - 1) / SL_RMSM_GROUP);
  const GLuint gy = GLuint((h + SL_RMSM_GROUP - 1) / SL_RMSM_GROUP);
  requestProgram_.use();
  map_.setLayoutUniforms(requestProgram_, view_.lightViewProj);
  glBindTextureUnit(SL_UNIT_G_POSITION, ctx.gbuffer.position.id());
  glBindTextureUnit(SL_UNIT_G_NORMAL, ctx.gbuffer.normal.id());
  glBindImageTexture(SL_RMSM_IMAGE_REQUESTS, requests_.image().id(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                     GL_R32UI);
  glDispatchCompute(gx, gy, 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  requests_.compact();
}

void RmsmShadowMap::bitonicSort(const gl::Buffer& keys, std::uint32_t count) const {
  sortProgram_.use();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SL_RMSM_BUFFER_SORT, keys.id());
  sortProgram_.set("u_count", unsigned(count));
  const GLuint groups = GLuint((count + SL_RMSM_SORT_GROUP - 1) / SL_RMSM_SORT_GROUP);
  for (std::uint32_t k = 2; k <= count; k <<= 1)
    for (std::uint32_t j = k >> 1; j > 0; j >>= 1) {
      sortProgram_.set("u_k", unsigned(k));
      sortProgram_.set("u_j", unsigned(j));
      glDispatchCompute(groups, 1, 1);
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
}

void RmsmShadowMap::sortUnique(FrameContext& ctx) {
  auto pass = ctx.timer.scope("rmsm sort");
  // The list's length sizes the sort (a power of two at least 2, padded with SL_PAGE_NONE,
  // which sorts last): 4 bytes read back.
  const std::uint32_t count = requests_.count();
  compactedCount_ = count;
  // Buffers of this frame's sort size (reallocated when the power of two changes): the bytes
  // follow the list, not the pixel count (a few KiB, not MiBs).
  const std::uint32_t n = std::bit_ceil(std::max(count, 2u));
  const GLsizeiptr bytes = GLsizeiptr(4) * n;
  if (!sortKeys_ || sortKeys_.size() != bytes) {
    sortKeys_ = gl::Buffer::create(bytes, nullptr);
    uniqueKeys_ = gl::Buffer::create(bytes, nullptr);
  }
  if (!uniqueCount_) uniqueCount_ = gl::Buffer::create(4, nullptr);
  if (count > 0) glCopyNamedBufferSubData(requests_.list().id(), sortKeys_.id(), 4, 0, 4 * count);
  const std::uint32_t none = SL_PAGE_NONE, zero = 0;
  if (n > count)
    glClearNamedBufferSubData(sortKeys_.id(), GL_R32UI, GLintptr(4) * count,
                              GLsizeiptr(4) * (n - count), GL_RED_INTEGER, GL_UNSIGNED_INT, &none);
  glNamedBufferSubData(uniqueCount_.id(), 0, 4, &zero);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  bitonicSort(sortKeys_, n);

  uniqueProgram_.use();
  uniqueProgram_.set("u_count", unsigned(n));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SL_RMSM_BUFFER_SORT, sortKeys_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SL_RMSM_BUFFER_UNIQUE, uniqueKeys_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SL_RMSM_BUFFER_UNIQUE_COUNT, uniqueCount_.id());
  glDispatchCompute(GLuint((n + SL_RMSM_SORT_GROUP - 1) / SL_RMSM_SORT_GROUP), 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  bitonicSort(uniqueKeys_, n);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
}

void RmsmShadowMap::allocate(FrameContext& ctx) {
  auto pass = ctx.timer.scope("rmsm allocate");
  // The compacted list too: the Pages panel's heat map of this frame's requests.
  last_.compacted = requests_.keys(compactedCount_);
  std::uint32_t unique = 0;
  glGetNamedBufferSubData(uniqueCount_.id(), 0, 4, &unique);
  last_.unique = readPageKeys(uniqueKeys_, 0, std::min<std::size_t>(unique, compactedCount_));
  pool_->releaseAll();
  last_.allocation = pages::allocatePages(last_.unique, *pool_, *table_);
  last_.superpages = pages::binSuperpages(last_.allocation.pages, layout_, SL_RMSM_SUPERPAGE);

  map_.uploadTable(*table_);
}

void RmsmShadowMap::renderPages(FrameContext& ctx) {
  if (ctx.params.getInt("rmsm.render") == kRenderSuperpages) {
    last_.renderTexels = map_.renderSuperpages(depthProgram_, ctx.sceneGpu, view_.lightViewProj,
                                               last_.superpages, *table_, SL_RMSM_SUPERPAGE, true,
                                               &ctx.timer, "rmsm superpages", "rmsm copy");
    last_.sceneDraws = int(last_.superpages.size());
    return;
  }
  map_.releaseSuperpageTarget();
  auto pass = ctx.timer.scope("rmsm pages");
  map_.renderPages(depthProgram_, ctx.sceneGpu, view_.lightViewProj, last_.allocation.pages,
                   last_.allocation.slots, true);
  last_.sceneDraws = int(last_.allocation.pages.size());
  last_.renderTexels = std::int64_t(last_.sceneDraws) * layout_.pageSize * layout_.pageSize;
}

void RmsmShadowMap::bindLookup(const gl::Program& resolve, int firstUnit) const {
  map_.bindLookup(resolve, firstUnit, view_);
}

MemoryStats RmsmShadowMap::memory() const {
  MemoryStats m;
  map_.addMemory(m);
  requests_.addMemory(m, "page requests (per pixel)");
  if (sortKeys_) m.add("sorted requests", "R32UI", int(sortKeys_.size() / 4), 1, 1, 4);
  if (uniqueKeys_) m.add("unique requests", "R32UI", int(uniqueKeys_.size() / 4), 1, 1, 4);
  if (uniqueCount_) m.add("unique count", "R32UI", 1, 1, 1, 4);
  return m;
}

std::optional<std::string> RmsmShadowMap::reloadShaders(const gl::ShaderLibrary& lib) {
  if (auto e = depthProgram_.rebuild(lib)) return e;
  if (auto e = requestProgram_.rebuild(lib)) return e;
  if (auto e = requests_.reloadShaders(lib)) return e;
  if (auto e = sortProgram_.rebuild(lib)) return e;
  return uniqueProgram_.rebuild(lib);
}

}  // namespace sl
