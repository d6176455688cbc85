// Adaptive shadow maps (AsmShadowMap.h): the coarse map, then iterations of shadow test + edge
// finding and RMSM's dedup + compaction in compute, the page cache of algo/asm on the CPU, one
// depth pass per new page into the pool.
#include "AsmShadowMap.h"

#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
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
  add(intParam("asm.coarse.resolution", "Coarse map", "ASM", 512, {16, 262144, 16})
          .withHelp("Texels per side of the coarse map ASM starts from (a power of two, every page "
                    "of that level always held): a shadow that falls inside one of its texels has "
                    "no edge there, and is never refined (the missed fine shadow)."));
  add(intParam("asm.iterations", "Iterations", "ASM", 4, {1, adaptive::kMaxIterations, 1})
          .withHelp("Refinement iterations per frame at most (edge finding, requests, allocation, "
                    "render): the loop also stops when an iteration allocates nothing."));
  add(intParam("asm.pages.per.frame", "Pages per frame", "ASM", 64, {1, 4096, 1})
          .withHelp("New pages rendered per frame at most (the coarse map after an invalidation "
                    "aside); the rest waits for the next frames (asm.deferred)."));

  add(choiceParam("asm.edge", "Edge test", "ASM", {"screen-mask", "map-texel"}, SL_ASM_EDGE_SCREEN)
          .withHelp("What makes a camera pixel an edge pixel that asks for a finer page. "
                    "screen-mask (the tool's): its shadow mask differs from a 4-neighbour's in the "
                    "camera image; unlike the paper it also fires at a terminator, where a pixel "
                    "facing away from the light counts as shadowed. map-texel (Fernando et al. "
                    "2001): the shadow-map texel it reads lies on a shadow edge of the map, the "
                    "pixel's depth tests at that texel and its 4 neighbours disagreeing."));
  add(choiceParam("asm.loop", "Refinement loop", "ASM", {"budget", "until-done"})
          .withHelp(
              "budget (the tool's): at most asm.iterations iterations and asm.pages.per.frame new "
              "pages a frame, the rest waiting for later frames. until-done (Fernando et al. "
              "2001): iterate until no page is requested, with no page budget, stopped only by "
              "asm.iterations.cap (asm.stop, asm.requests.left say when the cap stopped it and "
              "what it left) or a full pool."));
  add(pagedRenderParamDecl(
      "asm.render", "ASM",
      "How an iteration renders its new pages. superpages (the lecture's ASM loop: "
      "'bin requests into superpages, render shadow data into superpages, copy shadow "
      "data from superpage to quadtree'): the new pages are binned into " +
          std::to_string(SL_RMSM_SUPERPAGE) +
          "² blocks of one level, each block is rendered once into a superpage target "
          "and its new pages are copied into their pool slots (one scene draw per "
          "superpage; the target's 4 MiB count in memory()). pages (the tool's default): "
          "one scene draw per new page, straight into its slot, no superpage target."));
  add(intParam("asm.iterations.cap", "Iteration cap", "ASM", 16, {1, 64, 1})
          .withHelp("With asm.loop = until-done, the most iterations a frame runs (the paper has "
                    "no cap); when it stops a loop still refining, the frame publishes asm.stop = "
                    "1 and the pages still requested (asm.requests.left), and asm.cap.stops counts "
                    "it until the pages are next dropped."));

  TechniqueInfo info{"asm", "Adaptive shadow map",
                     "Fernando, Fernandez, Bala, Greenberg 2001: a quadtree of shadow-map pages "
                     "refined where camera pixels lie on shadow edges, starting from a coarse "
                     "map, kept between frames as a cache. Directional light only.",
                     std::move(p)};
  info.temporalState = true;  // the page cache
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
    info.passes.push_back(
        {iterationPass("pages", i), "Iteration " + n + ": render pages",
         "The new pages' exact depth into their pool slots (asm.render = pages: one draw per "
         "page; superpages: one draw per superpage holding new pages, then the pages copied "
         "into their slots); the cached pages are not rendered again.",
         "pages"});
  }
  info.passes.push_back(
      {"asm more", "Further iterations",
       "With asm.loop = until-done: every iteration after the " +
           std::to_string(adaptive::kMaxIterations) +
           "th (edge finding, allocation, pages), and when the cap stops a loop still refining, "
           "one more edge finding that counts the requests left. Otherwise empty.",
       "pages"});
  for (const char* key :
       {"asm.iterations.run", "asm.requests", "asm.new", "asm.hits", "asm.evicted", "asm.refused",
        "asm.deferred", "asm.cached", "asm.invalidations", "asm.pool", "asm.stop",
        "asm.requests.left", "asm.superpages", "asm.scene_draws", "asm.cap.stops"}) {
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
  info.publications[10].what =
      "Why the refinement loop stopped: 0 no new page requested (converged, the paper's end), "
      "1 the iteration cap (asm.iterations, or asm.iterations.cap with asm.loop = until-done), "
      "2 the per-frame page budget, 3 the pool held only pages used this frame.";
  info.publications[11].what =
      "Distinct pages still requested and not held when the loop stopped (0 when it "
      "converged; with asm.loop = budget, a cap stop counts only the last iteration's).";
  info.publications[12].what =
      "Superpages rendered this frame, all iterations (asm.render = superpages; 0 with pages).";
  info.publications[13].what =
      "Scene draws of the iterations' render steps this frame (coarse map aside): one per "
      "superpage, or one per new page.";
  info.publications[14].what =
      "Frames since the page cache was last dropped whose loop the iteration cap stopped "
      "(asm.stop 1): a cap stop stays visible after later frames converged.";
  // The Pages panel's page table, pool and requests, as rmsm's (the cache's states).
  for (PublicationDecl& d : pagedMapPublicationDecls()) info.publications.push_back(std::move(d));
  info.checkParams = checkAsmParams;
  return info;
}

AsmShadowMap::AsmShadowMap(const gl::ShaderLibrary& lib)
    : depthProgram_(lib),
      testProgram_(lib, testProgramDesc()),
      edgesProgram_(lib, edgesProgramDesc()),
      requests_(lib, "asm/compact") {}

void AsmShadowMap::commitFrame() {
  carried_.commit();
  map_.forgetKept();
}

void AsmShadowMap::discardFrame() {
  carried_.discard();
  map_.restoreKept();
  if (carried_->cache) map_.uploadTable(carried_->cache->table());
}

void AsmShadowMap::keepCommittedPages(std::span<const int> slots) {
  const std::optional<adaptive::PageCache>& committed = carried_.committed().cache;
  const adaptive::PageCache& now = *carried_->cache;
  if (!committed || committed->pool().capacity() != now.pool().capacity() ||
      committed->layout().pageSize != now.layout().pageSize)
    return;  // a new pool: the committed pages are gone with the old one
  std::vector<int> held;
  for (const int slot : slots)
    if (committed->lastUsed(slot) >= 0) held.push_back(slot);
  if (!held.empty()) map_.keepSlots(held);
}

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
  if (carried_->cache) carried_->cache->beginFrame();
  {
    auto pass = ctx.timer.scope("asm coarse");
    if (!carried_->cache || !(key == carried_->key)) {
      if (!carried_->cache || carried_->cache->pool().capacity() != poolPages ||
          carried_->cache->coarseLevel() != coarseLevel ||
          !(carried_->cache->layout().virtualResolution == layout.virtualResolution &&
            carried_->cache->layout().pageSize == layout.pageSize))
        carried_->cache.emplace(layout, poolPages, coarseLevel);
      carried_->key = key;
      std::vector<int> slots;
      const std::vector<pages::PageId> coarse = carried_->cache->invalidate(slots);
      std::vector<int> pool(std::size_t(carried_->cache->pool().capacity()));
      std::iota(pool.begin(), pool.end(), 0);
      keepCommittedPages(pool);  // the whole pool is cleared
      map_.uploadTable(carried_->cache->table());
      map_.renderPages(depthProgram_, ctx.sceneGpu, view_.lightViewProj, coarse, slots, true);
      last_.invalidated = true;
      carried_->capStops = 0;
      last_.coarsePages = int(coarse.size());
    }
  }

  const int w = ctx.width, h = ctx.height;
  if (!tested_ || tested_.width() != w || tested_.height() != h) {
    tested_ = gl::Texture::create2D(GL_RGBA32UI, w, h);
  }
  requests_.ensure(w, h);
  superpages_ = ctx.params.getInt("asm.render") == kRenderSuperpages;
  if (!superpages_) map_.releaseSuperpageTarget();
  const bool untilDone = ctx.params.getInt("asm.loop") == 1;
  int budget =
      untilDone ? std::numeric_limits<int>::max() : ctx.params.getInt("asm.pages.per.frame");
  const int iterations =
      untilDone ? ctx.params.getInt("asm.iterations.cap") : ctx.params.getInt("asm.iterations");
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
  {
    auto pass = ctx.timer.scope("asm more");
    for (int i = adaptive::kMaxIterations + 1; going && i <= iterations; ++i)
      going = iterate(ctx, i, budget);
    const adaptive::Refinement& r = last_.iterations.back();
    last_.requestsLeft = r.refused + r.deferred;
    if (r.refused > 0)
      last_.stop = kPoolFull;
    else if (r.deferred > 0 || budget <= 0)
      last_.stop = kBudget;
    else if (r.allocated.empty())
      last_.stop = kConverged;
    else {
      last_.stop = kIterationCap;
      if (untilDone) {
        // The cap stopped a loop that was still refining: one more edge finding says how many
        // pages it would still have asked for.
        findEdges(ctx);
        last_.requestsLeft = 0;
        for (pages::PageKey k : pages::sortUnique(requests_.compacted()))
          if (k != pages::kNoPage && (k & adaptive::kTouchBit) == 0 &&
              carried_->cache->table().slot(pages::unpackPage(k)) < 0)
            ++last_.requestsLeft;
        if (last_.requestsLeft == 0) last_.stop = kConverged;  // the cap was not needed
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
  publishNumber(ctx, "asm.cached", carried_->cache->pool().usedCount());
  publishNumber(ctx, "asm.invalidations", carried_->cache->invalidations());
  publishNumber(ctx, "asm.pool", poolPages);
  publishNumber(ctx, "asm.stop", last_.stop);
  publishNumber(ctx, "asm.requests.left", last_.requestsLeft);
  if (last_.stop == kIterationCap) ++carried_->capStops;
  publishNumber(ctx, "asm.cap.stops", carried_->capStops);
  publishNumber(ctx, "asm.superpages", last_.superpages);
  publishNumber(ctx, "asm.scene_draws", last_.sceneDraws);
  last_.requested = pages::sortUnique(last_.requestKeys);
  map_.publish(ctx, {.table = &carried_->cache->table(),
                     .levelStates =
                         [&](int l) {
                           return adaptive::cacheLevelStates(*carried_->cache, last_.requested, l);
                         },
                     .requests = last_.requestKeys,
                     .poolLevels = [&] { return adaptive::cachePoolLevels(*carried_->cache); },
                     .requested = int(last_.requested.size()),
                     .allocated = carried_->cache->pool().usedCount()});
}

void AsmShadowMap::findEdges(FrameContext& ctx) {
  const int w = ctx.width, h = ctx.height;
  const GLuint gx = GLuint((w + SL_RMSM_GROUP - 1) / SL_RMSM_GROUP);
  const GLuint gy = GLuint((h + SL_RMSM_GROUP - 1) / SL_RMSM_GROUP);
  // The shadow test through the quadtree as it stands (the resolve's lookup and bias).
  testProgram_.use();
  map_.bindLookup(testProgram_, SL_UNIT_LOOKUP_FIRST, view_);
  bindLight(testProgram_, ctx.light);
  glBindTextureUnit(SL_UNIT_G_POSITION, ctx.gbuffer.position.id());
  glBindTextureUnit(SL_UNIT_G_NORMAL, ctx.gbuffer.normal.id());
  glBindImageTexture(SL_ASM_IMAGE_TESTED, tested_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32UI);
  glDispatchCompute(gx, gy, 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  // Edges: one key per pixel.
  edgesProgram_.use();
  edgesProgram_.set("u_edgeTest", ctx.params.getInt("asm.edge"));
  glBindImageTexture(SL_ASM_IMAGE_TESTED, tested_.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32UI);
  glBindImageTexture(SL_RMSM_IMAGE_REQUESTS, requests_.image().id(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                     GL_R32UI);
  glDispatchCompute(gx, gy, 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  requests_.compact();  // RMSM's dedup + compaction
}

bool AsmShadowMap::iterate(FrameContext& ctx, int iteration, int& budget) {
  // Iterations past the declared ones run inside the caller's "asm more" pass.
  const bool timed = iteration <= adaptive::kMaxIterations;
  std::optional<gl::GpuTimer::Scope> pass;
  if (timed) pass.emplace(ctx.timer, iterationPass("edges", iteration));
  findEdges(ctx);
  pass.reset();
  adaptive::Refinement r;
  if (timed) pass.emplace(ctx.timer, iterationPass("allocate", iteration));
  last_.compacted = requests_.compacted();
  last_.unique = pages::sortUnique(last_.compacted);
  last_.uniquePerIteration.push_back(last_.unique);
  for (pages::PageKey k : last_.compacted)
    if (k != pages::kNoPage && (k & adaptive::kTouchBit) == 0) last_.requestKeys.push_back(k);
  r = carried_->cache->refine(last_.unique, budget);
  budget -= int(r.allocated.size());
  if (!r.allocated.empty()) map_.uploadTable(carried_->cache->table());
  pass.reset();
  if (timed) pass.emplace(ctx.timer, iterationPass("pages", iteration));
  if (!r.allocated.empty()) {
    keepCommittedPages(r.slots);
    if (superpages_) {
      // The lecture's loop: bin the new pages into superpages, render each, copy its pages.
      const std::vector<pages::Superpage> bins =
          pages::binSuperpages(r.allocated, carried_->cache->layout(), SL_RMSM_SUPERPAGE);
      map_.renderSuperpages(depthProgram_, ctx.sceneGpu, view_.lightViewProj, bins,
                            carried_->cache->table(), SL_RMSM_SUPERPAGE, false, nullptr, {}, {});
      last_.superpages += int(bins.size());
      last_.sceneDraws += int(bins.size());
    } else {
      map_.renderPages(depthProgram_, ctx.sceneGpu, view_.lightViewProj, r.allocated, r.slots,
                       false);
      last_.sceneDraws += int(r.allocated.size());
    }
  }
  pass.reset();
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
  requests_.addMemory(m, "edge requests (per pixel)");
  return m;
}

std::optional<std::string> AsmShadowMap::reloadShaders(const gl::ShaderLibrary& lib) {
  if (auto e = depthProgram_.rebuild(lib)) return e;
  if (auto e = testProgram_.rebuild(lib)) return e;
  if (auto e = edgesProgram_.rebuild(lib)) return e;
  return requests_.reloadShaders(lib);
}

}  // namespace sl
