// Image files and golden comparison: PNG round trip, pass/fail with the candidate and diff
// files written, blessing with SHADOWLAB_UPDATE_GOLDEN=1, the colour map's ends.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <vector>

#include "metrics/GoldenImage.h"
#include "metrics/Image.h"

namespace sl {
namespace {

namespace fs = std::filesystem;

/// A fresh, empty directory for one test under the test output directory.
fs::path testDir(const std::string& name) {
  const fs::path dir = fs::path(SHADOWLAB_TEST_OUT) / "ImageTest" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// A gradient with varying alpha (so an alpha premultiplication would show).
ImageRGBA8 gradient(int w, int h) {
  ImageRGBA8 img = makeImage(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = img.pixel(x, y);
      p[0] = std::uint8_t(x * 255 / std::max(w - 1, 1));
      p[1] = std::uint8_t(y * 255 / std::max(h - 1, 1));
      p[2] = std::uint8_t((x * 7 + y * 13) & 255);
      p[3] = std::uint8_t(255 - ((x + y) * 5 & 127));
    }
  return img;
}

TEST(Image, PngRoundTripIsExact) {
  const fs::path dir = testDir("RoundTrip");
  const ImageRGBA8 img = gradient(37, 21);
  const fs::path file = dir / "nested" / "deeper" / "gradient.png";  // parents created
  ASSERT_FALSE(writeImage(file, img));
  std::string error;
  const auto back = readImage(file, &error);
  ASSERT_TRUE(back) << error;
  EXPECT_EQ(back->width, 37);
  EXPECT_EQ(back->height, 21);
  EXPECT_EQ(back->pixels, img.pixels);
}

TEST(Image, ErrorsNameThePath) {
  const fs::path dir = testDir("Errors");
  std::string error;
  EXPECT_FALSE(readImage(dir / "missing.png", &error));
  EXPECT_NE(error.find("missing.png"), std::string::npos) << error;

  const auto err = writeImage(dir / "bad.png", ImageRGBA8{});
  ASSERT_TRUE(err);
  EXPECT_NE(err->find("bad.png"), std::string::npos) << *err;

  const auto unknown = writeImage(dir / "image.notaformat", gradient(2, 2));
  ASSERT_TRUE(unknown);
  EXPECT_NE(unknown->find("image.notaformat"), std::string::npos) << *unknown;
}

TEST(Image, FlipVertically) {
  ImageRGBA8 img = gradient(3, 4);
  const ImageRGBA8 original = img;
  flipVertically(img);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 3; ++x)
      for (int c = 0; c < 4; ++c) ASSERT_EQ(img.pixel(x, y)[c], original.pixel(x, 3 - y)[c]);
  flipVertically(img);
  EXPECT_EQ(img.pixels, original.pixels);
}

TEST(Image, ColorMapEndpoints) {
  const Rgba8 lo = viridis(0.0f), hi = viridis(1.0f);
  EXPECT_EQ(lo, (Rgba8{68, 1, 84, 255}));
  EXPECT_EQ(hi, (Rgba8{253, 231, 37, 255}));
  EXPECT_EQ(viridis(-3.0f), lo);
  EXPECT_EQ(viridis(7.0f), hi);
  const Rgba8 mid = viridis(0.5f);  // matplotlib: (33, 145, 140)
  EXPECT_NEAR(mid[0], 33, 2);
  EXPECT_NEAR(mid[1], 145, 2);
  EXPECT_NEAR(mid[2], 140, 2);

  const float inf = std::numeric_limits<float>::infinity();
  const std::vector<float> values{2.0f, 4.0f, 3.0f, -1.0f, 9.0f, std::nanf(""), inf, -inf};
  const ImageRGBA8 img = colorMapped(values, 4, 2, 2.0f, 4.0f);
  ASSERT_EQ(img.width, 4);
  ASSERT_EQ(img.height, 2);
  auto at = [&](int i) {
    const std::uint8_t* p = img.pixels.data() + 4 * i;
    return Rgba8{p[0], p[1], p[2], p[3]};
  };
  EXPECT_EQ(at(0), lo);
  EXPECT_EQ(at(1), hi);
  EXPECT_EQ(at(2), mid);
  EXPECT_EQ(at(3), lo);                     // below lo clamps
  EXPECT_EQ(at(4), hi);                     // above hi clamps
  EXPECT_EQ(at(5), (Rgba8{0, 0, 0, 255}));  // NaN: black
  EXPECT_EQ(at(6), hi);
  EXPECT_EQ(at(7), lo);

  const ImageRGBA8 reversed = colorMapped(values, 4, 2, 4.0f, 2.0f);
  EXPECT_EQ(reversed.pixel(0, 0)[0], hi[0]);
  EXPECT_THROW(colorMapped(values, 3, 2, 0.0f, 1.0f), std::invalid_argument);
}

TEST(Image, ColorMapIsMonotoneInLightness) {
  // Viridis is perceptually uniform: luma rises along the whole map.
  float previous = -1.0f;
  for (int i = 0; i <= 64; ++i) {
    const Rgba8 c = viridis(i / 64.0f);
    const float luma = 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2];
    EXPECT_GT(luma, previous) << "t = " << i / 64.0f;
    previous = luma;
  }
}

TEST(GoldenImage, PassesWithinTolerance) {
  const fs::path dir = testDir("Pass");
  const ImageRGBA8 golden = gradient(20, 10);
  ASSERT_FALSE(writeImage(dir / "golden.png", golden));
  ImageRGBA8 candidate = golden;
  candidate.pixel(3, 4)[1] += 2;     // within maxChannelDiff
  candidate.pixel(5, 5)[0] ^= 0x80;  // one failing pixel = 0.5 %, allowed 1 %
  const GoldenResult r =
      compareToGolden(candidate, dir / "golden.png", {2, 0.01}, dir, "pass", false);
  EXPECT_TRUE(r.pass) << r.message;
  EXPECT_DOUBLE_EQ(r.failingFraction, 1.0 / 200.0);
  EXPECT_EQ(r.maxDiff, 128);
  EXPECT_FALSE(fs::exists(dir / "pass.candidate.png"));
  EXPECT_FALSE(fs::exists(dir / "pass.diff.png"));
}

TEST(GoldenImage, FailureWritesCandidateAndDiff) {
  const fs::path dir = testDir("Fail");
  const ImageRGBA8 golden = gradient(20, 10);
  ASSERT_FALSE(writeImage(dir / "golden.png", golden));
  ImageRGBA8 candidate = golden;
  for (int x = 0; x < 10; ++x) candidate.pixel(x, 2)[2] += 3;  // 10 pixels, diff 3 > 2
  const fs::path out = dir / "out";
  const GoldenResult r =
      compareToGolden(candidate, dir / "golden.png", {2, 0.01}, out, "fail", false);
  EXPECT_FALSE(r.pass);
  EXPECT_DOUBLE_EQ(r.failingFraction, 10.0 / 200.0);
  EXPECT_EQ(r.maxDiff, 3);
  const fs::path candPath = out / "fail.candidate.png", diffPath = out / "fail.diff.png";
  EXPECT_NE(r.message.find(candPath.string()), std::string::npos) << r.message;
  EXPECT_NE(r.message.find(diffPath.string()), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("SHADOWLAB_UPDATE_GOLDEN=1"), std::string::npos) << r.message;

  const auto cand = readImage(candPath);
  ASSERT_TRUE(cand);
  EXPECT_EQ(cand->pixels, candidate.pixels);
  const auto diff = readImage(diffPath);
  ASSERT_TRUE(diff);
  ASSERT_EQ(diff->width, 20);
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 20; ++x) {
      const std::uint8_t* p = diff->pixel(x, y);
      const bool red = p[0] == 255 && p[1] == 0 && p[2] == 0;
      EXPECT_EQ(red, y == 2 && x < 10) << x << "," << y;
      if (!red) {
        EXPECT_LT(p[0], 100);  // dim copy
      }
    }
}

TEST(GoldenImage, MissingGoldenAndSizeMismatchFail) {
  const fs::path dir = testDir("Missing");
  const ImageRGBA8 candidate = gradient(8, 8);
  const GoldenResult missing =
      compareToGolden(candidate, dir / "nope.png", {0, 0.0}, dir, "missing", false);
  EXPECT_FALSE(missing.pass);
  EXPECT_EQ(missing.failingFraction, 1.0);
  EXPECT_NE(missing.message.find("nope.png"), std::string::npos) << missing.message;
  EXPECT_TRUE(fs::exists(dir / "missing.candidate.png"));
  EXPECT_TRUE(fs::exists(dir / "missing.diff.png"));

  ASSERT_FALSE(writeImage(dir / "small.png", gradient(4, 8)));
  const GoldenResult size =
      compareToGolden(candidate, dir / "small.png", {255, 1.0}, dir, "size", false);
  EXPECT_FALSE(size.pass);  // even with a tolerance that accepts anything
  EXPECT_NE(size.message.find("size mismatch"), std::string::npos) << size.message;
  EXPECT_TRUE(fs::exists(dir / "size.diff.png"));
}

TEST(GoldenImage, UpdateModeBlessesTheCandidate) {
  const fs::path dir = testDir("Update");
  const ImageRGBA8 old = gradient(16, 16);
  ImageRGBA8 candidate = old;
  for (std::uint8_t& b : candidate.pixels) b = std::uint8_t(255 - b);
  const fs::path golden = dir / "goldens" / "scene.png";
  // Missing golden: written (directories created), passes.
  const GoldenResult created = compareToGolden(old, golden, {0, 0.0}, dir, "scene", true);
  EXPECT_TRUE(created.pass) << created.message;
  EXPECT_NE(created.message.find("golden updated"), std::string::npos) << created.message;
  ASSERT_TRUE(fs::exists(golden));
  // Different candidate: replaces the golden, passes, says so.
  const GoldenResult updated = compareToGolden(candidate, golden, {0, 0.0}, dir, "scene", true);
  EXPECT_TRUE(updated.pass) << updated.message;
  EXPECT_NE(updated.message.find("golden updated"), std::string::npos) << updated.message;
  EXPECT_FALSE(fs::exists(dir / "scene.candidate.png"));
  const auto blessed = readImage(golden);
  ASSERT_TRUE(blessed);
  EXPECT_EQ(blessed->pixels, candidate.pixels);
  // Without updating, the blessed golden now passes and the old image fails.
  EXPECT_TRUE(compareToGolden(candidate, golden, {0, 0.0}, dir, "scene", false).pass);
  EXPECT_FALSE(compareToGolden(old, golden, {0, 0.0}, dir, "scene", false).pass);
}

// SHADOWLAB_UPDATE_GOLDEN's value (given here, never set in this process): only "1" blesses.
TEST(GoldenImage, UpdateRequestedOnlyByOne) {
  EXPECT_TRUE(goldenUpdateRequested("1"));
  EXPECT_FALSE(goldenUpdateRequested(nullptr));
  EXPECT_FALSE(goldenUpdateRequested(""));
  EXPECT_FALSE(goldenUpdateRequested("0"));
  EXPECT_FALSE(goldenUpdateRequested("yes"));
}

}  // namespace
}  // namespace sl
