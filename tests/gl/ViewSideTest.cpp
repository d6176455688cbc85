// core/ViewSide: one half of the GUI's view as the UI thread holds it — exact tests of its
// logic (no GL context is made: the technique registry is read, nothing is rendered). The
// equal-memory search the split half uses is tested in tests/cpu/MemoryMatchTest.cpp.
#include <gtest/gtest.h>

#include "core/ViewSide.h"

namespace sl {
namespace {

TEST(ViewSide, AnUnknownTechniqueIsRefusedNamingTheKnownOnesAndNothingChanges) {
  ViewSide side("uniform");
  const std::uint64_t before = side.revision();
  const auto e = side.setTechnique("no-such");
  ASSERT_TRUE(e);
  EXPECT_NE(e->find("unknown technique 'no-such'"), std::string::npos);
  EXPECT_NE(e->find("da-rtw"), std::string::npos);
  EXPECT_EQ(side.techniqueId(), "uniform");
  EXPECT_EQ(side.revision(), before);
  EXPECT_THROW(ViewSide("no-such"), std::invalid_argument);
}

TEST(ViewSide, ParametersAreKeptPerTechniqueAcrossSwitches) {
  ViewSide side("uniform");
  ASSERT_FALSE(side.params().set("resolution", 512.0));
  ASSERT_FALSE(side.setTechnique("da-rtw"));
  EXPECT_NE(side.params().getInt("resolution"), 512);  // da-rtw's own, at its default
  ASSERT_FALSE(side.setTechnique("uniform"));
  EXPECT_EQ(side.params().getInt("resolution"), 512);
  EXPECT_EQ(side.paramsOf("uniform").getInt("resolution"), 512);
}

TEST(ViewSide, EveryEditThatChangesTheImageMovesTheRevision) {
  ViewSide side("uniform");
  std::uint64_t r = side.revision();
  ASSERT_FALSE(side.params().set("resolution", 256.0));
  EXPECT_GT(side.revision(), r);
  r = side.revision();
  ASSERT_FALSE(side.params().set("resolution", 256.0));  // the same value
  EXPECT_EQ(side.revision(), r);
  side.resetTemporalState();
  EXPECT_GT(side.revision(), r);
  r = side.revision();
  ASSERT_FALSE(side.setTechnique("cascades"));
  EXPECT_GT(side.revision(), r);
  r = side.revision();
  ASSERT_FALSE(side.setTechnique("cascades"));  // already shown
  EXPECT_EQ(side.revision(), r);
  side.requestPublications({"pca.*"});  // what is published is not what is drawn
  EXPECT_EQ(side.revision(), r);
}

TEST(ViewSide, ARequestCopiesEveryValueAndTakesAPendingResetOnce) {
  ViewSide side("uniform");
  ASSERT_FALSE(side.params().set("resolution", 2048.0));
  side.requestPublications({"aliasing.*"});
  side.resetTemporalState();
  SideRequest first = side.takeRequest();
  EXPECT_EQ(first.techniqueId, "uniform");
  EXPECT_EQ(first.params.getInt("resolution"), 2048);
  EXPECT_TRUE(first.resetTemporal);
  EXPECT_EQ(first.publications, std::set<std::string>{"aliasing.*"});
  // The copy is the request's: later edits do not reach a request already sent.
  ASSERT_FALSE(side.params().set("resolution", 64.0));
  EXPECT_EQ(first.params.getInt("resolution"), 2048);
  const SideRequest second = side.takeRequest();
  EXPECT_FALSE(second.resetTemporal);
  EXPECT_EQ(second.params.getInt("resolution"), 64);
}

TEST(ViewSide, SyncParamsSetsOnlyTheValuesThatDiffer) {
  const TechniqueInfo* info = Renderer::findTechnique("uniform");
  ParamSet dst(info->params), src(info->params);
  EXPECT_EQ(syncParams(dst, src), 0);
  const unsigned r = dst.revision();
  EXPECT_EQ(dst.revision(), r);
  ASSERT_FALSE(src.set("resolution", 128.0));
  ASSERT_FALSE(src.set("bias.slope", 0.5));
  EXPECT_EQ(syncParams(dst, src), 2);
  EXPECT_EQ(dst, src);
  EXPECT_GT(dst.revision(), r);
  EXPECT_EQ(syncParams(dst, src), 0);
}

TEST(ViewSide, AnErrorBelongsToTheViewItWasMeasuredForAndNaIsNeverZero) {
  ViewSide side("uniform");
  EXPECT_FALSE(side.errorFor(1));
  side.setError(std::nullopt, "no covered pixel", 7);
  ASSERT_TRUE(side.errorFor(7));
  EXPECT_FALSE(side.errorFor(7)->pct);
  EXPECT_EQ(side.errorFor(7)->unmeasured, "no covered pixel");
  EXPECT_FALSE(side.errorFor(8));  // the view moved on: out of date
  side.setError(0.42, "ignored when measured", 8);
  EXPECT_DOUBLE_EQ(*side.errorFor(8)->pct, 0.42);
  EXPECT_TRUE(side.errorFor(8)->unmeasured.empty());
  ASSERT_FALSE(side.setTechnique("cascades"));  // another technique: not its error
  EXPECT_FALSE(side.errorFor(8));
}

TEST(ViewSide, AFrameIsOfTheTechniqueItWasDrawnWith) {
  ViewSide side("uniform");
  EXPECT_FALSE(side.hasFrame());
  FrameStats stats;
  stats.frameIndex = 3;
  Publication pub;
  pub.frameIndex = 3;
  side.setFrame(stats, pub);
  EXPECT_TRUE(side.hasFrame());
  EXPECT_EQ(side.stats().frameIndex, 3u);
  ASSERT_FALSE(side.setTechnique("da-rtw"));
  EXPECT_FALSE(side.hasFrame());
}

TEST(ViewSide, NonDefaultParamsNameOnlyTheChangedValues) {
  ViewSide side("uniform");
  EXPECT_EQ(side.nonDefaultParams(), "");
  ASSERT_FALSE(side.params().set("resolution", 512.0));
  EXPECT_EQ(side.nonDefaultParams(), "resolution=512");
}

TEST(ViewSide, TheCaptionPutsTheErrorFirstAndNeverShowsZeroForUnmeasured) {
  FrameStats stats;
  stats.totalMs = 3.14159;
  const std::string name = Renderer::findTechnique("uniform")->name;
  const std::string dot = "  \u00b7  ";
  EXPECT_EQ(sideCaption("uniform", stats, 0.42), name + dot + "error 0.420 %" + dot + "3.14 ms");
  EXPECT_EQ(sideCaption("uniform", stats, std::nullopt),
            name + dot + "error \u2014" + dot + "3.14 ms");
  EXPECT_EQ(sideCaption("uniform", stats, std::nullopt, {}, "no covered pixel"),
            name + dot + "error n/a (no covered pixel)" + dot + "3.14 ms");
  stats.totalMs = 123.456;
  EXPECT_EQ(sideCaption("uniform", stats, 1.0, "reference 0.8 s old"),
            name + dot + "error 1.000 %" + dot + "reference 0.8 s old" + dot + "123.5 ms");
  EXPECT_EQ(sideCaption("not-registered", stats, 1.0).rfind("not-registered", 0), 0u);
}

}  // namespace
}  // namespace sl
