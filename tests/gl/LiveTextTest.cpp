// Lesson texts quote the frame's own numbers (core/LiveText.h): the built-in keys, the
// publication's numbers and curve elements, the right half's, and n/a where the frame has
// nothing — and the keys a text needs are exactly what the renderer is asked to publish.
#include "GlTestEnv.h"
#include "core/LiveText.h"

namespace sl {
namespace {

TEST(LiveText, QuotesTheFramesNumbersAndNotAvailableWhereItHasNone) {
  Publication main;
  main.numbers["pca.anisotropy"] = 0.98765;
  main.curves["warp.x"] = {0.25f, 0.5f};
  Publication right;
  right.numbers["pca.anisotropy"] = 0.5;
  const LiveSide left{0.7462, 12.5, 4.0, &main};
  const LiveSide split{2.0671, std::nullopt, 1.0, &right};
  const std::string text =
      "{error_pct} vs {compare.error_pct:2}; a {pca.anisotropy:3} / {compare.pca.anisotropy:1}; "
      "w {warp.x[1]:2}, {warp.x[2]}; t {frame_ms:1} / {compare.frame_ms}; m {memory_mb:0}; "
      "{nothing.here}";
  EXPECT_EQ(fillLiveText(text, left, &split),
            "0.746 vs 2.07; a 0.988 / 0.5; w 0.50, n/a; t 12.5 / n/a; m 4; n/a");
  // No right half: its numbers are n/a; a side without a publication has only the built-ins.
  EXPECT_EQ(fillLiveText("{compare.error_pct} {pca.anisotropy} {error_pct:1}",
                         LiveSide{std::nullopt, 1.0, 1.0, nullptr}, nullptr),
            "n/a n/a n/a");
  EXPECT_EQ(livePublicationKeys(text, false),
            (std::set<std::string>{"pca.anisotropy", "warp.x", "nothing.here"}));
  EXPECT_EQ(livePublicationKeys(text, true), (std::set<std::string>{"pca.anisotropy"}));
}

TEST(LiveText, ATextRequestsAndQuotesWhatTheTechniquePublishes) {
  auto r = test::makeRenderer("band-diagonal", "da-rtw");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->params().set("resolution", 256));
  const std::string text = "The importance is thin ({pca.anisotropy:3}) and R = {rotation.deg:1}°.";
  r->requestPublications(livePublicationKeys(text, false));
  for (int f = 0; f < 3; ++f) ASSERT_FALSE(r->renderFrame(320, 180, 0));
  const Publication& pub = r->publication();
  ASSERT_TRUE(pub.numbers.count("pca.anisotropy"));
  ASSERT_TRUE(pub.numbers.count("rotation.deg"));
  const std::string filled = fillLiveText(text, LiveSide{std::nullopt, 1.0, 1.0, &pub}, nullptr);
  EXPECT_EQ(filled, "The importance is thin (" +
                        formatTextValue(pub.numbers.at("pca.anisotropy"), 3) +
                        ") and R = " + formatTextValue(pub.numbers.at("rotation.deg"), 1) + "°.");
  EXPECT_EQ(filled.find("n/a"), std::string::npos) << filled;
}

}  // namespace
}  // namespace sl
