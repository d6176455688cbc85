// Adaptive shadow maps (Fernando, Fernandez, Bala, Greenberg 2001; techniques.md §5, the
// lecture's construction loop): RMSM's virtual map, page table and pool (PagedMap,
// algo/pages), fitted to the whole scene so that pages stay valid while the camera moves.
// A coarse map first (every page of the level asm.coarse.resolution asks for), then up to
// asm.iterations times: shadow test + edge finding (compute: a pixel on a shadow edge whose
// page is coarser than its LOD asks for the page at its LOD) → dedup + compaction (RMSM's
// pass) → read back, sort, unique, allocate in the page cache (algo/asm: LRU eviction) → render
// the new pages, until no request is left or asm.pages.per.frame new pages were rendered
// (asm.loop = until-done: the paper's loop, until no page is requested, capped by
// asm.iterations.cap and publishing what the cap left; asm.render = superpages renders them as
// the lecture's loop does, binned into superpages). asm.edge picks the edge test: the
// screen-space shadow mask (the tool's) or a texel on a shadow edge of the map (the paper's).
// Pages are kept between frames; a change of the light or the geometry drops them all.
// Directional only.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "algo/asm/AdaptivePages.h"
#include "core/ShadowPass.h"
#include "core/Technique.h"
#include "core/paged/PageRequestList.h"
#include "core/paged/PagedMap.h"

namespace sl {

class AsmShadowMap : public Technique {
 public:
  static TechniqueInfo info();
  explicit AsmShadowMap(const gl::ShaderLibrary& lib);

  void renderShadows(FrameContext& ctx) override;
  std::string lookupShader() const override { return "asm/lookup.glsl"; }
  void bindLookup(const gl::Program& resolve, int firstUnit) const override;
  std::vector<const gl::Program*> programs() const override {
    std::vector<const gl::Program*> p = depthProgram_.programs();
    p.insert(p.end(), {&testProgram_, &edgesProgram_, &requests_.program()});
    return p;
  }
  std::vector<int> pageGrid() const override { return map_.pageGrid(); }
  MemoryStats memory() const override;
  std::optional<std::string> reloadShaders(const gl::ShaderLibrary& lib) override;
  /// A new scene (Renderer::setScene) or a reset: the cached pages are dropped; the next frame
  /// starts from the coarse map. (Not keyed on the scene's address: a new scene may be
  /// allocated where the old one was.)
  void resetTemporalState() override {
    carried_->key = {};
    carried_.commit();  // between frames: the committed key too
  }
  /// The page cache the next frame starts from is the last complete frame's: a discarded
  /// frame's allocations are forgotten, the pool slots it overwrote restored and the page table
  /// uploaded again.
  void commitFrame() override;
  void discardFrame() override;

  /// What the last frame did (tests, publications).
  struct FrameResult {
    bool invalidated = false;  ///< the cache was dropped (light, geometry, layout changed)
    int coarsePages = 0;  ///< pages of the coarse map rendered this frame (0 unless invalidated)
    std::vector<adaptive::Refinement> iterations;  ///< one per iteration run
    std::vector<pages::PageKey> compacted;         ///< the last iteration's GPU list
    std::vector<pages::PageKey> unique;            ///< ... sorted, unique
    /// Every iteration's sorted unique keys (touches included): what the page cache was fed.
    std::vector<std::vector<pages::PageKey>> uniquePerIteration;
    /// Every iteration's compacted requests (touches aside) and their sorted unique keys: the
    /// Pages panel's heat map and pending pages.
    std::vector<pages::PageKey> requestKeys, requested;
    int newPages = 0;  ///< rendered this frame (coarse map aside)
    /// Why the loop stopped (Stop), and the distinct pages still requested then and not
    /// held: the last iteration's refused and deferred requests, or, when the iteration cap
    /// stopped a loop that was still allocating with asm.loop = until-done, the requests of
    /// one more edge-finding pass (its pages not allocated).
    int stop = 0;
    int requestsLeft = 0;
    /// asm.render = superpages: superpages rendered, all iterations (0 with pages); the
    /// iterations' scene draws (one per superpage or per new page; coarse map aside).
    int superpages = 0;
    int sceneDraws = 0;
  };
  /// asm.render: rmsm.render's values, the same order.
  static constexpr int kRenderSuperpages = kPagedRenderSuperpages, kRenderPages = kPagedRenderPages;
  /// FrameResult::stop (asm.stop): no new page was requested (the paper's end of the loop),
  /// the iteration cap, the per-frame page budget, the pool (only pages used this frame).
  enum Stop : int { kConverged = 0, kIterationCap = 1, kBudget = 2, kPoolFull = 3 };
  const FrameResult& lastFrame() const { return last_; }
  const adaptive::PageCache* cache() const { return carried_->cache ? &*carried_->cache : nullptr; }
  /// The last iteration's shadow test (rgba32ui: mask, served key, refine key) and its
  /// per-pixel keys (r32ui), the page table.
  const gl::Texture& testedImage() const { return tested_; }
  const gl::Texture& requestImage() const { return requests_.image(); }
  const gl::Texture& pageTableTexture() const { return map_.pageTableTexture(); }
  const glm::mat4& lightViewProj() const { return view_.lightViewProj; }
  const DepthMapView& mapView() const { return view_; }
  const PagedMap& pagedMap() const { return map_; }

 private:
  /// One iteration; false when it allocated nothing (the loop stops). Iterations beyond
  /// adaptive::kMaxIterations are not timed on their own (the caller's "asm more" pass).
  bool iterate(FrameContext& ctx, int iteration, int& budget);
  void findEdges(FrameContext& ctx);
  /// Before this frame renders into `slots`: those holding a page of the last complete frame's
  /// cache are kept aside (PagedMap::keepSlots) for discardFrame.
  void keepCommittedPages(std::span<const int> slots);

  DepthProgram depthProgram_;
  gl::Program testProgram_, edgesProgram_;
  PagedMap map_;
  /// What the cached pages were rendered for: any change drops them (and so does a new scene,
  /// resetTemporalState). The default key matches no frame (lightViewProj is zero).
  struct CacheKey {
    glm::mat4 lightViewProj{0.0f};
    std::size_t primitives = 0;
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};
    int virtualResolution = 0, pageSize = 0, poolPages = 0, coarseLevel = 0;
    bool operator==(const CacheKey&) const = default;
  };
  /// What ASM carries across frames (TechniqueInfo::temporalState): the page cache, what its
  /// pages were rendered for, and the frames since the last invalidation the cap stopped.
  struct Carried {
    std::optional<adaptive::PageCache> cache;
    CacheKey key;
    int capStops = 0;
  };
  FrameCarried<Carried> carried_;
  gl::Texture tested_;        ///< RGBA32UI per camera pixel
  PageRequestList requests_;  ///< per pixel (edges), then compacted
  DepthMapView view_;
  FrameResult last_;
  bool superpages_ = false;  ///< this frame's asm.render = superpages
};

}  // namespace sl
