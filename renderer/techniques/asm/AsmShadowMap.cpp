// Adaptive shadow maps (AsmShadowMap.h): the coarse map, then iterations of shadow test + edge
// finding and RMSM's dedup + compaction in compute, the page cache of algo/asm on the CPU, one
// depth pass per new page into the pool.
#include "AsmShadowMap.h"

#include <cmath>
#include <stdexcept>

#include "algo/Focus.h"
#include "algo/pages/PageRequests.h"
#include "algo/pages/PageViews.h"
#include "common/shared_constants.h"
#include "core/LightBinding.h"
#include "core/Publish.h"
#include "core/SceneGpu.h"

namespace sl {

namespace {

gl::ProgramDesc testProgramDesc() {
  return {"asm/test", {{GL_COMPUTE_SHADER, "asm/test.comp"}}, {}, {}};
}
gl::ProgramDesc edgesProgramDesc() {
  return {"asm/edges", {{GL_COMPUTE_SHADER, "asm/edges.comp"}}, {}, {}};
}
gl::ProgramDesc compactProgramDesc() {
  return {"asm/compact", {{GL_COMPUTE_SHADER, "rmsm/compact.comp"}}, {}, {}};
}

std::string iterationPass(const char* what, int i) {
  return std::string("asm ") + what + " " + std::to_string(i);
}

/// The quadtree level of the coarse map: log2(virtual / coarse) (checkAsmParams held).
int coarseLevelOf(const pages::VirtualLayout& layout, int coarseResolution) {
  int level = 0;
  while ((layout.virtualResolution >> level) > coarseResolution) ++level;
  return level;
}

/// What renderShadows needs of the values together (TechniqueInfo::checkParams): the paged
/// map's, and a coarse map on a level of the quadtree that the pool holds.
std::optional<std::string> checkAsmParams(const ParamSet& p) {
  if (auto e = checkPagedMapParams(p)) return e;
  const pages::VirtualLayout layout = pagedLayoutOf(p);
  const int coarse = p.getInt("asm.coarse.resolution");
  const int coarsest = layout.virtualResolution >> layout.topLevel();
  if (auto e = checkPowerOfTwo(p, "asm.coarse.resolution")) return e;
  if (coarse < coarsest || coarse > layout.virtualResolution)
    return "asm.coarse.resolution = " + std::to_string(coarse) + " must be from " +
           std::to_string(coarsest) +
           " (the coarsest level of the quadtree of virtual.resolution = " +
           std::to_string(layout.virtualResolution) +
           " in pages of page.size = " + std::to_string(layout.pageSize) + ") to " +
           std::to_string(layout.virtualResolution) +
           "; change asm.coarse.resolution, page.size or virtual.resolution";
  const int level = coarseLevelOf(layout, coarse);
  const int coarsePages = layout.pagesPerSide(level) * layout.pagesPerSide(level);
  const int poolPages = p.getInt("pool.pages");
  if (poolPages < coarsePages)
    return "pool.pages = " + std::to_string(poolPages) + " cannot hold the " +
           std::to_string(coarsePages) +
           " pages of the coarse map (asm.coarse.resolution = " + std::to_string(coarse) +
           ", page.size = " + std::to_string(layout.pageSize) +
           "); raise pool.pages or lower asm.coarse.resolution";
  return std::nullopt;
}

}  // namespace

TechniqueInfo AsmShadowMap::info() {
  std::vector<ParamDecl> p = pagedMapParamDecls();
  setParamHelp(p, "virtual.resolution",
               "Texels per side of the virtual shadow map over the whole scene (level 0, the "
               "finest pages); a power of two. Its quadtree is cut at 8 levels, as RMSM's.");
  setParamHelp(p, "page.size",
               "Texels per side of one page (a power of two): the unit of refinement, caching "
               "and rendering.");
  setParamHelp(p, "lod.bias",
               "An edge pixel asks for the page this many levels finer than its footprint "
               "needs (0: one texel per pixel), as in rmsm.");
  setParamHelp(p, "pool.pages",
               "Pages the physical pool holds (256 pages of 128²: the bytes of one uniform "
               "2048² map), the coarse map's included. When it is full, the least recently "
               "used page no pixel of this frame used is evicted (asm.evicted).");
  auto add = [&](ParamDecl d) { p.push_back(std::move(d)); };
  add({.key = "asm.coarse.resolution",
       .label = "Coarse map",
       .group = "ASM",
       .type = ParamType::Int,
       .defaultValue = 512,
       .minValue = 16,
       .maxValue = 262144,
       .step = 16,
       .help = "Texels per side of the coarse map ASM starts from (a power of two, every page "
               "of that level always held): a shadow that falls inside one of its texels has "
               "no edge there, and is never refined (the missed fine shadow)."});
  add({.key = "asm.iterations",
       .label = "Iterations",
       .group = "ASM",
       .type = ParamType::Int,
       .defaultValue = 4,
       .minValue = 1,
       .maxValue = adaptive::kMaxIterations,
       .step = 1,
       .help = "Refinement iterations per frame at most (edge finding, requests, allocation, "
               "render): the loop also stops when an iteration allocates nothing."});
  add({.key = "asm.pages.per.frame",
       .label = "Pages per frame",
       .group = "ASM",
       .type = ParamType::Int,
       .defaultValue = 64,
       .minValue = 1,
       .maxValue = 4096,
       .step = 1,
       .help = "New pages rendered per frame at most (the coarse map after an invalidation "
               "aside); the rest waits for the next frames (asm.deferred)."});

  TechniqueInfo info{"asm", "Adaptive shadow map",
                     "Fernando, Fernandez, Bala, Greenberg 2001: a quadtree of shadow-map pages "
                     "refined where camera pixels lie on shadow edges, starting from a coarse "
                     "map, kept between frames as a cache. Directional light only.",
                     std::move(p)};
  info.passes.push_back(
      {"asm coarse", "Coarse map",
       "After an invalidation (the light or the geometry moved, the layout changed): every page "
       "of the coarse level rendered into the pool. Otherwise empty: the cached pages stay.",
       "pages"});
  for (int i = 1; i <= adaptive::kMaxIterations; ++i) {
    const std::string n = std::to_string(i);
    info.passes.push_back(
        {iterationPass("edges", i), "Iteration " + n + ": edge finding",
         "Per camera pixel (compute): the hard shadow test through the quadtree as it stands, "
         "then a pixel whose test differs from a neighbour's and whose page is coarser than its "
         "LOD asks for the page at its LOD; the other pixels mark the page they used; dedup and "
         "compaction as in rmsm. Empty when the loop stopped before iteration " +
             n + ".",
         "pages"});
    info.passes.push_back(
        {iterationPass("allocate", i), "Iteration " + n + ": allocate",
         "Read back, sort, unique; requested pages take free pool slots, coarsest first, or "
         "evict the least recently used page no pixel used this frame; at most "
         "asm.pages.per.frame per frame; the page table is uploaded.",
         "pages"});
    info.passes.push_back({iterationPass("pages", i), "Iteration " + n + ": render pages",
                           "The new pages' exact depth into their pool slots; the cached "
                           "pages are not rendered again.",
                           "pages"});
  }
  for (const char* key :
       {"asm.iterations.run", "asm.requests", "asm.new", "asm.hits", "asm.evicted", "asm.refused",
        "asm.deferred", "asm.cached", "asm.invalidations", "asm.pool"}) {
    info.publications.push_back({key, PublicationKind::Number, "", "", {}});
  }
  info.publications[0].what =
      "Refinement iterations this frame (the last allocated nothing, "
      "or the budget or asm.iterations ran out).";
  info.publications[1].what = "Page requests from edge pixels this frame, all iterations.";
  info.publications[2].what = "Pages rendered this frame (coarse map aside).";
  info.publications[3].what = "Cached pages from earlier frames used this frame.";
  info.publications[4].what = "Pages evicted (least recently used) this frame.";
  info.publications[5].what = "Requests refused: the pool held only pages used this frame.";
  info.publications[6].what = "Requests left for later frames (asm.pages.per.frame spent).";
  info.publications[7].what = "Pages the pool holds after this frame (coarse map included).";
  info.publications[8].what = "Times the cache was dropped since the technique was made.";
  info.publications[9].what = "Pages the pool holds at most (pool.pages).";
  // The Pages panel's page table, pool and requests, as rmsm's (the cache's states).
  for (PublicationDecl& d : pagedMapPublicationDecls()) info.publications.push_back(std::move(d));
  info.checkParams = checkAsmParams;
  return info;
}

AsmShadowMap::AsmShadowMap(const gl::ShaderLibrary& lib)
    : depthProgram_(lib),
      testProgram_(lib, testProgramDesc()),
      edgesProgram_(lib, edgesProgramDesc()),
      compactProgram_(lib, compactProgramDesc()) {}

void AsmShadowMap::renderShadows(FrameContext& ctx) {
  if (auto e = checkAsmParams(ctx.params)) throw std::runtime_error("asm: " + *e);
  const pages::VirtualLayout layout = pagedLayoutOf(ctx.params);
  const int poolPages = ctx.params.getInt("pool.pages");
  const int coarseLevel = coarseLevelOf(layout, ctx.params.getInt("asm.coarse.resolution"));
  map_.ensure(layout, poolPages, layout.topPages(), "asm");

  // The whole scene, not the view: pages stay valid while only the camera moves.
  LightFit fit;
  if (auto err = fitDirectionalLightToScene(ctx.scene.bounds, ctx.light.directionalTowards(), fit))
    throw std::runtime_error(*err);
  view_ = depthMapView(fit);
  ctx.addOutline(view_.lightViewProj, OutlineRole::LightMap);

  const CacheKey key{view_.lightViewProj,
                     ctx.scene.primitives.size(),
                     ctx.scene.bounds.min,
                     ctx.scene.bounds.max,
                     layout.virtualResolution,
                     layout.pageSize,
                     poolPages,
                     coarseLevel};
  last_ = FrameResult{};
  if (cache_) cache_->beginFrame();
  {
    auto pass = ctx.timer.scope("asm coarse");
    if (!cache_ || !(key == cacheKey_)) {
      if (!cache_ || cache_->pool().capacity() != poolPages ||
          cache_->coarseLevel() != coarseLevel ||
          !(cache_->layout().virtualResolution == layout.virtualResolution &&
            cache_->layout().pageSize == layout.pageSize))
        cache_ = std::make_unique<adaptive::PageCache>(layout, poolPages, coarseLevel);
      cacheKey_ = key;
      std::vector<int> slots;
      const std::vector<pages::PageId> coarse = cache_->invalidate(slots);
      map_.uploadTable(cache_->table());
      map_.renderPages(depthProgram_, ctx.sceneGpu, view_.lightViewProj, coarse, slots, true);
      last_.invalidated = true;
      last_.coarsePages = int(coarse.size());
    }
  }

  const int w = ctx.width, h = ctx.height;
  if (!tested_ || tested_.width() != w || tested_.height() != h) {
    tested_ = gl::Texture::create2D(GL_RGBA32UI, w, h);
    requests_ = gl::Texture::create2D(GL_R32UI, w, h);
    requestList_ = gl::Buffer::create(GLsizeiptr(4) * (1 + GLsizeiptr(w) * h), nullptr);
  }
  int budget = ctx.params.getInt("asm.pages.per.frame");
  const int iterations = ctx.params.getInt("asm.iterations");
  bool going = true;
  for (int i = 1; i <= adaptive::kMaxIterations; ++i) {
    if (going && i <= iterations) {
      going = iterate(ctx, i, budget);
    } else {
      // Every declared pass is timed every frame: the iterations not run are empty.
      for (const char* what : {"edges", "allocate", "pages"}) {
        auto pass = ctx.timer.scope(iterationPass(what, i));
      }
    }
  }

  int requests = 0, hits = 0, evicted = 0;
  for (const adaptive::Refinement& r : last_.iterations) {
    requests += r.requests;
    hits += r.hits;
    evicted += r.evicted;
  }
  const adaptive::Refinement& lastRun = last_.iterations.back();
  publishNumber(ctx, "asm.iterations.run", double(last_.iterations.size()));
  publishNumber(ctx, "asm.requests", requests);
  publishNumber(ctx, "asm.new", last_.newPages);
  publishNumber(ctx, "asm.hits", hits);
  publishNumber(ctx, "asm.evicted", evicted);
  publishNumber(ctx, "asm.refused", lastRun.refused);
  publishNumber(ctx, "asm.deferred", lastRun.deferred);
  publishNumber(ctx, "asm.cached", cache_->pool().usedCount());
  publishNumber(ctx, "asm.invalidations", cache_->invalidations());
  publishNumber(ctx, "asm.pool", poolPages);
  last_.requested = pages::sortUnique(last_.requestKeys);
  map_.publish(ctx,
               {.table = &cache_->table(),
                .levelStates =
                    [&](int l) { return adaptive::cacheLevelStates(*cache_, last_.requested, l); },
                .requests = last_.requestKeys,
                .poolLevels = [&] { return adaptive::cachePoolLevels(*cache_); },
                .requested = int(last_.requested.size()),
                .allocated = cache_->pool().usedCount()});
}

void AsmShadowMap::findEdges(FrameContext& ctx) {
  const int w = ctx.width, h = ctx.height;
  const GLuint gx = GLuint((w + SL_RMSM_GROUP - 1) / SL_RMSM_GROUP);
  const GLuint gy = GLuint((h + SL_RMSM_GROUP - 1) / SL_RMSM_GROUP);
  // The shadow test through the quadtree as it stands (the resolve's lookup and bias).
  testProgram_.use();
  map_.bindLookup(testProgram_, SL_UNIT_LOOKUP_FIRST, view_);
  bindLight(testProgram_, ctx.light);
  glBindTextureUnit(SL_UNIT_G_POSITION, ctx.gPosition.id());
  glBindTextureUnit(SL_UNIT_G_NORMAL, ctx.gNormal.id());
  glBindImageTexture(SL_ASM_IMAGE_TESTED, tested_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32UI);
  glDispatchCompute(gx, gy, 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  // Edges: one key per pixel.
  edgesProgram_.use();
  glBindImageTexture(SL_ASM_IMAGE_TESTED, tested_.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32UI);
  glBindImageTexture(SL_RMSM_IMAGE_REQUESTS, requests_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                     GL_R32UI);
  glDispatchCompute(gx, gy, 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  // RMSM's dedup + compaction.
  const std::uint32_t zero = 0;
  glNamedBufferSubData(requestList_.id(), 0, 4, &zero);
  compactProgram_.use();
  glBindImageTexture(SL_RMSM_IMAGE_REQUESTS, requests_.id(), 0, GL_FALSE, 0, GL_READ_ONLY,
                     GL_R32UI);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SL_RMSM_BUFFER_REQUESTS, requestList_.id());
  glDispatchCompute(gx, gy, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

bool AsmShadowMap::iterate(FrameContext& ctx, int iteration, int& budget) {
  {
    auto pass = ctx.timer.scope(iterationPass("edges", iteration));
    findEdges(ctx);
  }
  adaptive::Refinement r;
  {
    auto pass = ctx.timer.scope(iterationPass("allocate", iteration));
    std::uint32_t count = 0;
    glGetNamedBufferSubData(requestList_.id(), 0, 4, &count);
    const std::size_t capacity = std::size_t(requestList_.size() / 4 - 1);
    last_.compacted.assign(std::min<std::size_t>(count, capacity), 0u);
    if (!last_.compacted.empty())
      glGetNamedBufferSubData(requestList_.id(), 4, GLsizeiptr(4 * last_.compacted.size()),
                              last_.compacted.data());
    last_.unique = pages::sortUnique(last_.compacted);
    last_.uniquePerIteration.push_back(last_.unique);
    for (pages::PageKey k : last_.compacted)
      if (k != pages::kNoPage && (k & adaptive::kTouchBit) == 0) last_.requestKeys.push_back(k);
    r = cache_->refine(last_.unique, budget);
    budget -= int(r.allocated.size());
    if (!r.allocated.empty()) map_.uploadTable(cache_->table());
  }
  {
    auto pass = ctx.timer.scope(iterationPass("pages", iteration));
    if (!r.allocated.empty())
      map_.renderPages(depthProgram_, ctx.sceneGpu, view_.lightViewProj, r.allocated, r.slots,
                       false);
  }
  last_.newPages += int(r.allocated.size());
  const bool progressed = !r.allocated.empty() && budget > 0;
  last_.iterations.push_back(std::move(r));
  return progressed;
}

void AsmShadowMap::bindLookup(const gl::Program& resolve, int firstUnit) const {
  map_.bindLookup(resolve, firstUnit, view_);
}

MemoryStats AsmShadowMap::memory() const {
  MemoryStats m;
  map_.addMemory(m);
  if (tested_)
    m.add("shadow test (per pixel: mask, page, refine)", "RGBA32UI", tested_.width(),
          tested_.height(), 1, 16);
  if (requests_)
    m.add("edge requests (per pixel)", "R32UI", requests_.width(), requests_.height(), 1, 4);
  if (requestList_)
    m.add("compacted requests (count + keys)", "R32UI", int(requestList_.size() / 4), 1, 1, 4);
  return m;
}

std::optional<std::string> AsmShadowMap::reloadShaders(const gl::ShaderLibrary& lib) {
  if (auto e = depthProgram_.rebuild(lib)) return e;
  if (auto e = testProgram_.rebuild(lib)) return e;
  if (auto e = edgesProgram_.rebuild(lib)) return e;
  return compactProgram_.rebuild(lib);
}

}  // namespace sl
