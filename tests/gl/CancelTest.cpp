// Cancellation (Renderer::setCancelFlag): the host's stop flag read between renderFrame's steps
// and between a resolve's units. A stopped frame says so (stats().cancelled, not complete), is
// never measured (readback empty, computeError refuses), and leaves nothing behind that would
// change the next frame: that frame is byte for byte the frame of a renderer that never saw
// the stopped one.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <thread>

#include "GlTestEnv.h"
#include "core/Technique.h"

namespace sl {
namespace {

/// The scene a technique renders with its first supported light kind.
std::string sceneFor(const TechniqueInfo& info) {
  return !checkLightSupport(info, LightType::Directional) ? "diagonal" : "omni-room";
}

/// Virtual-tiled small enough for a test, slow enough that a frame takes tens of ms (16 tiles of
/// 1024²) or, at 2048², well over 100 ms on llvmpipe.
void slowVirtualTiled(Renderer& r, int tileResolution = 1024) {
  ASSERT_FALSE(r.params().set("tiles", 4));
  ASSERT_FALSE(r.params().set("tile.resolution", tileResolution));
}

/// Where a Stopping technique sets the host's flag while armed.
enum class StopAt {
  AfterShadows,  ///< right after its shadow passes
  InResolve,     ///< as its deferred resolve starts: it stops after its first unit
};
/// Armed: the flag a Stopping technique sets, and where.
std::atomic<bool>* gStopFlag = nullptr;
StopAt gStopAt = StopAt::AfterShadows;

/// A built-in technique that sets gStopFlag at gStopAt while armed: a frame stopped exactly
/// between its shadows and the rest, or within its resolve.
class Stopping : public Technique {
 public:
  explicit Stopping(std::unique_ptr<Technique> inner) : inner_(std::move(inner)) {}
  void renderShadows(FrameContext& ctx) override {
    inner_->renderShadows(ctx);
    if (gStopFlag && gStopAt == StopAt::AfterShadows) *gStopFlag = true;
  }
  ResolveMode resolveMode() const override { return inner_->resolveMode(); }
  std::string lookupShader() const override { return inner_->lookupShader(); }
  void bindLookup(const gl::Program& resolve, int firstUnit) const override {
    inner_->bindLookup(resolve, firstUnit);
  }
  void resolveDeferred(const ResolveTargets& targets, const ParamSet& params) override {
    if (gStopFlag && gStopAt == StopAt::InResolve) *gStopFlag = true;
    inner_->resolveDeferred(targets, params);
  }
  std::vector<const gl::Program*> programs() const override { return inner_->programs(); }
  MemoryStats memory() const override { return inner_->memory(); }
  std::optional<std::string> reloadShaders(const gl::ShaderLibrary& lib) override {
    return inner_->reloadShaders(lib);
  }
  void commitFrame() override { inner_->commitFrame(); }
  void discardFrame() override { inner_->discardFrame(); }
  void resetTemporalState() override { inner_->resetTemporalState(); }
  std::vector<int> pageGrid() const override { return inner_->pageGrid(); }

 private:
  std::unique_ptr<Technique> inner_;
};

const TechniqueEntry& builtInEntry(std::string_view id) {
  for (const TechniqueEntry& e : techniqueRegistry())
    if (e.info.id == id) return e;
  throw std::logic_error("no built-in technique " + std::string(id));
}

/// The technique a stoppingEntry wraps (read when the renderer creates it).
std::string gWrappedId;

/// The built-in technique `id` (its declaration, temporalState included) as "test-stop-<id>",
/// stopping its frame at gStopAt while armed.
TechniqueEntry stoppingEntry(const std::string& id) {
  gWrappedId = id;
  TechniqueEntry e;
  e.info = builtInEntry(id).info;
  e.info.id = "test-stop-" + id;
  e.create = [](const gl::ShaderLibrary& lib) -> std::unique_ptr<Technique> {
    return std::make_unique<Stopping>(builtInEntry(gWrappedId).create(lib));
  };
  return e;
}

int countScopes(const FrameStats& stats, const std::string& name) {
  int n = 0;
  for (const PassTiming& p : stats.passSequence) n += p.name == name;
  return n;
}

double msSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

/// A flag set before renderFrame: the frame stops after its first step (the G-buffer), says
/// so, and is not measured; clearing the flag renders again. Every technique.
TEST(Cancel, FlagSetBeforeTheFrameStopsAfterTheFirstStep) {
  for (const TechniqueInfo& info : Renderer::techniques()) {
    SCOPED_TRACE(info.id);
    auto r = test::makeRenderer(sceneFor(info), info.id);
    ASSERT_TRUE(r);
    std::atomic<bool> stop{true};
    r->setCancelFlag(&stop);
    EXPECT_FALSE(r->renderFrame(64, 48, 0));
    const FrameStats& st = r->stats();
    EXPECT_TRUE(st.cancelled);
    EXPECT_FALSE(st.complete());
    EXPECT_EQ(st.passOrder, std::vector<std::string>{"gbuffer"});
    EXPECT_EQ(st.stoppedBefore, "shadows");
    const FrameReadback rb = r->readback();
    EXPECT_TRUE(rb.cancelled);
    EXPECT_EQ(rb.width, 0);
    EXPECT_TRUE(rb.hardMask.empty());
    EXPECT_THROW((void)r->computeError(), std::runtime_error);
    test::expectNoGlErrors(*r);
  }
}

/// The flag is read again each frame: cleared, the next frame is complete; a null flag never
/// stops one. A stopped frame's publication and reference are not offered as a frame's.
TEST(Cancel, ClearedFlagRendersCompleteFramesAgain) {
  auto r = test::makeRenderer("plane-box", "uniform");
  ASSERT_TRUE(r);
  r->requestPublications({"camera.*"});
  ASSERT_FALSE(r->renderFrame(64, 48, 0));
  const std::uint64_t completeFrame = r->stats().frameIndex;
  ASSERT_EQ(r->publication().frameIndex, completeFrame);
  ASSERT_FALSE(r->publication().numbers.empty());
  std::atomic<bool> stop{true};
  r->setCancelFlag(&stop);
  ASSERT_FALSE(r->renderFrame(64, 48, 0));
  ASSERT_TRUE(r->stats().cancelled);
  EXPECT_GT(r->stats().frameIndex, completeFrame);
  EXPECT_EQ(r->publication().frameIndex, completeFrame) << "the last complete frame's";
  EXPECT_FALSE(r->publication().numbers.empty());
  Renderer::ReferenceSnapshot snap = r->snapshotForReference();
  EXPECT_TRUE(snap.frame.cancelled);
  EXPECT_FALSE(Renderer::traceReference(std::move(snap)));
  stop = false;
  ASSERT_FALSE(r->renderFrame(64, 48, 0));
  EXPECT_FALSE(r->stats().cancelled);
  EXPECT_TRUE(r->stats().complete());
  EXPECT_FALSE(r->readback().cancelled);
  EXPECT_EQ(r->readback().width, 64);
  stop = true;
  r->setCancelFlag(nullptr);
  ASSERT_FALSE(r->renderFrame(64, 48, 0));
  EXPECT_FALSE(r->stats().cancelled);
  test::expectNoGlErrors(*r);
}

/// A flag set from another thread a third of the way into a slow frame (one call) stops its
/// resolve between two tiles, before the composite; prints the latency from the flag to
/// renderFrame's return.
void expectThreadStopsSlowFrame(Renderer& r, const std::string& what) {
  auto start = std::chrono::steady_clock::now();
  ASSERT_FALSE(r.renderFrame(320, 240, 0));
  const double fullMs = msSince(start);
  const int tiles = countScopes(r.stats(), "tile apply");
  std::printf("%s at 320x240: a whole frame %.0f ms, %d tiles\n", what.c_str(), fullMs, tiles);
  ASSERT_GT(fullMs, 100.0);
  ASSERT_GT(tiles, 4);

  std::atomic<bool> stop{false};
  r.setCancelFlag(&stop);
  std::chrono::steady_clock::time_point setAt;
  std::thread host([&] {
    std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(fullMs / 3.0));
    setAt = std::chrono::steady_clock::now();
    stop = true;
  });
  ASSERT_FALSE(r.renderFrame(320, 240, 0));
  const auto returnedAt = std::chrono::steady_clock::now();
  host.join();
  const double latencyMs = std::chrono::duration<double, std::milli>(returnedAt - setAt).count();
  const FrameStats& st = r.stats();
  ASSERT_TRUE(st.cancelled);
  EXPECT_FALSE(st.complete());
  EXPECT_LT(countScopes(st, "tile apply"), tiles) << "stopped between the tiles";
  EXPECT_EQ(countScopes(st, "composite"), 0);
  EXPECT_NE(st.stoppedBefore, "");
  std::printf("%s: stop latency (flag set -> renderFrame returned) %.1f ms (a tile ~%.1f ms)\n",
              what.c_str(), latencyMs, fullMs / tiles);
  r.setCancelFlag(nullptr);
  test::expectNoGlErrors(r);
}

TEST(Cancel, FlagFromAnotherThreadStopsASlowFrame) {
  auto vt = test::makeRenderer("plane-box", "virtual-tiled");
  ASSERT_TRUE(vt);
  slowVirtualTiled(*vt, 2048);
  expectThreadStopsSlowFrame(*vt, "virtual-tiled 4x4 of 2048^2");
  auto fvsm = test::makeRenderer("plane-box", "fvsm");  // its defaults: ~0.4 s on llvmpipe
  ASSERT_TRUE(fvsm);
  expectThreadStopsSlowFrame(*fvsm, "fvsm");
}

/// Where a frame of the transactional tests is stopped.
enum class Stop {
  None,           ///< not stopped: a renderer that never saw the frame
  BeforeShadows,  ///< the flag set before renderFrame: it stops after its G-buffer
  AfterShadows,   ///< right after the technique's shadow passes (its resolve still runs)
  MidResolve,     ///< after the first unit of a deferred resolve
};

/// Renders `technique` (wrapped as "test-stop-<id>") on its scene: three complete frames with
/// the camera moving, so that state across frames exists; then, unless `stop` is None, a frame
/// at another view stopped there; then a view near the third, complete (the held state a
/// stopped frame would have left shows there: the cascades' held range, ASM's pages). Returns
/// what that last frame shows.
FrameReadback renderAfterStop(const std::string& technique, Stop stop) {
  const TechniqueInfo* info = Renderer::findTechnique(technique);
  EXPECT_TRUE(info);
  if (!info) return {};
  RendererOptions options;
  options.extraTechniques = {stoppingEntry(technique)};
  auto r = test::makeRenderer(sceneFor(*info), "test-stop-" + technique, options);
  EXPECT_TRUE(r);
  if (!r) return {};
  if (technique == "da-rtw") {  // the shadow-edge term reads the previous frame's mask
    EXPECT_FALSE(r->params().set("importance.edge", 1));
  }
  if (technique == "virtual-tiled") slowVirtualTiled(*r, 128);
  // A pool the frames fill: the stopped frame evicts (and overwrites) cached pages.
  if (technique == "asm") {
    EXPECT_FALSE(r->params().set("pool.pages", 40));
    EXPECT_FALSE(r->params().set("asm.pages.per.frame", 8));  // refined over several frames
  }
  std::atomic<bool> flag{false};
  r->setCancelFlag(&flag);
  const Camera first = r->camera();
  Camera second = first, third = first, moved = first, after = first;
  second.orbit(10.0f, 5.0f);
  third.orbit(4.0f, -3.0f);
  moved.orbit(-25.0f, 8.0f);
  after.orbit(6.0f, -2.0f);
  for (const Camera& c : {first, second, third}) {
    r->setCamera(c);
    EXPECT_FALSE(r->renderFrame(160, 120, 0));
    EXPECT_TRUE(r->stats().complete());
  }
  r->setCamera(moved);
  if (stop != Stop::None) {
    flag = stop == Stop::BeforeShadows;
    gStopAt = stop == Stop::MidResolve ? StopAt::InResolve : StopAt::AfterShadows;
    gStopFlag = stop == Stop::BeforeShadows ? nullptr : &flag;
    EXPECT_FALSE(r->renderFrame(160, 120, 0));
    gStopFlag = nullptr;
    EXPECT_TRUE(r->stats().cancelled);
    EXPECT_EQ(r->stats().stoppedBefore == "shadows", stop == Stop::BeforeShadows);
    if (technique == "asm" && stop == Stop::AfterShadows) {  // it overwrote cached pages
      const std::vector<ResourceInfo>& held = r->stats().memory.resources;
      EXPECT_TRUE(std::any_of(held.begin(), held.end(), [](const ResourceInfo& res) {
        return res.name == "page pool as the last complete frame left it";
      }));
    }
    flag = false;
  }
  r->setCamera(after);
  EXPECT_FALSE(r->renderFrame(160, 120, 0));
  EXPECT_TRUE(r->stats().complete());
  test::expectNoGlErrors(*r);
  return r->readback();
}

/// Frames are transactional: a frame stopped before its shadows, right after them or within
/// its resolve leaves no trace; the next frame is byte for byte (colour, hard mask, aliasing)
/// what a renderer that never saw it renders. Every technique with state across frames
/// (TechniqueInfo::temporalState), uniform as a stateless control, and virtual-tiled for a
/// stop within a (deferred, unit by unit) resolve.
TEST(Cancel, AStoppedFrameLeavesNoTrace) {
  std::vector<std::pair<std::string, Stop>> cases;
  for (const TechniqueInfo& info : Renderer::techniques())
    if (info.temporalState || info.id == "uniform")
      for (Stop stop : {Stop::BeforeShadows, Stop::AfterShadows}) cases.emplace_back(info.id, stop);
  ASSERT_GT(cases.size(), 2u) << "some technique declares temporalState";
  cases.emplace_back("virtual-tiled", Stop::MidResolve);
  std::map<std::string, FrameReadback> unseen;
  for (const auto& [technique, stop] : cases) {
    SCOPED_TRACE(technique + (stop == Stop::BeforeShadows  ? " stopped before the shadows"
                              : stop == Stop::AfterShadows ? " stopped after the shadows"
                                                           : " stopped within the resolve"));
    if (!unseen.count(technique)) unseen[technique] = renderAfterStop(technique, Stop::None);
    const FrameReadback& fresh = unseen[technique];
    ASSERT_FALSE(fresh.color.pixels.empty());
    const FrameReadback next = renderAfterStop(technique, stop);
    EXPECT_EQ(next.color.pixels, fresh.color.pixels);
    EXPECT_EQ(next.hardMask, fresh.hardMask);
    EXPECT_EQ(next.aliasing, fresh.aliasing);
  }
}

/// A progressive resolve stopped between its units (or before its resolve) goes on where it
/// stopped; once complete it equals the one-call frame pixel for pixel.
TEST(Cancel, ProgressiveResolveResumesAfterAStop) {
  auto r = test::makeRenderer("plane-box", "virtual-tiled");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->params().set("tiles", 4));
  ASSERT_FALSE(r->params().set("tile.resolution", 128));
  ASSERT_FALSE(r->renderFrame(160, 120, 0));
  const FrameReadback oneCall = r->readback();
  Camera moved = r->camera(), original = r->camera();
  moved.orbit(30.0f, 10.0f);
  r->setCamera(moved);
  ASSERT_FALSE(r->renderFrame(160, 120, 0));  // other pixels in the targets
  r->setCamera(original);

  std::atomic<bool> stop{false};
  r->setCancelFlag(&stop);
  r->setProgressiveBudget(1e-6);  // one tile per call
  ASSERT_FALSE(r->renderFrame(160, 120, 0));
  ASSERT_TRUE(r->stats().progress);
  EXPECT_EQ(r->stats().progress->done, 1);
  stop = true;  // before the frame: no unit done
  ASSERT_FALSE(r->renderFrame(160, 120, 0));
  EXPECT_TRUE(r->stats().cancelled);
  EXPECT_FALSE(r->stats().complete());
  stop = false;
  ASSERT_FALSE(r->renderFrame(160, 120, 0));
  EXPECT_EQ(r->stats().progress->done, 2) << "goes on after the stopped call";
  for (int calls = 0; calls < 40 && !r->stats().complete(); ++calls)
    ASSERT_FALSE(r->renderFrame(160, 120, 0));
  ASSERT_TRUE(r->stats().complete());
  const FrameReadback resumed = r->readback();
  EXPECT_EQ(resumed.hardMask, oneCall.hardMask);
  EXPECT_EQ(resumed.color.pixels, oneCall.color.pixels);
  test::expectNoGlErrors(*r);
}

/// The same with the flag set from another thread while a progressive call does its units
/// (a budget that would do them all): it stops between two units, the next call goes on from
/// there, and the finished frame equals the one-call frame.
TEST(Cancel, ProgressiveResolveStoppedBetweenUnitsGoesOn) {
  auto r = test::makeRenderer("plane-box", "virtual-tiled");
  ASSERT_TRUE(r);
  slowVirtualTiled(*r);
  auto start = std::chrono::steady_clock::now();
  ASSERT_FALSE(r->renderFrame(160, 120, 0));
  const double fullMs = msSince(start);
  const FrameReadback oneCall = r->readback();
  Camera moved = r->camera(), original = r->camera();
  moved.orbit(30.0f, 10.0f);
  r->setCamera(moved);
  ASSERT_FALSE(r->renderFrame(160, 120, 0));
  r->setCamera(original);

  std::atomic<bool> stop{false};
  r->setCancelFlag(&stop);
  r->setProgressiveBudget(1e9);
  std::thread host([&] {
    std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(fullMs / 3.0));
    stop = true;
  });
  ASSERT_FALSE(r->renderFrame(160, 120, 0));
  host.join();
  ASSERT_TRUE(r->stats().cancelled);
  ASSERT_TRUE(r->stats().progress);
  const int doneWhenStopped = r->stats().progress->done;
  const int total = r->stats().progress->total;
  std::printf("stopped after %d of %d units\n", doneWhenStopped, total);
  EXPECT_GT(doneWhenStopped, 0);
  EXPECT_LT(doneWhenStopped, total);
  stop = false;
  ASSERT_FALSE(r->renderFrame(160, 120, 0));
  ASSERT_TRUE(r->stats().complete());
  EXPECT_LT(countScopes(r->stats(), "tile depth"), total) << "went on, did not start over";
  const FrameReadback resumed = r->readback();
  EXPECT_EQ(resumed.hardMask, oneCall.hardMask);
  EXPECT_EQ(resumed.color.pixels, oneCall.color.pixels);
  test::expectNoGlErrors(*r);
}

}  // namespace
}  // namespace sl
