// Fitted virtual shadow maps: the CPU reference (Giegl & Wimmer, GI 2007; see Fvsm.h).
#include "algo/fvsm/Fvsm.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <stdexcept>

namespace sl::fvsm {
namespace {

bool isPowerOfTwo(int v) {
  return v > 0 && (v & (v - 1)) == 0;
}

int log2Exact(int v) {
  int l = 0;
  while ((1 << l) < v) ++l;
  return l;
}

glm::dvec2 projectToSmUv(const glm::dmat4& eyeToSmUv, const glm::dvec3& eye) {
  const glm::dvec4 c = eyeToSmUv * glm::dvec4(eye, 1.0);
  return glm::dvec2(c) / c.w;
}

/// The depth step along +`step` (m per pixel) towards whichever neighbour is nearer in
/// depth: zn − z towards the next pixel, z − zn from the previous one, so that a depth
/// falling along +step is negative; 0 when neither neighbour has a surface. On a tie the
/// previous pixel's step is kept.
double signedDepthStep(const EyeDepthView& view, glm::ivec2 pixel, glm::ivec2 step, double z) {
  bool found = false;
  double best = 0.0;
  for (int s : {-1, 1}) {
    const glm::ivec2 q = pixel + s * step;
    if (q.x < 0 || q.y < 0 || q.x >= view.width || q.y >= view.height) continue;
    const double zn = view.depthAt(q.x, q.y);
    if (zn <= 0.0) continue;
    const double d = double(s) * (zn - z);
    if (!found || std::abs(d) < std::abs(best)) best = d;
    found = true;
  }
  return best;
}

}  // namespace

EyeProjection eyeProjectionOf(const glm::dmat4& proj) {
  return {{1.0 / proj[0][0], 1.0 / proj[1][1]}, {proj[2][0], proj[2][1]}};
}

glm::dvec3 eyePosition(const EyeDepthView& view, glm::dvec2 pixel, double eyeDepthM) {
  const double ndcX = 2.0 * pixel.x / double(view.width) - 1.0 + view.ndcOffset.x;
  const double ndcY = 2.0 * pixel.y / double(view.height) - 1.0 + view.ndcOffset.y;
  return {ndcX * view.tanHalfFovX * eyeDepthM, ndcY * view.tanHalfFovY * eyeDepthM, -eyeDepthM};
}

int quantiseNeedLog2(double halfExtentUv) {
  if (!(halfExtentUv > 0.0)) return kMaxNeedLog2;
  const double need = std::ceil(-std::log2(halfExtentUv));
  return int(std::clamp(need, 0.0, double(kMaxNeedLog2)));
}

const char* footprintMeasureName(FootprintMeasure measure) {
  return measure == FootprintMeasure::Chord ? "chord" : "box";
}

glm::dvec2 footprintHalfExtent(glm::dvec2 a, glm::dvec2 b, FootprintMeasure measure) {
  const glm::dvec2 box = glm::abs(a) + glm::abs(b);
  if (measure == FootprintMeasure::Box) return box;
  const double det = std::abs(a.x * b.y - a.y * b.x);
  const double acrossU = std::max(std::abs(a.y), std::abs(b.y));  // the edges' extent along v
  const double acrossV = std::max(std::abs(a.x), std::abs(b.x));
  return {acrossU > 0.0 ? det / acrossU : box.x, acrossV > 0.0 ? det / acrossV : box.y};
}

SmtmmEntry smtmmEntry(const EyeDepthView& view, glm::ivec2 pixel, const glm::dmat4& eyeToSmUv,
                      FootprintMeasure measure) {
  SmtmmEntry e;
  const double z = view.depthAt(pixel.x, pixel.y);
  if (!(z > 0.0)) return e;
  const glm::dvec2 centre = glm::dvec2(pixel) + 0.5;
  const glm::dvec3 p = eyePosition(view, centre, z);
  const glm::dvec2 uv = projectToSmUv(eyeToSmUv, p);
  if (uv.x < 0.0 || uv.y < 0.0 || uv.x > 1.0 || uv.y > 1.0) return e;

  // Signed: the footprint tilts with the receiver, towards the camera where it falls.
  const double dzX = signedDepthStep(view, pixel, {1, 0}, z);
  const double dzY = signedDepthStep(view, pixel, {0, 1}, z);
  const glm::dvec3 a = 0.5 * (eyePosition(view, centre + glm::dvec2(0.5, 0.0), z + 0.5 * dzX) -
                              eyePosition(view, centre - glm::dvec2(0.5, 0.0), z - 0.5 * dzX));
  const glm::dvec3 b = 0.5 * (eyePosition(view, centre + glm::dvec2(0.0, 0.5), z + 0.5 * dzY) -
                              eyePosition(view, centre - glm::dvec2(0.0, 0.5), z - 0.5 * dzY));
  glm::dvec2 lo(1e300), hi(-1e300), smA(0.0), smB(0.0);
  for (double sa : {-1.0, 1.0}) {
    for (double sb : {-1.0, 1.0}) {
      const glm::dvec2 c = projectToSmUv(eyeToSmUv, p + sa * a + sb * b);
      lo = glm::min(lo, c);
      hi = glm::max(hi, c);
      smA += 0.25 * sa * c;
      smB += 0.25 * sb * c;
    }
  }
  // Box: the corners' own bounding box (exact under a projective map too).
  const glm::dvec2 half =
      measure == FootprintMeasure::Box ? 0.5 * (hi - lo) : footprintHalfExtent(smA, smB, measure);
  e.covered = true;
  e.smUv = uv;
  e.needLog2 = {quantiseNeedLog2(half.x), quantiseNeedLog2(half.y)};
  return e;
}

int entryBytes(EntryFormat format) {
  return format == EntryFormat::Packed4Byte ? 4 : 16;
}

std::uint32_t packSmtmmEntry(const SmtmmEntry& e) {
  if (!e.covered) return (SL_FVSM_ENTRY_EMPTY << 16) | (SL_FVSM_ENTRY_EMPTY << 24);
  const auto column = [](double uv) {
    return std::uint32_t(std::clamp(std::floor(uv * 256.0), 0.0, 255.0));
  };
  const auto need = [](int n) { return std::uint32_t(std::clamp(n, 0, kMaxNeedLog2)); };
  return column(e.smUv.x) | (column(e.smUv.y) << 8) | (need(e.needLog2.x) << 16) |
         (need(e.needLog2.y) << 24);
}

SmtmmEntry unpackSmtmmEntry(std::uint32_t packed) {
  const auto byte = [&](int k) { return (packed >> (8 * k)) & 0xffu; };
  SmtmmEntry e;
  if (byte(2) == SL_FVSM_ENTRY_EMPTY && byte(3) == SL_FVSM_ENTRY_EMPTY) return e;
  if (byte(2) > std::uint32_t(kMaxNeedLog2) || byte(3) > std::uint32_t(kMaxNeedLog2))
    throw std::invalid_argument("fvsm: a 4-byte SMTMM entry with a need byte above " +
                                std::to_string(kMaxNeedLog2));
  e.covered = true;
  e.smUv = (glm::dvec2(byte(0), byte(1)) + 0.5) / 256.0;
  e.needLog2 = glm::ivec2(int(byte(2)), int(byte(3)));
  return e;
}

glm::ivec2 smtmmSamplePixel(glm::ivec2 entry, glm::ivec2 smtmmSize, glm::ivec2 frameSize) {
  const glm::dvec2 p = (glm::dvec2(entry) + 0.5) * glm::dvec2(frameSize) / glm::dvec2(smtmmSize);
  return glm::min(glm::ivec2(glm::floor(p)), frameSize - 1);
}

std::vector<SmtmmEntry> buildSmtmm(const EyeDepthView& view, glm::ivec2 smtmmSize,
                                   const glm::dmat4& eyeToSmUv, FootprintMeasure measure) {
  if (smtmmSize.x <= 0 || smtmmSize.y <= 0 || view.width <= 0 || view.height <= 0 ||
      view.eyeDepthM.size() != std::size_t(view.width) * std::size_t(view.height)) {
    throw std::invalid_argument(
        "fvsm::buildSmtmm: empty SMTMM or frame, or depth buffer size "
        "is not width x height");
  }
  std::vector<SmtmmEntry> out(std::size_t(smtmmSize.x) * std::size_t(smtmmSize.y));
  const glm::ivec2 frame(view.width, view.height);
  for (int j = 0; j < smtmmSize.y; ++j) {
    for (int i = 0; i < smtmmSize.x; ++i) {
      out[std::size_t(j) * smtmmSize.x + i] =
          smtmmEntry(view, smtmmSamplePixel({i, j}, smtmmSize, frame), eyeToSmUv, measure);
    }
  }
  return out;
}

void HistogramSettings::validate() const {
  if (eta0 < 0 || eta1 > kMaxNeedLog2 || eta0 >= eta1) {
    throw std::invalid_argument(
        "fvsm histogram: need 0 <= eta0 < eta1 <= " + std::to_string(kMaxNeedLog2) +
        " (got eta0 = " + std::to_string(eta0) + ", eta1 = " + std::to_string(eta1) + ")");
  }
  if (outlierEntries < 0) {
    throw std::invalid_argument("fvsm histogram: outlier entries must be >= 0 (got " +
                                std::to_string(outlierEntries) + ")");
  }
}

int HistogramSettings::bucketOf(int needLog2) const {
  if (needLog2 <= eta0) return 0;
  if (needLog2 >= eta1) return eta1 - eta0;
  return needLog2 - eta0;
}

glm::ivec2 gridCellOf(glm::dvec2 uv, int n) {
  const glm::ivec2 c(glm::floor(uv * double(n)));
  return glm::clamp(c, glm::ivec2(0), glm::ivec2(n - 1));
}

int rejectOutliers(const GridCell& cell, int axis, const HistogramSettings& h) {
  if (cell.entries == 0) return -1;
  if (h.outlierEntries == 0) return cell.maxNeedLog2[axis];
  const int last = h.bucketCount() - 1;
  int discarded = 0;
  for (int b = last; b >= 1; --b) {
    const int count = cell.histogram[std::size_t(axis)][std::size_t(b)];
    if (count == 0) continue;
    if (discarded + count <= h.outlierEntries) {
      discarded += count;
      continue;
    }
    return b == last ? cell.maxNeedLog2[axis] : h.eta0 + b;
  }
  // Every entry above η0 was an outlier: the cell keeps its largest need up to η0, and
  // when it has none (only outliers), η0 itself, so that its pixels still get a tile.
  const int kept = cell.maxNeedAtMostEta0[axis];
  return kept >= 0 ? kept : h.eta0;
}

TileGrid accumulateGrid(std::span<const SmtmmEntry> smtmm, glm::ivec2 smtmmSize, int n,
                        const HistogramSettings& histogram) {
  histogram.validate();
  if (!isPowerOfTwo(n) || n > 256) {
    throw std::invalid_argument("fvsm tile grid: n must be a power of two in 1 .. 256 (got " +
                                std::to_string(n) + ")");
  }
  if (smtmmSize.x <= 0 || smtmmSize.y <= 0 ||
      smtmm.size() != std::size_t(smtmmSize.x) * std::size_t(smtmmSize.y)) {
    throw std::invalid_argument("fvsm tile grid: SMTMM size does not match its entries");
  }
  TileGrid grid;
  grid.n = n;
  grid.cells.assign(std::size_t(n) * std::size_t(n), GridCell{});
  for (int j = 0; j < smtmmSize.y; ++j) {
    for (int i = 0; i < smtmmSize.x; ++i) {
      const SmtmmEntry& e = smtmm[std::size_t(j) * smtmmSize.x + i];
      if (!e.covered) continue;
      const glm::ivec2 c = gridCellOf(e.smUv, n);
      GridCell& cell = grid.at(c.x, c.y);
      ++cell.entries;
      for (int axis = 0; axis < 2; ++axis) {
        const int need = e.needLog2[axis];
        cell.maxNeedLog2[axis] = std::max(cell.maxNeedLog2[axis], need);
        if (need <= histogram.eta0) {
          cell.maxNeedAtMostEta0[axis] = std::max(cell.maxNeedAtMostEta0[axis], need);
        }
        ++cell.histogram[std::size_t(axis)][std::size_t(histogram.bucketOf(need))];
      }
      cell.screen.include(glm::ivec2(i, j));
    }
  }
  for (GridCell& cell : grid.cells) {
    cell.needLog2 = {rejectOutliers(cell, 0, histogram), rejectOutliers(cell, 1, histogram)};
  }
  return grid;
}

Pyramid buildPyramid(const TileGrid& grid) {
  if (!isPowerOfTwo(grid.n) || grid.cells.size() != std::size_t(grid.n) * grid.n) {
    throw std::invalid_argument("fvsm pyramid: the grid is not n x n with n a power of two");
  }
  const int finest = log2Exact(grid.n);
  Pyramid p;
  p.levels.resize(std::size_t(finest) + 1);
  auto& top = p.levels[std::size_t(finest)];
  top.resize(grid.cells.size());
  for (std::size_t k = 0; k < grid.cells.size(); ++k) {
    top[k].needLog2 = grid.cells[k].needLog2;
    top[k].screen = grid.cells[k].screen;
  }
  for (int level = finest - 1; level >= 0; --level) {
    const int side = 1 << level;
    auto& cur = p.levels[std::size_t(level)];
    cur.assign(std::size_t(side) * side, PyramidCell{});
    for (int y = 0; y < side; ++y) {
      for (int x = 0; x < side; ++x) {
        PyramidCell& parent = cur[std::size_t(y) * side + x];
        for (int dy = 0; dy < 2; ++dy) {
          for (int dx = 0; dx < 2; ++dx) {
            const PyramidCell& child = p.at(level + 1, 2 * x + dx, 2 * y + dy);
            parent.needLog2 = glm::max(parent.needLog2, child.needLog2);
            parent.screen.include(child.screen);
          }
        }
      }
    }
  }
  return p;
}

void TraversalSettings::validate() const {
  if (maxTextureLog2 < 0 || maxTextureLog2 > 15 || minTextureLog2 < 0 ||
      minTextureLog2 > maxTextureLog2) {
    throw std::invalid_argument(
        "fvsm traversal: need 0 <= min texture log2 <= max texture log2 <= 15 (got " +
        std::to_string(minTextureLog2) + ", " + std::to_string(maxTextureLog2) + ")");
  }
  if (xi < kMinXi || xi > kMaxNeedLog2) {
    throw std::invalid_argument("fvsm traversal: xi must be in " + std::to_string(kMinXi) + " .. " +
                                std::to_string(kMaxNeedLog2) + " (got " + std::to_string(xi) + ")");
  }
}

PyramidCell nodeSummary(const Pyramid& pyramid, int levelX, int levelY, int ix, int iy) {
  const int level = std::max(levelX, levelY);
  const int sx = level - levelX, sy = level - levelY;
  PyramidCell out;
  for (int y = iy << sy; y < (iy + 1) << sy; ++y) {
    for (int x = ix << sx; x < (ix + 1) << sx; ++x) {
      const PyramidCell& c = pyramid.at(level, x, y);
      out.needLog2 = glm::max(out.needLog2, c.needLog2);
      out.screen.include(c.screen);
    }
  }
  return out;
}

std::vector<Tile> traverse(const Pyramid& pyramid, const TraversalSettings& settings) {
  settings.validate();
  struct Node {
    int levelX, levelY, ix, iy;
  };
  const int finest = pyramid.finestLevel();
  std::vector<Tile> tiles;
  std::deque<Node> queue{{0, 0, 0, 0}};
  while (!queue.empty()) {
    const Node node = queue.front();
    queue.pop_front();
    const PyramidCell s = nodeSummary(pyramid, node.levelX, node.levelY, node.ix, node.iy);
    if (s.needLog2.x < 0 && s.needLog2.y < 0) continue;  // no pixel looks into this node
    const glm::ivec2 need = glm::max(s.needLog2 - settings.xi, glm::ivec2(0));
    const glm::ivec2 tileNeed = need - glm::ivec2(node.levelX, node.levelY);
    const int ex = tileNeed.x > settings.maxTextureLog2 && node.levelX < finest ? 1 : 0;
    const int ey = tileNeed.y > settings.maxTextureLog2 && node.levelY < finest ? 1 : 0;
    if (ex > 0 || ey > 0) {
      for (int dy = 0; dy <= ey; ++dy) {
        for (int dx = 0; dx <= ex; ++dx) {
          queue.push_back(
              {node.levelX + ex, node.levelY + ey, (node.ix << ex) + dx, (node.iy << ey) + dy});
        }
      }
      continue;
    }
    Tile t;
    t.levelX = node.levelX;
    t.levelY = node.levelY;
    t.ix = node.ix;
    t.iy = node.iy;
    t.needLog2 = need;
    t.textureLog2 = glm::clamp(tileNeed, glm::ivec2(settings.minTextureLog2),
                               glm::ivec2(settings.maxTextureLog2));
    t.screen = s.screen;
    t.unmet = tileNeed.x > settings.maxTextureLog2 || tileNeed.y > settings.maxTextureLog2;
    tiles.push_back(t);
  }
  return tiles;
}

const char* textureModeName(TextureMode mode) {
  switch (mode) {
    case TextureMode::SubRect:
      return "sub-rectangle";
    case TextureMode::PowerOfTwo:
      return "power-of-two";
    case TextureMode::ExactSize:
      return "exact";
  }
  return "?";
}

TileTexture tileTexture(TextureMode mode, glm::ivec2 textureLog2, int maxTextureLog2,
                        int borderTexels) {
  if (borderTexels < 0) throw std::invalid_argument("fvsm: a negative tile border");
  const int b2 = 2 * borderTexels;
  const glm::ivec2 viewport((1 << textureLog2.x) + b2, (1 << textureLog2.y) + b2);
  switch (mode) {
    case TextureMode::SubRect:
      return {glm::ivec2((1 << maxTextureLog2) + b2), viewport};
    case TextureMode::PowerOfTwo:
      return {glm::ivec2((1 << std::max(textureLog2.x, textureLog2.y)) + b2), viewport};
    case TextureMode::ExactSize:
      return {viewport, viewport};
  }
  throw std::invalid_argument("fvsm: unknown texture mode");
}

std::uint64_t textureModeBoundTexels(TextureMode mode, int maxTextureLog2, int minTextureLog2,
                                     int borderTexels) {
  if (borderTexels < 0) throw std::invalid_argument("fvsm: a negative tile border");
  const std::uint64_t tmax = std::uint64_t(1) << maxTextureLog2;
  const std::uint64_t b2 = 2 * std::uint64_t(borderTexels);
  switch (mode) {
    case TextureMode::SubRect:
      return (tmax + b2) * (tmax + b2);
    case TextureMode::PowerOfTwo: {
      std::uint64_t sum = 0;
      for (int k = minTextureLog2; k <= maxTextureLog2; ++k) {
        const std::uint64_t side = (std::uint64_t(1) << k) + b2;
        sum += side * side;
      }
      return sum;
    }
    case TextureMode::ExactSize: {
      const std::uint64_t sizes = std::uint64_t(maxTextureLog2 - minTextureLog2 + 1);
      const std::uint64_t side = 2 * tmax - (std::uint64_t(1) << minTextureLog2) + b2 * sizes;
      return side * side;
    }
  }
  throw std::invalid_argument("fvsm: unknown texture mode");
}

void tileUvRectWithOverlap(const Tile& tile, int overlapTexels, glm::dvec2& uvMin,
                           glm::dvec2& uvMax) {
  const glm::dvec2 lo = tile.uvMin(), hi = tile.uvMax();
  const glm::dvec2 texel =
      (hi - lo) / glm::dvec2(double(1 << tile.textureLog2.x), double(1 << tile.textureLog2.y));
  uvMin = lo - double(overlapTexels) * texel;
  uvMax = hi + double(overlapTexels) * texel;
}

void tileScreenRectPixels(const EntryRect& rect, glm::ivec2 smtmmSize, glm::ivec2 frameSize,
                          int marginEntries, glm::ivec2& minPixel, glm::ivec2& maxPixel) {
  if (rect.empty()) {
    minPixel = maxPixel = glm::ivec2(0);
    return;
  }
  const glm::ivec2 lo = glm::clamp(rect.min - marginEntries, glm::ivec2(0), smtmmSize);
  const glm::ivec2 hi = glm::clamp(rect.max + 1 + marginEntries, glm::ivec2(0), smtmmSize);
  // Entry i covers pixels [floor(i W / n), floor((i + 1) W / n)).
  minPixel = lo * frameSize / smtmmSize;
  maxPixel = hi * frameSize / smtmmSize;
}

std::vector<float> gridChannels(const TileGrid& grid) {
  std::vector<float> out;
  out.reserve(grid.cells.size() * kGridChannels);
  for (const GridCell& c : grid.cells) {
    out.insert(out.end(), {float(c.needLog2.x), float(c.needLog2.y), float(c.entries),
                           float(c.maxNeedLog2.x), float(c.maxNeedLog2.y)});
  }
  return out;
}

std::vector<float> gridHistogramChannels(const TileGrid& grid, const HistogramSettings& h) {
  const int buckets = h.bucketCount();
  std::vector<float> out;
  out.reserve(grid.cells.size() * std::size_t(2 * buckets));
  for (const GridCell& c : grid.cells) {
    for (int axis = 0; axis < 2; ++axis) {
      for (int b = 0; b < buckets; ++b)
        out.push_back(float(c.histogram[std::size_t(axis)][std::size_t(b)]));
    }
  }
  return out;
}

std::vector<float> packTileRecords(std::span<const Tile> tiles, TextureMode mode,
                                   int maxTextureLog2, int borderTexels) {
  std::vector<float> out;
  out.reserve(tiles.size() * kTileRecordFloats);
  for (const Tile& t : tiles) {
    const TileTexture tex = tileTexture(mode, t.textureLog2, maxTextureLog2, borderTexels);
    const EntryRect r = t.screen.empty() ? EntryRect{} : t.screen;
    out.insert(out.end(), {float(t.levelX), float(t.levelY), float(t.ix), float(t.iy),
                           float(t.needLog2.x), float(t.needLog2.y), float(t.textureLog2.x),
                           float(t.textureLog2.y), float(tex.size.x), float(tex.size.y),
                           float(tex.viewport.x), float(tex.viewport.y), float(r.min.x),
                           float(r.min.y), float(r.max.x), float(r.max.y), t.unmet ? 1.0f : 0.0f});
  }
  return out;
}

std::vector<TileRecord> unpackTileRecords(std::span<const float> values) {
  if (values.size() % kTileRecordFloats != 0) {
    throw std::invalid_argument("fvsm tile records: " + std::to_string(values.size()) +
                                " floats is not a multiple of " +
                                std::to_string(kTileRecordFloats));
  }
  const auto integer = [](float v) {
    if (!(std::abs(v) <= float(1 << 30)) || v != std::floor(v))
      throw std::invalid_argument("fvsm tile records: a value is not an integer");
    return int(v);
  };
  std::vector<TileRecord> out;
  for (std::size_t k = 0; k < values.size(); k += kTileRecordFloats) {
    int f[kTileRecordFloats];
    for (int i = 0; i < kTileRecordFloats; ++i) f[i] = integer(values[k + std::size_t(i)]);
    TileRecord r;
    r.tile.levelX = f[0];
    r.tile.levelY = f[1];
    r.tile.ix = f[2];
    r.tile.iy = f[3];
    r.tile.needLog2 = {f[4], f[5]};
    r.tile.textureLog2 = {f[6], f[7]};
    r.texture.size = {f[8], f[9]};
    r.texture.viewport = {f[10], f[11]};
    r.tile.screen.min = {f[12], f[13]};
    r.tile.screen.max = {f[14], f[15]};
    r.tile.unmet = f[16] != 0;
    out.push_back(r);
  }
  return out;
}

glm::ivec2 thumbnailUsedSize(glm::ivec2 frameSize, int side) {
  if (frameSize.x <= 0 || frameSize.y <= 0 || side <= 0)
    throw std::invalid_argument("thumbnailUsedSize: sizes must be positive");
  const int longer = std::max(frameSize.x, frameSize.y);
  // Integer rounding of side * length / longer (exact, no floating point).
  const auto scaled = [&](int length) {
    return std::clamp(int((std::int64_t(length) * side * 2 + longer) / (std::int64_t(2) * longer)),
                      1, side);
  };
  return {scaled(frameSize.x), scaled(frameSize.y)};
}

glm::ivec2 thumbnailSamplePixel(glm::ivec2 t, glm::ivec2 used, glm::ivec2 frameSize) {
  // floor((t + ½) frame / used) = floor((2t + 1) frame / (2 used)), in integers.
  const auto axis = [](int ti, int u, int f) {
    return std::min(int((std::int64_t(2 * ti + 1) * f) / (std::int64_t(2) * u)), f - 1);
  };
  return {axis(t.x, used.x, frameSize.x), axis(t.y, used.y, frameSize.y)};
}

}  // namespace sl::fvsm
