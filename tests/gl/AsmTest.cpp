// The `asm` technique (adaptive shadow maps, Fernando et al. 2001): GPU-vs-CPU parity of the
// edge-finding pass and its dedup + compaction (algo/asm and algo/pages are the reference),
// the shadow test pass agreeing with the resolve once the quadtree converged, the page cache
// (camera moves keep pages, a light change or a new scene drops them and no stale page is
// used), exact memory, declared passes == timed passes, bad parameters, the Pages panel's
// publications (the CPU cache's states); the paper's map-texel edge test against its CPU
// reference, the paper's loop until no request and the cap that says what it left.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>

#include "GlTestEnv.h"
#include "algo/asm/AdaptivePages.h"
#include "algo/pages/PageRequests.h"
#include "algo/pages/PageViews.h"
#include "common/shared_constants.h"
#include "core/Preset.h"
#include "core/Technique.h"
#include "gl/Gl.h"
#include "techniques/asm/AsmShadowMap.h"

namespace sl {
namespace {

AsmShadowMap* g_probe = nullptr;

std::unique_ptr<Renderer> makeProbe(const std::string& scene) {
  test::eglContext().makeCurrent();
  RendererOptions o;
  TechniqueEntry e{AsmShadowMap::info(), [](const gl::ShaderLibrary& lib) {
                     auto t = std::make_unique<AsmShadowMap>(lib);
                     g_probe = t.get();
                     return std::unique_ptr<Technique>(std::move(t));
                   }};
  e.info.id = "asm-probe";
  o.extraTechniques.push_back(std::move(e));
  auto r = std::make_unique<Renderer>(o);
  auto s = test::loadBuiltin(scene);
  if (!s) return nullptr;
  r->setScene(s);
  r->setCamera(s->cameras.empty() ? s->defaultCamera() : s->cameras.front().camera);
  EXPECT_FALSE(r->setTechnique("asm-probe"));
  return r;
}

std::vector<std::uint32_t> readUint(const gl::Texture& t, GLenum format, int channels) {
  std::vector<std::uint32_t> out(std::size_t(t.width()) * t.height() * channels);
  glGetTextureImage(t.id(), 0, format, GL_UNSIGNED_INT, GLsizei(out.size() * 4), out.data());
  return out;
}

std::vector<adaptive::TestedPixel> readTested(const AsmShadowMap& t) {
  const std::vector<std::uint32_t> raw = readUint(t.testedImage(), GL_RGBA_INTEGER, 4);
  std::vector<adaptive::TestedPixel> px(raw.size() / 4);
  for (std::size_t i = 0; i < px.size(); ++i)
    px[i] = {raw[4 * i], raw[4 * i + 1], raw[4 * i + 2], raw[4 * i + 3]};
  return px;
}

// One iteration from the coarse map: the GPU's per-pixel keys are findEdges of the GPU's own
// shadow test (exact), its compacted list is dedup + compaction of those keys (exact, order
// aside), every served page is allocated and every refine key lies below its served page.
TEST(Asm, EdgeFindingMatchesTheCpuReference) {
  auto r = makeProbe("plane-box");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->params().set("virtual.resolution", 16384));
  ASSERT_FALSE(r->params().set("asm.iterations", 1));
  const int w = 160, h = 90;
  ASSERT_FALSE(r->renderFrame(w, h, 0));
  ASSERT_TRUE(g_probe);
  const AsmShadowMap& t = *g_probe;
  const std::vector<adaptive::TestedPixel> tested = readTested(t);
  const std::vector<pages::PageKey> cpu = adaptive::findEdges(tested, w, h);
  const std::vector<std::uint32_t> gpu = readUint(t.requestImage(), GL_RED_INTEGER, 1);
  EXPECT_EQ(gpu, cpu);
  int covered = 0, lit = 0, edgeRequests = 0;
  for (std::size_t i = 0; i < tested.size(); ++i) {
    const adaptive::TestedPixel& p = tested[i];
    if (p.mask == SL_MASK_EMPTY) continue;
    ++covered;
    lit += p.mask == SL_MASK_LIT;
    ASSERT_NE(p.served, pages::kNoPage);
    const pages::PageId served = pages::unpackPage(p.served);
    EXPECT_GE(t.cache()->table().slot(served), 0) << "served page not allocated";
    if (p.refine != pages::kNoPage) {
      EXPECT_LT(pages::unpackPage(p.refine).level, served.level);
    }
    edgeRequests += cpu[i] != pages::kNoPage && (cpu[i] & adaptive::kTouchBit) == 0;
  }
  std::printf("%d covered, %d lit, %d edge requests from the coarse map\n", covered, lit,
              edgeRequests);
  EXPECT_GT(lit, covered / 4);
  EXPECT_LT(lit, covered);
  EXPECT_GT(edgeRequests, 10);

  std::vector<pages::PageKey> cpuCompact = pages::compactRequests(pages::dedupRequests(gpu, w, h));
  std::vector<pages::PageKey> gpuCompact = t.lastFrame().compacted;
  std::sort(cpuCompact.begin(), cpuCompact.end());
  std::sort(gpuCompact.begin(), gpuCompact.end());
  EXPECT_EQ(gpuCompact, cpuCompact);
  ASSERT_EQ(t.lastFrame().iterations.size(), 1u);
  EXPECT_GT(t.lastFrame().iterations[0].allocated.size(), 0u);
  test::expectNoGlErrors(*r);
}

// The paper's edge test (asm.edge = map-texel) from the coarse map: the GPU's per-pixel keys
// are findEdges(MapTexel) of its own shadow test (exact), and its map-edge flag is the CPU's
// mapTexelOnShadowEdge of the coarse map read back from the pool, for the receiver
// receiverInMap gives of the G-buffer's point and normal: at most 0.5 % of the covered pixels
// may differ (float rounding of the receiver's plane right at a texel's depth).
TEST(Asm, MapEdgeTestMatchesTheCpuReference) {
  auto r = makeProbe("plane-box");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->params().set("virtual.resolution", 16384));
  ASSERT_FALSE(r->params().set("asm.iterations", 1));
  ASSERT_FALSE(r->params().set("asm.edge", SL_ASM_EDGE_MAP));
  const int w = 160, h = 90;
  ASSERT_FALSE(r->renderFrame(w, h, 0));
  ASSERT_TRUE(g_probe);
  const AsmShadowMap& t = *g_probe;
  const std::vector<adaptive::TestedPixel> tested = readTested(t);
  EXPECT_EQ(readUint(t.requestImage(), GL_RED_INTEGER, 1),
            adaptive::findEdges(tested, w, h, adaptive::EdgeTest::MapTexel));

  // The coarse level of the virtual map, from its pages in the pool.
  const adaptive::PageCache& cache = *t.cache();
  const pages::VirtualLayout& layout = cache.layout();
  const int level = cache.coarseLevel(), ps = layout.pageSize;
  const int n = layout.virtualResolution >> level;
  const gl::Texture& pool = t.pagedMap().poolTexture();
  std::vector<float> poolDepth(std::size_t(pool.width()) * pool.height());
  glGetTextureImage(pool.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(poolDepth.size() * 4),
                    poolDepth.data());
  std::vector<float> depth(std::size_t(n) * n);
  const int columns = t.pagedMap().poolColumns();
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const int slot = cache.table().slot({level, x / ps, y / ps});
      ASSERT_GE(slot, 0);
      const int px = (slot % columns) * ps + x % ps, py = (slot / columns) * ps + y % ps;
      depth[std::size_t(y) * n + x] = poolDepth[std::size_t(py) * pool.width() + px];
    }
  const adaptive::DepthGrid grid{depth, n};

  const DepthMapView& v = t.mapView();
  const DepthMapFrame frame{v.lightViewProj, v.extentM, v.depthPerMAtUnitW(), v.extentWPower,
                            v.depthWPower};
  const ShadowBiasSettings bias{float(r->params().get("bias.normal")),
                                float(r->params().get("bias.slope")),
                                float(r->params().get("bias.constant"))};
  const glm::vec3 towards = r->light().directionalTowards();
  const FrameReadback fr = r->readback();
  int covered = 0, gpuEdges = 0, differ = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const adaptive::TestedPixel& p = tested[std::size_t(y) * w + x];
      if (p.mask == SL_MASK_EMPTY) continue;
      ASSERT_EQ(pages::unpackPage(p.served).level, level);
      const std::size_t i = std::size_t(h - 1 - y) * w + x;
      const MapReceiver rc =
          receiverInMap(frame, glm::vec3(fr.positions[i]), glm::vec3(fr.normals[i]), towards,
                        glm::vec2(1.0f / float(n)), bias);
      const bool cpu = adaptive::mapTexelOnShadowEdge(grid, rc);
      ++covered;
      gpuEdges += p.mapEdge != 0;
      differ += cpu != (p.mapEdge != 0);
    }
  std::printf("%d covered, %d on a shadow edge of the coarse map, %d differ from the CPU\n",
              covered, gpuEdges, differ);
  EXPECT_GT(gpuEdges, 10);
  EXPECT_LT(gpuEdges, covered / 4);
  EXPECT_LE(differ, covered / 200);
  test::expectNoGlErrors(*r);
}

// asm.loop = until-done: the paper's loop runs until no page is requested and says it
// converged; a cap publishes why it stopped and the pages still requested (0 exactly when the
// loop had in fact converged); the tool's per-frame budget publishes what it deferred.
TEST(Asm, UntilDoneConvergesAndAStoppedLoopSaysWhatItLeft) {
  const int w = 320, h = 180;
  auto frame = [&](int loop, int cap, int perFrame) {
    auto r = makeProbe("plane-box");
    EXPECT_TRUE(r);
    EXPECT_FALSE(r->params().set("pool.pages", 1024));
    EXPECT_FALSE(r->params().set("asm.edge", SL_ASM_EDGE_MAP));
    EXPECT_FALSE(r->params().set("asm.loop", loop));
    EXPECT_FALSE(r->params().set("asm.iterations.cap", cap));
    EXPECT_FALSE(r->params().set("asm.pages.per.frame", perFrame));
    r->requestPublications({"asm.*"});
    EXPECT_FALSE(r->renderFrame(w, h, 0));
    test::expectNoGlErrors(*r);
    return r->publication().numbers;
  };
  const auto done = frame(1, 16, 1);  // until-done ignores the per-frame budget
  std::printf("until done: %.0f iterations, %.0f new, stop %.0f\n", done.at("asm.iterations.run"),
              done.at("asm.new"), done.at("asm.stop"));
  EXPECT_EQ(done.at("asm.stop"), double(AsmShadowMap::kConverged));
  EXPECT_EQ(done.at("asm.requests.left"), 0.0);
  EXPECT_GT(done.at("asm.new"), 1.0);
  const auto capped = frame(1, 1, 64);
  EXPECT_EQ(capped.at("asm.iterations.run"), 1.0);
  EXPECT_EQ(capped.at("asm.stop") == double(AsmShadowMap::kIterationCap),
            capped.at("asm.requests.left") > 0.0);
  const auto budget = frame(0, 16, 1);
  EXPECT_EQ(budget.at("asm.new"), 1.0);
  EXPECT_EQ(budget.at("asm.stop"), double(AsmShadowMap::kBudget));
  EXPECT_EQ(budget.at("asm.requests.left"), done.at("asm.new") - 1.0);
}

// The iteration-cap preset (scenes/papers/001-asm-iteration-cap.json) as a user opens it: its
// first frame stops at the cap with pages still requested, published (asm.stop 1,
// asm.requests.left > 0); the same view with a cap high enough converges in more iterations
// than the preset allows, so the cap is what stopped it; a still camera then converges over
// the next frames (the cache keeps the pages), each published.
TEST(Asm, TheIterationCapPresetStopsTheLoopVisibly) {
  std::string error;
  const auto preset = loadPreset(std::filesystem::path(SHADOWLAB_TEST_DATA) / ".." / ".." /
                                     "scenes" / "papers" / "001-asm-iteration-cap.json",
                                 &error);
  ASSERT_TRUE(preset) << error;
  auto frame = [&](int cap, int frames) {
    auto r = test::makeRenderer(preset->scene, preset->technique);
    EXPECT_TRUE(r);
    for (const auto& [key, value] : preset->params)
      EXPECT_FALSE(r->params().setFromString(key, value)) << key;
    if (cap > 0) {
      EXPECT_FALSE(r->params().set("asm.iterations.cap", cap));
    }
    r->requestPublications({"asm.*"});
    std::vector<std::map<std::string, double>> out;
    for (int f = 0; f < frames; ++f) {
      EXPECT_FALSE(r->renderFrame(320, 180, 0));
      out.push_back(r->publication().numbers);
    }
    test::expectNoGlErrors(*r);
    return out;
  };
  const auto capped = frame(0, 3);
  const double cap = std::stod(preset->params.at("asm.iterations.cap"));
  std::printf(
      "preset: %.0f iterations, %.0f new, stop %.0f, %.0f left; frames 2, 3: stop %.0f, "
      "%.0f\n",
      capped[0].at("asm.iterations.run"), capped[0].at("asm.new"), capped[0].at("asm.stop"),
      capped[0].at("asm.requests.left"), capped[1].at("asm.stop"), capped[2].at("asm.stop"));
  EXPECT_EQ(capped[0].at("asm.iterations.run"), cap);
  EXPECT_EQ(capped[0].at("asm.stop"), double(AsmShadowMap::kIterationCap));
  EXPECT_GT(capped[0].at("asm.requests.left"), 0.0);
  const auto free = frame(64, 1);
  EXPECT_EQ(free[0].at("asm.stop"), double(AsmShadowMap::kConverged));
  EXPECT_EQ(free[0].at("asm.requests.left"), 0.0);
  EXPECT_GT(free[0].at("asm.iterations.run"), cap);
  EXPECT_GT(free[0].at("asm.new"), capped[0].at("asm.new"));
  EXPECT_EQ(capped[0].at("asm.cap.stops"), 1.0);
  EXPECT_EQ(free[0].at("asm.cap.stops"), 0.0);
  // A still camera: the next frames go on from the cached pages until converged, and the
  // frame the cap stopped stays counted.
  EXPECT_EQ(capped.back().at("asm.stop"), double(AsmShadowMap::kConverged));
  EXPECT_EQ(capped.back().at("asm.requests.left"), 0.0);
  EXPECT_EQ(capped.back().at("asm.cap.stops"), 1.0);
}

// Frames until the cache stops growing: then the last iteration's shadow test saw the final
// quadtree, and its mask is the resolve's hard mask (the same lookup in compute).
TEST(Asm, ConvergesAndTheShadowTestIsTheResolves) {
  auto r = makeProbe("plane-box");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->params().set("virtual.resolution", 16384));
  ASSERT_FALSE(r->params().set("asm.pages.per.frame", 32));
  const int w = 160, h = 90;
  r->requestPublications({"asm.*"});
  int frames = 0;
  for (; frames < 12; ++frames) {
    ASSERT_FALSE(r->renderFrame(w, h, 0));
    if (r->publication().numbers.at("asm.new") == 0.0) break;
  }
  std::printf("converged after %d frames, %.0f pages held\n", frames + 1,
              r->publication().numbers.at("asm.cached"));
  ASSERT_LT(frames, 12);
  EXPECT_GT(frames, 0) << "the per-frame budget spreads refinement over frames";
  EXPECT_EQ(r->publication().numbers.at("asm.invalidations"), 1.0);
  const std::vector<adaptive::TestedPixel> tested = readTested(*g_probe);
  const FrameReadback fr = r->readback();
  int differ = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      differ += tested[std::size_t(y) * w + x].mask != fr.hardMask[std::size_t(h - 1 - y) * w + x];
  EXPECT_EQ(differ, 0);
  test::expectNoGlErrors(*r);
}

// A camera move keeps every page (cache hits, no invalidation); a light move drops them, and
// the frame after it is pixel for pixel a fresh renderer's under that light (no stale page).
TEST(Asm, CacheSurvivesTheCameraNotTheLight) {
  auto r = test::makeRenderer("plane-box", "asm");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->params().set("virtual.resolution", 16384));
  r->requestPublications({"asm.*"});
  const int w = 128, h = 72;
  for (int f = 0; f < 3; ++f) ASSERT_FALSE(r->renderFrame(w, h, 0));
  Camera cam = r->camera();
  cam.position += glm::vec3(0.3f, 0.0f, 0.2f);
  r->setCamera(cam);
  ASSERT_FALSE(r->renderFrame(w, h, 0));
  const Publication& pub = r->publication();
  EXPECT_EQ(pub.numbers.at("asm.invalidations"), 1.0);
  EXPECT_GT(pub.numbers.at("asm.hits"), 0.0);

  Light light = r->light();
  light.azimuthDeg += 20.0f;
  r->setLight(light);
  ASSERT_FALSE(r->renderFrame(w, h, 0));
  EXPECT_EQ(r->publication().numbers.at("asm.invalidations"), 2.0);
  EXPECT_EQ(r->publication().numbers.at("asm.hits"), 0.0);
  const std::vector<std::uint8_t> after = r->readback().hardMask;

  auto fresh = test::makeRenderer("plane-box", "asm");
  ASSERT_TRUE(fresh);
  ASSERT_FALSE(fresh->params().set("virtual.resolution", 16384));
  fresh->setCamera(cam);
  fresh->setLight(light);
  ASSERT_FALSE(fresh->renderFrame(w, h, 0));
  EXPECT_EQ(after, fresh->readback().hardMask);
  test::expectNoGlErrors(*r);
}

// A new scene drops the cached pages even when everything the cache is keyed on matches (same
// light, primitive count and bounds): here the box moves inside the plane, so the old pages are
// wrong; the frame equals a fresh renderer's.
TEST(Asm, ANewSceneDropsTheCacheEvenWithTheSameBounds) {
  auto r = test::makeRenderer("plane-box", "asm");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->params().set("virtual.resolution", 16384));
  r->requestPublications({"asm.*"});
  const int w = 128, h = 72;
  for (int f = 0; f < 2; ++f) ASSERT_FALSE(r->renderFrame(w, h, 0));
  ASSERT_EQ(r->publication().numbers.at("asm.invalidations"), 1.0);

  auto moved = std::make_shared<Scene>(*r->scene());
  const Aabb bounds = moved->bounds;
  bool movedOne = false;
  for (MeshPrimitive& p : moved->primitives) {
    Aabb b;
    for (const glm::vec3& v : p.positions) b.extend(v);
    if (b.max.x - b.min.x > 0.5f * (bounds.max.x - bounds.min.x)) continue;  // the plane
    for (glm::vec3& v : p.positions) v.x += 0.25f * (b.max.x - b.min.x);
    movedOne = true;
  }
  ASSERT_TRUE(movedOne);
  Aabb after;
  for (const MeshPrimitive& p : moved->primitives)
    for (const glm::vec3& v : p.positions) after.extend(v);
  ASSERT_EQ(after.min, bounds.min) << "the box must stay inside the plane's bounds";
  ASSERT_EQ(after.max, bounds.max);

  const Camera cam = r->camera();
  const Light light = r->light();
  r->setScene(moved);
  r->setCamera(cam);
  r->setLight(light);
  ASSERT_FALSE(r->renderFrame(w, h, 0));
  EXPECT_EQ(r->publication().numbers.at("asm.invalidations"), 2.0);

  auto fresh = test::makeRenderer("plane-box", "asm");
  ASSERT_TRUE(fresh);
  ASSERT_FALSE(fresh->params().set("virtual.resolution", 16384));
  fresh->setScene(moved);
  fresh->setCamera(cam);
  fresh->setLight(light);
  ASSERT_FALSE(fresh->renderFrame(w, h, 0));
  EXPECT_EQ(r->readback().hardMask, fresh->readback().hardMask);
  test::expectNoGlErrors(*r);
}

// memory() lists every byte: the pool, the page table's levels, the shadow test, the request
// image and list.
TEST(Asm, MemoryIsExact) {
  auto r = test::makeRenderer("diagonal", "uniform");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->renderFrame(160, 90, 0));
  const std::uint64_t before = gl::allocatedBytes() - r->stats().memory.bytes();
  ASSERT_FALSE(r->setTechnique("asm"));
  for (auto [pool, page, virt, coarse] :
       {std::tuple{256, 128, 16384, 128}, {10, 64, 2048, 128}, {4, 256, 4096, 512}}) {
    SCOPED_TRACE(pool);
    ASSERT_FALSE(r->params().set("pool.pages", pool));
    ASSERT_FALSE(r->params().set("page.size", page));
    ASSERT_FALSE(r->params().set("virtual.resolution", virt));
    ASSERT_FALSE(r->params().set("asm.coarse.resolution", coarse));
    ASSERT_FALSE(r->renderFrame(160, 90, 0));
    const MemoryStats& m = r->stats().memory;
    EXPECT_EQ(m.bytes(), gl::allocatedBytes() - before) << "memory() must list every byte";
    int columns = 1;
    while (columns * columns < pool) ++columns;
    const std::uint64_t rows = std::uint64_t((pool + columns - 1) / columns);
    std::uint64_t table = 0;
    for (int n = virt / page; n >= 1; n /= 2) table += 4ull * std::uint64_t(n) * std::uint64_t(n);
    EXPECT_EQ(m.bytes(), 4ull * std::uint64_t(columns * page) * rows * std::uint64_t(page) + table +
                             16ull * 160 * 90 + 4ull * 160 * 90 + 4ull * (1 + 160 * 90));
  }
  test::expectNoGlErrors(*r);
}

std::vector<float> readDepth(const gl::Texture& t) {
  std::vector<float> out(std::size_t(t.width()) * t.height());
  glGetTextureImage(t.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(out.size() * 4), out.data());
  return out;
}

// asm.render = superpages (the lecture's loop: bin, render superpages, copy into the quadtree)
// against page by page: the same frame allocates the same pages into the same slots in every
// iteration, the pools hold the same depths up to float rounding of the rasterised positions
// (as rmsm's Rmsm.SuperpagesFillThePoolLikePageByPage), the error is the same; superpages draw
// the scene fewer times; memory() lists the superpage target and equals what was allocated.
TEST(Asm, SuperpagesFillThePoolLikePageByPage) {
  auto frame = [&](int render, AsmShadowMap*& probe) {
    auto r = makeProbe("plane-box");
    EXPECT_TRUE(r);
    probe = g_probe;
    for (auto [key, value] :
         std::initializer_list<std::pair<const char*, double>>{{"virtual.resolution", 16384},
                                                               {"page.size", 64},
                                                               {"pool.pages", 256},
                                                               {"asm.coarse.resolution", 512},
                                                               {"asm.edge", SL_ASM_EDGE_MAP},
                                                               {"asm.loop", 1},
                                                               {"asm.render", render}})
      EXPECT_FALSE(r->params().set(key, value)) << key;
    r->requestPublications({"asm.*"});
    EXPECT_FALSE(r->renderFrame(160, 90, 0));
    return r;
  };
  AsmShadowMap *pagesProbe = nullptr, *superProbe = nullptr;
  const std::uint64_t before = gl::allocatedBytes();
  auto pagesR = frame(AsmShadowMap::kRenderPages, pagesProbe);
  const std::uint64_t pagesBytes = gl::allocatedBytes() - before;
  auto superR = frame(AsmShadowMap::kRenderSuperpages, superProbe);
  const std::uint64_t superBytes = gl::allocatedBytes() - before - pagesBytes;
  ASSERT_TRUE(pagesProbe && superProbe && pagesR && superR);
  const AsmShadowMap::FrameResult &p = pagesProbe->lastFrame(), &s = superProbe->lastFrame();
  ASSERT_EQ(s.uniquePerIteration, p.uniquePerIteration);
  ASSERT_EQ(s.iterations.size(), p.iterations.size());
  for (std::size_t i = 0; i < s.iterations.size(); ++i) {
    EXPECT_EQ(s.iterations[i].allocated, p.iterations[i].allocated);
    EXPECT_EQ(s.iterations[i].slots, p.iterations[i].slots);
  }
  const std::vector<float> pagesPool = readDepth(pagesProbe->pagedMap().poolTexture());
  const std::vector<float> superPool = readDepth(superProbe->pagedMap().poolTexture());
  ASSERT_EQ(superPool.size(), pagesPool.size());
  const int W = pagesProbe->pagedMap().poolTexture().width();
  const int H = int(pagesPool.size() / std::size_t(W));
  auto at = [&](int u, int v) { return pagesPool[std::size_t(v) * W + u]; };
  int over = 0, overSlope = 0, rendered = 0;
  for (std::size_t i = 0; i < superPool.size(); ++i) {
    rendered += pagesPool[i] < 1.0f;
    const float d = std::abs(superPool[i] - pagesPool[i]);
    if (d <= 1e-6f) continue;
    ++over;
    const int x = int(i % std::size_t(W)), y = int(i / std::size_t(W));
    float g = 0.0f;
    if (x > 0) g = std::max(g, std::abs(at(x, y) - at(x - 1, y)));
    if (x + 1 < W) g = std::max(g, std::abs(at(x + 1, y) - at(x, y)));
    if (y > 0) g = std::max(g, std::abs(at(x, y) - at(x, y - 1)));
    if (y + 1 < H) g = std::max(g, std::abs(at(x, y + 1) - at(x, y)));
    overSlope += d > 1e-6f + 1e-4f * g;
  }
  const double pagesError = pagesR->computeError().stats.errorPct;
  const double superError = superR->computeError().stats.errorPct;
  std::printf(
      "%zu iterations, %d new pages: %d superpages (%d scene draws, page by page %d); "
      "%d texels rendered, %d off by more than 1e-6; error %.4f %% (page by page %.4f "
      "%%)\n",
      s.iterations.size(), s.newPages, s.superpages, s.sceneDraws, p.sceneDraws, rendered, over,
      superError, pagesError);
  EXPECT_GT(s.iterations.size(), 1u);
  EXPECT_EQ(p.superpages, 0);
  EXPECT_EQ(p.sceneDraws, p.newPages);
  EXPECT_EQ(s.sceneDraws, s.superpages);
  EXPECT_GT(s.superpages, 0);
  EXPECT_LT(s.superpages, s.newPages);
  EXPECT_EQ(pagesR->publication().numbers.at("asm.superpages"), 0.0);
  EXPECT_EQ(superR->publication().numbers.at("asm.superpages"), double(s.superpages));
  EXPECT_EQ(superR->publication().numbers.at("asm.scene_draws"), double(s.sceneDraws));
  // The scene covers much of the pages held (the coarse map's 8 x 8 and the new ones).
  EXPECT_GT(rendered, (64 + s.newPages) * 64 * 64 / 4);
  EXPECT_EQ(overSlope, 0);
  EXPECT_LE(over, rendered / 10000);
  EXPECT_EQ(superError, pagesError);
  // memory(): the superpage target (1024² DEPTH_COMPONENT32F) is there only with superpages,
  // and each renderer's memory() is what it allocated beyond the other's.
  auto target = [](const MemoryStats& m) {
    std::uint64_t b = 0;
    for (const ResourceInfo& res : m.resources)
      if (res.name == "superpage target") b = res.bytes;
    return b;
  };
  EXPECT_EQ(target(pagesR->stats().memory), 0u);
  EXPECT_EQ(target(superR->stats().memory), 4ull << 20);
  EXPECT_EQ(superR->stats().memory.bytes(), pagesR->stats().memory.bytes() + (4ull << 20));
  EXPECT_EQ(superBytes, pagesBytes + (4ull << 20)) << "memory() must list every byte";
  test::expectNoGlErrors(*superR);
}

// Every declared pass is timed, in declaration order (iterations not run are empty passes);
// bad parameters name themselves.
TEST(Asm, DeclaredPassesAndBadParameters) {
  auto r = test::makeRenderer("plane-box", "asm");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->params().set("asm.iterations", 2));
  ASSERT_FALSE(r->renderFrame(96, 64, 0));
  std::vector<std::string> declared;
  for (const PassDecl& d : framePassDecls(AsmShadowMap::info())) declared.push_back(d.id);
  test::expectDeclaredPassesOpened(r->stats(), declared);
  ASSERT_FALSE(r->params().set("asm.coarse.resolution", 1000));
  auto err = r->renderFrame(96, 64, 0);
  ASSERT_TRUE(err);
  EXPECT_NE(err->find("asm.coarse.resolution = 1000 must be a power of two"), std::string::npos)
      << *err;
  // A page size whose coarsest level is finer than the coarse map names both parameters.
  ASSERT_FALSE(r->params().set("asm.coarse.resolution", 512));
  ASSERT_FALSE(r->params().set("page.size", 1024));
  err = r->renderFrame(96, 64, 0);
  ASSERT_TRUE(err);
  EXPECT_NE(err->find("asm.coarse.resolution = 512 must be from 1024"), std::string::npos) << *err;
  EXPECT_NE(err->find("page.size = 1024"), std::string::npos) << *err;
  ASSERT_FALSE(r->params().set("page.size", 128));
  ASSERT_FALSE(r->params().set("asm.coarse.resolution", 4096));  // 32 x 32 pages
  ASSERT_FALSE(r->params().set("pool.pages", 1000));
  err = r->renderFrame(96, 64, 0);
  ASSERT_TRUE(err);
  EXPECT_NE(err->find("pool.pages = 1000 cannot hold the 1024 pages of the coarse map"),
            std::string::npos)
      << *err;
  ASSERT_FALSE(r->params().set("pool.pages", 1100));
  EXPECT_FALSE(r->renderFrame(96, 64, 0));
}

// NaN (a free slot, an entry nothing covers) equal to NaN.
bool sameValues(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!(a[i] == b[i] || (std::isnan(a[i]) && std::isnan(b[i])))) return false;
  return true;
}

// The Pages panel's publications of asm are the CPU PageCache's: the GPU's keys of every
// iteration replayed through a CPU cache of the same layout, pool and budget allocate the same
// pages into the same slots, and the published page table (per level: allocated this frame,
// cached used / unused, evicted, requested and waiting), pool levels and served levels equal
// the CPU's views, over 3 frames: the coarse map + refinement, the same view again (cached
// pages used, hits), a cut from the close-up of a shadow corner to the next corner with a
// pool too small for both views (evictions).
TEST(Asm, PagesPanelPublicationsAreTheCpuCaches) {
  auto r = makeProbe("plane-box");
  ASSERT_TRUE(r);
  const pages::VirtualLayout layout{16384, 128, SL_PAGED_LOOKUP_LEVELS};
  const int pool = 6, budget = 64, coarseLevel = 7;  // 128² coarse map: one page
  ASSERT_FALSE(r->params().set("virtual.resolution", layout.virtualResolution));
  ASSERT_FALSE(r->params().set("page.size", layout.pageSize));
  ASSERT_FALSE(r->params().set("pool.pages", pool));
  ASSERT_FALSE(r->params().set("asm.pages.per.frame", budget));
  ASSERT_FALSE(r->params().set("asm.coarse.resolution", 128));
  r->requestPublications({"pages.*", "asm.*"});
  adaptive::PageCache cpu(layout, pool, coarseLevel);
  // The close-up of a shadow corner fills the pool with fine pages; the close-up of the
  // next corner then needs other pages and evicts the first corner's (unused there).
  const Camera closeup = *test::bookmark(*r->scene(), "edge-closeup");
  r->setCamera(closeup);
  const int w = 128, h = 72;
  std::array<std::array<int, pages::kPageStates>, 3> cells{};
  for (int f = 0; f < 3; ++f) {
    SCOPED_TRACE(f);
    if (f == 2) {  // the next corner of the 2 x 2 m shadow (2 m along z), the same look
      Camera cam = closeup;
      cam.position += glm::vec3(0.0f, 0.0f, 2.0f);
      cam.target += glm::vec3(0.0f, 0.0f, 2.0f);
      r->setCamera(cam);
    }
    ASSERT_FALSE(r->renderFrame(w, h, 0));
    const AsmShadowMap::FrameResult& gpu = g_probe->lastFrame();
    ASSERT_EQ(gpu.invalidated, f == 0);
    std::vector<int> slots;
    if (f == 0)
      cpu.invalidate(slots);
    else
      cpu.beginFrame();
    int left = budget;
    std::vector<pages::PageKey> requests;
    ASSERT_EQ(gpu.uniquePerIteration.size(), gpu.iterations.size());
    for (std::size_t i = 0; i < gpu.uniquePerIteration.size(); ++i) {
      const adaptive::Refinement ref = cpu.refine(gpu.uniquePerIteration[i], left);
      left -= int(ref.allocated.size());
      EXPECT_EQ(ref.allocated, gpu.iterations[i].allocated) << "iteration " << i;
      EXPECT_EQ(ref.slots, gpu.iterations[i].slots) << "iteration " << i;
      for (pages::PageKey k : gpu.uniquePerIteration[i])
        if (k != pages::kNoPage && (k & adaptive::kTouchBit) == 0) requests.push_back(k);
    }
    const std::vector<pages::PageKey> requested = pages::sortUnique(requests);
    const Publication& pub = r->publication();
    EXPECT_EQ(pub.numbers.at("pages.requested"), double(requested.size()));
    EXPECT_EQ(pub.numbers.at("pages.allocated"), double(cpu.pool().usedCount()));
    for (int l = 0; l < layout.levels(); ++l) {
      const auto it = pub.images.find("pages.table." + std::to_string(l));
      ASSERT_NE(it, pub.images.end()) << l;
      const std::vector<float> states = adaptive::cacheLevelStates(cpu, requested, l);
      EXPECT_EQ(it->second.values, states) << "level " << l;
      for (float v : states) ++cells[std::size_t(f)][std::size_t(v)];
    }
    EXPECT_TRUE(sameValues(pub.curves.at("pages.pool.levels"), adaptive::cachePoolLevels(cpu)));
    EXPECT_TRUE(sameValues(pub.images.at("pages.served").values, pages::servedLevels(cpu.table())));
    // The cells agree with the cache's own counts.
    using PS = pages::PageState;
    const auto& c = cells[std::size_t(f)];
    EXPECT_EQ(double(c[int(PS::New)]), pub.numbers.at("asm.new") + (f == 0 ? 1 : 0));
    EXPECT_EQ(double(c[int(PS::CachedHit)]), pub.numbers.at("asm.hits"));
    EXPECT_EQ(double(c[int(PS::New)] + c[int(PS::CachedHit)] + c[int(PS::CachedIdle)]),
              pub.numbers.at("asm.cached"));
    EXPECT_LE(double(c[int(PS::Evicted)]), pub.numbers.at("asm.evicted"));
    std::printf("frame %d: new %d, cached hit %d, idle %d, evicted %d, waiting %d\n", f,
                c[int(PS::New)], c[int(PS::CachedHit)], c[int(PS::CachedIdle)], c[int(PS::Evicted)],
                c[int(PS::Pending)]);
  }
  using PS = pages::PageState;
  EXPECT_EQ(cells[0][int(PS::CachedHit)] + cells[0][int(PS::CachedIdle)], 0);
  EXPECT_GT(cells[0][int(PS::New)], 1) << "the first frame refines the coarse map";
  EXPECT_GT(cells[1][int(PS::CachedHit)], 0) << "the second frame uses pages it kept";
  EXPECT_EQ(cells[1][int(PS::Evicted)], 0);
  EXPECT_GT(cells[2][int(PS::Evicted)], 0) << "the new view evicts the old view's pages";
  EXPECT_GT(cells[2][int(PS::CachedIdle)] + cells[2][int(PS::CachedHit)], 0);
  test::expectNoGlErrors(*r);
}

}  // namespace
}  // namespace sl
