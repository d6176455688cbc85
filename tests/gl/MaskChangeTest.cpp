// The renderer's mask change since the previous frame (common/mask_change.comp, the
// "changed" overlay of composite.frag, "mask.*" and FrameStats::maskChange) against the CPU
// mirror compareConsecutiveMasks over the two frames' read-back hard masks: the counts
// exactly, and the overlay's vivid pixels exactly the changed ones (tolerance: 0 pixels).
#include <cmath>

#include "GlTestEnv.h"
#include "algo/metrics/BenchStats.h"

namespace sl {
namespace {

constexpr int kW = 241, kH = 157;  // odd sizes: partial work groups

bool isChangedColour(const std::uint8_t* rgba) {
  const float c[3] = {SL_CHANGED_COLOUR};
  for (int i = 0; i < 3; ++i)
    if (rgba[i] != std::uint8_t(std::lround(c[i] * 255.0f))) return false;
  return true;
}

struct Case {
  const char* scene;
  const char* technique;
  float azimuthStepDeg;  ///< the light turns by this between the two frames
};

TEST(MaskChange, GpuCountAndOverlayMatchTheCpuOverTwoFrames) {
  const Case cases[] = {{"plane-box", "uniform", 3.0f}, {"corridor", "uniform", 1.0f}};
  for (const Case& c : cases) {
    SCOPED_TRACE(std::string(c.scene) + " " + c.technique);
    auto r = test::makeRenderer(c.scene, c.technique);
    ASSERT_TRUE(r);
    ASSERT_FALSE(r->rendererParams().setFromString("view.overlay", "changed"));
    r->requestPublications({"mask.*"});
    ASSERT_FALSE(r->renderFrame(kW, kH, 0));
    // The first frame at a size has nothing to compare with: no count, no vivid pixel.
    EXPECT_FALSE(r->stats().maskChange);
    EXPECT_FALSE(r->publication().numbers.count("mask.changed_pixels"));
    FrameReadback first = r->readback();
    for (std::size_t i = 0; i < first.hardMask.size(); ++i)
      ASSERT_FALSE(isChangedColour(&first.color.pixels[4 * i])) << "pixel " << i;

    Light light = r->light();
    ASSERT_EQ(light.type, LightType::Directional);
    light.azimuthDeg += c.azimuthStepDeg;
    r->setLight(light);
    ASSERT_FALSE(r->renderFrame(kW, kH, 0));
    const FrameReadback second = r->readback();
    const MaskChange cpu = compareConsecutiveMasks(first.hardMask, second.hardMask);
    ASSERT_GT(cpu.changed, 20u) << "the light's turn must change some pixels";
    ASSERT_TRUE(r->stats().maskChange);
    EXPECT_EQ(r->stats().maskChange->changed, cpu.changed);
    EXPECT_EQ(r->stats().maskChange->compared, cpu.compared);
    const Publication& pub = r->publication();
    ASSERT_EQ(pub.frameIndex, r->stats().frameIndex);
    EXPECT_EQ(pub.numbers.at("mask.changed_pixels"), double(cpu.changed));
    EXPECT_EQ(pub.numbers.at("mask.compared_pixels"), double(cpu.compared));
    // The overlay draws exactly those pixels.
    std::size_t vivid = 0, mismatched = 0;
    for (std::size_t i = 0; i < second.hardMask.size(); ++i) {
      const bool changed =
          first.hardMask[i] != kStatsMaskUncovered && second.hardMask[i] != kStatsMaskUncovered &&
          (first.hardMask[i] == kStatsMaskShadowed) != (second.hardMask[i] == kStatsMaskShadowed);
      const bool drawn = isChangedColour(&second.color.pixels[4 * i]);
      vivid += drawn;
      mismatched += drawn != changed;
    }
    EXPECT_EQ(vivid, cpu.changed);
    EXPECT_EQ(mismatched, 0u);

    // A third frame of the same view changes nothing.
    ASSERT_FALSE(r->renderFrame(kW, kH, 0));
    ASSERT_TRUE(r->stats().maskChange);
    EXPECT_EQ(r->stats().maskChange->changed, 0u);
    EXPECT_EQ(r->stats().maskChange->compared, cpu.compared);
    test::expectNoGlErrors(*r);
  }
}

TEST(MaskChange, NotCountedWithoutTheOverlayOrARequest) {
  auto r = test::makeRenderer("plane-box", "uniform");
  ASSERT_TRUE(r);
  for (int f = 0; f < 2; ++f) ASSERT_FALSE(r->renderFrame(96, 64, 0));
  EXPECT_FALSE(r->stats().maskChange);
  // Requested without the overlay: counted and published, 8 bytes read back.
  r->requestPublications({"mask.changed_pixels", "mask.compared_pixels"});
  ASSERT_FALSE(r->renderFrame(96, 64, 0));
  ASSERT_TRUE(r->stats().maskChange);
  EXPECT_EQ(r->publication().numbers.at("mask.changed_pixels"), 0.0);
  EXPECT_GT(r->publication().numbers.at("mask.compared_pixels"), 1000.0);
  EXPECT_EQ(r->stats().publicationBytes, 8u);  // the two counters, never a mask
  EXPECT_EQ(declaredPublicationBytes(*Renderer::findTechnique("uniform"), r->params(),
                                     {"mask.changed_pixels"}),
            8u);
  test::expectNoGlErrors(*r);
}

TEST(MaskChange, ReadColorIsTheReadbacksColour) {
  auto r = test::makeRenderer("plane-box", "uniform");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->renderFrame(kW, kH, 0));
  const ImageRGBA8 color = r->readColor();
  const FrameReadback frame = r->readback();
  EXPECT_EQ(color.width, kW);
  EXPECT_EQ(color.height, kH);
  EXPECT_TRUE(color.pixels == frame.color.pixels);
}

}  // namespace
}  // namespace sl
