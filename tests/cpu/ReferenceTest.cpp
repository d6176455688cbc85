// The exact ray-traced reference against analytic answers: a 2x2 m square 1 m above a
// 20x20 m ground casts the square translated by -h * L.xz / L.y; alpha-masked casters
// cast their alpha texture; evaluate() agrees with isLit() pixel for pixel.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <vector>

#include "metrics/ErrorMetrics.h"
#include "metrics/ShadowReference.h"

namespace sl {
namespace {

constexpr float kPi = 3.14159265358979f;

/// Unit vector towards a light at `elevationDeg` above the horizon and `azimuthDeg` from
/// +z towards +x.
glm::vec3 lightDir(float elevationDeg, float azimuthDeg) {
  const float el = elevationDeg * kPi / 180.0f, az = azimuthDeg * kPi / 180.0f;
  return {std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)};
}

/// A horizontal quad at height y over [x0, x1] x [z0, z1], counter-clockwise seen from
/// above, with u along x (0..uvScale) and v along z (0..uvScale).
MeshPrimitive horizontalQuad(const std::string& name, float x0, float x1, float z0, float z1,
                             float y, int material, float uvScale = 1.0f) {
  MeshPrimitive p;
  p.name = name;
  p.positions = {{x0, y, z0}, {x0, y, z1}, {x1, y, z1}, {x1, y, z0}};
  p.normals.assign(4, glm::vec3(0, 1, 0));
  p.uvs = {{0, 0}, {0, uvScale}, {uvScale, uvScale}, {uvScale, 0}};
  p.indices = {0, 1, 2, 0, 2, 3};
  p.material = material;
  return p;
}

// The test scene: ground 20x20 m at y = 0, occluder 2x2 m at y = 1 (off-centre on purpose).
constexpr float kHalfGround = 10.0f;
constexpr float kOccX0 = -0.3f, kOccX1 = 1.7f, kOccZ0 = -1.4f, kOccZ1 = 0.6f, kOccY = 1.0f;

Scene groundAndSquare(int occluderMaterial = -1) {
  Scene s;
  s.name = "ground-and-square";
  s.primitives.push_back(
      horizontalQuad("ground", -kHalfGround, kHalfGround, -kHalfGround, kHalfGround, 0, -1));
  s.primitives.push_back(
      horizontalQuad("square", kOccX0, kOccX1, kOccZ0, kOccZ1, kOccY, occluderMaterial));
  return s;
}

/// Where the ray from ground point p towards the light crosses the occluder's plane.
glm::vec2 hitOnOccluderPlane(const glm::vec3& p, const glm::vec3& l) {
  const glm::vec3 q = p + l * ((kOccY - p.y) / l.y);
  return {q.x, q.z};
}

/// Distance (metres, in the occluder plane) from q to the square's border lines.
float distanceToSquareBorder(glm::vec2 q) {
  return std::min({std::abs(q.x - kOccX0), std::abs(q.x - kOccX1), std::abs(q.y - kOccZ0),
                   std::abs(q.y - kOccZ1)});
}

bool insideSquare(glm::vec2 q) {
  return q.x > kOccX0 && q.x < kOccX1 && q.y > kOccZ0 && q.y < kOccZ1;
}

TEST(ShadowReference, SquareOccluderMatchesAnalyticShadow) {
  const ShadowReference ref(groundAndSquare());
  EXPECT_EQ(ref.triangleCount(), 4u);
  // 1e-5 of the 28 m diagonal: the origin offset shifts the shadow by < 1 mm at 30 deg.
  EXPECT_LT(ref.normalOffsetM() / std::tan(30.0f * kPi / 180.0f), 1e-3f);
  const glm::vec3 up(0, 1, 0);
  for (float elevation : {30.0f, 45.0f, 60.0f, 80.0f}) {
    for (float azimuth : {0.0f, 35.0f, 110.0f, 200.0f, 290.0f}) {
      const glm::vec3 l = lightDir(elevation, azimuth);
      int checked = 0, shadowed = 0, wrong = 0;
      for (int iz = 0; iz < 200; ++iz) {
        for (int ix = 0; ix < 200; ++ix) {
          // A grid with an irrational offset so samples do not line up with the edges.
          const glm::vec3 p(-9.95f + 0.1f * ix + 0.0123f, 0.0f, -9.95f + 0.1f * iz + 0.0071f);
          const glm::vec2 q = hitOnOccluderPlane(p, l);
          if (distanceToSquareBorder(q) <= 1e-3f) continue;  // within 1 mm of the border
          const bool expectLit = !insideSquare(q);
          const bool lit = ref.isLit(p, up, l);
          ++checked;
          shadowed += !expectLit;
          if (lit != expectLit && ++wrong <= 5)
            ADD_FAILURE() << "elevation " << elevation << " azimuth " << azimuth << " point ("
                          << p.x << ", " << p.z << "): isLit " << lit << ", analytic " << expectLit;
        }
      }
      EXPECT_EQ(wrong, 0) << "elevation " << elevation << " azimuth " << azimuth;
      EXPECT_GT(checked, 39000);
      // The shadow's area is the square's 4 m^2: about 400 samples of 0.01 m^2.
      EXPECT_NEAR(shadowed, 400, 60) << "elevation " << elevation << " azimuth " << azimuth;
    }
  }
}

TEST(ShadowReference, SamplesCloseToTheShadowBorder) {
  // Points 2 mm either side of the analytic shadow border (1 mm margin, 0.28 mm offset).
  const ShadowReference ref(groundAndSquare());
  const glm::vec3 up(0, 1, 0);
  for (float elevation : {30.0f, 55.0f, 80.0f}) {
    const glm::vec3 l = lightDir(elevation, 0.0f);  // shadow shifted towards -z
    const float shift = kOccY / l.y;
    const float zEdge = kOccZ0 - l.z * shift;  // shadow of the square's z0 edge
    const float x = 0.5f * (kOccX0 + kOccX1);
    EXPECT_TRUE(ref.isLit({x, 0, zEdge - 0.002f}, up, l)) << elevation;
    EXPECT_FALSE(ref.isLit({x, 0, zEdge + 0.002f}, up, l)) << elevation;
  }
}

TEST(ShadowReference, SceneFarFromTheOriginKeepsItsShadowBorders) {
  // The same scene 5e4 m from the origin (float spacing 3.9 mm there). The self-shadowing
  // offset is four spacings (1.6 cm), not a share of the distance from the origin (which
  // lifted every ray by 0.7 m and moved the border by as much): points 5 cm either side of
  // the analytic border answer as at the origin.
  const glm::vec3 shift(5e4f, 0.0f, 5e4f);
  Scene far = groundAndSquare();
  for (MeshPrimitive& prim : far.primitives)
    for (glm::vec3& v : prim.positions) v += shift;
  const ShadowReference ref(far);
  EXPECT_LT(ref.normalOffsetM(), 1e-3f);  // the scene's own share: its diagonal
  const glm::vec3 up(0, 1, 0);
  for (float elevation : {45.0f, 60.0f, 80.0f}) {
    const glm::vec3 l = lightDir(elevation, 0.0f);
    const float zEdge = kOccZ0 - l.z * (kOccY / l.y);
    const float x = 0.5f * (kOccX0 + kOccX1);
    EXPECT_TRUE(ref.isLit(shift + glm::vec3(x, 0, zEdge - 0.05f), up, l)) << elevation;
    EXPECT_FALSE(ref.isLit(shift + glm::vec3(x, 0, zEdge + 0.05f), up, l)) << elevation;
    // Far from any occluder: lit (no self-shadowing at 3.9 mm precision).
    EXPECT_TRUE(ref.isLit(shift + glm::vec3(-8.0f, 0, 8.0f), up, l)) << elevation;
  }
}

// ---- positional lights: rays end at the light ---------------------------------------------

/// Centred occluder for the positional tests: side kSide at height kH over the ground.
constexpr float kSide = 2.0f, kH = 1.0f;

Scene groundAndCentredSquare() {
  Scene s;
  s.primitives.push_back(
      horizontalQuad("ground", -kHalfGround, kHalfGround, -kHalfGround, kHalfGround, 0, -1));
  s.primitives.push_back(
      horizontalQuad("square", -0.5f * kSide, 0.5f * kSide, -0.5f * kSide, 0.5f * kSide, kH, -1));
  return s;
}

TEST(ShadowReference, PointLightCastsTheScaledSquare) {
  // A point light at height H over the square's centre: the shadow is a square of side
  // s H / (H - h) (similar triangles). Ground samples every 1 cm (a pixel's footprint),
  // those within one footprint of the analytic edge skipped.
  const ShadowReference ref(groundAndCentredSquare());
  for (float H : {2.5f, 4.0f, 7.0f}) {
    const Light light = Light::point({0, H, 0});
    const float half = 0.5f * kSide * H / (H - kH);
    std::vector<glm::vec4> pos, nrm;
    for (int i = -300; i <= 300; ++i)
      for (int j = -300; j <= 300; j += 7) {
        pos.emplace_back(0.01f * float(i), 0.0f, 0.01f * float(j), 1.0f);
        nrm.emplace_back(0, 1, 0, 0);
      }
    std::vector<std::uint8_t> mask;
    ref.evaluate(pos, nrm, light, mask);
    int checked = 0, wrong = 0, shadowed = 0;
    for (std::size_t k = 0; k < pos.size(); ++k) {
      const float edge = std::max(std::abs(pos[k].x), std::abs(pos[k].z));
      if (std::abs(edge - half) < 0.01f) continue;
      ++checked;
      const bool analyticLit = edge > half;
      if (analyticLit != (mask[k] == kMaskLit)) ++wrong;
      if (mask[k] == kMaskShadowed) ++shadowed;
      EXPECT_EQ(mask[k] == kMaskLit, ref.isLit(glm::vec3(pos[k]), {0, 1, 0}, light));
    }
    EXPECT_EQ(wrong, 0) << "H " << H;
    EXPECT_GT(shadowed, 1000) << "H " << H;
    EXPECT_GT(checked, 20000);
    // The shadow's side along x through the centre, measured on the mask: s H / (H - h).
    EXPECT_FALSE(ref.isLit({half - 0.005f, 0, 0}, {0, 1, 0}, light)) << H;
    EXPECT_TRUE(ref.isLit({half + 0.005f, 0, 0}, {0, 1, 0}, light)) << H;
  }
}

TEST(ShadowReference, SpotConeAndRangeAreNotLit) {
  const ShadowReference ref(groundAndCentredSquare());
  const glm::vec3 up(0, 1, 0);
  // Straight down from 5 m, 45 degree cone: the lit disc has radius 5 m on the ground.
  const Light spot = Light::spot({0, 5, 0}, {0, -1, 0}, 45.0f);
  EXPECT_FALSE(ref.isLit({0, 0, 0}, up, spot));     // under the square
  EXPECT_TRUE(ref.isLit({4.9f, 0, 0}, up, spot));   // in the cone, unoccluded
  EXPECT_FALSE(ref.isLit({5.1f, 0, 0}, up, spot));  // outside the cone, unoccluded
  Light ranged = spot;
  ranged.rangeM = 6.0f;  // reaches sqrt(25 + r^2) <= 6: r <= 3.32 m
  EXPECT_TRUE(ref.isLit({3.2f, 0, 0}, up, ranged));
  EXPECT_FALSE(ref.isLit({3.5f, 0, 0}, up, ranged));
  EXPECT_FALSE(ref.isLit({3.5f, 0, 0}, up, Light::point({0, 5, 0}, 6.0f)));
  EXPECT_TRUE(ref.isLit({3.5f, 0, 0}, up, Light::point({0, 5, 0})));
  // Below the light but facing up towards it from above the light's height: facing away.
  EXPECT_FALSE(ref.isLit({2, 6, 0}, up, Light::point({0, 5, 0})));
  // An invalid light lights nothing.
  EXPECT_FALSE(ref.isLit({3.5f, 0, 0}, up, Light::point({0, 5, 0}, -1.0f)));
}

TEST(ShadowReference, OccludersBeyondThePositionalLightCastNothing) {
  // The square at 1 m, the light at 0.5 m under it: rays stop at the light, so the square
  // (beyond the light) shadows nothing; a directional light from above is blocked by it.
  const ShadowReference ref(groundAndCentredSquare());
  const glm::vec3 up(0, 1, 0);
  EXPECT_TRUE(ref.isLit({0.1f, 0, 0.1f}, up, Light::point({0, 0.5f, 0})));
  EXPECT_FALSE(ref.isLit({0.1f, 0, 0.1f}, up, Light::directional(0, 90)));
  std::vector<glm::vec4> pos = {{0.1f, 0, 0.1f, 1}, {0, 0.5f, 0, 1}};  // the 2nd at the light
  std::vector<glm::vec4> nrm = {{0, 1, 0, 0}, {0, 1, 0, 0}};
  std::vector<std::uint8_t> mask;
  ref.evaluate(pos, nrm, Light::point({0, 0.5f, 0}), mask);
  EXPECT_EQ(mask[0], kMaskLit);
  EXPECT_EQ(mask[1], kMaskLit);
}

TEST(ShadowReference, FacingAwayIsUnlitAndNoSelfShadowing) {
  const ShadowReference ref(groundAndSquare());
  const glm::vec3 l = lightDir(50.0f, 35.0f);
  const glm::vec3 litPoint(-8.0f, 0.0f, -8.0f);
  EXPECT_TRUE(ref.isLit(litPoint, {0, 1, 0}, l));
  EXPECT_TRUE(ref.isLit(litPoint, {0, 5, 0}, l));  // normals need not be unit
  EXPECT_FALSE(ref.isLit(litPoint, {0, -1, 0}, l));
  EXPECT_FALSE(ref.isLit(litPoint, -l, l));
  EXPECT_FALSE(ref.isLit(litPoint, glm::normalize(glm::cross(l, glm::vec3(0, 1, 0))), l));
  EXPECT_FALSE(ref.isLit(litPoint, {0, 1, 0}, glm::vec3(0.0f)));  // no light direction
  // The occluder's own surfaces: the top is lit, the underside faces away.
  const glm::vec3 top(0.5f * (kOccX0 + kOccX1), kOccY, 0.5f * (kOccZ0 + kOccZ1));
  EXPECT_TRUE(ref.isLit(top, {0, 1, 0}, l));
  EXPECT_FALSE(ref.isLit(top, {0, -1, 0}, l));
  // Grazing light: still no acne on the ground far from the occluder.
  const glm::vec3 grazing = lightDir(2.0f, 200.0f);
  EXPECT_TRUE(ref.isLit({9.0f, 0.0f, 9.0f}, {0, 1, 0}, grazing));
}

TEST(ShadowReference, EmptySceneIsLitWhenFacingTheLight) {
  const ShadowReference ref(Scene{});
  EXPECT_EQ(ref.triangleCount(), 0u);
  const glm::vec3 l = lightDir(40.0f, 10.0f);
  EXPECT_TRUE(ref.isLit({0, 0, 0}, {0, 1, 0}, l));
  EXPECT_FALSE(ref.isLit({0, 0, 0}, {0, -1, 0}, l));
  std::vector<glm::vec4> pos{{0, 0, 0, 1}, {1, 0, 0, 0}, {2, 0, 0, 1}};
  std::vector<glm::vec4> nrm{{0, 1, 0, 0}, {0, 1, 0, 0}, {0, -1, 0, 0}};
  std::vector<std::uint8_t> out;
  ref.evaluate(pos, nrm, l, out);
  EXPECT_EQ(out, (std::vector<std::uint8_t>{kMaskLit, kMaskUncovered, kMaskShadowed}));
}

TEST(ShadowReference, BadIndicesThrowNamingThePrimitive) {
  Scene s = groundAndSquare();
  s.primitives[1].indices.back() = 4;
  try {
    ShadowReference ref(s);
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("square"), std::string::npos) << e.what();
  }
}

/// A checkerboard alpha texture: texel (x, y) is opaque when x + y is even.
SceneImage checkerAlpha(int w, int h) {
  SceneImage img;
  img.name = "checker";
  img.width = w;
  img.height = h;
  img.rgba.resize(std::size_t(w) * h * 4, 255);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) img.rgba[4 * (std::size_t(y) * w + x) + 3] = (x + y) % 2 ? 0 : 255;
  return img;
}

struct CheckerCase {
  int texW, texH;
  float uvScale;  ///< uv runs 0..uvScale across the square (> 1 exercises REPEAT)
};

TEST(ShadowReference, AlphaMaskedCheckerboardCastsCheckerboardShadow) {
  for (const CheckerCase& c : {CheckerCase{4, 2, 1.0f}, CheckerCase{2, 2, 2.0f}}) {
    Scene s;
    s.images.push_back(checkerAlpha(c.texW, c.texH));
    Material m;
    m.name = "leaves";
    m.alphaMode = AlphaMode::Mask;
    m.alphaCutoff = 0.5f;
    m.baseColorTexture = 0;
    s.materials.push_back(m);
    s.primitives.push_back(
        horizontalQuad("ground", -kHalfGround, kHalfGround, -kHalfGround, kHalfGround, 0, -1));
    s.primitives.push_back(
        horizontalQuad("square", kOccX0, kOccX1, kOccZ0, kOccZ1, kOccY, 0, c.uvScale));
    const ShadowReference ref(s);
    EXPECT_EQ(ref.alphaTestedTriangles(), 2u);
    for (const glm::vec3& l :
         {glm::vec3(0, 1, 0), lightDir(60.0f, 35.0f), lightDir(35.0f, 250.0f)}) {
      int checked = 0, lit = 0, shadowed = 0, wrong = 0;
      for (int iz = 0; iz < 150; ++iz) {
        for (int ix = 0; ix < 150; ++ix) {
          // Sample the ground under (the shadow of) the square.
          const glm::vec2 target(kOccX0 - 0.2f + 2.4f * (ix + 0.5f) / 150.0f,
                                 kOccZ0 - 0.2f + 2.4f * (iz + 0.5f) / 150.0f);
          const glm::vec3 p = glm::vec3(target.x, kOccY, target.y) - l * (kOccY / l.y);
          const glm::vec2 q = hitOnOccluderPlane(p, l);
          if (distanceToSquareBorder(q) <= 1e-3f) continue;
          bool expectLit = true;
          if (insideSquare(q)) {
            const float tx = (q.x - kOccX0) / (kOccX1 - kOccX0) * c.uvScale * c.texW;
            const float ty = (q.y - kOccZ0) / (kOccZ1 - kOccZ0) * c.uvScale * c.texH;
            const float fx = tx - std::floor(tx), fy = ty - std::floor(ty);
            if (std::min({fx, 1 - fx, fy, 1 - fy}) < 0.05f) continue;  // texel borders
            const int x = int(std::floor(tx)) % c.texW, y = int(std::floor(ty)) % c.texH;
            expectLit = (x + y) % 2 != 0;  // transparent texel
          }
          const bool got = ref.isLit(p, {0, 1, 0}, l);
          ++checked;
          lit += got;
          shadowed += !got;
          if (got != expectLit && ++wrong <= 5)
            ADD_FAILURE() << "texture " << c.texW << "x" << c.texH << " uv scale " << c.uvScale
                          << " light (" << l.x << ", " << l.y << ", " << l.z << ") at (" << q.x
                          << ", " << q.y << "): isLit " << got << ", expected " << expectLit;
        }
      }
      EXPECT_EQ(wrong, 0);
      EXPECT_GT(checked, 10000);
      EXPECT_GT(shadowed, checked / 4);  // half the square casts
      EXPECT_GT(lit, checked / 4);
    }
  }
}

TEST(ShadowReference, AlphaModesAndFactor) {
  const glm::vec3 l(0, 1, 0);
  const glm::vec3 up(0, 1, 0);
  const float cx = kOccX0 + 0.25f, cz = kOccZ0 + 0.25f;  // under texel (0, 0) of a 4x4 map
  const float tx = kOccX0 + 0.75f;                       // under texel (1, 0): transparent
  auto make = [&](AlphaMode mode, float factorAlpha, bool texture) {
    Scene s = groundAndSquare(0);
    s.images.push_back(checkerAlpha(4, 4));
    Material m;
    m.alphaMode = mode;
    m.baseColorFactor.a = factorAlpha;
    m.baseColorTexture = texture ? 0 : -1;
    s.materials.push_back(m);
    return s;
  };
  {  // Mask: the checker decides.
    const ShadowReference ref(make(AlphaMode::Mask, 1.0f, true));
    EXPECT_FALSE(ref.isLit({cx, 0, cz}, up, l));
    EXPECT_TRUE(ref.isLit({tx, 0, cz}, up, l));
  }
  {  // Mask with factor alpha 0.4 < cutoff: nothing casts.
    const ShadowReference ref(make(AlphaMode::Mask, 0.4f, true));
    EXPECT_TRUE(ref.isLit({cx, 0, cz}, up, l));
    EXPECT_TRUE(ref.isLit({tx, 0, cz}, up, l));
    EXPECT_EQ(ref.triangleCount(), 2u);  // only the ground
  }
  {  // Mask without texture, factor alpha above the cutoff: opaque, no filter.
    const ShadowReference ref(make(AlphaMode::Mask, 0.6f, false));
    EXPECT_FALSE(ref.isLit({tx, 0, cz}, up, l));
    EXPECT_EQ(ref.alphaTestedTriangles(), 0u);
  }
  for (AlphaMode mode : {AlphaMode::Opaque, AlphaMode::Blend}) {  // alpha ignored
    const ShadowReference ref(make(mode, 0.1f, true));
    EXPECT_FALSE(ref.isLit({cx, 0, cz}, up, l));
    EXPECT_FALSE(ref.isLit({tx, 0, cz}, up, l));
  }
}

/// Random frame: ground points, occluder points, uncovered pixels, random normals.
void randomFrame(std::size_t n, std::uint32_t seed, std::vector<glm::vec4>& pos,
                 std::vector<glm::vec4>& nrm) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u01(0.0f, 1.0f);
  pos.resize(n);
  nrm.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const float r = u01(rng);
    glm::vec3 p(-5.0f + 10.0f * u01(rng), 0.0f, -5.0f + 10.0f * u01(rng));
    glm::vec3 normal(0, 1, 0);
    if (r < 0.1f) {
      p = glm::vec3(kOccX0 + 2 * u01(rng), kOccY, kOccZ0 + 2 * u01(rng));  // on the square
    } else if (r < 0.2f) {
      normal = glm::vec3(u01(rng) - 0.5f, u01(rng) - 0.5f, u01(rng) - 0.5f);  // any direction
    }
    pos[i] = glm::vec4(p, r > 0.9f ? 0.0f : 1.0f);  // 10 % not covered
    nrm[i] = glm::vec4(normal, 0.0f);
  }
}

TEST(ShadowReference, EvaluateEqualsIsLitPerPixel) {
  Scene s = groundAndSquare(0);
  s.images.push_back(checkerAlpha(8, 8));
  Material m;
  m.alphaMode = AlphaMode::Mask;
  m.baseColorTexture = 0;
  s.materials.push_back(m);
  const ShadowReference ref(s);
  std::vector<glm::vec4> pos, nrm;
  randomFrame(160 * 120, 7, pos, nrm);
  for (const glm::vec3& l : {lightDir(45.0f, 30.0f), lightDir(75.0f, 300.0f)}) {
    std::vector<std::uint8_t> out;
    ref.evaluate(pos, nrm, l, out);
    ASSERT_EQ(out.size(), pos.size());
    std::size_t lit = 0, shadowed = 0, uncovered = 0;
    for (std::size_t i = 0; i < pos.size(); ++i) {
      const std::uint8_t expected =
          pos[i].w > 0 ? (ref.isLit(pos[i], nrm[i], l) ? kMaskLit : kMaskShadowed) : kMaskUncovered;
      ASSERT_EQ(out[i], expected) << "pixel " << i;
      lit += out[i] == kMaskLit;
      shadowed += out[i] == kMaskShadowed;
      uncovered += out[i] == kMaskUncovered;
    }
    EXPECT_GT(lit, 0u);
    EXPECT_GT(shadowed, 0u);
    EXPECT_GT(uncovered, 0u);
  }
  std::vector<std::uint8_t> out;
  EXPECT_THROW(ref.evaluate(pos, std::span(nrm).first(10), {0, 1, 0}, out), std::invalid_argument);
  ref.evaluate({}, {}, {0, 1, 0}, out);
  EXPECT_TRUE(out.empty());
}

Scene boxField();

TEST(ShadowReference, EvaluateEqualsIsLitOnCoherentFrame) {
  // Row-major ground points (as a G-buffer gives them): Embree's coherent stream path.
  const ShadowReference ref(boxField());
  constexpr int kSide = 200;
  std::vector<glm::vec4> pos(std::size_t(kSide) * kSide), nrm(pos.size(), {0, 1, 0, 0});
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x)
      pos[std::size_t(y) * kSide + x] =
          glm::vec4(-9.9f + 19.8f * x / kSide, 0.0f, -9.9f + 19.8f * y / kSide, 1.0f);
  const glm::vec3 l = lightDir(35.0f, 40.0f);
  std::vector<std::uint8_t> out;
  ref.evaluate(pos, nrm, l, out);
  std::size_t shadowed = 0;
  for (std::size_t i = 0; i < pos.size(); ++i) {
    ASSERT_EQ(out[i], ref.isLit(pos[i], nrm[i], l) ? kMaskLit : kMaskShadowed) << "pixel " << i;
    shadowed += out[i] == kMaskShadowed;
  }
  EXPECT_GT(shadowed, pos.size() / 10);
  EXPECT_LT(shadowed, pos.size() * 9 / 10);
}

/// About 10k triangles: the ground and 840 random boxes (12 triangles each).
Scene boxField() {
  Scene s;
  s.primitives.push_back(
      horizontalQuad("ground", -kHalfGround, kHalfGround, -kHalfGround, kHalfGround, 0, -1));
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u01(0.0f, 1.0f);
  MeshPrimitive boxes;
  boxes.name = "boxes";
  for (int b = 0; b < 840; ++b) {
    const glm::vec3 lo(-9.5f + 19.0f * u01(rng), 0.0f, -9.5f + 19.0f * u01(rng));
    const glm::vec3 hi =
        lo + glm::vec3(0.1f + 0.3f * u01(rng), 0.2f + 1.5f * u01(rng), 0.1f + 0.3f * u01(rng));
    const auto base = std::uint32_t(boxes.positions.size());
    for (int c = 0; c < 8; ++c)
      boxes.positions.emplace_back(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z);
    const std::uint32_t faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& f : faces)
      for (std::uint32_t k : {f[0], f[1], f[2], f[0], f[2], f[3]})
        boxes.indices.push_back(base + k);
  }
  boxes.normals.assign(boxes.positions.size(), glm::vec3(0, 1, 0));
  s.primitives.push_back(std::move(boxes));
  return s;
}

// Run with --gtest_also_run_disabled_tests --gtest_filter='*Throughput*'.
TEST(ShadowReference, DISABLED_Throughput) {
  const auto t0 = std::chrono::steady_clock::now();
  const ShadowReference ref(boxField());
  const auto t1 = std::chrono::steady_clock::now();
  std::printf("scene: %zu triangles, BVH build %.1f ms\n", ref.triangleCount(),
              std::chrono::duration<double, std::milli>(t1 - t0).count());
  constexpr int kSide = 1024;  // 1M rays from ground points in a camera-like order
  std::vector<glm::vec4> pos(std::size_t(kSide) * kSide), nrm(pos.size(), {0, 1, 0, 0});
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x)
      pos[std::size_t(y) * kSide + x] =
          glm::vec4(-9.99f + 19.98f * x / kSide, 0.0f, -9.99f + 19.98f * y / kSide, 1.0f);
  std::vector<glm::vec4> shuffled = pos;
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(1));
  const glm::vec3 l = lightDir(35.0f, 40.0f);
  std::vector<std::uint8_t> out;
  auto timeIt = [&](const char* label, auto&& fn) {
    fn();  // warm up
    double best = 1e30;
    for (int rep = 0; rep < 3; ++rep) {
      const auto a = std::chrono::steady_clock::now();
      fn();
      best = std::min(best,
                      std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count());
    }
    std::printf("%-40s %8.1f ms  %6.2f Mrays/s\n", label, best * 1e3, pos.size() / best * 1e-6);
  };
  timeIt("evaluate (all threads, streams)", [&] { ref.evaluate(pos, nrm, l, out); });
  std::size_t shadowed = 0;
  for (std::uint8_t v : out) shadowed += v == kMaskShadowed;
  std::printf("shadowed: %.1f %%\n", 100.0 * shadowed / out.size());
  timeIt("evaluate, shuffled pixels", [&] { ref.evaluate(shuffled, nrm, l, out); });
  timeIt("isLit loop (1 thread)", [&] {
    std::size_t lit = 0;
    for (std::size_t i = 0; i < pos.size(); ++i) lit += ref.isLit(pos[i], nrm[i], l);
    out.assign(1, std::uint8_t(lit & 1));
  });
}

}  // namespace
}  // namespace sl
