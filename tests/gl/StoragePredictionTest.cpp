// Prediction against measurement (issue 10): on a ground plane that spans the view frustum,
// the measured perspective aliasing m of `uniform` (the renderer's GPU statistics,
// "aliasing.p95" / "aliasing.max") against the storage-factor analysis of Lloyd et al. 2006
// (algo/partition/StorageFactor: beam widths, M_x, M_z) for 3 map resolutions x 2 camera
// pitches; then `lispsm` and `cascades` (log split, k = 2..4, warped and plain) against the
// same analysis (WarpedMeasuredAliasingTracksTheAnalysis).
//
// Units: the analysis is for a 1x1 map and a 1x1 image (res = 1); m counts texels per pixel,
// so a map of R texels per side seen in an image H pixels high has m = M * H / R.
// What the two measure: the paper's M is the maximum over the WHOLE view frustum of the
// per-axis ratios m_x, m_z; the renderer's m is 1 / sqrt(area) of a texel's footprint in
// pixels on the VISIBLE surface: sqrt(m_x m_z) (area, not per axis), times the projective
// factor sqrt(|r.N| / (|r.v| |L.N|)) (r the view ray, v the view vector, N the ground's
// normal, L the light), over pixels only, with the map fitted to view frustum ∩ scene
// bounds (the ground), not to the frustum. The test evaluates the analysis on exactly that:
// the uniform warp fitted to the renderer's focus body, the beam widths at every covered
// pixel's surface point, and compares p95 and max; and it shows how far the paper's
// whole-frustum M lies above the measurement, and why.
#include <cmath>
#include <cstdio>
#include <functional>

#include "GlTestEnv.h"
#include "algo/Focus.h"
#include "algo/metrics/BenchStats.h"
#include "algo/partition/CascadeFit.h"
#include "algo/partition/StorageFactor.h"

namespace sl {
namespace {

/// A 4 km square ground (two triangles, y = 0, normal up): it spans every frustum below.
std::shared_ptr<Scene> groundScene() {
  auto s = std::make_shared<Scene>();
  s->name = "ground";
  MeshPrimitive g;
  const float h = 2000.0f;
  g.positions = {{-h, 0, -h}, {h, 0, -h}, {h, 0, h}, {-h, 0, h}};
  g.normals.assign(4, glm::vec3(0, 1, 0));
  g.indices = {0, 2, 1, 0, 3, 2};
  s->primitives.push_back(g);
  s->bounds.min = {-h, 0.0f, -h};
  s->bounds.max = {h, 0.0f, h};
  return s;
}

TEST(StoragePrediction, UniformMeasuredAliasingTracksTheAnalysis) {
  test::eglContext().makeCurrent();
  Renderer r;
  r.setScene(groundScene());
  ASSERT_FALSE(r.setTechnique("uniform"));
  const Light light = Light::directional(0.0f, 90.0f);  // overhead: the paper's §4.1 case
  r.setLight(light);
  const int size = 480;  // square image: the paper's analysis assumes aspect 1
  const glm::dvec3 towardsLight(light.directionalTowards());
  r.requestPublications({"aliasing.p95", "aliasing.max", "aliasing.pixels"});

  for (const double pitchDeg : {25.0, 55.0}) {
    Camera cam;
    cam.position = {0.0f, 3.0f, 0.0f};
    const double p = glm::radians(pitchDeg);
    cam.target = cam.position + glm::vec3(0.0f, float(-std::sin(p)), float(-std::cos(p)));
    cam.fovYDeg = 60.0f;
    cam.nearM = 1.0f;
    cam.farM = 100.0f;
    r.setCamera(cam);
    const warp::ViewFrustum view = warp::ViewFrustum::fromCamera(cam, 1.0);

    // The renderer's body: Focus fits uniform's map to view frustum ∩ scene bounds.
    LightFit focus;
    ASSERT_FALSE(fitDirectionalLight(cam, 1.0f, r.scene()->bounds, glm::vec3(towardsLight),
                                     FocusSettings{}, focus));
    std::vector<glm::dvec3> body(focus.focusPoints.begin(), focus.focusPoints.end());
    warp::WarpSettings ws;
    ws.kind = warp::WarpKind::Uniform;
    warp::WarpFit visible;
    ASSERT_FALSE(warp::fitWarp(view, body, towardsLight, ws, visible));
    // Focus pads each side by FocusSettings::paddingFraction: texels (1 + 2 pad) larger.
    const double pad = 1.0 + 2.0 * double(FocusSettings{}.paddingFraction);
    // The same texel area as the renderer's light frustum (overhead light: the two fits'
    // axes are both world-aligned).
    EXPECT_NEAR((visible.hi.x - visible.lo.x) * visible.depthM * pad * pad,
                double(focus.extentM.x) * double(focus.extentM.y),
                1e-3 * double(focus.extentM.x) * double(focus.extentM.y));

    // The paper's metric: uniform fitted to the whole view frustum.
    partition::SchemeSettings uniform;
    uniform.scheme = partition::Scheme::Uniform;
    partition::StorageResult paper;
    ASSERT_FALSE(partition::evaluateScheme(view, towardsLight, uniform, paper));

    std::vector<double> normalised;  // measured max * R / H, per resolution
    for (const int res : {512, 1024, 2048}) {
      SCOPED_TRACE("pitch " + std::to_string(pitchDeg) + " resolution " + std::to_string(res));
      ASSERT_FALSE(r.params().set("resolution", res));
      ASSERT_FALSE(r.renderFrame(size, size, 0));
      const Publication& pub = r.publication();
      const double measuredMax = pub.numbers.at("aliasing.max");
      const double measuredP95 = pub.numbers.at("aliasing.p95");
      const FrameReadback frame = r.readback();
      const double scale = double(size) / double(res);  // res = 1 -> texels per pixel

      // The analysis at every covered pixel's surface point.
      std::vector<float> predicted;
      for (std::size_t i = 0; i < frame.positions.size(); ++i) {
        if (frame.positions[i].w <= 0.0f) continue;
        const glm::dvec3 P(frame.positions[i]);
        const glm::dvec3 N(frame.normals[i]);
        const glm::dvec2 mxz = partition::aliasingAt(view, visible, P);
        const glm::dvec3 ray = glm::normalize(P - view.eye);
        const double projective =
            std::sqrt(std::abs(glm::dot(ray, N)) / (std::abs(glm::dot(ray, view.forward)) *
                                                    std::abs(glm::dot(towardsLight, N))));
        predicted.push_back(float(scale * pad * std::sqrt(mxz.x * mxz.y) * projective));
      }
      ASSERT_GT(predicted.size(), std::size_t(size * size / 4));
      EXPECT_EQ(pub.numbers.at("aliasing.pixels"), double(predicted.size()));
      double predictedMax = 0.0;
      for (float v : predicted) predictedMax = std::max(predictedMax, double(v));
      const double predictedP95 = percentile(std::span<const float>(predicted), 95.0);
      const double paperM = scale * std::sqrt(paper.mx * paper.mz);
      std::printf(
          "pitch %2.0f deg, %4d^2 map, %dx%d: measured m p95 %.4f max %.4f | analysis on the "
          "visible ground p95 %.4f max %.4f | paper's whole-frustum sqrt(M_x M_z) H/R %.3f "
          "(M_x %.3f, M_z %.3f at res 1) = %.1fx the measured max\n",
          pitchDeg, res, size, size, measuredP95, measuredMax, predictedP95, predictedMax, paperM,
          paper.mx * scale, paper.mz * scale, paperM / measuredMax);
      // Tolerance 1.5 % (measured: at most 0.4 %): the measured m comes from finite
      // differences over the pixel's 2x2 quad of a projective map (a first-order error in
      // 1/H), and the p95 carries the histogram's half bin (2^(1/64) - 1 = 1.1 %).
      EXPECT_NEAR(measuredMax / predictedMax, 1.0, 0.015);
      EXPECT_NEAR(measuredP95 / predictedP95, 1.0, 0.015);
      // The paper's M bounds the measurement from above: its map covers the whole frustum
      // (larger texels) and its maximum is at the near plane, which the ground never reaches.
      EXPECT_LT(measuredMax, paperM);
      normalised.push_back(measuredMax / scale);
    }
    // Resolution scaling: m * R / H does not depend on R (measured: within 0.1 %).
    for (double v : normalised) EXPECT_NEAR(v / normalised.front(), 1.0, 0.01);
  }
  test::expectNoGlErrors(r);
}

/// The texel footprint's area (at res = 1, metres^2, overhead light: light x, z are ground
/// x, z) of the map that serves world point P, as the technique fitted it.
using TexelArea = std::function<double(const glm::dvec3& P, int map)>;

struct Compared {
  double measuredMax = 0, measuredP95 = 0, predictedMax = 0, predictedP95 = 0;
};

/// Renders one frame (after `warmup`) and evaluates the analysis at every covered pixel:
/// m = (H / R) sqrt(area) / w_i * projective (the uniform test above explains each factor).
Compared compareAtPixels(Renderer& r, const warp::ViewFrustum& view, int size, int res,
                         const TexelArea& area) {
  Compared c;
  const Publication& pub = r.publication();
  c.measuredMax = pub.numbers.at("aliasing.max");
  c.measuredP95 = pub.numbers.at("aliasing.p95");
  const FrameReadback frame = r.readback();
  const double scale = double(size) / double(res);
  std::vector<float> predicted;
  for (std::size_t i = 0; i < frame.positions.size(); ++i) {
    if (frame.positions[i].w <= 0.0f) continue;
    const glm::dvec3 P(frame.positions[i]), N(frame.normals[i]);
    const glm::dvec3 ray = glm::normalize(P - view.eye);
    const double projective =
        std::sqrt(std::abs(glm::dot(ray, N)) / std::abs(glm::dot(ray, view.forward)));
    const int map = frame.mapIndex.empty() ? 0 : int(frame.mapIndex[i]);
    predicted.push_back(
        float(scale * std::sqrt(area(P, map)) / partition::imageBeamWidth(view, P) * projective));
  }
  EXPECT_GT(predicted.size(), std::size_t(size * size / 4));
  for (float v : predicted) c.predictedMax = std::max(c.predictedMax, double(v));
  c.predictedP95 = percentile(std::span<const float>(predicted), 95.0);
  return c;
}

Camera groundCamera(double pitchDeg) {
  Camera cam;
  cam.position = {0.0f, 3.0f, 0.0f};
  const double p = glm::radians(pitchDeg);
  cam.target = cam.position + glm::vec3(0.0f, float(-std::sin(p)), float(-std::cos(p)));
  cam.fovYDeg = 60.0f;
  cam.nearM = 1.0f;
  cam.farM = 100.0f;
  return cam;
}

// The warps (issue 10's "prediction against measurement" for LiSPSM and cascades, log split,
// k = 2..4, warped and plain): the same ground, overhead light, square image, 1024^2 per map.
// The MAXIMUM of m is compared, not the p95: the analysis is a maximum (per-axis maxima at
// the body's vertices, §4.4), reached at the near edge of the visible ground, which the
// image's bottom row covers, so the measured max samples it; a p95 depends on how pixels
// spread over depth, which StorageFactor does not model. Three predictions:
//  1. per pixel: the beam widths (eqs. 3-4) of the map as the technique fitted it at every
//     covered pixel's surface point: max and p95 agree within 1.5 % (as uniform's), which
//     checks the whole chain (fit, warp, selection, resolve);
//  2. StorageFactor's sqrt(M_x M_z) of each fitted map over the ground it serves (slice ∩
//     scene bounds), times the projective factor at the image's bottom edge (the paper's
//     m is across the ray, the measured one on the surface): within 1.5 % (measured: the
//     factor alone explains the 1.031x at 25 degrees and 0.934x at 55 before it);
//  3. the paper's own: sqrt(M_x M_z) of the scheme over the view frustum clipped to the
//     ground's visible depth range. It lies ABOVE the measurement, by 1.08x to 1.89x here:
//     its warps are fitted to the whole clipped frustum (the air above the ground too:
//     wider light-space x and z than the ground polygon the renderer fits), and its maxima
//     are per axis over all 8 vertices. Asserted: measured <= paper < 2 x measured.
TEST(StoragePrediction, WarpedMeasuredAliasingTracksTheAnalysis) {
  test::eglContext().makeCurrent();
  const Light light = Light::directional(0.0f, 90.0f);
  const glm::dvec3 towardsLight(light.directionalTowards());
  const int size = 480, res = 1024;
  struct Config {
    std::string technique;
    int k;
    bool warp;
  };
  const std::vector<Config> configs = {{"lispsm", 1, true},    {"cascades", 2, true},
                                       {"cascades", 3, true},  {"cascades", 4, true},
                                       {"cascades", 2, false}, {"cascades", 4, false}};
  for (const double pitchDeg : {25.0, 55.0}) {
    const Camera cam = groundCamera(pitchDeg);
    const warp::ViewFrustum view = warp::ViewFrustum::fromCamera(cam, 1.0);
    for (const Config& cfg : configs) {
      const std::string label =
          cfg.technique + (cfg.technique == "cascades"
                               ? " k=" + std::to_string(cfg.k) + (cfg.warp ? " warped" : " plain")
                               : "");
      SCOPED_TRACE("pitch " + std::to_string(pitchDeg) + " " + label);
      Renderer r;
      r.setScene(groundScene());
      ASSERT_FALSE(r.setTechnique(cfg.technique));
      r.setLight(light);
      r.setCamera(cam);
      ASSERT_FALSE(r.params().set("resolution", res));
      const Aabb bounds = r.scene()->bounds;
      partition::CascadeFit cfit;
      warp::WarpFit lfit;
      if (cfg.technique == "cascades") {
        // Tight and over the frustum ∩ scene (no G-buffer range): the fit below is the
        // renderer's exactly.
        ASSERT_FALSE(r.params().set("partitions", cfg.k));
        ASSERT_FALSE(r.params().set("split", double(int(partition::SplitScheme::Log))));
        ASSERT_FALSE(r.params().set("stabilize", 0));
        ASSERT_FALSE(r.params().set("depth.fit", 0));
        ASSERT_FALSE(r.params().set("partition.warp", cfg.warp ? 1 : 0));
        partition::CascadeSettings cs;
        cs.partitions = cfg.k;
        cs.split = partition::SplitScheme::Log;
        cs.resolution = res;
        cs.stabilize = false;
        cs.warp = cfg.warp;
        ASSERT_FALSE(partition::fitCascades(cam, 1.0f, bounds, glm::vec3(towardsLight), cs, cfit));
        for (const auto& p : cfit.parts) EXPECT_EQ(p.warped(), cfg.warp);
      } else {  // as PerspectiveShadowMap::renderShadows
        const auto pts =
            intersectFrustumWithBox(cam.frustumCorners(1.0f, cam.nearM, cam.farM), bounds);
        const std::vector<glm::dvec3> body(pts.begin(), pts.end());
        warp::WarpSettings ws;
        ws.kind = warp::WarpKind::Eta;
        const auto box = bounds.corners();
        ws.depthOnly.assign(box.begin(), box.end());
        ASSERT_FALSE(warp::fitWarp(view.clippedToBody(body), body, towardsLight, ws, lfit));
        ASSERT_TRUE(lfit.warped());
      }
      r.requestPublications({"aliasing.p95", "aliasing.max"});
      ASSERT_FALSE(r.renderFrame(size, size, 0));
      const TexelArea area = [&](const glm::dvec3& P, int map) {
        if (cfg.technique != "cascades") {
          const glm::dvec2 b = lfit.beamWidths(P);
          return b.x * b.y;
        }
        const partition::CascadePart& p = cfit.parts.at(std::size_t(map));
        if (p.warped()) {
          const glm::dvec2 b = p.warpFit->beamWidths(P);
          return b.x * b.y;
        }
        return p.extentM.x * p.extentM.y;  // orthographic: one texel size
      };
      const Compared c = compareAtPixels(r, view, size, res, area);

      // StorageFactor's per-axis maxima (M_x, M_z at the body's vertices, §4.4) of each map
      // as fitted, over the part of the ground it serves (frustum slice ∩ scene bounds).
      double visibleM = 0.0;
      for (std::size_t i = 0; i < std::max<std::size_t>(1, cfit.parts.size()); ++i) {
        const bool casc = cfg.technique == "cascades";
        const float n = casc ? float(cfit.parts[i].nearM) : cam.nearM;
        const float f = casc ? float(cfit.parts[i].farM) : cam.farM;
        const auto pts = intersectFrustumWithBox(cam.frustumCorners(1.0f, n, f), bounds);
        const std::vector<glm::dvec3> body(pts.begin(), pts.end());
        partition::Storage st;
        if (!casc || cfit.parts[i].warped()) {
          st = partition::storageOfBody(view, casc ? *cfit.parts[i].warpFit : lfit, body);
        } else {
          for (const glm::dvec3& v : body) {
            const double wi = partition::imageBeamWidth(view, v);
            st.mx = std::max(st.mx, cfit.parts[i].extentM.x / wi);
            st.mz = std::max(st.mz, cfit.parts[i].extentM.y / wi);
          }
        }
        visibleM = std::max(visibleM, double(size) / res * std::sqrt(st.mx * st.mz));
      }

      // The paper's scheme on the frustum clipped to the ground's visible depth range.
      const glm::dvec2 range = partition::visibleDepthRange(cam, 1.0f, bounds);
      warp::ViewFrustum clipped = view;
      clipped.nearM = range.x;
      clipped.farM = range.y;
      partition::SchemeSettings ss;
      ss.scheme =
          cfg.technique == "cascades" ? partition::Scheme::Cascades : partition::Scheme::Lispsm;
      ss.partitions = cfg.k;
      ss.split = partition::SplitScheme::Log;
      ss.partitionWarp = cfg.warp;
      partition::StorageResult paper;
      ASSERT_FALSE(partition::evaluateScheme(clipped, towardsLight, ss, paper));
      const double paperM = double(size) / res * std::sqrt(paper.mx * paper.mz);
      std::printf(
          "pitch %2.0f, %-20s measured m p95 %.4f max %.4f | per pixel p95 %.4f max %.4f | "
          "fitted maps' sqrt(M_x M_z) over the ground %.4f = %.3fx | paper sqrt(M_x M_z) over "
          "[%.2f, %.2f] m: %.4f = %.2fx the measured max\n",
          pitchDeg, label.c_str(), c.measuredP95, c.measuredMax, c.predictedP95, c.predictedMax,
          visibleM, visibleM / c.measuredMax, range.x, range.y, paperM, paperM / c.measuredMax);
      EXPECT_NEAR(c.measuredMax / c.predictedMax, 1.0, 0.015);
      EXPECT_NEAR(c.measuredP95 / c.predictedP95, 1.0, 0.015);
      // The paper's m is per beam, across the ray; the measured one is per pixel on the
      // surface: the projective factor sqrt(|r.N| / |r.v|) (overhead light, L.N = 1) at the
      // maximum, the bottom edge of the image (the ray 30 degrees below the view vector).
      const double bottom = glm::radians(pitchDeg + 30.0);
      const double projective = std::sqrt(std::sin(bottom) / std::cos(glm::radians(30.0)));
      EXPECT_NEAR(c.measuredMax / (visibleM * projective), 1.0, 0.015);
      EXPECT_GT(paperM, c.measuredMax * 0.985);
      EXPECT_LT(paperM, 2.0 * c.measuredMax);
      test::expectNoGlErrors(r);
    }
  }
}
}  // namespace
}  // namespace sl
