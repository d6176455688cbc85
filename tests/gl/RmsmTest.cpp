// The `rmsm` technique (resolution-matched shadow maps): GPU-vs-CPU parity of the per-pixel
// requests, the dedup + compaction list and the page table (algo/pages is the reference),
// accuracy against the Embree reference next to uniform, the pool running out (coarser pages,
// counted, no GL error), exact memory, declared passes == timed passes, superpages == page by page.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <set>

#include "GlTestEnv.h"
#include "algo/pages/PageRequests.h"
#include "algo/pages/PageViews.h"
#include "common/shared_constants.h"
#include "core/Technique.h"
#include "gl/Gl.h"
#include "techniques/rmsm/RmsmShadowMap.h"

namespace sl {
namespace {

// The technique the probe renderer made last: lets the parity test read its GPU state.
RmsmShadowMap* g_probe = nullptr;

std::unique_ptr<Renderer> makeProbe(const std::string& scene) {
  test::eglContext().makeCurrent();
  RendererOptions o;
  TechniqueEntry e{RmsmShadowMap::info(), [](const gl::ShaderLibrary& lib) {
                     auto t = std::make_unique<RmsmShadowMap>(lib);
                     g_probe = t.get();
                     return std::unique_ptr<Technique>(std::move(t));
                   }};
  e.info.id = "rmsm-probe";
  o.extraTechniques.push_back(std::move(e));
  auto r = std::make_unique<Renderer>(o);
  auto s = test::loadBuiltin(scene);
  if (!s) return nullptr;
  r->setScene(s);
  r->setCamera(s->cameras.empty() ? s->defaultCamera() : s->cameras.front().camera);
  EXPECT_FALSE(r->setTechnique("rmsm-probe"));
  return r;
}

std::vector<std::uint32_t> readR32ui(const gl::Texture& t, int level = 0) {
  const int w = std::max(t.width() >> level, 1), h = std::max(t.height() >> level, 1);
  std::vector<std::uint32_t> out(std::size_t(w) * h);
  glGetTextureImage(t.id(), level, GL_RED_INTEGER, GL_UNSIGNED_INT, GLsizei(out.size() * 4),
                    out.data());
  return out;
}

// The read-back G-buffer as pixelRequests' input: rows bottom-up like the GPU image (the
// readback's row 0 is the top), light uv through the virtual map's matrix.
std::vector<pages::PixelUv> pixelUvsOf(const FrameReadback& fr, const glm::mat4& lightViewProj,
                                       int w, int h) {
  std::vector<pages::PixelUv> px(std::size_t(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t from = std::size_t(h - 1 - y) * w + x;
      const glm::vec4 P = fr.positions[from];
      pages::PixelUv& p = px[std::size_t(y) * w + x];
      p.covered = P.w > 0.0f;
      p.position = glm::vec3(P);
      p.normal = glm::vec3(fr.normals[from]);
      const glm::vec4 c = lightViewProj * glm::vec4(glm::vec3(P), 1.0f);
      p.st = glm::vec2(c) / c.w * 0.5f + 0.5f;
    }
  return px;
}

// Requests from the G-buffer on the GPU against algo/pages::pixelRequests on the read-back
// positions; the GPU's dedup + compaction against the CPU's on the GPU's own request image
// (exact: the same input); the page table's mip chain against PageTable::finalised (exact).
TEST(Rmsm, RequestsCompactionAndPageTableMatchTheCpuReference) {
  auto r = makeProbe("plane-box");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->params().set("virtual.resolution", 4096));
  ASSERT_FALSE(r->params().set("lod.bias", 1));
  const int w = 160, h = 90;
  ASSERT_FALSE(r->renderFrame(w, h, 0));
  ASSERT_TRUE(g_probe);
  const RmsmShadowMap& t = *g_probe;
  const FrameReadback fr = r->readback();

  const std::vector<pages::PixelUv> px = pixelUvsOf(fr, t.lightViewProj(), w, h);
  const std::vector<pages::PageKey> cpu = pages::pixelRequests(px, w, h, t.layout(), 1);
  const std::vector<std::uint32_t> gpu = readR32ui(t.requestImage());
  ASSERT_EQ(gpu.size(), cpu.size());
  int covered = 0, differ = 0;
  for (std::size_t i = 0; i < cpu.size(); ++i) {
    covered += cpu[i] != pages::kNoPage;
    differ += cpu[i] != gpu[i];
  }
  std::printf("requests: %d covered pixels, %d differ from the CPU\n", covered, differ);
  EXPECT_GT(covered, w * h / 4);
  // Float rounding may flip floor(log2 sqrt A) or a page index at a boundary: 0.5 %.
  EXPECT_LE(differ, covered / 200);

  // Dedup + compaction: exact on the same per-pixel keys (order aside).
  std::vector<pages::PageKey> cpuCompact = pages::compactRequests(pages::dedupRequests(gpu, w, h));
  std::vector<pages::PageKey> gpuCompact = t.lastFrame().compacted;
  EXPECT_LT(gpuCompact.size(), std::size_t(covered) / 4) << "dedup keeps few requests";
  std::sort(cpuCompact.begin(), cpuCompact.end());
  std::sort(gpuCompact.begin(), gpuCompact.end());
  EXPECT_EQ(gpuCompact, cpuCompact);
  const std::vector<pages::PageKey> cpuUnique = pages::sortUnique(cpu);
  const std::vector<pages::PageKey> cpuUniqueReq(
      cpuUnique.begin(), std::find(cpuUnique.begin(), cpuUnique.end(), pages::kNoPage));
  std::vector<pages::PageKey> onlyOne;
  std::set_symmetric_difference(cpuUniqueReq.begin(), cpuUniqueReq.end(),
                                t.lastFrame().unique.begin(), t.lastFrame().unique.end(),
                                std::back_inserter(onlyOne));
  std::printf("unique pages: GPU %zu, CPU %zu, in one only %zu\n", t.lastFrame().unique.size(),
              cpuUniqueReq.size(), onlyOne.size());
  EXPECT_GT(t.lastFrame().unique.size(), 4u);
  EXPECT_LE(onlyOne.size(), 1 + cpuUniqueReq.size() / 50);

  // The page table: every level as the CPU finalised it.
  const std::vector<std::uint32_t> table = t.pageTable()->finalised();
  std::size_t at = 0;
  for (int l = 0; l < t.layout().levels(); ++l) {
    const std::vector<std::uint32_t> level = readR32ui(t.pageTableTexture(), l);
    const std::vector<std::uint32_t> want(table.begin() + std::ptrdiff_t(at),
                                          table.begin() + std::ptrdiff_t(at + level.size()));
    EXPECT_EQ(level, want) << "level " << l;
    at += level.size();
  }
  EXPECT_EQ(at, table.size());
  test::expectNoGlErrors(*r);
}

// lod.derivatives = same-surface: the GPU's per-pixel requests against pixelRequests with
// the read-back positions and normals (the same tolerance as above), and the silhouettes of
// plane-box (box against floor) ask for finer pages than with the neighbour's step.
TEST(Rmsm, SameSurfaceRequestsMatchTheCpuReference) {
  auto r = makeProbe("plane-box");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->params().set("virtual.resolution", 4096));
  ASSERT_FALSE(r->params().set("lod.derivatives", SL_RMSM_DERIVATIVES_SAME_SURFACE));
  const int w = 160, h = 90;
  ASSERT_FALSE(r->renderFrame(w, h, 0));
  ASSERT_TRUE(g_probe);
  const RmsmShadowMap& t = *g_probe;
  const FrameReadback fr = r->readback();
  const std::vector<pages::PixelUv> px = pixelUvsOf(fr, t.lightViewProj(), w, h);
  const auto cpu = pages::pixelRequests(px, w, h, t.layout(), 1, pages::Derivatives::SameSurface);
  const auto neighbour = pages::pixelRequests(px, w, h, t.layout(), 1);
  const std::vector<std::uint32_t> gpu = readR32ui(t.requestImage());
  ASSERT_EQ(gpu.size(), cpu.size());
  int covered = 0, differ = 0, finer = 0, coarser = 0;
  for (std::size_t i = 0; i < cpu.size(); ++i) {
    covered += cpu[i] != pages::kNoPage;
    differ += cpu[i] != gpu[i];
    if (cpu[i] == pages::kNoPage) continue;
    const int a = pages::unpackPage(cpu[i]).level, b = pages::unpackPage(neighbour[i]).level;
    finer += a < b;
    coarser += a > b;
  }
  std::printf(
      "same-surface requests: %d covered, %d differ from the CPU, %d finer and %d "
      "coarser than the neighbour's step\n",
      covered, differ, finer, coarser);
  EXPECT_GT(covered, w * h / 4);
  EXPECT_LE(differ, covered / 200);
  EXPECT_GT(finer, 0);
  test::expectNoGlErrors(*r);
}

// The GPU's sort and unique (bitonic sort, unique, second sort) against std::sort +
// std::unique of the same read-back compacted list: exact, on three scenes at three sizes and
// LOD biases (list lengths 57 to 770, none a power of two: the padding is exercised).
TEST(Rmsm, GpuSortUniqueEqualsTheCpuReference) {
  for (const char* scene : {"plane-box", "diagonal", "corridor"}) {
    auto r = makeProbe(scene);
    ASSERT_TRUE(r);
    for (auto [w, h, bias] : {std::tuple{96, 64, 0}, {160, 90, 1}, {320, 180, 2}}) {
      SCOPED_TRACE(testing::Message() << scene << " " << w << "x" << h << " lod.bias " << bias);
      ASSERT_FALSE(r->params().set("lod.bias", bias));
      ASSERT_FALSE(r->renderFrame(w, h, 0));
      const RmsmShadowMap& t = *g_probe;
      const std::vector<pages::PageKey> cpu = pages::sortUnique(t.lastFrame().compacted);
      std::printf("%s %dx%d bias %d: %zu compacted, %zu unique\n", scene, w, h, bias,
                  t.lastFrame().compacted.size(), cpu.size());
      EXPECT_GT(cpu.size(), 2u);
      EXPECT_EQ(t.lastFrame().unique, cpu);
    }
    test::expectNoGlErrors(*r);
  }
}

std::vector<float> readDepth(const gl::Texture& t) {
  std::vector<float> out(std::size_t(t.width()) * t.height());
  glGetTextureImage(t.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(out.size() * 4), out.data());
  return out;
}

// Lefohn et al.'s render step against the page-by-page one: the same frame with rmsm.render =
// pages, then superpages, allocates the same pages to the same slots, and the pools hold the
// same depths (both each texel centre's exact depth, rasterised in a 1024² block instead of a
// page.size² viewport): no texel off by more than 1e-6 + 1e-4 x its depth step to a
// neighbour, at most 0.01 % off by more than 1e-6 (measured: plane-box 3 of 242346 texels, at
// most 1.55e-6, where depth steps 0.11 per texel; diagonal 0, at most 5.4e-7); one scene draw
// per superpage instead of per page; the error metric is the same to the last digit.
TEST(Rmsm, SuperpagesFillThePoolLikePageByPage) {
  for (auto [scene, virt] : {std::pair{"plane-box", 4096}, {"diagonal", 16384}}) {
    SCOPED_TRACE(scene);
    auto r = makeProbe(scene);
    ASSERT_TRUE(r);
    ASSERT_FALSE(r->params().set("virtual.resolution", virt));
    ASSERT_FALSE(r->params().set("page.size", 64));
    ASSERT_FALSE(r->params().set("rmsm.render", RmsmShadowMap::kRenderPages));
    ASSERT_FALSE(r->renderFrame(160, 90, 0));
    ASSERT_TRUE(g_probe);
    const RmsmShadowMap::FrameResult pagesFrame = g_probe->lastFrame();
    const std::vector<float> pagesPool = readDepth(g_probe->poolTexture());
    const double pagesError = r->computeError().stats.errorPct;
    EXPECT_EQ(pagesFrame.sceneDraws, int(pagesFrame.allocation.pages.size()));

    ASSERT_FALSE(r->params().set("rmsm.render", RmsmShadowMap::kRenderSuperpages));
    ASSERT_FALSE(r->renderFrame(160, 90, 0));
    const RmsmShadowMap::FrameResult& superFrame = g_probe->lastFrame();
    ASSERT_EQ(superFrame.allocation.pages, pagesFrame.allocation.pages);
    ASSERT_EQ(superFrame.allocation.slots, pagesFrame.allocation.slots);
    const std::vector<float> superPool = readDepth(g_probe->poolTexture());
    ASSERT_EQ(superPool.size(), pagesPool.size());
    // Texel-centre depths rasterised at window positions that differ by float rounding (a
    // position 1024 texels from the target's origin carries ~6e-5 texel of it): a surface whose
    // depth changes by g per texel may differ by ~6e-5 g. Counted: texels off by more than 1e-6,
    // and off by more than 1e-6 + 1e-4 g (g: the larger depth step to a 4-neighbour in the
    // page-by-page pool).
    const int W = g_probe->poolTexture().width();
    auto at = [&](int u, int v) { return pagesPool[std::size_t(v) * W + u]; };
    int over = 0, overSlope = 0, differ = 0, rendered = 0;
    float maxDiff = 0.0f;
    for (std::size_t i = 0; i < superPool.size(); ++i) {
      const float d = std::abs(superPool[i] - pagesPool[i]);
      differ += superPool[i] != pagesPool[i];
      rendered += pagesPool[i] < 1.0f;
      maxDiff = std::max(maxDiff, d);
      if (d <= 1e-6f) continue;
      ++over;
      const int x = int(i % W), y = int(i / W), h = int(pagesPool.size() / W);
      float g = 0.0f;
      if (x > 0) g = std::max(g, std::abs(at(x, y) - at(x - 1, y)));
      if (x + 1 < W) g = std::max(g, std::abs(at(x + 1, y) - at(x, y)));
      if (y > 0) g = std::max(g, std::abs(at(x, y) - at(x, y - 1)));
      if (y + 1 < h) g = std::max(g, std::abs(at(x, y + 1) - at(x, y)));
      overSlope += d > 1e-6f + 1e-4f * g;
      std::printf("  pool texel %d,%d: %.8f vs %.8f, off by %.3g, depth step to a neighbour %.3g\n",
                  x, y, double(pagesPool[i]), double(superPool[i]), double(d), double(g));
    }
    const double superError = r->computeError().stats.errorPct;
    std::printf(
        "%s: %zu pages in %zu superpages (%d scene draws, page by page %d); %d texels "
        "below the far plane; %d differ, %d by more than 1e-6, %d by more than 1e-6 + 1e-4 x "
        "the depth step (max %.3g); error %.4f %% (page by page %.4f %%)\n",
        scene, superFrame.allocation.pages.size(), superFrame.superpages.size(),
        superFrame.sceneDraws, pagesFrame.sceneDraws, rendered, differ, over, overSlope,
        double(maxDiff), superError, pagesError);
    EXPECT_GT(superFrame.superpages.size(), 1u);
    EXPECT_LT(superFrame.superpages.size(), superFrame.allocation.pages.size());
    EXPECT_EQ(superFrame.sceneDraws, int(superFrame.superpages.size()));
    EXPECT_EQ(pagesFrame.renderTexels, std::int64_t(pagesFrame.allocation.pages.size()) * 64 * 64);
    EXPECT_GE(superFrame.renderTexels, pagesFrame.renderTexels) << "blocks hold their pages";
    EXPECT_GT(rendered, int(superPool.size() / 20)) << "the scene covers the pool's pages";
    EXPECT_EQ(overSlope, 0);
    EXPECT_LE(over, rendered / 10000) << "at most 0.01 % of the texels off by more than 1e-6";
    EXPECT_EQ(superError, pagesError);
    test::expectNoGlErrors(*r);
  }
}

double errorOf(const std::string& scene, const std::string& technique,
               const std::vector<std::pair<const char*, double>>& sets, int w = 320, int h = 180) {
  auto r = test::makeRenderer(scene, technique);
  if (!r) return -1.0;
  for (const auto& [k, v] : sets) EXPECT_FALSE(r->params().set(k, v)) << k;
  EXPECT_FALSE(r->renderFrame(w, h, 0));
  const double e = r->computeError().stats.errorPct;
  test::expectNoGlErrors(*r);
  return e;
}

// diagonal and corridor at 320x180: a pool of 256 pages of 128² (the bytes of uniform 2048²),
// the 65536² virtual map, pages two levels finer than the footprint (lod.bias 2), against
// uniform 2048² and rtw-backward 1024². Measured: diagonal 0.049 % (uniform 0.220 %, RTW
// 0.102 %, at 16384²), corridor 0.898 % (18.9 %, 1.92 %).
TEST(Rmsm, BeatsUniformAndRtwAtTheBytesOfUniform2048) {
  for (const char* scene : {"diagonal", "corridor"}) {
    SCOPED_TRACE(scene);
    const double uniform = errorOf(scene, "uniform", {{"resolution", 2048}});
    const double rtw = errorOf(scene, "rtw-backward", {{"resolution", 1024}});
    const double rmsm = errorOf(scene, "rmsm", {{"lod.bias", 2}});
    std::printf("%s 320x180: uniform 2048^2 %.3f %%, rtw-backward 1024^2 %.3f %%, rmsm %.3f %%\n",
                scene, uniform, rtw, rmsm);
    EXPECT_GE(rmsm, 0.0);
    EXPECT_LT(rmsm, uniform);
    EXPECT_LT(rmsm, rtw);
  }
}

// A pool of 4 pages: the finest levels are coarsened until the root and the requests fit;
// counted, no GL error, a valid (coarser) shadow.
TEST(Rmsm, ExhaustedPoolCoarsensAndCounts) {
  auto r = test::makeRenderer("plane-box", "rmsm");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->params().set("virtual.resolution", 16384));  // one root page
  ASSERT_FALSE(r->params().set("pool.pages", 4));
  r->requestPublications({"pages.*"});
  ASSERT_FALSE(r->renderFrame(160, 90, 0));
  const Publication& pub = r->publication();
  std::printf("pool of 4: requested %.0f, allocated %.0f, coarsened %.0f\n",
              pub.numbers.at("pages.requested"), pub.numbers.at("pages.allocated"),
              pub.numbers.at("pages.coarsened"));
  EXPECT_GT(pub.numbers.at("pages.requested"), 4.0);
  EXPECT_LE(pub.numbers.at("pages.allocated"), 4.0);
  EXPECT_GT(pub.numbers.at("pages.coarsened"), 0.0);
  EXPECT_EQ(pub.numbers.at("pages.pool"), 4.0);
  // The Pages panel's views: every allocated page is one Requested / Fallback cell of its
  // level and one used pool slot; some request is marked coarsened; the pool depth is read.
  int allocatedCells = 0, coarsenedCells = 0;
  for (int l = 0; l < 8; ++l) {
    const FloatImage& t = pub.images.at("pages.table." + std::to_string(l));
    EXPECT_EQ(t.width, 128 >> l);
    for (float v : t.values) {
      allocatedCells += v == 1.0f || v == 2.0f;
      coarsenedCells += v == 3.0f;
    }
  }
  EXPECT_EQ(allocatedCells, int(pub.numbers.at("pages.allocated")));
  EXPECT_GT(coarsenedCells, 0);
  const std::vector<float>& slots = pub.curves.at("pages.pool.levels");
  ASSERT_EQ(slots.size(), 4u);
  EXPECT_EQ(std::count_if(slots.begin(), slots.end(), [](float v) { return v == v; }),
            std::ptrdiff_t(pub.numbers.at("pages.allocated")));
  EXPECT_EQ(pub.images.at("pages.pool.depth").width, 2 * 128);
  EXPECT_EQ(pub.images.at("pages.served").width, 128);
  EXPECT_GT(pub.images.at("pages.requests.heat").values[0] +
                *std::max_element(pub.images.at("pages.requests.heat").values.begin(),
                                  pub.images.at("pages.requests.heat").values.end()),
            0.0f);
  const double e = r->computeError().stats.errorPct;
  EXPECT_GE(e, 0.0);
  EXPECT_LT(e, 50.0);
  test::expectNoGlErrors(*r);
}

// memory() lists every byte: the pool, the page table's levels, the request image and list,
// and (rmsm.render = superpages) the superpage target of min(1024, virtual.resolution)².
TEST(Rmsm, MemoryIsExact) {
  auto r = test::makeRenderer("diagonal", "uniform");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->renderFrame(160, 90, 0));
  const std::uint64_t before = gl::allocatedBytes() - r->stats().memory.bytes();
  ASSERT_FALSE(r->setTechnique("rmsm"));
  for (auto [pool, page, virt, render] : {std::tuple{256, 128, 16384, 0},
                                          {10, 64, 2048, 0},
                                          {3, 256, 4096, 0},
                                          {10, 64, 512, 0},
                                          {256, 128, 16384, 1},
                                          {10, 64, 512, 1}}) {
    SCOPED_TRACE(testing::Message() << pool << " " << page << " " << virt << " " << render);
    ASSERT_FALSE(r->params().set("pool.pages", pool));
    ASSERT_FALSE(r->params().set("page.size", page));
    ASSERT_FALSE(r->params().set("virtual.resolution", virt));
    ASSERT_FALSE(r->params().set("rmsm.render", render));
    ASSERT_FALSE(r->renderFrame(160, 90, 0));
    const MemoryStats& m = r->stats().memory;
    EXPECT_EQ(m.bytes(), gl::allocatedBytes() - before) << "memory() must list every byte";
    int columns = 1;
    while (columns * columns < pool) ++columns;
    const std::uint64_t rows = std::uint64_t((pool + columns - 1) / columns);
    std::uint64_t table = 0;
    for (int n = virt / page; n >= 1; n /= 2) table += 4ull * std::uint64_t(n) * std::uint64_t(n);
    const std::uint64_t side = std::uint64_t(std::min(SL_RMSM_SUPERPAGE, virt));
    const std::uint64_t superpage =
        render == RmsmShadowMap::kRenderSuperpages ? 4 * side * side : 0;
    // The sort's two buffers: the compacted length rounded up to a power of two, each.
    std::uint64_t sorted = 0, unique = 0;
    for (const ResourceInfo& res : m.resources) {
      if (res.name == "sorted requests") sorted = res.bytes;
      if (res.name == "unique requests") unique = res.bytes;
    }
    EXPECT_EQ(sorted, unique);
    EXPECT_TRUE(sorted >= 8 && std::has_single_bit(sorted)) << sorted;
    EXPECT_LE(sorted, 4ull * std::bit_ceil(std::uint64_t(160 * 90)));
    const std::uint64_t sortKeys = sorted;
    EXPECT_EQ(m.bytes(), 4ull * std::uint64_t(columns * page) * rows * std::uint64_t(page) + table +
                             4ull * 160 * 90 + 4ull * (1 + 160 * 90) + superpage + 2 * sortKeys +
                             4);
  }
  test::expectNoGlErrors(*r);
}

// pool.budget: memory() — pool, page table, request image and list, sort buffers, superpage
// target — never exceeds the budget and leaves less than a few pages of it, frame after frame,
// at budgets from uniform 1024²'s to uniform 4096²'s total bytes, two view sizes and both render
// paths; every byte is what the GL wrappers allocated; the
// pool is what the Pages panel publishes. A budget that cannot hold the top level names itself.
TEST(Rmsm, BudgetHoldsTheWholeMemory) {
  auto r = test::makeRenderer("diagonal", "uniform");
  ASSERT_TRUE(r);
  r->requestPublications({"pages.pool"});
  const std::uint64_t page = 4ull * 128 * 128;
  for (auto [budget, render, w, h] : {std::tuple{16777216, 1, 320, 180},
                                      {16777216, 1, 160, 90},
                                      {16777216, 0, 320, 180},
                                      {8000000, 1, 320, 180},
                                      {8000000, 0, 160, 90},
                                      // the total bytes of uniform 1024² and 4096² maps
                                      {4194304, 1, 320, 180},
                                      {4194304, 1, 160, 90},
                                      {67108864, 1, 320, 180},
                                      {67108864, 0, 160, 90}}) {
    SCOPED_TRACE(testing::Message() << budget << " " << render << " " << w << "x" << h);
    // The renderer's own targets follow the view's size: counted apart at this size.
    ASSERT_FALSE(r->setTechnique("uniform"));
    ASSERT_FALSE(r->renderFrame(w, h, 0));
    const std::uint64_t before = gl::allocatedBytes() - r->stats().memory.bytes();
    ASSERT_FALSE(r->setTechnique("rmsm"));
    ASSERT_FALSE(r->params().set("pool.budget", budget));
    ASSERT_FALSE(r->params().set("rmsm.render", render));
    for (int frame = 0; frame < 2; ++frame) {
      ASSERT_FALSE(r->renderFrame(w, h, 0));
      const MemoryStats& m = r->stats().memory;
      EXPECT_EQ(m.bytes(), gl::allocatedBytes() - before) << "memory() must list every byte";
      EXPECT_LE(m.bytes(), std::uint64_t(budget));
      EXPECT_LT(std::uint64_t(budget) - m.bytes(), 4 * page);
      std::uint64_t pool = 0, superpage = 0;
      for (const ResourceInfo& res : m.resources) {
        if (res.name == "page pool") pool = res.bytes;
        if (res.name == "superpage target") superpage = res.bytes;
      }
      EXPECT_EQ(pool, std::uint64_t(r->publication().numbers.at("pages.pool")) * page);
      EXPECT_EQ(superpage, render == RmsmShadowMap::kRenderSuperpages ? 4ull << 20 : 0u);
    }
  }
  // Uniform 1024²'s 4 MiB cannot also hold the 4 MiB superpage target: refused, named.
  ASSERT_FALSE(r->params().set("rmsm.render", RmsmShadowMap::kRenderSuperpages));
  ASSERT_FALSE(r->params().set("pool.budget", 4194304));
  const auto small = r->renderFrame(160, 90, 0);
  ASSERT_TRUE(small);
  EXPECT_NE(small->find("pool.budget = 4194304 bytes cannot hold"), std::string::npos) << *small;
  EXPECT_NE(small->find("superpage target"), std::string::npos) << *small;
  // 65536² in 128² pages: the top level's 16 pages (1 MiB) and the 1.4 MiB page table.
  ASSERT_FALSE(r->params().set("pool.budget", 2000000));
  const auto err = r->renderFrame(160, 90, 0);
  ASSERT_TRUE(err);
  EXPECT_NE(err->find("pool.budget = 2000000 bytes cannot hold the 16 pages of the coarsest "
                      "level (1048576 bytes)"),
            std::string::npos)
      << *err;
  test::expectNoGlErrors(*r);
}

// Every declared pass of each rmsm.render value is timed (superpages: "rmsm superpages" and
// "rmsm copy"; pages: "rmsm pages"), the other value's are not; bad parameters name themselves.
TEST(Rmsm, DeclaredPassesAndBadParameters) {
  auto r = test::makeRenderer("plane-box", "rmsm");
  ASSERT_TRUE(r);
  for (int render : {RmsmShadowMap::kRenderSuperpages, RmsmShadowMap::kRenderPages}) {
    SCOPED_TRACE(render);
    ASSERT_FALSE(r->params().set("rmsm.render", render));
    ASSERT_FALSE(r->renderFrame(96, 64, 0));
    // This frame's passes (FrameStats::passOrder: timer-query times arrive a frame late).
    const std::vector<std::string>& timed = r->stats().passOrder;
    std::vector<std::string> declared;
    for (const PassDecl& d : framePassDecls(RmsmShadowMap::info(), r->params()))
      declared.push_back(d.id);
    test::expectDeclaredPassesOpened(r->stats(), declared);
    const bool super = render == RmsmShadowMap::kRenderSuperpages;
    for (const char* id : {"rmsm superpages", "rmsm copy"}) {
      EXPECT_EQ(std::count(declared.begin(), declared.end(), id), super ? 1 : 0) << id;
      EXPECT_EQ(std::count(timed.begin(), timed.end(), id), super ? 1 : 0) << id;
    }
    EXPECT_EQ(std::count(timed.begin(), timed.end(), "rmsm pages"), super ? 0 : 1);
    EXPECT_EQ(std::count(declared.begin(), declared.end(), "rmsm pages"), super ? 0 : 1);
  }
  EXPECT_EQ(framePassDecls(RmsmShadowMap::info()).size(),
            framePassDecls(RmsmShadowMap::info(), r->params()).size() + 2);
  ASSERT_FALSE(r->params().set("rmsm.render", RmsmShadowMap::kRenderSuperpages));
  ASSERT_FALSE(r->params().set("virtual.resolution", 1000));
  const auto err = r->renderFrame(96, 64, 0);
  ASSERT_TRUE(err);
  EXPECT_NE(err->find("virtual.resolution = 1000 must be a power of two (256..262144)"),
            std::string::npos)
      << *err;
  // The same check, declared with the technique, runs without GL (the CLI's up-front check).
  EXPECT_EQ("technique 'rmsm': " + checkTechniqueParams(RmsmShadowMap::info(), r->params()).value(),
            *err);
  // 65536 / 128 = 512 pages a side, cut at 8 levels: the top level has 4 x 4 pages.
  ASSERT_FALSE(r->params().set("virtual.resolution", 65536));
  ASSERT_FALSE(r->params().set("pool.pages", 15));
  const auto small = r->renderFrame(96, 64, 0);
  ASSERT_TRUE(small);
  EXPECT_NE(small->find("pool.pages = 15 cannot hold the 16 pages of the coarsest level"),
            std::string::npos)
      << *small;
  ASSERT_FALSE(r->params().set("pool.pages", 16));
  EXPECT_FALSE(r->renderFrame(96, 64, 0));
}

// The pages overlay (view.overlay = pages): the composite paints exactly the pixels that
// pages::pageBorders finds from the read-back map index, uv and coverage (0 mismatches), for
// rmsm and asm (both paged maps: one map per quadtree level, pages per side halving per level);
// every other pixel is grey.
TEST(Rmsm, PageBorderOverlayIsWhereThePageChanges) {
  const pages::VirtualLayout layout{16384, 128, SL_PAGED_LOOKUP_LEVELS};
  std::vector<int> grid;
  for (int l = 0; l < layout.levels(); ++l) grid.push_back(layout.pagesPerSide(l));
  for (const char* id : {"rmsm", "asm"}) {
    SCOPED_TRACE(id);
    auto r = test::makeRenderer("plane-box", id);
    ASSERT_TRUE(r);
    ASSERT_FALSE(r->params().set("virtual.resolution", layout.virtualResolution));
    ASSERT_FALSE(r->rendererParams().setFromString("view.overlay", "pages"));
    const int w = 160, h = 90;
    ASSERT_FALSE(r->renderFrame(w, h, 0));
    const FrameReadback fr = r->readback();
    std::vector<std::uint8_t> covered(fr.positions.size());
    for (std::size_t i = 0; i < covered.size(); ++i) covered[i] = fr.positions[i].w > 0.0f;
    const std::vector<std::uint8_t> border =
        pages::pageBorders(fr.texel, fr.mapIndex, covered, w, h, grid);
    int borders = 0, mismatches = 0, levels = 0;
    std::set<int> used;
    for (std::size_t i = 0; i < border.size(); ++i) {
      const std::uint8_t* c = &fr.color.pixels[4 * i];
      const bool painted = c[0] == 255 && c[1] == 89 && c[2] == 0;  // SL_PAGE_BORDER_COLOUR
      mismatches += painted != (border[i] != 0);
      borders += border[i];
      if (covered[i]) used.insert(fr.mapIndex[i]);
    }
    levels = int(used.size());
    std::printf("%s: %d border pixels of %d, %d levels used, %d mismatches\n", id, borders, w * h,
                levels, mismatches);
    EXPECT_EQ(mismatches, 0);
    EXPECT_GT(borders, 100);
    EXPECT_GT(levels, 1);
    test::expectNoGlErrors(*r);
  }
}

}  // namespace
}  // namespace sl
