// Fitted virtual shadow maps (Giegl & Wimmer, GI 2007; seed 003, docs/techniques.md §6): the
// CPU reference of eq. (1) (a pixel's eye-space position from the eye-space depth buffer, §3.2)
// and of every step after that buffer — the SMTMM entry of one pixel
// from its depth neighbourhood (§4.3), the tile grid with its η histogram and outlier
// rejection (§4.4), the max pyramid (§4.5), the top-down kd-tree traversal (§4.6) with ξ
// (§4.9), and the three tile texture modes (§4.10). Plain C++: the `fvsm` technique runs
// steps 3-5 with these very functions on its read-back SMTMM.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "common/shared_constants.h"

namespace sl::fvsm {

/// Cap of a quantised need (log2 of texels along one axis of the whole virtual map): a
/// pixel whose footprint collapses to a line along an SM axis needs "infinite" resolution
/// and is stored as this.
inline constexpr int kMaxNeedLog2 = SL_FVSM_MAX_NEED_LOG2;

// ---------------------------------------------------------------------------------------
// Step 2: SMTMM entries.

/// Eq. (1)'s terms of a camera's perspective projection P (OpenGL: clip w = −z_eye): the
/// paper's 1 / a_x, 1 / a_y (`tanHalfFov`: 1 / P[0][0], 1 / P[1][1]) and b_x, b_y
/// (`ndcOffset`: P[2][0], P[2][1]; 0 for a centred frustum).
struct EyeProjection {
  glm::dvec2 tanHalfFov{1.0};
  glm::dvec2 ndcOffset{0.0};
};
EyeProjection eyeProjectionOf(const glm::dmat4& proj);

/// What the SMTMM pass knows about the camera: a perspective camera looking along its −z
/// with the given half-angle tangents (and frustum offset, eyeProjectionOf), and the linear
/// eye-space depth buffer (metres along −z, 0 = no surface). Eq. (1) of the paper: a pixel's
/// eye-space position from its screen position and its linear depth.
struct EyeDepthView {
  int width = 0, height = 0;
  double tanHalfFovX = 1.0, tanHalfFovY = 1.0;
  glm::dvec2 ndcOffset{0.0};         ///< b_x, b_y (EyeProjection)
  std::span<const float> eyeDepthM;  ///< width * height, row-major, row 0 at the bottom
  float depthAt(int x, int y) const { return eyeDepthM[std::size_t(y) * width + x]; }
};

/// Eye-space position of screen position `pixel` (pixel units, (0, 0) = the bottom-left
/// corner of the frame; a pixel's centre is at +0.5) at linear depth `eyeDepthM` (eq. 1):
/// d ((ndc + b) tanHalfFov, −1). The GPU's is shaders/common/tiled/eye_depth.glsl.
glm::dvec3 eyePosition(const EyeDepthView& view, glm::dvec2 pixel, double eyeDepthM);

/// One SMTMM entry. `smUv`: where in the virtual shadow map ([0, 1]²) the pixel looks;
/// `needLog2`: the log2 of the resolution the WHOLE virtual map needs along each SM axis
/// there, so that one texel is no larger than half the pixel's footprint (Δ, the half
/// extent of the footprint's SM-axis-aligned box: need = ceil(−log2 Δ), clamped to
/// [0, kMaxNeedLog2]). Not `covered`: no surface, or the point leaves the map's [0, 1]².
struct SmtmmEntry {
  bool covered = false;
  glm::dvec2 smUv{0.0};
  glm::ivec2 needLog2{0};
  bool operator==(const SmtmmEntry&) const = default;
};

/// The quantisation of one half extent Δ (SM uv units): ceil(−log2 Δ) in [0, kMaxNeedLog2];
/// Δ <= 0 gives kMaxNeedLog2.
int quantiseNeedLog2(double halfExtentUv);

/// How a footprint's SM parallelogram c ± a' ± b' becomes a half extent per SM axis.
/// `Box`: the half sides of its SM-axis-aligned bounding box, |a'| + |b'| per axis (the
/// paper's rectangle). `Chord`: the half length of its chord through c along that axis,
/// |det(a', b')| / max(|a'_v|, |b'_v|) along u (likewise v) — for a footprint elongated along
/// an SM diagonal the box is as long as the footprint along both axes, the chord only as
/// long as its narrow width (x √2); for an axis-aligned one both are equal. A footprint
/// flat along the other axis (both edges' components 0) keeps the box's value.
enum class FootprintMeasure : int { Box = SL_FVSM_FOOTPRINT_BOX, Chord = SL_FVSM_FOOTPRINT_CHORD };
const char* footprintMeasureName(FootprintMeasure measure);
/// Half extents (SM uv) of the parallelogram with half edges `a`, `b` along both SM axes.
glm::dvec2 footprintHalfExtent(glm::dvec2 a, glm::dvec2 b, FootprintMeasure measure);

/// The entry of the pixel whose centre is at `pixel` (integer coordinates) — §4.3: the
/// depth step Δz_x towards whichever of the left/right neighbours has the smaller |Δz|,
/// with its sign along +x (zn − z to the right, z − zn from the left: negative where the
/// depth falls along +x), likewise Δz_y (neighbours without a surface or outside the frame
/// are ignored; none: Δz = 0; a tie keeps the left/lower one), the pixel's footprint
/// as the parallelogram P ± a ± b with a = (P(x + ½, z + Δz_x / 2) − P(x − ½, z − Δz_x / 2)) / 2
/// and b likewise along y, its four corners through `eyeToSmUv` (eye space → SM uv in
/// x, y; w divided), and their half extents per SM axis (`measure`; the SM half edges are
/// a' = (c₊₊ + c₊₋ − c₋₊ − c₋₋) / 4, b' likewise).
SmtmmEntry smtmmEntry(const EyeDepthView& view, glm::ivec2 pixel, const glm::dmat4& eyeToSmUv,
                      FootprintMeasure measure = FootprintMeasure::Box);

/// How an SMTMM entry is stored on the GPU and read back (fvsm.smtmm.entry). `Float16Byte`:
/// four floats, SM u and v as computed. `Packed4Byte`: the paper's 4 bytes (§4.3) — the SM
/// position as the column and row of 256 that hold it, min(floor(256 uv), 255) per axis, and
/// the two needs, integers in [0, kMaxNeedLog2] and so exact. What it loses: where inside
/// its 1/256 column the pixel looks (read back as the column's centre, (k + ½) / 256, within
/// 1/512 of the float). The grid does not lose it: for n ≤ 256 a cell is floor(n uv) =
/// column >> (8 − log2 n), so every entry lands in the same cell, and the tiles are the same.
/// (The paper leaves the conversion to the hardware's [0, 1] → byte rounding, round(255 uv),
/// which moves entries within half a step of a cell border into the next cell.)
enum class EntryFormat : int {
  Float16Byte = SL_FVSM_ENTRY_16_BYTE,
  Packed4Byte = SL_FVSM_ENTRY_4_BYTE
};
/// Bytes per entry of a format: 16 or 4.
int entryBytes(EntryFormat format);
/// The 4-byte entry: byte 0 (lowest) the u column, 1 the v row, 2 need u, 3 need v; an entry
/// that is not covered has both need bytes SL_FVSM_ENTRY_EMPTY (255) and position 0.
std::uint32_t packSmtmmEntry(const SmtmmEntry& e);
/// The inverse, the position read back as the column's centre; throws
/// std::invalid_argument for a need byte above kMaxNeedLog2 that is not the empty marker.
SmtmmEntry unpackSmtmmEntry(std::uint32_t packed);

/// The SMTMM of `n` x `m` entries (row-major, row 0 at the bottom): entry (i, j) is the
/// entry of the pixel at the centre of its block, (floor((i + ½) W / n), floor((j + ½) H / m)).
glm::ivec2 smtmmSamplePixel(glm::ivec2 entry, glm::ivec2 smtmmSize, glm::ivec2 frameSize);
std::vector<SmtmmEntry> buildSmtmm(const EyeDepthView& view, glm::ivec2 smtmmSize,
                                   const glm::dmat4& eyeToSmUv,
                                   FootprintMeasure measure = FootprintMeasure::Box);

// ---------------------------------------------------------------------------------------
// Step 3: the tile grid.

/// The histogram's end buckets (§4.4; the paper found η0 = 17, η1 = 22 to work): bucket 0
/// counts needs <= η0, bucket k (1 .. η1 − η0 − 1) the need η0 + k, the last bucket needs
/// >= η1. `outlierEntries`: at most this many entries of a cell needing more than η0 are
/// discarded (the highest needs first, whole buckets only); 0 keeps every entry (plain max).
struct HistogramSettings {
  int eta0 = 17;
  int eta1 = 22;
  int outlierEntries = 0;
  /// Throws std::invalid_argument naming the problem (η0 < η1 within [0, kMaxNeedLog2],
  /// outlierEntries >= 0).
  void validate() const;
  int bucketCount() const { return eta1 - eta0 + 1; }
  int bucketOf(int needLog2) const;
};

/// Screen rectangle in SMTMM entries, inclusive; empty while min > max.
struct EntryRect {
  glm::ivec2 min{1 << 30}, max{-(1 << 30)};
  bool empty() const { return min.x > max.x || min.y > max.y; }
  void include(glm::ivec2 p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  void include(const EntryRect& r) {
    if (r.empty()) return;
    include(r.min);
    include(r.max);
  }
  bool operator==(const EntryRect&) const = default;
};

/// Maximum number of histogram buckets (η1 − η0 + 1 <= kMaxNeedLog2 + 1).
inline constexpr int kMaxBuckets = kMaxNeedLog2 + 1;

struct GridCell {
  int entries = 0;                                          ///< SMTMM entries landing here
  glm::ivec2 maxNeedLog2{-1};                               ///< plain max per axis, −1 empty
  glm::ivec2 maxNeedAtMostEta0{-1};                         ///< max of needs <= η0, per axis
  std::array<std::array<int, kMaxBuckets>, 2> histogram{};  ///< [axis][bucket]
  EntryRect screen;
  /// The need after outlier rejection (HistogramSettings), −1 for an empty cell.
  glm::ivec2 needLog2{-1};
};

/// n x n cells (n a power of two, 1 .. 256), row-major, cell (0, 0) at SM uv (0, 0).
struct TileGrid {
  int n = 0;
  std::vector<GridCell> cells;
  GridCell& at(int x, int y) { return cells[std::size_t(y) * n + x]; }
  const GridCell& at(int x, int y) const { return cells[std::size_t(y) * n + x]; }
};

/// The cell of SM uv `uv` in an n x n grid (uv = 1 falls in the last cell).
glm::ivec2 gridCellOf(glm::dvec2 uv, int n);
/// The need of one axis of a cell after discarding outliers (see HistogramSettings).
int rejectOutliers(const GridCell& cell, int axis, const HistogramSettings& h);
/// §4.4: every covered entry updates its cell's max, histogram and screen rectangle; then
/// each cell's `needLog2` is its need after outlier rejection. Throws std::invalid_argument
/// for n not a power of two in 1 .. 256 or a size mismatch.
TileGrid accumulateGrid(std::span<const SmtmmEntry> smtmm, glm::ivec2 smtmmSize, int n,
                        const HistogramSettings& histogram);

// ---------------------------------------------------------------------------------------
// Step 4: the max pyramid.

struct PyramidCell {
  glm::ivec2 needLog2{-1};  ///< max of the children's, −1 when all are empty
  EntryRect screen;         ///< union of the children's
  bool operator==(const PyramidCell&) const = default;
};
/// levels[p] holds 2^p x 2^p cells; levels.back() is the grid's own (its `needLog2`).
struct Pyramid {
  std::vector<std::vector<PyramidCell>> levels;
  int finestLevel() const { return int(levels.size()) - 1; }
  const PyramidCell& at(int level, int x, int y) const {
    return levels[std::size_t(level)][std::size_t(y) * (std::size_t(1) << level) + x];
  }
};
Pyramid buildPyramid(const TileGrid& grid);

// ---------------------------------------------------------------------------------------
// Step 5: the kd-tree traversal.

/// The lowest ξ: 16 times the texels per axis the SMTMM asks for.
inline constexpr int kMinXi = -4;

struct TraversalSettings {
  int maxTextureLog2 = 12;  ///< t_max = 2^12 = 4096 texels per axis
  int minTextureLog2 = 4;   ///< the smallest tile texture side (16 texels)
  /// ξ: subtracted from every need (§4.9), in [kMinXi, kMaxNeedLog2]; below 0 it asks for
  /// 2^−ξ times the texels per axis the SMTMM asks for (finer than sub-pixel accuracy).
  int xi = 0;
  /// Throws std::invalid_argument naming the problem.
  void validate() const;
};

/// One rendered SM tile: a kd-tree leaf. It covers SM uv [ix, ix + 1) / 2^levelX along u
/// (likewise v) and is rendered at `textureLog2` texels per axis (its need minus its level
/// and ξ, clamped to [minTextureLog2, maxTextureLog2]); `screen` is the union of the screen
/// rectangles of the grid cells below it. `unmet`: the finest grid level was reached with
/// a need still above t_max (rendered at t_max).
struct Tile {
  int levelX = 0, levelY = 0;
  int ix = 0, iy = 0;
  glm::ivec2 needLog2{0};  ///< max need (after ξ) of the grid cells below it
  glm::ivec2 textureLog2{0};
  EntryRect screen;
  bool unmet = false;
  glm::dvec2 uvMin() const {
    return {double(ix) / double(1 << levelX), double(iy) / double(1 << levelY)};
  }
  glm::dvec2 uvMax() const {
    return {double(ix + 1) / double(1 << levelX), double(iy + 1) / double(1 << levelY)};
  }
  bool operator==(const Tile&) const = default;
};

/// The max need and screen rectangle over the grid cells below kd node (levelX, levelY,
/// ix, iy), read from pyramid level max(levelX, levelY) (the paper's MaxSmResInRect).
PyramidCell nodeSummary(const Pyramid& pyramid, int levelX, int levelY, int ix, int iy);

/// §4.6, breadth first from the root: a node without entries is dropped; a node whose need
/// (minus ξ, minus its level) along an axis exceeds maxTextureLog2 is split in two along
/// that axis (in four when both do) unless the grid's finest level is reached along it;
/// otherwise it is a leaf. The leaves in the order they are found.
std::vector<Tile> traverse(const Pyramid& pyramid, const TraversalSettings& settings);

// ---------------------------------------------------------------------------------------
// §4.10: tile textures.

enum class TextureMode : int {
  SubRect = 0,     ///< every tile draws into a sub-rectangle of one t_max² texture
  PowerOfTwo = 1,  ///< the smallest square of the series t_max², (t_max/2)², … that holds it
  ExactSize = 2,   ///< a texture of exactly the tile's w x h
};
inline constexpr int kTextureModes = 3;
const char* textureModeName(TextureMode mode);

/// Where a tile of 2^textureLog2 texels is drawn: texture `size`, viewport `viewport`
/// at its origin. With a border of b texels (the tile overlap against seams, §5) the viewport
/// is 2^textureLog2 + 2b per axis: the kd cell keeps its 2^textureLog2 texels, on the same
/// lattice, and the border adds b of the same texels on every side (it is not carved out of
/// the cell's). Every mode's texture holds that viewport: t_max + 2b, 2^k + 2b, exact.
struct TileTexture {
  glm::ivec2 size{0};
  glm::ivec2 viewport{0};
  bool operator==(const TileTexture&) const = default;
};
TileTexture tileTexture(TextureMode mode, glm::ivec2 textureLog2, int maxTextureLog2,
                        int borderTexels);

/// Texels of every texture a mode can need (border b = 0): SubRect t_max² and PowerOfTwo the
/// series from t_max² down to (2^minTextureLog2)² (< 4/3 t_max², the sum the paper derives,
/// §4.10); ExactSize every w x h with both sides powers of two in [2^min, t_max], each its own
/// texture ((2 t_max − 2^min)², about 4 t_max²: the tool's bound of allocating every shape; a
/// frame allocates only the shapes it uses). The paper's sum for exact sizes, 2 · 4/3 t_max²,
/// counts per level only the square and the two rectangles halved along one axis, not the
/// thinner shapes the traversal can ask for (t_max x t_max/4, …), so it is no bound; its
/// results call the third mode's memory 4/3 of the other two's, which its sums do not give.
/// Neither is this function's. A border
/// adds 2b to every side: (t_max + 2b)², sum of (2^k + 2b)², (2 t_max − 2^min + 2b L)² for L
/// sizes.
std::uint64_t textureModeBoundTexels(TextureMode mode, int maxTextureLog2, int minTextureLog2,
                                     int borderTexels);

/// Tile overlap against seams (§5): the tile's SM uv rectangle grown by `overlapTexels` of
/// its own texels on every side (0 = the exact kd cell): what tileTexture's viewport with
/// that border covers.
void tileUvRectWithOverlap(const Tile& tile, int overlapTexels, glm::dvec2& uvMin,
                           glm::dvec2& uvMax);

/// A tile's screen rectangle in pixels [min, max) for a frame of `frameSize` pixels and an
/// SMTMM of `smtmmSize` entries: the entries' pixel blocks grown by `marginEntries` blocks on
/// every side (a pixel between two sampled pixels may look into the tile), clamped.
void tileScreenRectPixels(const EntryRect& rect, glm::ivec2 smtmmSize, glm::ivec2 frameSize,
                          int marginEntries, glm::ivec2& minPixel, glm::ivec2& maxPixel);

// ---------------------------------------------------------------------------------------
// The FVSM panel's camera thumbnail (fvsm.camera; shaders/fvsm/camera_thumbnail.comp): the
// frame scaled into a side x side image with its aspect kept, from the bottom-left.

/// The frame's part of the thumbnail: the longer side `side`, the other rounded, >= 1.
glm::ivec2 thumbnailUsedSize(glm::ivec2 frameSize, int side);
/// The frame pixel thumbnail texel `t` (inside `used`) shows: the pixel under its centre.
glm::ivec2 thumbnailSamplePixel(glm::ivec2 t, glm::ivec2 used, glm::ivec2 frameSize);

// ---------------------------------------------------------------------------------------
// What the renderer publishes for the FVSM panel (plain floats, so that the panel needs no
// GL and the CPU tests can check the layout exactly).

/// The grid as an n x n image (row 0 = grid row 0, v = 0), kGridChannels per cell: the need
/// after outlier rejection along u, v (−1 empty), the SMTMM entries in the cell, the plain
/// max need along u, v (−1 empty).
inline constexpr int kGridChannels = 5;
std::vector<float> gridChannels(const TileGrid& grid);
/// The histograms as an n x n image of 2 · h.bucketCount() channels: the counts of bucket
/// 0 .. B − 1 along u, then along v (bucket b counts the need η0 + b; 0: ≤ η0, B − 1: ≥ η1).
std::vector<float> gridHistogramChannels(const TileGrid& grid, const HistogramSettings& h);

/// One kd leaf as the panel draws it: the tile, its texture (the mode's size and the
/// viewport it draws into) and its screen rectangle in SMTMM entries.
struct TileRecord {
  Tile tile;
  TileTexture texture;
  bool operator==(const TileRecord&) const = default;
};
/// kTileRecordFloats floats per leaf: levelX, levelY, ix, iy, need u, need v, texture log2 u,
/// v, texture width, height, viewport width, height, screen min x, y, max x, y (entries,
/// inclusive; min > max: empty), unmet (0 / 1).
inline constexpr int kTileRecordFloats = 17;
std::vector<float> packTileRecords(std::span<const Tile> tiles, TextureMode mode,
                                   int maxTextureLog2, int borderTexels);
/// The inverse; throws std::invalid_argument when the size is not a multiple of
/// kTileRecordFloats or a value is not an integer.
std::vector<TileRecord> unpackTileRecords(std::span<const float> values);

}  // namespace sl::fvsm
