// shadowlab-cli reproduce's runner (app/cli/Reproduce.h, linked from shadowlab_cli_core): a
// claim measured on a technique that is wrong on purpose (test-all-lit: every receiver lit,
// registered here only) is "not reproduced", and the same claim on the technique it names is
// reproduced; the verdict follows the measurement and the threshold.
#include <fstream>

#include <gtest/gtest.h>

#include "CliCommon.h"
#include "GlTestEnv.h"
#include "Reproduce.h"
#include "TestTechniques.h"

namespace sl::test {
namespace {

std::filesystem::path writeClaims(const std::string& name, const std::string& techniqueA) {
  const std::filesystem::path dir = testOut("reproduce");
  const std::filesystem::path file = dir / (name + ".json");
  std::ofstream(file) << R"({
  "seed": "000",
  "source": "test",
  "sizes": {"quick": {"size": "96x54", "frames": 2, "warmup": 1}},
  "claims": [{
    "id": ")" << name << R"(",
    "kind": "tool",
    "statement": "A shadow map of 1024 texels a side has at most 1.1 times the wrong pixels of uniform 1024.",
    "paper_number": "<= 1.1",
    "measure": {"kind": "error-compare", "scene": "plane-box",
                "a": {"technique": ")"
                      << techniqueA << R"(", "params": {"resolution": "1024"}},
                "b": {"technique": "uniform", "params": {"resolution": "1024"}}},
    "expect": {"op": "<=", "value": 1.1}
  }]
})";
  return file;
}

struct RegisterAllLit {
  RegisterAllLit() { cli::addExtraTechnique(allLitTechnique()); }
};

TEST(Reproduce, ABrokenTechniqueMakesTheClaimNotReproduced) {
  eglContext().makeCurrent();
  static RegisterAllLit once;
  const std::vector<cli::Claim> broken = cli::loadClaims(writeClaims("broken", "test-all-lit"));
  ASSERT_EQ(broken.size(), 1u);
  const cli::ClaimOutcome o = cli::runClaim(broken[0], true, testOut("reproduce"));
  ASSERT_TRUE(o.main.measured) << o.main.why;
  EXPECT_GT(o.main.interval.low, 1.1) << o.main.text;  // every shadow false lit, every frame
  EXPECT_EQ(o.verdict, "not reproduced") << o.main.text;
  EXPECT_TRUE(o.indicative);  // 2 frames of a quick run

  // The control: the same claim on uniform itself measures 1 and is reproduced. (A claims
  // file may not compare a configuration with itself: the control is built here.)
  cli::Claim sound = broken[0];
  sound.measurement.configs[0] = sound.measurement.configs[1];
  const cli::ClaimOutcome s = cli::runClaim(sound, true, testOut("reproduce"));
  ASSERT_TRUE(s.main.measured) << s.main.why;
  EXPECT_NEAR(s.main.value, 1.0, 1e-9) << s.main.text;
  EXPECT_EQ(s.verdict, "reproduced");
}

TEST(Reproduce, AConfigurationThatCannotRenderIsNotMeasured) {
  // A spot light, which the cascades do not render (TechniqueInfo::lights): nothing is
  // measured, so the verdict is "not measured" whatever the threshold.
  eglContext().makeCurrent();
  cli::Claim c;
  c.id = "refused";
  c.expect = {"<=", 1e9, 0.0};
  c.measurement.kind = "error-compare";
  c.measurement.scene = "plane-box";
  c.measurement.lightText = "spot:0,4,0,0,-1,0,40";
  c.measurement.light = cli::parseLight("light", c.measurement.lightText);
  c.measurement.metric = "error_pct";
  c.measurement.combine = "ratio";
  c.measurement.quick = {96, 54, 1, 0};
  c.measurement.configs = {{"uniform", {}, "uniform"}, {"cascades", {}, "cascades"}};
  const cli::ClaimOutcome o = cli::runClaim(c, true, testOut("reproduce"));
  EXPECT_FALSE(o.main.measured);
  EXPECT_NE(o.main.why.find("cascades"), std::string::npos) << o.main.why;
  EXPECT_EQ(o.verdict, "not testable here");
}

TEST(Reproduce, TheVerdictFollowsTheValueAndTheThreshold) {
  cli::Claim c;
  c.expect = {"<=", 1.0, 0.0};
  cli::MeasuredValue v;
  v.why = "frame 0: refused";
  EXPECT_EQ(cli::verdictFor(c, v), "not testable here");
  v.measured = true;
  v.value = 2.0;
  v.interval = {2.0, 1.8, 2.2, 20};
  EXPECT_EQ(cli::verdictFor(c, v), "not reproduced");
  v.interval = {1.0, 0.9, 1.1, 20};  // straddles the threshold
  EXPECT_EQ(cli::verdictFor(c, v), "inconclusive");
  v.interval = {0.5, 0.4, 0.6, 20};
  EXPECT_EQ(cli::verdictFor(c, v), "reproduced");
  c.expect = {"within", 85.7365, 1e-6};
  v.interval = {85.7365, 85.7365, 85.7365, 0};
  EXPECT_EQ(cli::verdictFor(c, v), "reproduced");
  v.interval.low = v.interval.high = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(cli::verdictFor(c, v), "reproduced");
}

}  // namespace
}  // namespace sl::test
