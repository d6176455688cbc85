// Where the straight bands of RTW's aliasing overlay come from. RTW's warp is separable: a
// light-space column (row) gets the texel density its most important texel asks for (the 1D
// maps are maxima over the importance map's columns and rows, Rosen 2012). A steep face under
// a high sun has a large orientation term (cos theta_eye / cos theta_light), so its column and
// row are widened all the way across the map and the ground along them is oversampled: the
// blue bands. Changing that cause alone (importance.orientation = off) takes most of them away.
#include <algorithm>
#include <cmath>

#include "GlTestEnv.h"

namespace sl {
namespace {

/// How far the ground's m dips below its row, on average, in octaves: over the ground's pixels
/// (normal within 8 degrees of up), max(0, -log2(m / the median m of the ground in the same
/// image row)). The row's median follows the distance falloff; a band is a strip below it.
double groundDipOctaves(const FrameReadback& f) {
  double dip = 0.0;
  std::size_t ground = 0;
  std::vector<float> row;
  for (int y = 0; y < f.height; ++y) {
    row.clear();
    for (int x = 0; x < f.width; ++x) {
      const std::size_t i = std::size_t(y) * f.width + x;
      if (f.positions[i].w > 0.5f && f.normals[i].y > 0.99f && f.aliasing[i] > 0.0f)
        row.push_back(f.aliasing[i]);
    }
    if (row.size() < 16) continue;
    std::vector<float> sorted = row;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    const double median = sorted[sorted.size() / 2];
    for (float m : row) dip += std::max(0.0, -std::log2(double(m) / median));
    ground += row.size();
  }
  return ground ? dip / double(ground) : 0.0;
}

/// Peak over median of a blurred 1D importance map: how far its most important column (row)
/// stands above a typical one.
double peakOverMedian(const std::vector<float>& curve) {
  std::vector<float> s = curve;
  std::nth_element(s.begin(), s.begin() + s.size() / 2, s.end());
  return double(*std::max_element(curve.begin(), curve.end())) / double(s[s.size() / 2]);
}

TEST(RtwBands, TheOrientationTermWidensWholeRowsAndColumnsOfTheGround) {
  // The default scene's steep faces under the sun (pergola, posts, monolith): the only change
  // is the orientation term. (Elsewhere the eye term makes bands too: on `diagonal` a near
  // object's row stands 13x above the median with the orientation term off.)
  for (const char* scene : {"default"}) {
    double dip[2] = {}, peak[2] = {};
    for (int on = 0; on < 2; ++on) {
      SCOPED_TRACE(std::string(scene) + (on ? ", orientation on" : ", orientation off"));
      auto r = test::makeRenderer(scene, "rtw-backward");
      ASSERT_TRUE(r);
      ASSERT_FALSE(r->params().setFromString("importance.orientation", on ? "on" : "off"));
      r->requestPublications({"importance.x.blurred", "importance.y.blurred"});
      for (int frame = 0; frame < 2; ++frame) ASSERT_FALSE(r->renderFrame(480, 270, 0));
      dip[on] = groundDipOctaves(r->readback());
      const Publication& pub = r->publication();
      peak[on] = std::max(peakOverMedian(pub.curves.at("importance.x.blurred")),
                          peakOverMedian(pub.curves.at("importance.y.blurred")));
    }
    SCOPED_TRACE(scene);
    // The cause: with the term, a few columns (rows) stand far above the rest of the map.
    EXPECT_GT(peak[1], 2.0 * peak[0])
        << "1D importance peak/median " << peak[1] << " on, " << peak[0] << " off";
    // The effect: the ground dips below its row where those columns cross it.
    EXPECT_GT(dip[1], 2.0 * dip[0])
        << "ground dip " << dip[1] << " octaves on, " << dip[0] << " off";
  }
}

}  // namespace
}  // namespace sl
