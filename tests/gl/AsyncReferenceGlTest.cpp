// computeError() in its three steps (issue 15 item 6: the GUI traces on a worker thread):
// snapshot + trace on another thread give computeError()'s exact numbers and mask; a
// cancelled trace gives nothing; a mask of another size is refused for the error overlay;
// the adaptive present size leaves every target and readback at the rendered size.
#include <atomic>
#include <chrono>

#include "GlTestEnv.h"
#include "Watchdog.h"

namespace sl {
namespace {

TEST(AsyncReferenceGl, SnapshotTracedOnAnotherThreadEqualsComputeError) {
  auto r = test::makeRenderer("default", "uniform");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->renderFrame(160, 96, 0));
  const Renderer::ErrorResult sync = r->computeError();
  ASSERT_GT(sync.stats.covered, 0u);

  Renderer::ReferenceSnapshot snap = r->snapshotForReference();
  ASSERT_TRUE(snap.reference);
  EXPECT_EQ(snap.frameSignature, r->frameSignature());
  std::optional<Renderer::ErrorResult> async;
  std::atomic<bool> cancelled{false};
  // On another thread (no GL there); a trace that never returns fails within a bound (then
  // the cancel flag, seen between bands, ends it) instead of hanging until the ctest timeout.
  ASSERT_TRUE(test::finishesWithin(
      std::chrono::seconds(120), "traceReference on a worker thread",
      [&] { async = Renderer::traceReference(snap, &cancelled); }, [&] { cancelled = true; }));
  ASSERT_TRUE(async);
  EXPECT_EQ(async->referenceMask, sync.referenceMask);
  EXPECT_EQ(async->stats.covered, sync.stats.covered);
  EXPECT_EQ(async->stats.falseLit, sync.stats.falseLit);
  EXPECT_EQ(async->stats.falseShadow, sync.stats.falseShadow);
  EXPECT_EQ(async->stats.errorPct, sync.stats.errorPct);

  cancelled = true;
  EXPECT_FALSE(Renderer::traceReference(snap, &cancelled));  // seen before the first band

  EXPECT_TRUE(r->setReferenceMask(snap.frameSignature, async->referenceMask, 160, 96));
  const std::vector<std::uint8_t> wrong(80 * 48, 1);
  EXPECT_FALSE(r->setReferenceMask(snap.frameSignature, wrong, 80, 48));  // not this size
}

TEST(AsyncReferenceGl, APresentSizeKeepsTheRenderedSize) {
  auto r = test::makeRenderer("default", "uniform");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->renderFrame(80, 48, 0, 320, 192));  // surfaceless: nothing to stretch into
  EXPECT_EQ(r->stats().width, 80);
  EXPECT_EQ(r->stats().height, 48);
  const FrameReadback f = r->readback();
  EXPECT_EQ(f.width, 80);
  EXPECT_EQ(f.positions.size(), 80u * 48u);
  const Renderer::ErrorResult e = r->computeError();
  EXPECT_EQ(e.referenceMask.size(), 80u * 48u);
}

}  // namespace
}  // namespace sl
