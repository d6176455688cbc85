// Frame spacing along a camera path (app/cli/Measure.h, `--path-hz`): between the measured
// frames each configuration renders an unmeasured frame every 1/HZ s of path time, right
// before its own measured frame, and the reference is traced at the measured frames only.
// Counted with a test-only technique that logs every frame it renders (test-count).
#include <gtest/gtest.h>

#include "CliCommon.h"
#include "GlTestEnv.h"
#include "measure/Measure.h"
#include "TestTechniques.h"

namespace sl::test {
namespace {

struct RegisterCounting {
  RegisterCounting() { cli::addExtraTechnique(countingTechnique()); }
};

std::vector<std::unique_ptr<cli::ConfigRunner>> countingRunners(
    std::shared_ptr<const Scene> scene) {
  static RegisterCounting once;
  std::vector<std::unique_ptr<cli::ConfigRunner>> runners;
  for (const char* res : {"256", "512"}) {
    cli::ConfigSpec spec{"test-count", {{"resolution", res}}, std::string("count ") + res};
    runners.push_back(std::make_unique<cli::ConfigRunner>(spec, scene, std::nullopt));
  }
  return runners;
}

cli::MeasureOptions smallFrames() {
  cli::MeasureOptions o;
  o.width = 64;
  o.height = 36;
  o.publishing = true;  // as bench asks
  return o;
}

bool near(const glm::vec3& a, const glm::vec3& b) {
  return glm::length(a - b) < 1e-5f;
}

TEST(PathHz, InBetweenFramesRunRightBeforeEachMeasuredFrameWithoutTheReference) {
  eglContext().makeCurrent();
  if (!ShadowReference::available()) GTEST_SKIP() << ShadowReference::unavailableReason();
  std::shared_ptr<Scene> scene = loadBuiltin("diagonal");
  ASSERT_TRUE(scene);
  ASSERT_FALSE(scene->paths.empty());
  const CameraPath& path = scene->paths.front();
  ASSERT_FLOAT_EQ(path.startS(), 0.0f);
  ASSERT_FLOAT_EQ(path.durationS(), 10.0f);

  // 3 measured frames at 0, 5 and 10 s; at 2 Hz, 9 frames in each 5 s gap (0.5 ... 4.5 s,
  // 5.5 ... 9.5 s), the last 0.5 s before its measured frame.
  std::string text;
  const cli::MeasureCameras cams = cli::measureCameras(*scene, "", "", 3, 2.0, text);
  ASSERT_TRUE(cams.alongPath);
  ASSERT_EQ(cams.measured.size(), 3u);
  ASSERT_EQ(cams.between.size(), 3u);
  EXPECT_EQ(cams.between[0].size(), 0u);
  ASSERT_EQ(cams.between[1].size(), 9u);
  ASSERT_EQ(cams.between[2].size(), 9u);
  EXPECT_EQ(cams.betweenCount(), 18u);
  EXPECT_TRUE(near(cams.between[1].front().position, path.sample(0.5f).position));
  EXPECT_TRUE(near(cams.between[1].back().position, path.sample(4.5f).position));
  EXPECT_TRUE(near(cams.between[2].back().position, path.sample(9.5f).position));
  EXPECT_TRUE(near(cams.measured[2].position, path.sample(10.0f).position));

  auto runners = countingRunners(scene);
  countedFrames().clear();
  cli::ReferenceCache reference(*scene);
  const auto samples = cli::runInterleaved(runners, cams, smallFrames(), &reference, 1, nullptr);

  // Every frame each configuration rendered: 1 warm-up + 3 measured + 18 in between.
  const std::vector<CountedFrame> log = countedFrames();
  ASSERT_EQ(log.size(), 2u * (1 + 3 + 18));
  for (const auto& r : runners) EXPECT_EQ(r->framesRendered(), 22u);
  // The reference was traced at the 3 measured frames only (shared by both configurations),
  // and every measured sample has its error.
  EXPECT_EQ(reference.evaluations(), 3);
  ASSERT_EQ(samples.size(), 2u);
  for (const auto& s : samples) {
    ASSERT_EQ(s.size(), 3u);
    for (const cli::FrameSample& f : s) {
      EXPECT_FALSE(f.failed()) << f.renderError;
      EXPECT_TRUE(f.hasReference);
      EXPECT_GT(f.error.covered, 0u);
    }
  }

  // The order: warm-up of each, then per measured frame the configurations in rotating order,
  // each with its in-between frames (in path order) right before its measured frame.
  const void* instance[2] = {log[0].instance, log[1].instance};
  ASSERT_NE(instance[0], instance[1]);
  std::vector<CountedFrame> want = {{instance[0], cams.measured[0].position},
                                    {instance[1], cams.measured[0].position}};
  for (std::size_t f = 0; f < 3; ++f)
    for (std::size_t k = 0; k < 2; ++k) {
      const std::size_t i = (k + f) % 2;
      for (const Camera& c : cams.between[f]) want.push_back({instance[i], c.position});
      want.push_back({instance[i], cams.measured[f].position});
    }
  ASSERT_EQ(want.size(), log.size());
  for (std::size_t n = 0; n < log.size(); ++n) {
    EXPECT_EQ(log[n].instance, want[n].instance) << "frame " << n << " ran for the other runner";
    EXPECT_TRUE(near(log[n].cameraPosition, want[n].cameraPosition))
        << "frame " << n << " rendered another camera";
  }
}

TEST(PathHz, ZeroAndAFixedCameraRenderOnlyTheMeasuredFrames) {
  eglContext().makeCurrent();
  std::shared_ptr<Scene> scene = loadBuiltin("diagonal");
  ASSERT_TRUE(scene);
  std::string text;
  // 0: the measured frames only, at the same cameras as at any rate.
  const cli::MeasureCameras none = cli::measureCameras(*scene, "", "", 3, 0.0, text);
  const cli::MeasureCameras some = cli::measureCameras(*scene, "", "", 3, 30.0, text);
  EXPECT_EQ(none.betweenCount(), 0u);
  EXPECT_EQ(some.betweenCount(), 2u * 149u);  // 5 s gaps at 30 Hz
  for (std::size_t f = 0; f < 3; ++f)
    EXPECT_TRUE(near(none.measured[f].position, some.measured[f].position));
  auto runners = countingRunners(scene);
  countedFrames().clear();
  (void)cli::runInterleaved(runners, none, smallFrames(), nullptr, 1, nullptr);
  EXPECT_EQ(countedFrames().size(), 2u * (1 + 3));

  // A fixed bookmark: no path, nothing in between whatever the rate.
  ASSERT_FALSE(scene->cameras.empty());
  const cli::MeasureCameras fixed =
      cli::measureCameras(*scene, "", scene->cameras.front().name, 3, 30.0, text);
  EXPECT_FALSE(fixed.alongPath);
  EXPECT_EQ(fixed.betweenCount(), 0u);
  EXPECT_EQ(fixed.measured.size(), 3u);

  // A rate whose frames would pass kMaxInBetweenFrames is refused naming the option.
  CameraPath longPath = scene->paths.front();
  longPath.keys.back().timeS = 1.0e6f;
  try {
    (void)cli::pathCameras(longPath, 2, 30.0);
    ADD_FAILURE() << "a 10^6 s path at 30 Hz was not refused";
  } catch (const cli::UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("--path-hz"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sl::test
