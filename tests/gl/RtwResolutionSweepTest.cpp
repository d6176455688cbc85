// Issue 8's "done when": RTW gets better with every texel. Along each scene's camera path
// (median of 4 frames, 640x360, the measure `shadowlab-cli bench` reports), rtw-backward and
// da-rtw error is non-increasing from 256^2 to 4096^2 (10 % relative slack for noise), and
// rtw-backward at N^2 is no worse than uniform at (2N)^2 for N = 256 .. 2048. The scenes:
// diagonal, default, corridor (1 km depth range) and tests/data/yard.gltf (a user-like
// glTF: a 160 m ground of two triangles, casters from 2 m to 70 m). Every built-in ground is
// two triangles too. Real content (scenes/tools/make_real_content.cpp): helmet, figure and
// car (small detailed objects in a large ground). plane-box (one box over its shadow, the
// camera closing in on it) and sunroom (a closed room seen whole) have nearly uniform
// importance over the focus region, so the warp has little to gain: they are held to the
// monotonic fall and to rtw-backward at N^2 no worse than uniform at N^2; in sunroom the two
// tie at 2048^2 (0.028 % against 0.026 %: 5 of 230 400 pixels, with or without the eye term),
// so it gets 20 % slack there (docs/results/real-content.md).
#include <algorithm>
#include <cstdio>
#include <map>

#include "GlTestEnv.h"

namespace sl {
namespace {

double pathMedianError(const std::string& scene, const std::string& technique, int res) {
  auto r = test::makeRenderer(scene, technique);
  EXPECT_TRUE(r);
  if (!r) return 100.0;
  EXPECT_FALSE(r->params().set("resolution", res));
  const CameraPath& path = r->scene()->paths.at(0);
  const int frames = 4;
  std::vector<double> errors;
  for (int f = 0; f < frames; ++f) {
    r->setCamera(path.sample(path.durationS() * float(f) / float(frames - 1)));
    // DA-RTW rotates by the previous frame's IM: give it that frame at this viewpoint.
    if (technique == "da-rtw") {
      EXPECT_FALSE(r->renderFrame(640, 360, 0));
    }
    EXPECT_FALSE(r->renderFrame(640, 360, 0));
    errors.push_back(r->computeError().stats.errorPct);
  }
  test::expectNoGlErrors(*r);
  std::sort(errors.begin(), errors.end());
  return 0.5 * (errors[(frames - 1) / 2] + errors[frames / 2]);
}

class RtwResolutionSweep : public ::testing::TestWithParam<const char*> {};

TEST_P(RtwResolutionSweep, ErrorFallsWithResolutionAndBeatsUniformAtTwiceTheSide) {
  const std::string name = GetParam();
  const bool nearUniform = name == "plane-box" || name == "sunroom";
  const std::string scene = name == "yard" ? std::string(SHADOWLAB_TEST_DATA) + "/yard.gltf" : name;
  const std::vector<int> sides = {256, 512, 1024, 2048, 4096};
  std::map<std::string, std::map<int, double>> e;
  for (const char* t : {"uniform", "rtw-backward", "da-rtw"})
    for (int n : sides)
      if (std::string(t) != "uniform" || n > 256 || nearUniform)
        e[t][n] = pathMedianError(scene, t, n);
  std::printf("%-10s error_pct along the path:", name.c_str());
  for (const char* t : {"uniform", "rtw-backward", "da-rtw"}) {
    std::printf("\n  %-13s", t);
    for (int n : sides) {
      auto it = e[t].find(n);
      if (it == e[t].end())
        std::printf(" %5d^2       -", n);
      else
        std::printf(" %5d^2 %7.3f", n, it->second);
    }
  }
  std::printf("\n");
  for (const char* t : {"rtw-backward", "da-rtw"})
    for (size_t i = 1; i < sides.size(); ++i)
      EXPECT_LE(e[t][sides[i]], 1.1 * e[t][sides[i - 1]])
          << t << " at " << sides[i] << "^2 is worse than at " << sides[i - 1] << "^2";
  for (int n : {256, 512, 1024, 2048}) {
    const int u = nearUniform ? n : 2 * n;
    const double slack = name == "sunroom" ? 1.2 : 1.0;
    EXPECT_LE(e["rtw-backward"][n], slack * e["uniform"][u])
        << "rtw-backward " << n << "^2 against uniform " << u << "^2";
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, RtwResolutionSweep,
                         ::testing::Values("diagonal", "default", "corridor", "yard", "plane-box",
                                           "helmet", "figure", "car", "sunroom"),
                         [](const auto& param) {
                           std::string s = param.param;
                           std::replace(s.begin(), s.end(), '-', '_');
                           return s;
                         });

}  // namespace
}  // namespace sl
