// The renderer's measured aliasing statistics ("aliasing.*", a GPU histogram of log2 m and
// the exact maximum, common/aliasing_stats.comp) against the CPU over FrameReadback::aliasing
// (computeAliasingStats): max exactly, pixel count exactly, p50 / p95 within half a bin.
#include <cmath>

#include "GlTestEnv.h"
#include "algo/metrics/BenchStats.h"

namespace sl {
namespace {

const std::set<std::string> kAliasingKeys = {"aliasing.p50", "aliasing.p95", "aliasing.max",
                                             "aliasing.pixels", "aliasing.bin_octaves"};
constexpr std::uint64_t kAliasingBytes = 4u * (4u + SL_ALIASING_BINS);

struct Case {
  const char* scene;
  const char* technique;
  int resolution;
};

TEST(AliasingStats, GpuHistogramMatchesTheCpuOverTheReadback) {
  const Case cases[] = {{"plane-box", "uniform", 1024},
                        {"default", "uniform", 512},
                        {"corridor", "uniform", 2048},
                        {"diagonal", "rtw-backward", 512},
                        {"default", "da-rtw", 256}};
  for (const Case& c : cases) {
    SCOPED_TRACE(std::string(c.scene) + " " + c.technique);
    auto r = test::makeRenderer(c.scene, c.technique);
    ASSERT_TRUE(r);
    ASSERT_FALSE(r->params().set("resolution", c.resolution));
    r->requestPublications(kAliasingKeys);
    for (int f = 0; f < 2; ++f) ASSERT_FALSE(r->renderFrame(333, 197, 0));  // odd sizes
    const Publication& pub = r->publication();
    ASSERT_EQ(pub.frameIndex, r->stats().frameIndex);
    // Only the 4 KiB of counters and histogram are read back, never the m image.
    EXPECT_EQ(r->stats().publicationBytes, kAliasingBytes);
    EXPECT_EQ(r->stats().publicationBytes,
              declaredPublicationBytes(*Renderer::findTechnique(c.technique), r->params(),
                                       kAliasingKeys));
    const FrameReadback frame = r->readback();
    const AliasingStats cpu = computeAliasingStats(frame.aliasing, frame.hardMask);
    ASSERT_GT(cpu.pixels, 1000u);
    EXPECT_EQ(cpu.nonFinite, 0u);
    EXPECT_EQ(pub.numbers.at("aliasing.pixels"), double(cpu.pixels));
    EXPECT_EQ(pub.numbers.at("aliasing.max"), cpu.max);  // exactly: atomicMax on the bits
    const double bin = pub.numbers.at("aliasing.bin_octaves");
    EXPECT_DOUBLE_EQ(bin, 1.0 / SL_ALIASING_BINS_PER_OCTAVE);
    // Half a bin, and 1e-4 octave for a value on a bin edge that float log2 puts in the
    // neighbouring bin (its centre is then half a bin and that epsilon away).
    const double tol = 0.5 * bin + 1e-4;
    const std::vector<float> kept = [&] {
      std::vector<float> v;
      for (std::size_t i = 0; i < frame.aliasing.size(); ++i)
        if (frame.hardMask[i] != kStatsMaskUncovered && frame.aliasing[i] > 0.0f)
          v.push_back(frame.aliasing[i]);
      return v;
    }();
    const double p50 = percentile(std::span<const float>(kept), 50.0);
    EXPECT_LE(std::abs(std::log2(pub.numbers.at("aliasing.p95") / cpu.p95)), tol)
        << "gpu " << pub.numbers.at("aliasing.p95") << " cpu " << cpu.p95;
    EXPECT_LE(std::abs(std::log2(pub.numbers.at("aliasing.p50") / p50)), tol)
        << "gpu " << pub.numbers.at("aliasing.p50") << " cpu " << p50;
    // The CPU mirror of the histogram gives the same percentiles from the readback.
    const Log2Histogram h = aliasingHistogram(frame.aliasing, frame.hardMask);
    EXPECT_EQ(h.total(), cpu.pixels);
    EXPECT_LE(
        std::abs(std::log2(histogramPercentile(h, 95.0, cpu.max) / pub.numbers.at("aliasing.p95"))),
        1e-4);
    test::expectNoGlErrors(*r);
  }
}

TEST(AliasingStats, APointLightPublishesItsKindAndNoDirection) {
  // The storage panel analyses directional lights only: it reads light.type to say so.
  auto r = test::makeRenderer("omni-room", "cube");
  ASSERT_TRUE(r);
  r->requestPublications({"light.type", "light.azimuth_deg", "light.elevation_deg"});
  ASSERT_FALSE(r->renderFrame(160, 90, 0));
  const Publication& pub = r->publication();
  ASSERT_EQ(r->light().type, LightType::Point);
  EXPECT_EQ(pub.numbers.at("light.type"), double(int(LightType::Point)));
  EXPECT_FALSE(pub.numbers.count("light.azimuth_deg"));
  EXPECT_FALSE(pub.numbers.count("light.elevation_deg"));
}

TEST(AliasingStats, NothingIsComputedOrReadWhenNotRequested) {
  auto r = test::makeRenderer("plane-box", "uniform");
  ASSERT_TRUE(r);
  r->requestPublications({"camera.*", "light.type", "light.azimuth_deg", "param.*"});
  ASSERT_FALSE(r->renderFrame(160, 90, 0));
  EXPECT_EQ(r->stats().publicationBytes, 0u);
  const Publication& pub = r->publication();
  EXPECT_FALSE(pub.numbers.count("aliasing.max"));
  // The frame's numbers: what the storage panel reads (camera, light, parameter values).
  EXPECT_EQ(pub.numbers.at("camera.near_m"), double(r->camera().nearM));
  EXPECT_EQ(pub.numbers.at("camera.fov_deg"), double(r->camera().fovYDeg));
  EXPECT_NEAR(pub.numbers.at("camera.aspect"), 160.0 / 90.0, 1e-6);
  EXPECT_EQ(pub.numbers.at("light.azimuth_deg"), double(r->light().azimuthDeg));
  EXPECT_FALSE(pub.numbers.count("light.elevation_deg"));
  EXPECT_EQ(pub.numbers.at("light.type"), double(int(LightType::Directional)));
  EXPECT_EQ(pub.numbers.at("param.resolution"), r->params().get("resolution"));
  const glm::vec3 f(pub.numbers.at("camera.forward.x"), pub.numbers.at("camera.forward.y"),
                    pub.numbers.at("camera.forward.z"));
  const glm::vec3 u(pub.numbers.at("camera.up.x"), pub.numbers.at("camera.up.y"),
                    pub.numbers.at("camera.up.z"));
  EXPECT_NEAR(glm::length(f - r->camera().forward()), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::dot(f, u), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(u), 1.0f, 1e-6f);
  test::expectNoGlErrors(*r);
}

}  // namespace
}  // namespace sl
