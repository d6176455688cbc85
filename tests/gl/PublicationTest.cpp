// Per-key publishing: a frame reads back exactly what is requested. The bytes the readback
// helpers count (FrameStats::publicationBytes) are checked against the sizes of the keys a
// panel draws (ui/panels/rtw/RtwPanelKeys.h) and against the declared costs
// (TechniqueInfo::publications), for one panel, every panel and none.
#include <algorithm>
#include <numeric>

#include "GlTestEnv.h"
#include "panels/rtw/RtwPanelKeys.h"

namespace sl {
namespace {

std::set<std::string> allPanelKeys() {
  std::set<std::string> all;
  for (const auto& keys :
       {ui::rtw::importancePanelKeys(), ui::rtw::covariancePanelKeys(), ui::rtw::warpPanelKeys(),
        ui::rtw::shadowMapPanelKeys(), ui::rtw::momentPanelKeys()})
    all.insert(keys.begin(), keys.end());
  return all;
}

/// Bytes of what `pub` holds: 4 per image texel and curve value (numbers cost nothing but
/// the renderer's measured aliasing statistics: their 4 KiB histogram).
std::uint64_t heldBytes(const Publication& pub) {
  std::uint64_t bytes = pub.numbers.count("aliasing.max") ? 4u * (4u + SL_ALIASING_BINS) : 0u;
  // The mask change's two counters (mask.*), read back whenever one of its keys is published.
  if (pub.numbers.count("mask.changed_pixels") || pub.numbers.count("mask.compared_pixels"))
    bytes += 8u;
  for (const auto& [key, image] : pub.images) bytes += 4ull * image.values.size();
  for (const auto& [key, curve] : pub.curves) bytes += 4ull * curve.size();
  return bytes;
}

TEST(Publication, KeyPatterns) {
  EXPECT_TRUE(publicationKeyMatches("moment.*", "moment.I"));
  EXPECT_TRUE(publicationKeyMatches("moment.*", "moment.xI.3"));
  EXPECT_TRUE(publicationKeyMatches("moment.*.*", "moment.xI.3"));
  EXPECT_FALSE(publicationKeyMatches("moment.*.*", "moment.xI"));
  EXPECT_TRUE(publicationKeyMatches("*", "shadow map"));
  EXPECT_FALSE(publicationKeyMatches("importance", "importance.x"));
  EXPECT_FALSE(publicationKeyMatches("", "importance"));
  EXPECT_TRUE(publicationKeyMatches("*.blurred", "importance.x.blurred"));
}

// The CLI warms a temporal rotation up by reading these numbers: a technique that declares
// the rotation must publish them (and only DA-RTW keeps one today).
TEST(Publication, TemporalRotationDeclaresTheNumbersItsWarmUpReads) {
  std::vector<std::string> temporal;
  for (const TechniqueInfo& t : Renderer::techniques()) {
    if (!t.temporalRotation) continue;
    temporal.push_back(t.id);
    for (const char* key : {"pca.valid", "rotation.held", "rotation.step_deg"})
      EXPECT_NE(t.findPublication(key), nullptr) << t.id << " does not publish " << key;
  }
  EXPECT_EQ(temporal, std::vector<std::string>{"da-rtw"});
}

TEST(Publication, ReadsBackOnlyTheRequestedKeys) {
  auto r = test::makeRenderer("diagonal", "da-rtw");
  ASSERT_TRUE(r);
  ASSERT_FALSE(r->params().set("resolution", 512));
  ASSERT_FALSE(r->params().set("im.resolution", 256));
  const TechniqueInfo& info = *Renderer::findTechnique("da-rtw");
  auto frame = [&](std::set<std::string> keys) {
    r->requestPublications(std::move(keys));
    for (int f = 0; f < 2; ++f) EXPECT_FALSE(r->renderFrame(160, 90, 0));  // moments a frame late
    return r->stats().publicationBytes;
  };

  // The turn prediction's curves are computed on the CPU from the snapshot the frame reads
  // anyway: held, never read back for the publication.
  auto predictionBytes = [&] {
    std::uint64_t b = 0;
    for (const auto& [key, values] : r->publication().curves)
      if (key.rfind("prediction.", 0) == 0) b += 4u * values.size();
    return b;
  };
  // Only the Covariance panel's keys: its one image (the IM it draws the ellipses over),
  // 256^2 floats, the predicted curve and numbers that cost no readback. Neither the RTW
  // curves, the shadow maps nor the moment chain are read.
  const std::uint64_t covariance = frame(ui::rtw::covariancePanelKeys());
  EXPECT_EQ(covariance, 4u * 256 * 256);
  EXPECT_EQ(covariance + predictionBytes(), heldBytes(r->publication()));
  EXPECT_EQ(covariance,
            declaredPublicationBytes(info, r->params(), ui::rtw::covariancePanelKeys()));
  EXPECT_EQ(r->publication().images.size(), 1u);
  EXPECT_TRUE(r->publication().images.count("importance"));
  EXPECT_EQ(r->publication().curves.size(), 1u);
  EXPECT_EQ(r->publication().curves.count("prediction.curve")
                ? r->publication().curves.at("prediction.curve").size()
                : 0u,
            37u);
  EXPECT_TRUE(r->publication().numbers.count("e_x"));
  for (const auto& [key, value] : r->publication().numbers)
    EXPECT_TRUE(ui::rtw::covariancePanelKeys().count(key)) << key << " was not requested";

  // Every panel: both 512^2 shadow maps, the IM, the curves and the whole moment chain.
  const std::uint64_t all = frame(allPanelKeys());
  std::uint64_t chainTexels = 0;
  for (int s = 128;; s = (s + 1) / 2) {
    chainTexels += std::uint64_t(s) * std::uint64_t(s);
    if (s == 1) break;
  }
  const std::uint64_t expected = 4u * (2 * 512 * 512        // shadow map + unwarped contrast map
                                       + 256 * 256          // importance
                                       + 4 * 256            // importance.{x,y}[.blurred]
                                       + 2 * 257            // warp.{x,y}
                                       + 6 * chainTexels);  // moment.<c>.<level>
  EXPECT_EQ(all, expected);
  EXPECT_EQ(all + predictionBytes(), heldBytes(r->publication()));
  EXPECT_EQ(all, declaredPublicationBytes(info, r->params(), allPanelKeys()));
  EXPECT_GT(all, 8 * covariance);

  // Nothing requested: nothing read, and the panel-only work is gone from memory().
  EXPECT_EQ(frame({}), 0u);
  for (const ResourceInfo& res : r->stats().memory.resources)
    EXPECT_EQ(res.name.find("while a panel"), std::string::npos) << res.name;

  // "*" reads every declared key: the declared total for everything.
  const std::uint64_t everything = frame({"*"});
  EXPECT_EQ(everything, declaredPublicationBytes(info, r->params(), {"*"}));
  // + the two collapsed 1D maps (256 floats each) read for importance.halfmass.x and .y,
  // which the publication holds as two numbers.
  EXPECT_EQ(everything + predictionBytes(), heldBytes(r->publication()) + 2 * 4 * 256);
  test::expectNoGlErrors(*r);
}

TEST(Publication, EveryPublishedKeyIsDeclaredAndEveryPassIsTimed) {
  for (const TechniqueInfo& info : Renderer::techniques()) {
    SCOPED_TRACE(info.id);
    // A technique without directional lights (cube) on a point-lit scene.
    const bool directional = !checkLightSupport(info, LightType::Directional);
    auto r = test::makeRenderer(directional ? "diagonal" : "omni-room", info.id);
    ASSERT_TRUE(r);
    // Small budgets on llvmpipe, for the keys the technique declares (the virtual maps have
    // tiles instead of one resolution; rmsm's pool is pool.pages of page.size²).
    for (const auto& [key, value] : {std::pair{"resolution", 256},
                                     {"tiles", 2},
                                     {"tile.resolution", 256},
                                     {"fvsm.max_texture", 256},
                                     {"fvsm.fallback.resolution", 256}}) {
      if (std::any_of(info.params.begin(), info.params.end(),
                      [&](const ParamDecl& d) { return d.key == key; })) {
        ASSERT_FALSE(r->params().set(key, value));
      }
    }
    r->requestPublications({"*"});
    for (int f = 0; f < 2; ++f) ASSERT_FALSE(r->renderFrame(160, 90, 0));
    const Publication& pub = r->publication();
    std::vector<std::string> keys;
    for (const auto& [k, v] : pub.images) keys.push_back(k);
    for (const auto& [k, v] : pub.curves) keys.push_back(k);
    for (const auto& [k, v] : pub.numbers) keys.push_back(k);
    EXPECT_FALSE(keys.empty());
    for (const std::string& k : keys)
      EXPECT_TRUE(findFramePublication(info, k)) << k << " undeclared";
    EXPECT_EQ(r->stats().publicationBytes, declaredPublicationBytes(info, r->params(), {"*"}));
    // The declared passes are the ones this frame opened, in the same order.
    std::vector<std::string> declared;
    for (const PassDecl& p : framePassDecls(info, r->params())) declared.push_back(p.id);
    test::expectDeclaredPassesOpened(r->stats(), declared);
    test::expectNoGlErrors(*r);
  }
}

// A map larger than kMaxPublishedImageSide per side is published as a nearest-sampled view of
// at most that (a panel of a 16384² map read back 1 GiB, the GUI took 4.6 GB): the image says
// the map's own size, the bytes read are the view's and match the declared cost, and the view
// holds the map's depths (the same range as the map at its published size).
TEST(Publication, LargeMapsArePublishedDownsampled) {
  EXPECT_EQ(publishedImageSize(2048, 2048), std::make_pair(2048, 2048));
  EXPECT_EQ(publishedImageSize(4096, 4096), std::make_pair(2048, 2048));
  EXPECT_EQ(publishedImageSize(16384, 16384), std::make_pair(2048, 2048));
  EXPECT_EQ(publishedImageSize(6000, 100), std::make_pair(2000, 34));
  EXPECT_EQ(publishedImageBytes(16384, 16384), 4ull * 2048 * 2048);

  for (const char* technique : {"uniform", "cascades"}) {
    SCOPED_TRACE(technique);
    auto r = test::makeRenderer("plane-box", technique);
    ASSERT_TRUE(r);
    const TechniqueInfo& info = *Renderer::findTechnique(technique);
    const std::set<std::string> keys{technique == std::string("uniform") ? "shadow map"
                                                                         : "partition.*.map"};
    ASSERT_FALSE(r->params().set("resolution", 2048));
    r->requestPublications(keys);
    ASSERT_FALSE(r->renderFrame(160, 90, 0));
    std::vector<std::pair<float, float>> fullRange;  // per map: min and max depth below 1
    for (const auto& [key, image] : r->publication().images) {
      EXPECT_EQ(image.width, 2048);
      EXPECT_EQ(image.sourceWidth, 0);
      float lo = 1, hi = 0;
      for (float v : image.values)
        if (v < 1) lo = std::min(lo, v), hi = std::max(hi, v);
      fullRange.push_back({lo, hi});
    }

    ASSERT_FALSE(r->params().set("resolution", 8192));
    ASSERT_FALSE(r->renderFrame(160, 90, 0));
    const Publication& pub = r->publication();
    ASSERT_EQ(pub.images.size(), fullRange.size());
    std::size_t i = 0;
    for (const auto& [key, image] : pub.images) {
      SCOPED_TRACE(key);
      EXPECT_EQ(image.width, 2048);
      EXPECT_EQ(image.height, 2048);
      EXPECT_EQ(image.sourceWidth, 8192);
      EXPECT_EQ(image.sourceHeight, 8192);
      float lo = 1, hi = 0;
      for (float v : image.values)
        if (v < 1) lo = std::min(lo, v), hi = std::max(hi, v);
      EXPECT_NEAR(lo, fullRange[i].first, 2e-3f);  // the same scene seen at the same depths
      EXPECT_NEAR(hi, fullRange[i].second, 2e-3f);
      ++i;
    }
    EXPECT_EQ(r->stats().publicationBytes, heldBytes(pub));
    EXPECT_EQ(r->stats().publicationBytes, declaredPublicationBytes(info, r->params(), keys));
    EXPECT_EQ(r->stats().publicationBytes, 4ull * 2048 * 2048 * pub.images.size());
    test::expectNoGlErrors(*r);
  }
}

}  // namespace
}  // namespace sl
