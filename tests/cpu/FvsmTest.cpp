// algo/fvsm (Giegl & Wimmer 2007): SMTMM entries from hand-made depth neighbourhoods, the tile
// grid's max / histogram / outlier rejection, the max pyramid, the kd-tree traversal with ξ
// and the max texture size, the three texture modes' sizes, overlap and screen rectangles —
// all exact, on grids small enough to work out by hand (the numbers are in the comments).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "algo/fvsm/Fvsm.h"

namespace sl::fvsm {
namespace {

/// An 8 x 8 frame with tan(half fov) = 1: a pixel at eye depth z is 2z / 8 = z / 4 m wide.
EyeDepthView frame8(const std::vector<float>& depth) {
  EyeDepthView v;
  v.width = v.height = 8;
  v.tanHalfFovX = v.tanHalfFovY = 1.0;
  v.eyeDepthM = depth;
  return v;
}

/// SM uv = (x_e, y_e) / 64 m + 0.5: a light looking along the camera's view axis.
glm::dmat4 lightAlongView() {
  glm::dmat4 m(1.0);
  m[0][0] = m[1][1] = 1.0 / 64.0;
  m[3][0] = m[3][1] = 0.5;
  return m;
}

/// SM uv = (−z_e / 64 m, y_e / 64 m + 0.5): a light looking along the camera's x axis,
/// so u measures eye depth.
glm::dmat4 lightAcrossView() {
  glm::dmat4 m(0.0);
  m[2][0] = -1.0 / 64.0;  // u from z_e
  m[1][1] = 1.0 / 64.0;   // v from y_e
  m[3][1] = 0.5;
  m[3][3] = 1.0;
  return m;
}

TEST(FvsmSmtmm, EyePositionIsEquationOne) {
  std::vector<float> d(64, 4.0f);
  const EyeDepthView v = frame8(d);
  EXPECT_EQ(eyePosition(v, {4.0, 4.0}, 2.0), glm::dvec3(0.0, 0.0, -2.0));
  EXPECT_EQ(eyePosition(v, {8.0, 6.0}, 2.0), glm::dvec3(2.0, 1.0, -2.0));
  EXPECT_EQ(eyePosition(v, {0.0, 0.0}, 3.0), glm::dvec3(-3.0, -3.0, -3.0));
}

// Eq. (1) inverts the camera's projection: an eye-space point projected by P to a pixel and
// its depth −z comes back from eyePosition with eyeProjectionOf(P)'s terms, for a centred
// frustum (glm::perspective: tan(fov/2) x aspect, tan(fov/2), no offset) and an off-centre
// one (glm::frustum, b = (r + l) / (r − l)). Double against double: within 1e-12 m.
TEST(FvsmSmtmm, EyePositionInvertsTheProjection) {
  const EyeProjection centred =
      eyeProjectionOf(glm::perspective(glm::radians(60.0), 2.0, 0.1, 50.0));
  EXPECT_NEAR(centred.tanHalfFov.y, std::tan(glm::radians(30.0)), 1e-15);
  EXPECT_NEAR(centred.tanHalfFov.x, 2.0 * std::tan(glm::radians(30.0)), 1e-15);
  EXPECT_EQ(centred.ndcOffset, glm::dvec2(0.0));
  const glm::dmat4 offCentre = glm::frustum(-0.3, 0.5, -0.1, 0.2, 0.25, 40.0);
  const EyeProjection off = eyeProjectionOf(offCentre);
  EXPECT_NEAR(off.ndcOffset.x, 0.2 / 0.8, 1e-15);
  EXPECT_NEAR(off.ndcOffset.y, 0.1 / 0.3, 1e-15);
  std::vector<float> none;
  for (const glm::dmat4& proj :
       {glm::dmat4(glm::perspective(glm::radians(60.0), 2.0, 0.1, 50.0)), offCentre}) {
    EyeDepthView v;
    v.width = 160;
    v.height = 90;
    const EyeProjection t = eyeProjectionOf(proj);
    v.tanHalfFovX = t.tanHalfFov.x;
    v.tanHalfFovY = t.tanHalfFov.y;
    v.ndcOffset = t.ndcOffset;
    v.eyeDepthM = none;
    for (const glm::dvec3 e : {glm::dvec3(0.3, -0.2, -2.0), glm::dvec3(-4.0, 1.5, -17.5),
                               glm::dvec3(0.01, 0.02, -0.3)}) {
      const glm::dvec4 clip = proj * glm::dvec4(e, 1.0);
      const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
      const glm::dvec2 pixel = (ndc + 1.0) * 0.5 * glm::dvec2(v.width, v.height);
      const glm::dvec3 back = eyePosition(v, pixel, -e.z);
      EXPECT_NEAR(back.x, e.x, 1e-12);
      EXPECT_NEAR(back.y, e.y, 1e-12);
      EXPECT_EQ(back.z, e.z);
    }
  }
}

TEST(FvsmSmtmm, QuantisationIsCeilOfMinusLog2) {
  EXPECT_EQ(quantiseNeedLog2(1.0 / 128.0), 7);
  EXPECT_EQ(quantiseNeedLog2(0.01), 7);  // -log2 0.01 = 6.64
  EXPECT_EQ(quantiseNeedLog2(1.0 / 129.0), 8);
  EXPECT_EQ(quantiseNeedLog2(0.5), 1);
  EXPECT_EQ(quantiseNeedLog2(1.0), 0);
  EXPECT_EQ(quantiseNeedLog2(4.0), 0);  // clamped
  EXPECT_EQ(quantiseNeedLog2(0.0), kMaxNeedLog2);
  EXPECT_EQ(quantiseNeedLog2(1e-30), kMaxNeedLog2);
}

TEST(FvsmSmtmm, FlatWallFacingTheLight) {
  // Depth 4 everywhere: pixels are 1 m squares, the footprint's half extent 0.5 m = 1/128 uv.
  std::vector<float> d(64, 4.0f);
  const SmtmmEntry e = smtmmEntry(frame8(d), {3, 3}, lightAlongView());
  ASSERT_TRUE(e.covered);
  // Centre (3.5, 3.5): ndc −0.125, x_e = −0.5 m, u = 0.5 − 0.5 / 64.
  EXPECT_EQ(e.smUv, glm::dvec2(0.5 - 0.5 / 64.0));
  EXPECT_EQ(e.needLog2, glm::ivec2(7, 7));
}

TEST(FvsmSmtmm, DepthSlopeSeenFromTheSide) {
  // z = 4 + column: pixel (3, 3) at z = 7, its x neighbours at 6 and 8 (Δz_x = 1), its y
  // neighbours at 7 (Δz_y = 0). u = z / 64: a.z = −0.5 → Δu = 0.5 / 64 → need 7.
  // v: a.y = ½ (−0.125 · 7.5 + 0.125 · 6.5) = −0.0625, b.y = ½ (0 − (−0.25 · 7)) = 0.875,
  // Δv = 0.9375 / 64 → −log2 = 6.09 → need 7.
  std::vector<float> d(64);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) d[std::size_t(y) * 8 + x] = float(4 + x);
  const SmtmmEntry e = smtmmEntry(frame8(d), {3, 3}, lightAcrossView());
  ASSERT_TRUE(e.covered);
  EXPECT_EQ(e.smUv, glm::dvec2(7.0 / 64.0, 0.5 - 0.125 * 7.0 / 64.0));
  EXPECT_EQ(e.needLog2, glm::ivec2(7, 7));
}

// A plane receiver seen by the 8 x 8 frame: the eye depth of every pixel centre (the ray
// d (ndc tanHalfFov, −1) meets the plane n · (e − e0) = 0), and the exact footprint of pixel
// `pixel`: its four corners' rays meeting the plane.
struct PlaneReceiver {
  glm::dvec3 normal, point;
  double depthAt(const EyeDepthView& v, glm::dvec2 pixel) const {
    const glm::dvec3 dir = eyePosition(v, pixel, 1.0);
    return glm::dot(normal, point) / glm::dot(normal, dir);
  }
  std::vector<float> depthBuffer(const EyeDepthView& v) const {
    std::vector<float> d(std::size_t(v.width) * std::size_t(v.height));
    for (int y = 0; y < v.height; ++y)
      for (int x = 0; x < v.width; ++x)
        d[std::size_t(y) * std::size_t(v.width) + std::size_t(x)] =
            float(depthAt(v, glm::dvec2(x, y) + 0.5));
    return d;
  }
  /// The corners c₋₋, c₋₊, c₊₋, c₊₊ (x first) of the pixel's footprint on the plane.
  std::array<glm::dvec3, 4> footprint(const EyeDepthView& v, glm::ivec2 pixel) const {
    std::array<glm::dvec3, 4> c;
    for (int i = 0; i < 4; ++i) {
      const glm::dvec2 corner = glm::dvec2(pixel) + glm::dvec2(i / 2, i % 2);
      c[std::size_t(i)] = eyePosition(v, corner, depthAt(v, corner));
    }
    return c;
  }
};

/// A light straight above the plane (looking along −normal): SM u along the plane's x
/// direction, v across it, centred on `centre` and scaled per axis so that the exact
/// footprint's half extent (`measure`) is 2^−7.5 uv along both axes: an estimate within a
/// factor √2 of it needs 2^8 texels per axis of the whole map, one off by more does not.
glm::dmat4 lightAbove(const PlaneReceiver& plane, const std::array<glm::dvec3, 4>& exact,
                      glm::dvec3 centre, FootprintMeasure measure) {
  const glm::dvec3 n = glm::normalize(plane.normal);
  const glm::dvec3 u = glm::normalize(glm::dvec3(1, 0, 0) - n * n.x), v = glm::cross(n, u);
  glm::dvec2 sm[4];
  for (int i = 0; i < 4; ++i)
    sm[i] = {glm::dot(u, exact[std::size_t(i)]), glm::dot(v, exact[std::size_t(i)])};
  const glm::dvec2 a = 0.25 * (sm[2] + sm[3] - sm[0] - sm[1]),
                   b = 0.25 * (sm[1] + sm[3] - sm[0] - sm[2]);
  glm::dvec2 half = footprintHalfExtent(a, b, measure);
  if (measure == FootprintMeasure::Box) {
    const glm::dvec2 lo = glm::min(glm::min(sm[0], sm[1]), glm::min(sm[2], sm[3]));
    const glm::dvec2 hi = glm::max(glm::max(sm[0], sm[1]), glm::max(sm[2], sm[3]));
    half = 0.5 * (hi - lo);
  }
  const glm::dvec2 scale = std::exp2(-7.5) / half;
  glm::dmat4 m(0.0);
  for (int k = 0; k < 3; ++k) {
    m[k][0] = scale.x * u[k];
    m[k][1] = scale.y * v[k];
  }
  m[3][0] = 0.5 - scale.x * glm::dot(u, centre);
  m[3][1] = 0.5 - scale.y * glm::dot(v, centre);
  m[3][3] = 1.0;
  return m;
}

// The SMTMM builds the pixel's footprint from the smaller depth step towards its neighbours
// (§4.3) with its sign: a receiver whose depth falls along +x is sheared the other way from
// one whose depth rises. Three planes through (0, 0, −8 m) tilted by atan(1/2) (falling
// along +x, rising along +x, falling along the diagonal x + y), each seen from straight
// above by the light, scaled so that the exact footprint of pixel (3, 3) needs 8 texels per
// axis with a margin of a factor √2 either way: the entry asks for 8 with both measures.
// Measured before the sign was kept: the falling planes' footprints came out about half as
// long along their slope (need 9).
TEST(FvsmSmtmm, TheDepthSlopesSignShearsTheFootprint) {
  const struct {
    const char* name;
    glm::dvec3 normal;
  } planes[] = {{"falling along +x", {-0.5, 0.0, 1.0}},
                {"rising along +x", {0.5, 0.0, 1.0}},
                {"falling along x + y", {-0.5, -0.5, 1.0}}};
  for (const auto& p : planes) {
    for (const FootprintMeasure measure : {FootprintMeasure::Box, FootprintMeasure::Chord}) {
      SCOPED_TRACE(std::string(p.name) + ", " + footprintMeasureName(measure));
      const PlaneReceiver plane{p.normal, {0.0, 0.0, -8.0}};
      std::vector<float> d;
      EyeDepthView view = frame8(d);
      d = plane.depthBuffer(view);
      view.eyeDepthM = d;
      const glm::ivec2 pixel(3, 3);
      const glm::dvec3 centre = eyePosition(view, glm::dvec2(pixel) + 0.5, view.depthAt(3, 3));
      const glm::dmat4 light = lightAbove(plane, plane.footprint(view, pixel), centre, measure);
      const SmtmmEntry e = smtmmEntry(view, pixel, light, measure);
      ASSERT_TRUE(e.covered);
      EXPECT_EQ(e.needLog2, glm::ivec2(8, 8));
    }
  }
}

// Mirroring the frame and the light in x turns a depth falling along +x into one rising
// along +x and changes no need: the entry of pixel (3, 3) on the falling plane equals that
// of pixel (4, 3) on its mirror image (the same rays with x negated), for both measures.
TEST(FvsmSmtmm, MirroringTheFrameChangesNoNeed) {
  const PlaneReceiver falling{{-0.5, 0.0, 1.0}, {0.0, 0.0, -8.0}};
  const PlaneReceiver rising{{0.5, 0.0, 1.0}, {0.0, 0.0, -8.0}};
  std::vector<float> none;
  EyeDepthView view = frame8(none);
  const std::vector<float> dFalling = falling.depthBuffer(view), dRising = rising.depthBuffer(view);
  // A light looking down the plane's slope at 45°: u = (x_e − z_e) / 16 + 1/2, v = y_e / 16
  // + 1/2; its mirror image negates x_e.
  glm::dmat4 light(0.0), mirrored(0.0);
  light[0][0] = 1.0 / 16.0;
  light[2][0] = -1.0 / 16.0;
  light[1][1] = 1.0 / 16.0;
  light[3][0] = 0.5 - 8.0 / 16.0;
  light[3][1] = 0.5;
  light[3][3] = 1.0;
  mirrored = light;
  mirrored[0][0] = -light[0][0];
  for (const FootprintMeasure measure : {FootprintMeasure::Box, FootprintMeasure::Chord}) {
    SCOPED_TRACE(footprintMeasureName(measure));
    view.eyeDepthM = dFalling;
    const SmtmmEntry a = smtmmEntry(view, {3, 3}, light, measure);
    view.eyeDepthM = dRising;
    const SmtmmEntry b = smtmmEntry(view, {4, 3}, mirrored, measure);
    ASSERT_TRUE(a.covered && b.covered);
    EXPECT_NEAR(a.smUv.x, b.smUv.x, 1e-12);
    EXPECT_NEAR(a.smUv.y, b.smUv.y, 1e-12);
    EXPECT_EQ(a.needLog2, b.needLog2);
  }
}

TEST(FvsmSmtmm, FootprintBoxAndChordAlongAnAxisAreEqual) {
  // Half edges (1/4, 0) and (0, 1/2): box = chord = (1/4, 1/2) (det 1/8 over 1/2 and 1/4).
  const glm::dvec2 a(0.25, 0.0), b(0.0, 0.5);
  EXPECT_EQ(footprintHalfExtent(a, b, FootprintMeasure::Box), glm::dvec2(0.25, 0.5));
  EXPECT_EQ(footprintHalfExtent(a, b, FootprintMeasure::Chord), glm::dvec2(0.25, 0.5));
}

TEST(FvsmSmtmm, FootprintChordOfAThinDiagonalFootprint) {
  // Long along the diagonal a = (1, 1) / 4, narrow b = (1, −1) / 64: its box is 1/4 + 1/64
  // along both axes (need 2), its chord through the centre along u: s/4 − t/64 = 0 → s =
  // t/16, u = t/64 + t/64, half length 1/32 (det 1/128 over 1/4) along both axes (need 5).
  const glm::dvec2 a(0.25, 0.25), b(1.0 / 64.0, -1.0 / 64.0);
  EXPECT_EQ(footprintHalfExtent(a, b, FootprintMeasure::Box), glm::dvec2(0.265625));
  EXPECT_EQ(footprintHalfExtent(a, b, FootprintMeasure::Chord), glm::dvec2(1.0 / 32.0));
  EXPECT_EQ(quantiseNeedLog2(0.265625), 2);
  EXPECT_EQ(quantiseNeedLog2(1.0 / 32.0), 5);
}

TEST(FvsmSmtmm, FootprintChordOfAFlatFootprint) {
  // Both edges along u (v components 0): no chord across v, u keeps the box (3/8); along v
  // the footprint has no extent at all (det 0): the cap.
  const glm::dvec2 a(0.25, 0.0), b(0.125, 0.0);
  EXPECT_EQ(footprintHalfExtent(a, b, FootprintMeasure::Chord), glm::dvec2(0.375, 0.0));
  EXPECT_EQ(quantiseNeedLog2(0.0), kMaxNeedLog2);
}

TEST(FvsmSmtmm, ChordEntryOfADiagonalLight) {
  // The slope of DepthSlopeSeenFromTheSide seen through SM axes turned by 45°: u = (y − z) /
  // 96 + 1/2, v = (−y − z) / 96 + 1/2. Eye half edges a = (·, −1/16, −1/2), b = (·, 7/8, 0):
  // SM a' = (7/16, 9/16) / 96, b' = (7/8, −7/8) / 96. Box (21/16, 23/16) / 96: −log2 6.19,
  // 6.06: needs 7, 7; chord: det (7/8) / 96² over (7/8) / 96 = 1/96 along both: −log2 6.58:
  // needs 7, 7 (the entry's a', b' are its corners' differences: the wiring of the measure).
  std::vector<float> d(64);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) d[std::size_t(y) * 8 + x] = float(4 + x);
  glm::dmat4 m(0.0);
  m[1][0] = 1.0 / 96.0;
  m[2][0] = -1.0 / 96.0;
  m[1][1] = -1.0 / 96.0;
  m[2][1] = -1.0 / 96.0;
  m[3][0] = m[3][1] = 0.5;
  m[3][3] = 1.0;
  const SmtmmEntry box = smtmmEntry(frame8(d), {3, 3}, m, FootprintMeasure::Box);
  const SmtmmEntry chord = smtmmEntry(frame8(d), {3, 3}, m, FootprintMeasure::Chord);
  ASSERT_TRUE(box.covered && chord.covered);
  EXPECT_EQ(box.smUv, chord.smUv);
  EXPECT_EQ(box.needLog2, glm::ivec2(7, 7));
  EXPECT_EQ(chord.needLog2, glm::ivec2(7, 7));
}

TEST(FvsmSmtmm, TheSmallerNeighbourStepIsTaken) {
  // Flat at 4 with the light across the view: Δz = 0 collapses the footprint along u (a
  // line seen edge-on): the need is the cap. A depth discontinuity on the right (100 m)
  // does not count while the left neighbour is flat.
  std::vector<float> d(64, 4.0f);
  d[3 * 8 + 4] = 100.0f;
  EXPECT_EQ(smtmmEntry(frame8(d), {3, 3}, lightAcrossView()).needLog2.x, kMaxNeedLog2);
  // Left neighbour at 5: min(|5 − 4|, |100 − 4|) = 1, as on the slope: a.z = −0.5 → 7.
  d[3 * 8 + 2] = 5.0f;
  EXPECT_EQ(smtmmEntry(frame8(d), {3, 3}, lightAcrossView()).needLog2.x, 7);
  // Neighbours without a surface are ignored: only the right one (at 4 + 2 = 6) is left.
  d[3 * 8 + 2] = 0.0f;
  d[3 * 8 + 4] = 6.0f;
  EXPECT_EQ(smtmmEntry(frame8(d), {3, 3}, lightAcrossView()).needLog2.x, 6);  // a.z = −1
}

TEST(FvsmSmtmm, EmptyPixelsAndPointsOutsideTheMapAreNotCovered) {
  std::vector<float> d(64, 4.0f);
  d[0] = 0.0f;
  EXPECT_FALSE(smtmmEntry(frame8(d), {0, 0}, lightAlongView()).covered);
  glm::dmat4 shifted = lightAlongView();
  shifted[3][0] = 0.5 + 3.6 / 64.0;  // x_e = 3.5 m at pixel 7 → u = 0.5 + 7.1 / 64 ≤ 1
  EXPECT_TRUE(smtmmEntry(frame8(d), {7, 3}, shifted).covered);
  shifted[3][0] = 1.0 - 3.4 / 64.0;  // u = 1 + 0.1 / 64 > 1
  EXPECT_FALSE(smtmmEntry(frame8(d), {7, 3}, shifted).covered);
}

TEST(FvsmSmtmm, BuildSamplesTheCentreOfEachBlock) {
  EXPECT_EQ(smtmmSamplePixel({0, 0}, {4, 4}, {8, 8}), glm::ivec2(1, 1));
  EXPECT_EQ(smtmmSamplePixel({3, 2}, {4, 4}, {8, 8}), glm::ivec2(7, 5));
  EXPECT_EQ(smtmmSamplePixel({1, 0}, {3, 1}, {10, 5}), glm::ivec2(5, 2));  // 1.5 · 10 / 3
  std::vector<float> d(64, 4.0f);
  const auto smtmm = buildSmtmm(frame8(d), {4, 4}, lightAlongView());
  ASSERT_EQ(smtmm.size(), 16u);
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      const SmtmmEntry& e = smtmm[std::size_t(j) * 4 + i];
      EXPECT_EQ(e, smtmmEntry(frame8(d), {2 * i + 1, 2 * j + 1}, lightAlongView()));
      EXPECT_EQ(e.needLog2, glm::ivec2(7, 7));
    }
  }
  EXPECT_THROW(buildSmtmm(frame8(std::vector<float>(63, 1.0f)), {4, 4}, lightAlongView()),
               std::invalid_argument);
}

SmtmmEntry entry(double u, double v, int needX, int needY) {
  return {true, {u, v}, {needX, needY}};
}

// The paper's 4-byte entry (fvsm.smtmm.entry = 4-byte): the SM position as the column and row
// of 256 that hold it, the needs exact, empty as need bytes 255.
TEST(FvsmSmtmm, TheFourByteEntryPacksColumnRowAndNeeds) {
  EXPECT_EQ(entryBytes(EntryFormat::Float16Byte), 16);
  EXPECT_EQ(entryBytes(EntryFormat::Packed4Byte), 4);
  // u = 0.3 → column floor(76.8) = 76 (0x4c), v = 0.75 → row 192 (0xc0), needs 17 and 24.
  EXPECT_EQ(packSmtmmEntry(entry(0.3, 0.75, 17, 24)), 0x1811c04cu);
  EXPECT_EQ(unpackSmtmmEntry(0x1811c04cu), entry(76.5 / 256.0, 192.5 / 256.0, 17, 24));
  EXPECT_EQ(packSmtmmEntry(entry(0.0, 1.0, 0, 0)), 0x0000ff00u);  // uv = 1: the last row
  EXPECT_EQ(packSmtmmEntry(SmtmmEntry{}), 0xffff0000u);
  EXPECT_EQ(unpackSmtmmEntry(0xffff0000u), SmtmmEntry{});
  EXPECT_THROW(unpackSmtmmEntry(0x19000000u), std::invalid_argument);  // need 25 > the cap
  for (int need = 0; need <= kMaxNeedLog2; ++need)
    EXPECT_EQ(unpackSmtmmEntry(packSmtmmEntry(entry(0.5, 0.5, need, kMaxNeedLog2 - need))).needLog2,
              glm::ivec2(need, kMaxNeedLog2 - need));
}

// What the 4-byte entry loses is where inside its column the pixel looks (the read-back u is
// within 1/512 of the float's), never the grid cell: at every grid size n = 1 … 256, u on
// both sides of every column border (k / 256 ± 1e-9), 0 and 1 fall in the same cell.
TEST(FvsmSmtmm, TheFourByteEntryKeepsEveryGridCell) {
  std::vector<double> us = {0.0, 1.0, 0.5, 1.0 / 3.0};
  for (int k = 1; k < 256; ++k)
    us.insert(us.end(), {k / 256.0 - 1e-9, k / 256.0, k / 256.0 + 1e-9});
  int checked = 0;
  for (const double u : us) {
    const SmtmmEntry e = entry(u, 1.0 - u, 9, 9);
    const SmtmmEntry back = unpackSmtmmEntry(packSmtmmEntry(e));
    EXPECT_LE(std::abs(back.smUv.x - u), 1.0 / 512.0) << u;
    EXPECT_LE(std::abs(back.smUv.y - (1.0 - u)), 1.0 / 512.0) << u;
    for (int n = 1; n <= 256; n *= 2) {
      EXPECT_EQ(gridCellOf(back.smUv, n), gridCellOf(e.smUv, n)) << "u " << u << ", n " << n;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 9 * (4 + 3 * 255));
}

/// 4 x 2 entries into a 2 x 2 grid (η0 = 17, η1 = 22: buckets ≤17, 18, 19, 20, 21, ≥22).
std::vector<SmtmmEntry> handGrid() {
  return {entry(0.1, 0.1, 5, 6), entry(0.2, 0.3, 18, 3), entry(0.7, 0.2, 4, 4),
          SmtmmEntry{},          entry(0.1, 0.9, 23, 2), entry(0.4, 0.1, 20, 1),
          entry(1.0, 1.0, 2, 2), entry(0.45, 0.45, 7, 7)};
}

TEST(FvsmGrid, MaxHistogramAndScreenRectangle) {
  const TileGrid g = accumulateGrid(handGrid(), {4, 2}, 2, HistogramSettings{});
  const GridCell& c00 = g.at(0, 0);  // entries (0,0) (1,0) (1,1) (3,1)
  EXPECT_EQ(c00.entries, 4);
  EXPECT_EQ(c00.maxNeedLog2, glm::ivec2(20, 7));
  EXPECT_EQ(c00.maxNeedAtMostEta0, glm::ivec2(7, 7));
  EXPECT_EQ(c00.histogram[0][0], 2);  // x needs 5, 7
  EXPECT_EQ(c00.histogram[0][1], 1);  // 18
  EXPECT_EQ(c00.histogram[0][3], 1);  // 20
  EXPECT_EQ(c00.histogram[1][0], 4);
  EXPECT_EQ(c00.screen.min, glm::ivec2(0, 0));
  EXPECT_EQ(c00.screen.max, glm::ivec2(3, 1));
  EXPECT_EQ(c00.needLog2, glm::ivec2(20, 7));  // no rejection: the plain max
  EXPECT_EQ(g.at(1, 0).needLog2, glm::ivec2(4, 4));
  EXPECT_EQ(g.at(1, 0).screen, (EntryRect{{2, 0}, {2, 0}}));
  EXPECT_EQ(g.at(0, 1).needLog2, glm::ivec2(23, 2));
  EXPECT_EQ(g.at(0, 1).histogram[0][5], 1);          // ≥ η1
  EXPECT_EQ(g.at(1, 1).needLog2, glm::ivec2(2, 2));  // uv = 1 falls in the last cell
  EXPECT_EQ(g.at(1, 1).screen, (EntryRect{{2, 1}, {2, 1}}));
}

TEST(FvsmGrid, OutlierRejectionDropsWholeBucketsFromTheTop) {
  HistogramSettings h;
  h.outlierEntries = 1;  // cell (0,0): 20 dropped, then 18 is one entry too many → 18
  TileGrid g = accumulateGrid(handGrid(), {4, 2}, 2, h);
  EXPECT_EQ(g.at(0, 0).needLog2, glm::ivec2(18, 7));
  // Cell (0,1): its only entry (23) is an outlier; with no need ≤ η0 left it gets η0.
  EXPECT_EQ(g.at(0, 1).needLog2, glm::ivec2(17, 2));
  h.outlierEntries = 2;  // 20 and 18 dropped: the largest need ≤ η0, 7
  g = accumulateGrid(handGrid(), {4, 2}, 2, h);
  EXPECT_EQ(g.at(0, 0).needLog2, glm::ivec2(7, 7));
  // Moving the buckets: η0 = 4, η1 = 6. Cell (0,0) x: 5 | 18, 20, 7 (≥ η1: 3 entries), no
  // need ≤ 4; y: 3, 1 (≤ η0) | 6, 7 (≥ η1: 2 entries).
  h = {4, 6, 2};
  g = accumulateGrid(handGrid(), {4, 2}, 2, h);
  EXPECT_EQ(g.at(0, 0).needLog2, glm::ivec2(20, 3));  // x: 3 entries ≥ η1 cannot go
  h.outlierEntries = 3;  // x: they go, then 5 is one too many → η0 + 1
  g = accumulateGrid(handGrid(), {4, 2}, 2, h);
  EXPECT_EQ(g.at(0, 0).needLog2, glm::ivec2(5, 3));
}

TEST(FvsmGrid, BadSettingsAreRefused) {
  EXPECT_THROW(accumulateGrid(handGrid(), {4, 2}, 3, {}), std::invalid_argument);
  EXPECT_THROW(accumulateGrid(handGrid(), {4, 2}, 512, {}), std::invalid_argument);
  EXPECT_THROW(accumulateGrid(handGrid(), {4, 3}, 2, {}), std::invalid_argument);
  EXPECT_THROW(accumulateGrid(handGrid(), {4, 2}, 2, HistogramSettings{22, 17, 0}),
               std::invalid_argument);
  EXPECT_THROW(accumulateGrid(handGrid(), {4, 2}, 2, HistogramSettings{17, 22, -1}),
               std::invalid_argument);
  try {
    HistogramSettings{5, 5, 0}.validate();
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("eta0 = 5, eta1 = 5"), std::string::npos);
  }
}

TEST(FvsmPyramid, MaxAndUnionPerLevel) {
  const Pyramid p = buildPyramid(accumulateGrid(handGrid(), {4, 2}, 2, HistogramSettings{}));
  ASSERT_EQ(p.levels.size(), 2u);
  EXPECT_EQ(p.at(1, 0, 1).needLog2, glm::ivec2(23, 2));
  EXPECT_EQ(p.at(0, 0, 0).needLog2, glm::ivec2(23, 7));
  EXPECT_EQ(p.at(0, 0, 0).screen, (EntryRect{{0, 0}, {3, 1}}));
}

/// A 4 x 4 grid by hand: cell (0,0) needs (4, 2), (1,0) needs (3, 3), (3,3) needs (2, 2).
TileGrid handTileGrid(glm::ivec2 need00 = {4, 2}) {
  TileGrid g;
  g.n = 4;
  g.cells.assign(16, GridCell{});
  g.at(0, 0).needLog2 = need00;
  g.at(0, 0).screen = {{0, 0}, {1, 1}};
  g.at(1, 0).needLog2 = {3, 3};
  g.at(1, 0).screen = {{2, 0}, {3, 2}};
  g.at(3, 3).needLog2 = {2, 2};
  g.at(3, 3).screen = {{5, 5}, {6, 7}};
  return g;
}

Tile tile(int lx, int ly, int ix, int iy, glm::ivec2 need, glm::ivec2 tex, EntryRect screen,
          bool unmet = false) {
  return {lx, ly, ix, iy, need, tex, screen, unmet};
}

TEST(FvsmTraversal, SplitsWhileTheNeedExceedsTheMaxTexture) {
  // t_max = 2^2. Root needs (4, 3): both > 2 → four children at level (1, 1). Two are empty;
  // (1,1 | 1,1) needs (2, 2) − 1 = (1, 1): a leaf. (1,1 | 0,0) needs (4, 3) − 1 = (3, 2):
  // split along u only → (2,1 | 0,0) needs (4, 2) − (2, 1) = (2, 1) and (2,1 | 1,0) needs
  // (3, 3) − (2, 1) = (1, 2): leaves.
  const Pyramid p = buildPyramid(handTileGrid());
  TraversalSettings s;
  s.maxTextureLog2 = 2;
  s.minTextureLog2 = 0;
  const std::vector<Tile> expected = {
      tile(1, 1, 1, 1, {2, 2}, {1, 1}, {{5, 5}, {6, 7}}),
      tile(2, 1, 0, 0, {4, 2}, {2, 1}, {{0, 0}, {1, 1}}),
      tile(2, 1, 1, 0, {3, 3}, {1, 2}, {{2, 0}, {3, 2}}),
  };
  EXPECT_EQ(traverse(p, s), expected);
  EXPECT_EQ(expected[1].uvMin(), glm::dvec2(0.0, 0.0));
  EXPECT_EQ(expected[2].uvMax(), glm::dvec2(0.5, 0.5));
}

TEST(FvsmTraversal, XiLowersEveryNeed) {
  const Pyramid p = buildPyramid(handTileGrid());
  TraversalSettings s;
  s.maxTextureLog2 = 2;
  s.minTextureLog2 = 0;
  s.xi = 1;  // root (3, 2): split along u; (1,0 | 0,0) (3, 2) − (1, 0) = (2, 2);
             // (1,0 | 1,0): cell (3,3) only, (1, 1) − (1, 0) = (0, 1).
  EXPECT_EQ(traverse(p, s), (std::vector<Tile>{
                                tile(1, 0, 0, 0, {3, 2}, {2, 2}, {{0, 0}, {3, 2}}),
                                tile(1, 0, 1, 0, {1, 1}, {0, 1}, {{5, 5}, {6, 7}}),
                            }));
  s.xi = 3;  // one tile: an ordinary shadow map at the need (1, 0) of the whole view
  s.minTextureLog2 = 1;
  EXPECT_EQ(traverse(p, s),
            (std::vector<Tile>{tile(0, 0, 0, 0, {1, 0}, {1, 1}, {{0, 0}, {6, 7}})}));
  s.xi = 30;
  EXPECT_THROW(traverse(p, s), std::invalid_argument);
}

TEST(FvsmTraversal, NegativeXiRaisesEveryNeed) {
  // Root need (4, 3) (SplitsWhileTheNeedExceedsTheMaxTexture) under t_max 2^10: one leaf at
  // the need; ξ = −2 asks for 4 times the texels per axis; below kMinXi is refused.
  const Pyramid p = buildPyramid(handTileGrid());
  TraversalSettings s;
  s.maxTextureLog2 = 10;
  s.minTextureLog2 = 0;
  EXPECT_EQ(traverse(p, s),
            (std::vector<Tile>{tile(0, 0, 0, 0, {4, 3}, {4, 3}, {{0, 0}, {6, 7}})}));
  s.xi = -2;
  EXPECT_EQ(traverse(p, s),
            (std::vector<Tile>{tile(0, 0, 0, 0, {6, 5}, {6, 5}, {{0, 0}, {6, 7}})}));
  s.xi = kMinXi - 1;
  EXPECT_THROW(traverse(p, s), std::invalid_argument);
}

TEST(FvsmTraversal, TheFinestLevelStopsTheSplitAndMarksItUnmet) {
  const Pyramid p = buildPyramid(handTileGrid({6, 0}));
  TraversalSettings s;
  s.maxTextureLog2 = 2;
  s.minTextureLog2 = 0;
  const std::vector<Tile> tiles = traverse(p, s);
  // Root (6, 3) → (1,1): (0,0) (6, 3) − 1 = (5, 2) → (2,1 | 0,0) (6, 0) − (2, 1) = (4, −1):
  // finest along u, unmet, t_max along u, the minimum along v.
  ASSERT_EQ(tiles.size(), 3u);
  EXPECT_EQ(tiles[1], tile(2, 1, 0, 0, {6, 0}, {2, 0}, {{0, 0}, {1, 1}}, true));
  EXPECT_FALSE(tiles[0].unmet);
  EXPECT_FALSE(tiles[2].unmet);
}

TEST(FvsmTraversal, EmptyGridRendersNothing) {
  TileGrid g;
  g.n = 2;
  g.cells.assign(4, GridCell{});
  EXPECT_TRUE(traverse(buildPyramid(g), TraversalSettings{}).empty());
}

TEST(FvsmTextures, ThreeModes) {
  EXPECT_EQ(tileTexture(TextureMode::SubRect, {3, 5}, 12, 0), (TileTexture{{4096, 4096}, {8, 32}}));
  EXPECT_EQ(tileTexture(TextureMode::PowerOfTwo, {3, 5}, 12, 0), (TileTexture{{32, 32}, {8, 32}}));
  EXPECT_EQ(tileTexture(TextureMode::ExactSize, {3, 5}, 12, 0), (TileTexture{{8, 32}, {8, 32}}));
  EXPECT_EQ(textureModeBoundTexels(TextureMode::SubRect, 12, 4, 0), 16777216u);
  // 4^4 + … + 4^12 = (4^13 − 4^4) / 3 = 22369536 ≤ 4/3 · 4096² = 22369621.3
  EXPECT_EQ(textureModeBoundTexels(TextureMode::PowerOfTwo, 12, 4, 0), 22369536u);
  EXPECT_LE(3 * textureModeBoundTexels(TextureMode::PowerOfTwo, 12, 0, 0), 4u * 16777216u);
  EXPECT_EQ(textureModeBoundTexels(TextureMode::ExactSize, 12, 4, 0), 8176u * 8176u);
  EXPECT_STREQ(textureModeName(TextureMode::PowerOfTwo), "power-of-two");
}

// The tile overlap is a border of b texels added around the cell's 2^t (not carved out of
// them): the viewport is 2^t + 2b per axis, and every mode's texture holds it.
TEST(FvsmTextures, TheBorderAddsTexels) {
  EXPECT_EQ(tileTexture(TextureMode::SubRect, {3, 5}, 12, 1),
            (TileTexture{{4098, 4098}, {10, 34}}));
  EXPECT_EQ(tileTexture(TextureMode::PowerOfTwo, {3, 5}, 12, 2), (TileTexture{{36, 36}, {12, 36}}));
  EXPECT_EQ(tileTexture(TextureMode::ExactSize, {3, 5}, 12, 4), (TileTexture{{16, 40}, {16, 40}}));
  EXPECT_EQ(tileTexture(TextureMode::PowerOfTwo, {12, 12}, 12, 1).size, glm::ivec2(4098));
  EXPECT_THROW(tileTexture(TextureMode::SubRect, {3, 5}, 12, -1), std::invalid_argument);
  EXPECT_EQ(textureModeBoundTexels(TextureMode::SubRect, 12, 4, 1), 4098u * 4098u);
  // (16 + 2)² + (32 + 2)² + … + (4096 + 2)², 9 sizes
  std::uint64_t series = 0;
  for (int k = 4; k <= 12; ++k) series += std::uint64_t((1 << k) + 2) * std::uint64_t((1 << k) + 2);
  EXPECT_EQ(textureModeBoundTexels(TextureMode::PowerOfTwo, 12, 4, 1), series);
  // Sides 16 + 2 … 4096 + 2: every w x h pair sums to (8176 + 9 · 2)².
  EXPECT_EQ(textureModeBoundTexels(TextureMode::ExactSize, 12, 4, 1), 8194u * 8194u);
  // Every leaf's viewport, its border included, fits in its mode's texture.
  for (int mode = 0; mode < kTextureModes; ++mode)
    for (int b = 0; b <= 4; ++b)
      for (int x = 4; x <= 12; ++x)
        for (int y = 4; y <= 12; ++y) {
          const TileTexture t = tileTexture(TextureMode(mode), {x, y}, 12, b);
          EXPECT_TRUE(t.viewport.x <= t.size.x && t.viewport.y <= t.size.y)
              << mode << " " << b << " " << x << " " << y;
          EXPECT_EQ(t.viewport, glm::ivec2((1 << x) + 2 * b, (1 << y) + 2 * b));
        }
}

// The texels per uv of a bordered tile are its cell's 2^t, and its lattice starts b texels
// before the cell: texel b's left edge is the cell's left edge (the uv rectangle that
// tileUvRectWithOverlap gives, drawn into tileTexture's viewport).
TEST(FvsmTextures, TheBorderKeepsTheCellsLattice) {
  const Tile t = tile(2, 1, 1, 0, {3, 3}, {5, 3}, {{1, 0}, {2, 1}});
  for (int b = 0; b <= 4; ++b) {
    glm::dvec2 lo, hi;
    tileUvRectWithOverlap(t, b, lo, hi);
    const TileTexture tex = tileTexture(TextureMode::ExactSize, t.textureLog2, 12, b);
    const glm::dvec2 texelsPerUv = glm::dvec2(tex.viewport) / (hi - lo);
    const glm::dvec2 cellTexelsPerUv =
        glm::dvec2(1 << t.textureLog2.x, 1 << t.textureLog2.y) / (t.uvMax() - t.uvMin());
    EXPECT_NEAR(texelsPerUv.x, cellTexelsPerUv.x, 1e-9 * cellTexelsPerUv.x) << b;
    EXPECT_NEAR(texelsPerUv.y, cellTexelsPerUv.y, 1e-9 * cellTexelsPerUv.y) << b;
    const glm::dvec2 cellStartTexel = (t.uvMin() - lo) * texelsPerUv;
    EXPECT_NEAR(cellStartTexel.x, double(b), 1e-9) << b;
    EXPECT_NEAR(cellStartTexel.y, double(b), 1e-9) << b;
  }
}

TEST(FvsmTiles, OverlapAndScreenRectangle) {
  const Tile t = tile(2, 1, 1, 0, {3, 3}, {2, 1}, {{1, 0}, {2, 1}});
  glm::dvec2 lo, hi;
  tileUvRectWithOverlap(t, 0, lo, hi);
  EXPECT_EQ(lo, glm::dvec2(0.25, 0.0));
  EXPECT_EQ(hi, glm::dvec2(0.5, 0.5));
  tileUvRectWithOverlap(t, 2, lo, hi);  // texel (1/16, 1/4)
  EXPECT_EQ(lo, glm::dvec2(0.125, -0.5));
  EXPECT_EQ(hi, glm::dvec2(0.625, 1.0));
  glm::ivec2 pmin, pmax;
  tileScreenRectPixels(t.screen, {4, 2}, {10, 5}, 0, pmin, pmax);
  EXPECT_EQ(pmin, glm::ivec2(2, 0));  // 1 · 10 / 4
  EXPECT_EQ(pmax, glm::ivec2(7, 5));  // 3 · 10 / 4, 2 · 5 / 2
  tileScreenRectPixels(t.screen, {4, 2}, {10, 5}, 1, pmin, pmax);
  EXPECT_EQ(pmin, glm::ivec2(0, 0));
  EXPECT_EQ(pmax, glm::ivec2(10, 5));
  tileScreenRectPixels(EntryRect{}, {4, 2}, {10, 5}, 1, pmin, pmax);
  EXPECT_EQ(pmin, pmax);
}

TEST(FvsmPublished, GridAndHistogramChannels) {
  // handGrid's cells (FvsmGrid.MaxHistogramAndScreenRectangle), η0 = 17, η1 = 22: 6 buckets.
  const HistogramSettings h;
  const TileGrid g = accumulateGrid(handGrid(), {4, 2}, 2, h);
  const std::vector<float> cells = gridChannels(g);
  ASSERT_EQ(cells.size(), 4u * kGridChannels);
  EXPECT_EQ(std::vector<float>(cells.begin(), cells.begin() + 5),
            (std::vector<float>{20, 7, 4, 20, 7}));  // cell (0,0)
  EXPECT_EQ(std::vector<float>(cells.begin() + 5, cells.begin() + 10),
            (std::vector<float>{4, 4, 1, 4, 4}));  // cell (1,0)
  EXPECT_EQ(std::vector<float>(cells.begin() + 10, cells.begin() + 15),
            (std::vector<float>{23, 2, 1, 23, 2}));  // cell (0,1)
  const std::vector<float> hist = gridHistogramChannels(g, h);
  ASSERT_EQ(hist.size(), 4u * 12u);
  // Cell (0,0) along u: 5, 7 (≤ 17), 18, 20; along v: four needs ≤ 17.
  EXPECT_EQ(std::vector<float>(hist.begin(), hist.begin() + 12),
            (std::vector<float>{2, 1, 0, 1, 0, 0, 4, 0, 0, 0, 0, 0}));
  // Cell (0,1): u 23 (≥ η1, the last bucket), v 2.
  EXPECT_EQ(std::vector<float>(hist.begin() + 24, hist.begin() + 36),
            (std::vector<float>{0, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 0}));
}

TEST(FvsmPublished, TileRecordsRoundTrip) {
  const std::vector<Tile> tiles = {tile(2, 1, 1, 0, {14, 13}, {12, 12}, {{1, 0}, {2, 1}}),
                                   tile(0, 0, 0, 0, {5, 3}, {5, 4}, EntryRect{}, true)};
  const std::vector<float> packed = packTileRecords(tiles, TextureMode::PowerOfTwo, 12, 0);
  ASSERT_EQ(packed.size(), 2u * kTileRecordFloats);
  EXPECT_EQ(
      std::vector<float>(packed.begin(), packed.begin() + kTileRecordFloats),
      (std::vector<float>{2, 1, 1, 0, 14, 13, 12, 12, 4096, 4096, 4096, 4096, 1, 0, 2, 1, 0}));
  const std::vector<TileRecord> back = unpackTileRecords(packed);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].tile, tiles[0]);
  EXPECT_EQ(back[0].texture, tileTexture(TextureMode::PowerOfTwo, {12, 12}, 12, 0));
  EXPECT_EQ(back[1].tile, tiles[1]);  // the empty rectangle survives
  EXPECT_TRUE(back[1].tile.screen.empty());
  EXPECT_EQ(back[1].texture.size, glm::ivec2(32, 32));  // power-of-two: the larger side
  EXPECT_EQ(back[1].texture.viewport, glm::ivec2(32, 16));
  EXPECT_EQ(
      unpackTileRecords(packTileRecords(tiles, TextureMode::ExactSize, 12, 0))[1].texture.size,
      glm::ivec2(32, 16));
  EXPECT_THROW(unpackTileRecords(std::vector<float>(16, 0.0f)), std::invalid_argument);
  std::vector<float> bad = packed;
  bad[3] = 0.5f;
  EXPECT_THROW(unpackTileRecords(bad), std::invalid_argument);
}

// The panel's camera thumbnail: the frame scaled to fit side² with its aspect kept, each
// texel showing the pixel under its centre.
TEST(FvsmThumbnail, KeepsTheAspectAndSamplesThePixelUnderEachCentre) {
  EXPECT_EQ(thumbnailUsedSize({1280, 720}, 256), glm::ivec2(256, 144));
  EXPECT_EQ(thumbnailUsedSize({720, 1280}, 256), glm::ivec2(144, 256));
  EXPECT_EQ(thumbnailUsedSize({160, 90}, 256), glm::ivec2(256, 144));   // enlarged
  EXPECT_EQ(thumbnailUsedSize({1000, 3}, 256), glm::ivec2(256, 1));     // 0.768 rounds to 1
  EXPECT_EQ(thumbnailUsedSize({1000, 1}, 256), glm::ivec2(256, 1));     // never 0
  EXPECT_EQ(thumbnailUsedSize({300, 200}, 256), glm::ivec2(256, 171));  // 170.67
  EXPECT_THROW(thumbnailUsedSize({0, 10}, 256), std::invalid_argument);
  // 1280 / 256 = 5 pixels per texel: texel t shows pixel 5t + 2 (its centre 5t + 2.5).
  EXPECT_EQ(thumbnailSamplePixel({0, 0}, {256, 144}, {1280, 720}), glm::ivec2(2, 2));
  EXPECT_EQ(thumbnailSamplePixel({255, 143}, {256, 144}, {1280, 720}), glm::ivec2(1277, 717));
  // Enlarged: 160 pixels over 256 texels, texel 1's centre 1.5 x 0.625 = 0.9375 -> pixel 0.
  EXPECT_EQ(thumbnailSamplePixel({1, 255}, {256, 144}, {160, 90}), glm::ivec2(0, 89));
  EXPECT_EQ(thumbnailSamplePixel({2, 143}, {256, 144}, {160, 90}), glm::ivec2(1, 89));
}

}  // namespace
}  // namespace sl::fvsm
