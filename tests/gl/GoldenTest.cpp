// A golden image for every registered technique: one table row per golden (technique, scene,
// camera, overlay, what the image shows), each on a small built-in scene at 320x240 so that it
// shows the technique's own structure (an omni map's seam, a paged map's page borders, a tiled
// map's tile edges, a warp's texel grid). Goldens that other tests already render are listed
// with the test that renders them. Bless new goldens with SHADOWLAB_UPDATE_GOLDEN=1
// (docs/developer/tests.md, "Golden images").
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <ostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "GlTestEnv.h"
#include "core/Technique.h"
#include "metrics/GoldenImage.h"

namespace sl {
namespace {

/// One golden image: how it is rendered and what it shows.
struct GoldenCase {
  const char* technique;  ///< a techniqueRegistry() id
  const char* golden;     ///< tests/golden/<golden>.png
  const char* scene;      ///< a built-in scene
  const char* camera;     ///< one of its bookmarks
  /// KEY=VALUE settings separated by spaces, as the CLI's --set: the technique's parameters
  /// and the renderer's (view.overlay)
  const char* settings;
  int frames;         ///< frames rendered before the readback (temporal techniques settle)
  const char* shows;  ///< what the image shows (docs/developer/tests.md, "Golden images")
  /// Where another test renders this golden ("File.cpp: Suite.Test"); null: rendered here.
  const char* renderedBy = nullptr;
};

void PrintTo(const GoldenCase& c, std::ostream* os) {
  *os << c.golden;
}

constexpr int kWidth = 320, kHeight = 240;

// llvmpipe renders the same pixels run after run on one machine; the tolerance absorbs what
// differs between Mesa versions and a real GPU: rasterisation and depth precision at shadow
// edges, silhouettes and one-pixel overlay lines, where a pixel can flip. A pixel fails when
// a channel differs by more than 24/255; the image fails when more than 1 % of its pixels
// fail (as the other goldens).
constexpr GoldenTolerance kTolerance{24, 0.01};

const std::vector<GoldenCase>& goldenCases() {
  static const std::vector<GoldenCase> cases = {
      // Rendered by other tests (the settings are theirs).
      {"uniform", "default-uniform", "default", "overview", "", 1,
       "the default scene's shadows from one orthographic map",
       "UniformAccuracyTest.cpp: Golden.DefaultSceneUniform"},
      {"rtw-backward", "diagonal-rtw-backward", "diagonal", "row-end", "resolution=1024", 3,
       "the row of posts seen from its end: sharp shadows near and far from one warped map",
       "UniformAccuracyTest.cpp: Golden.DiagonalRowEndRtw"},
      {"da-rtw", "diagonal-da-rtw", "diagonal", "row-end", "resolution=1024", 3,
       "the same view after DA-RTW has turned its frustum to the row",
       "UniformAccuracyTest.cpp: Golden.DiagonalRowEndRtw"},
      {"cascades", "corridor-cascades-partition", "corridor", "start", "view.overlay=partition", 3,
       "the cascades' slices along the corridor in partition colours",
       "CascadesTest.cpp: Golden.CorridorCascadesPartitionOverlay"},
      {"lispsm", "corridor-lispsm-outside", "corridor", "start", "resolution=1024 view.outside=on",
       1, "the outside view: the view frustum and the warped light frustum around it",
       "OutsideViewTest.cpp: Golden.CorridorLispsmOutsideView"},
      // Rendered here, 320x240.
      {"rtw-forward", "diagonal-rtw-forward-grid", "diagonal", "row-end-low",
       "resolution=512 view.overlay=warp-grid", 1,
       "the warp: the texel grid fine near the camera, coarser along the row"},
      {"rtw-hybrid", "diagonal-rtw-hybrid-grid", "diagonal", "row-end",
       "resolution=512 view.overlay=warp-grid", 3,
       "the warp: grid cells of a similar size on screen near and far along the row"},
      {"psm", "corridor-psm-grid", "corridor", "start", "resolution=512 view.overlay=warp-grid", 1,
       "the post-perspective warp: the texel grid finest at the camera"},
      {"tsm", "corridor-tsm-grid", "corridor", "start-level",
       "resolution=512 view.overlay=warp-grid", 1,
       "the trapezoid warp: grid lines fan out from the far end of the corridor"},
      {"face-partition", "dueling-face-partition", "dueling", "into-sun",
       "resolution=512 view.overlay=partition", 1,
       "one partition per frustum face: left wall, floor, right wall in three colours"},
      {"cube", "omni-room-cube-faces", "omni-room", "overview",
       "resolution=256 view.overlay=partition", 1,
       "the cube's face seams across walls, floor and ceiling, one colour per face"},
      {"dual-paraboloid", "omni-room-dp-hemispheres", "omni-room", "overview",
       "resolution=512 view.overlay=partition", 1,
       "the seam between the two hemispheres, a horizontal line at the bulb's height"},
      {"spherical", "omni-room-spherical-pole", "omni-room", "floor",
       "resolution=256 view.overlay=warp-grid", 1,
       "the lat-long grid's pole: meridians meeting on the floor under the bulb"},
      {"rmsm", "plane-box-rmsm-pages", "plane-box", "overview",
       "virtual.resolution=16384 view.overlay=pages", 1,
       "page borders: pages finer towards the camera, about one size on screen"},
      {"asm", "plane-box-asm-pages", "plane-box", "overview",
       "virtual.resolution=16384 view.overlay=pages", 1,
       "page borders: pages refined along the shadow's and the plate's edges only"},
      {"virtual-tiled", "plane-box-virtual-tiled-tiles", "plane-box", "overview",
       "tiles=4 tile.resolution=128 view.overlay=partition", 1,
       "the 4x4 tiles in partition colours, a tile edge through the shadow"},
      {"fvsm", "plane-box-fvsm-tiles", "plane-box", "overview", "view.overlay=partition", 1,
       "the fitted tiles: small ones around the plate and its shadow, large ones elsewhere"},
  };
  return cases;
}

std::filesystem::path goldenPath(const GoldenCase& c) {
  return std::filesystem::path(SHADOWLAB_GOLDEN_DIR) / (std::string(c.golden) + ".png");
}

// The table covers the registry: a technique added without a golden fails here.
TEST(GoldenTable, EveryRegisteredTechniqueHasAGolden) {
  std::set<std::string> registered, covered, names;
  for (const TechniqueEntry& e : techniqueRegistry()) registered.insert(e.info.id);
  for (const GoldenCase& c : goldenCases()) {
    EXPECT_TRUE(registered.count(c.technique)) << c.golden << ": no technique " << c.technique;
    EXPECT_TRUE(names.insert(c.golden).second) << c.golden << " twice";
    EXPECT_TRUE(std::filesystem::exists(goldenPath(c))) << goldenPath(c);
    covered.insert(c.technique);
  }
  for (const std::string& id : registered)
    EXPECT_TRUE(covered.count(id)) << id << " has no golden image: add a row to goldenCases()";
  EXPECT_GE(goldenCases().size(), registered.size());
}

// A golden rendered by another test names that test, and the test is still there.
TEST(GoldenTable, GoldensRenderedElsewhereNameTheirTest) {
  for (const GoldenCase& c : goldenCases()) {
    if (!c.renderedBy) continue;
    const std::string by = c.renderedBy;
    const std::size_t colon = by.find(": ");
    ASSERT_NE(colon, std::string::npos) << by;
    const std::string file = by.substr(0, colon), test = by.substr(by.rfind('.') + 1);
    std::ifstream in(std::filesystem::path(SHADOWLAB_GOLDEN_DIR) / ".." / "gl" / file);
    ASSERT_TRUE(in) << file;
    const std::string text{std::istreambuf_iterator<char>(in), {}};
    EXPECT_NE(text.find("TEST(Golden, " + test + ")"), std::string::npos) << by;
  }
}

class GoldenTechnique : public testing::TestWithParam<GoldenCase> {};

TEST_P(GoldenTechnique, MatchesGolden) {
  const GoldenCase& c = GetParam();
  auto r = test::makeRenderer(c.scene, c.technique);
  ASSERT_TRUE(r);
  const Camera* camera = test::bookmark(*r->scene(), c.camera);
  ASSERT_TRUE(camera) << c.camera;
  r->setCamera(*camera);
  std::istringstream settings(c.settings);
  for (std::string kv; settings >> kv;) {
    const std::size_t eq = kv.find('=');
    ASSERT_NE(eq, std::string::npos) << kv;
    const std::string key = kv.substr(0, eq);
    ParamSet& params = r->params().has(key) ? r->params() : r->rendererParams();
    ASSERT_FALSE(params.setFromString(key, kv.substr(eq + 1))) << kv;
  }
  for (int f = 0; f < c.frames; ++f) ASSERT_FALSE(r->renderFrame(kWidth, kHeight, 0));
  const GoldenResult g = compareToGolden(r->readback().color, goldenPath(c), kTolerance,
                                         test::testOut("golden"), c.golden);
  std::printf("%s\n", g.message.c_str());  // the failing fraction and max diff, passed or not
  EXPECT_TRUE(g.pass) << c.shows << ": " << g.message;
  test::expectNoGlErrors(*r);
}

std::vector<GoldenCase> renderedHere() {
  std::vector<GoldenCase> out;
  std::copy_if(goldenCases().begin(), goldenCases().end(), std::back_inserter(out),
               [](const GoldenCase& c) { return !c.renderedBy; });
  return out;
}

INSTANTIATE_TEST_SUITE_P(Techniques, GoldenTechnique, testing::ValuesIn(renderedHere()),
                         [](const testing::TestParamInfo<GoldenCase>& row) {
                           std::string name = row.param.golden;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace
}  // namespace sl
