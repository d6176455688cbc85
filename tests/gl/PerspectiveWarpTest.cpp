// PSM / LiSPSM / TSM (techniques/perspective) against the Embree reference and the uniform
// map at the same resolution; eta = -1 and the square-frustum fallback are the uniform map;
// the fallback published; tsm is one warp with the eta it publishes (and the Storage factor
// panel's scheme says so); memory, passes and lights as declared.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "GlTestEnv.h"
#include "algo/warp/PerspectiveWarp.h"
#include "gl/Gl.h"
#include "panels/analysis/StoragePanelKeys.h"
#include "measure/StorageScheme.h"

namespace sl {
namespace {

struct Measured {
  double errorPct = 0.0;
  double nPrime = 0.0, eta = 0.0, fallback = 0.0, cause = 0.0;
  double mP50 = 0.0, mP95 = 0.0;  ///< aliasing m over covered pixels
  std::vector<std::uint8_t> mask;
};

/// One frame of `technique` at `res`^2 (parameters `set` applied after the defaults).
Measured measure(Renderer& r, const std::string& technique, int res,
                 std::initializer_list<std::pair<const char*, double>> set = {}) {
  Measured m;
  EXPECT_FALSE(r.setTechnique(technique));
  EXPECT_FALSE(r.params().set("resolution", res));
  // This file tests the light-space warps: psm as Lloyd et al.'s eta = 1 reading (its
  // post-perspective map, the default, has PostPerspectiveTest).
  if (technique == "psm") {
    EXPECT_FALSE(r.params().set("psm.method", 1.0));
  }
  for (const auto& [k, v] : set) EXPECT_FALSE(r.params().set(k, v)) << k;
  r.requestPublications({"warp.*"});
  EXPECT_FALSE(r.renderFrame(320, 180, 0));
  const Renderer::ErrorResult err = r.computeError();
  m.errorPct = err.stats.errorPct;
  m.mask = err.frame.hardMask;
  std::vector<float> ms;
  for (size_t i = 0; i < err.frame.aliasing.size(); ++i)
    if (err.frame.positions[i].w > 0.0f && err.frame.aliasing[i] > 0.0f)
      ms.push_back(err.frame.aliasing[i]);
  if (!ms.empty()) {
    std::sort(ms.begin(), ms.end());
    m.mP50 = ms[ms.size() / 2];
    m.mP95 = ms[ms.size() * 95 / 100];
  }
  const Publication& pub = r.publication();
  if (technique != "uniform") {
    EXPECT_EQ(pub.numbers.count("warp.n_prime"), 1u);
    EXPECT_EQ(pub.numbers.count("warp.fallback"), 1u);
    if (pub.numbers.count("warp.n_prime")) m.nPrime = pub.numbers.at("warp.n_prime");
    if (pub.numbers.count("warp.eta")) m.eta = pub.numbers.at("warp.eta");
    if (pub.numbers.count("warp.fallback")) m.fallback = pub.numbers.at("warp.fallback");
    if (pub.numbers.count("warp.fallback_cause")) m.cause = pub.numbers.at("warp.fallback_cause");
  }
  r.requestPublications({});
  test::expectNoGlErrors(r);
  std::printf("  %-8s %4d^2: error %.3f%%, m p50 %.2f p95 %.2f, n' %.3g, eta %.2f, fallback %.0f\n",
              technique.c_str(), res, m.errorPct, m.mP50, m.mP95, m.nPrime, m.eta, m.fallback);
  return m;
}

void useBookmark(Renderer& r, const char* name) {
  const Camera* c = test::bookmark(*r.scene(), name);
  ASSERT_TRUE(c) << name;
  r.setCamera(*c);
}

// A camera along a ground plane (corridor: 0.1 m to 1 km, light 30°, 50°): the uniform map
// spends its texels on the far kilometre, LiSPSM on what is near. Measured (llvmpipe,
// 320x180, 1024^2): start-level uniform 26.0 %, lispsm 1.39 %; midway 3.85 % vs 0.23 %.
TEST(PerspectiveWarp, LispsmBeatsUniformAlongTheCorridor) {
  auto r = test::makeRenderer("corridor", "uniform");
  ASSERT_TRUE(r);
  struct Case {
    const char* bookmark;
    double uniformAtLeast, lispsmAtMost;
  };
  for (const Case& c : {Case{"start-level", 15.0, 3.0}, Case{"midway", 2.0, 0.6}}) {
    SCOPED_TRACE(c.bookmark);
    std::printf("corridor %s\n", c.bookmark);
    useBookmark(*r, c.bookmark);
    const Measured u = measure(*r, "uniform", 1024);
    const Measured l = measure(*r, "lispsm", 1024);
    EXPECT_GT(u.errorPct, c.uniformAtLeast);
    EXPECT_LT(l.errorPct, c.lispsmAtMost);
    EXPECT_LT(l.mP95, 0.1 * u.mP95) << "the warp removes the perspective aliasing";
    EXPECT_EQ(l.fallback, 0.0);
    EXPECT_EQ(l.eta, 0.0);
    EXPECT_TRUE(std::isfinite(l.nPrime) && l.nPrime > 0.0);
  }
}

// The default scene: near the ground (tree: 0.87 % vs 0.52 %) LiSPSM wins; from the
// overview, which looks down on the scene rather than along it, the uniform map has no
// perspective aliasing to remove (m p95 1.00) and the warp's shift of texels towards the
// near edge costs the middle where the shadows are (0.34 % vs 0.56 %): asserted both ways.
TEST(PerspectiveWarp, DefaultSceneNearTheGroundAndFromAbove) {
  auto r = test::makeRenderer("default", "uniform");
  ASSERT_TRUE(r);
  std::printf("default tree\n");
  useBookmark(*r, "tree");
  const Measured u = measure(*r, "uniform", 1024);
  const Measured l = measure(*r, "lispsm", 1024);
  EXPECT_LT(l.errorPct, 0.8 * u.errorPct);
  EXPECT_LT(l.mP95, 0.6 * u.mP95);
  std::printf("default overview\n");
  useBookmark(*r, "overview");
  const Measured uo = measure(*r, "uniform", 1024);
  const Measured lo = measure(*r, "lispsm", 1024);
  EXPECT_LT(uo.mP95, 1.1);
  EXPECT_GT(lo.mP50, 1.5 * uo.mP50) << "texels moved towards the near edge";
  EXPECT_GT(lo.errorPct, uo.errorPct);
}

// eta = -1 is n' = infinity: the technique renders the uniform map itself (the same fit),
// so the hard mask is identical pixel for pixel; asked for, it is not a fallback.
TEST(PerspectiveWarp, EtaMinusOneIsTheUniformMapExactly) {
  auto r = test::makeRenderer("corridor", "uniform");
  ASSERT_TRUE(r);
  useBookmark(*r, "midway");
  const Measured u = measure(*r, "uniform", 512);
  for (const char* t : {"lispsm", "psm"}) {
    SCOPED_TRACE(t);
    const Measured e = measure(*r, t, 512, {{"warp.eta", -1.0}});
    EXPECT_EQ(e.errorPct, u.errorPct);
    EXPECT_TRUE(e.mask == u.mask);
    EXPECT_EQ(e.fallback, 0.0);
    EXPECT_EQ(e.cause, 0.0);
    EXPECT_EQ(e.eta, -1.0);
    EXPECT_TRUE(std::isinf(e.nPrime));
  }
  // And eta moves the error: PSM (1) differs from LiSPSM (0) here.
  const Measured p = measure(*r, "lispsm", 512, {{"warp.eta", 1.0}});
  const Measured l = measure(*r, "lispsm", 512, {{"warp.eta", 0.0}});
  EXPECT_NE(p.errorPct, l.errorPct);
  EXPECT_LT(p.nPrime, l.nPrime);
}

// The light straight behind the viewer: the frustum looks square from the light, every
// warp falls back to the uniform map and says so (warp.fallback = 1, eta -1, n' inf).
TEST(PerspectiveWarp, LightBehindTheViewerFallsBackToUniformAndSaysSo) {
  auto r = test::makeRenderer("default", "uniform");
  ASSERT_TRUE(r);
  Camera cam = r->camera();
  cam.position = {0.0f, 12.0f, 20.0f};
  cam.target = {0.0f, 0.0f, 0.0f};
  cam.up = {0.0f, 1.0f, 0.0f};
  ASSERT_FALSE(cam.validate());
  r->setCamera(cam);
  r->setLight(Light::directionalFromTowards(glm::normalize(cam.position - cam.target)));
  const Measured u = measure(*r, "uniform", 512);
  for (const char* t : {"lispsm", "psm", "tsm"}) {
    SCOPED_TRACE(t);
    const Measured f = measure(*r, t, 512);
    EXPECT_EQ(f.fallback, 1.0);
    EXPECT_EQ(f.cause, double(int(warp::FallbackCause::SquareLightBehind)));
    EXPECT_EQ(f.eta, -1.0);
    EXPECT_TRUE(std::isinf(f.nPrime));
    EXPECT_TRUE(f.mask == u.mask);
  }
  // Turned away by 60 degrees of azimuth, the light no longer lies in the view cone: warped.
  r->setLight(Light::directional(60.0f, 31.0f));
  EXPECT_EQ(measure(*r, "lispsm", 512).fallback, 0.0);
}

// TSM: the focus point at 50 % of the visible depth goes to the 80 % line (a finite n',
// eta in (-1, 1)); pushed to the far end it lies beyond the line and TSM reverts to uniform.
TEST(PerspectiveWarp, TsmFocusAndItsFallback) {
  auto r = test::makeRenderer("corridor", "uniform");
  ASSERT_TRUE(r);
  useBookmark(*r, "start-level");
  const Measured t = measure(*r, "tsm", 512);
  EXPECT_EQ(t.fallback, 0.0);
  EXPECT_GT(t.eta, -1.0);
  EXPECT_LT(t.eta, 1.0);
  const Measured far = measure(*r, "tsm", 512, {{"warp.focus", 1.0}});
  EXPECT_EQ(far.fallback, 1.0);
  EXPECT_EQ(far.cause, double(int(warp::FallbackCause::TsmFocusBeyondLine)));
  EXPECT_TRUE(std::isinf(far.nPrime));
}

// Lloyd et al. 2006 (§4.3): a TSM is one perspective warp along light-space z with some n',
// i.e. some eta (eq. 11 inverted, warp::etaFromNPrime). tsm publishes that eta; lispsm given
// it as warp.eta fits the same warp (the same light space and body, n' back through eq. 11
// within 1e-9 relative) and renders the same hard mask pixel for pixel. And the Storage
// factor panel analyses tsm as exactly that warp: schemeFromDeclarations (what the panel
// calls on the frame's numbers) gives one warp with the published eta, not uniform.
TEST(PerspectiveWarp, TsmIsOneWarpWithThePublishedEtaAndThePanelAnalysesIt) {
  auto r = test::makeRenderer("corridor", "uniform");
  ASSERT_TRUE(r);
  for (const char* bookmark : {"start-level", "midway"})
    for (double focus : {0.2, 0.5}) {
      SCOPED_TRACE(std::string(bookmark) + " focus " + std::to_string(focus));
      useBookmark(*r, bookmark);
      const Measured t = measure(*r, "tsm", 512, {{"warp.focus", focus}});
      ASSERT_EQ(t.fallback, 0.0);
      ASSERT_GT(t.eta, -1.0);
      ASSERT_LT(t.eta, 1.0);
      // The panel's scheme for this very frame (tsm declares no warp.eta parameter).
      r->requestPublications(ui::analysis::storagePanelKeys());
      ASSERT_FALSE(r->renderFrame(320, 180, 0));
      const Publication& pub = r->publication();
      auto num = [&](const std::string& key) -> std::optional<double> {
        auto it = pub.numbers.find(key);
        if (it == pub.numbers.end()) return std::nullopt;
        return it->second;
      };
      measure::StorageInputs in;
      measure::schemeFromDeclarations(
          Renderer::findTechnique("tsm"), [&](const std::string& k) { return num("param." + k); },
          num, in);
      EXPECT_EQ(in.settings.scheme, partition::Scheme::Eta) << in.schemeLabel;
      EXPECT_EQ(in.settings.eta, t.eta) << in.schemeLabel;
      ASSERT_TRUE(in.eta);
      EXPECT_EQ(*in.eta, t.eta);
      r->requestPublications({});
      // lispsm with that eta: the same n' and the same mask.
      const Measured l = measure(*r, "lispsm", 512, {{"warp.eta", t.eta}});
      EXPECT_NEAR(l.nPrime, t.nPrime, 1e-9 * t.nPrime);
      EXPECT_TRUE(l.mask == t.mask) << "tsm and lispsm at its eta render different masks";
      EXPECT_EQ(l.errorPct, t.errorPct);
    }
  // The other schemes as before: lispsm's eta is its parameter, uniform has none.
  for (const char* id : {"lispsm", "uniform"}) {
    measure::StorageInputs in;
    measure::schemeFromDeclarations(
        Renderer::findTechnique(id),
        [&](const std::string& k) -> std::optional<double> {
          return k == "warp.eta" ? std::optional<double>(0.25) : std::nullopt;
        },
        [](const std::string&) -> std::optional<double> { return 0.75; }, in);
    EXPECT_EQ(in.settings.scheme,
              std::string(id) == "lispsm" ? partition::Scheme::Eta : partition::Scheme::Uniform)
        << id;
    if (std::string(id) == "lispsm") {
      EXPECT_EQ(in.settings.eta, 0.25);
    }
  }
  // tsm without a published eta (not requested): nothing to analyse it by but uniform.
  measure::StorageInputs none;
  measure::schemeFromDeclarations(
      Renderer::findTechnique("tsm"), [](const std::string&) { return std::optional<double>(); },
      [](const std::string&) { return std::optional<double>(); }, none);
  EXPECT_EQ(none.settings.scheme, partition::Scheme::Uniform);
}

TEST(PerspectiveWarp, MemoryPassesAndLights) {
  auto r = test::makeRenderer("default", "uniform");
  ASSERT_TRUE(r);
  for (const char* id : {"psm", "lispsm", "tsm"}) {
    SCOPED_TRACE(id);
    ASSERT_FALSE(r->setTechnique("uniform"));
    ASSERT_FALSE(r->renderFrame(160, 90, 0));
    const std::uint64_t before = gl::allocatedBytes() - r->stats().memory.bytes();
    ASSERT_FALSE(r->setTechnique(id));
    ASSERT_FALSE(r->params().set("resolution", 768));
    for (int f = 0; f < 2; ++f) ASSERT_FALSE(r->renderFrame(160, 90, 0));
    EXPECT_EQ(r->stats().memory.bytes(), gl::allocatedBytes() - before);
    EXPECT_EQ(r->stats().memory.bytes(), 768u * 768u * 4u);
    std::vector<std::string> declared;
    for (const PassDecl& p : framePassDecls(*Renderer::findTechnique(id))) declared.push_back(p.id);
    test::expectDeclaredPassesOpened(r->stats(), declared);
    test::expectNoGlErrors(*r);
  }
  auto spot = test::makeRenderer("spot-box", "lispsm");
  ASSERT_TRUE(spot);
  auto err = spot->renderFrame(64, 48, 0);
  ASSERT_TRUE(err);
  EXPECT_EQ(*err, "technique 'lispsm' supports: directional; the light is a spot light");
}

}  // namespace
}  // namespace sl
