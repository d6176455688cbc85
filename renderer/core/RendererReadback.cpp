// What a host reads of a rendered frame (Renderer.h): a pixel's probe, the colour image, the
// readback the metrics use, and the error against the ray-traced reference (traced on any
// thread from a snapshot), kept for the error overlay.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <mutex>
#include <span>
#include <stdexcept>
#include <utility>

#include "common/shared_constants.h"
#include "core/LightBinding.h"
#include "core/ParamBinding.h"
#include "core/SceneGpu.h"
#include "core/Technique.h"
#include "algo/metrics/BenchStats.h"
#include "gl/Gl.h"
#include "metrics/ShadowReference.h"
#include "core/RendererState.h"

namespace sl {

std::optional<PixelProbe> Renderer::probePixel(int x, int y) const {
  const Targets& t = s_->targets;
  if (t.width == 0 || x < 0 || y < 0 || x >= t.width || y >= t.height) return std::nullopt;
  const int row = t.height - 1 - y;  // GL textures: bottom row first
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  auto read = [&](const gl::Texture& tex, GLenum format, GLenum type, GLsizei bytes, void* out) {
    glGetTextureSubImage(tex.id(), 0, x, row, 0, 1, 1, 1, format, type, bytes, out);
  };
  PixelProbe p;
  p.x = x;
  p.y = y;
  glm::vec4 position(0.0f);
  read(t.position, GL_RGBA, GL_FLOAT, sizeof(position), &position);
  p.covered = position.w > 0.0f;
  if (!p.covered) return p;
  p.worldM = glm::vec3(position);
  read(t.hard, GL_RED_INTEGER, GL_UNSIGNED_BYTE, 1, &p.hard);
  read(t.aliasing, GL_RED, GL_FLOAT, sizeof(float), &p.aliasing);
  std::uint8_t map = 0;
  read(t.mapIndex, GL_RED_INTEGER, GL_UNSIGNED_BYTE, 1, &map);
  p.map = map;
  read(t.texel, GL_RG, GL_FLOAT, sizeof(glm::vec2), &p.mapUv);
  return p;
}

ImageRGBA8 Renderer::readColor() const {
  const Targets& t = s_->targets;
  const bool outside = s_->lastFrameOutside && s_->outsideTargets.width == t.width &&
                       s_->outsideTargets.height == t.height;
  ImageRGBA8 image;
  image.width = t.width;
  image.height = t.height;
  if (t.width == 0) return image;
  image.pixels.resize(size_t(t.width) * size_t(t.height) * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage((outside ? s_->outsideTargets : t).color.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE,
                    GLsizei(image.pixels.size()), image.pixels.data());
  flipVertically(image);
  return image;
}

FrameReadback Renderer::readback() const {
  const Targets& t = s_->targets;
  FrameReadback r;
  r.cancelled = s_->lastFrameCancelled;
  if (r.cancelled) return r;  // the targets hold part of a frame: not one to measure
  r.width = t.width;
  r.height = t.height;
  if (t.width == 0) return r;
  const size_t n = size_t(t.width) * size_t(t.height);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  r.positions.resize(n);
  r.normals.resize(n);
  r.hardMask.resize(n);
  glGetTextureImage(t.position.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(n * sizeof(glm::vec4)),
                    r.positions.data());
  glGetTextureImage(t.normal.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(n * sizeof(glm::vec4)),
                    r.normals.data());
  glGetTextureImage(t.hard.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, GLsizei(n),
                    r.hardMask.data());
  r.aliasing.resize(n);
  glGetTextureImage(t.aliasing.id(), 0, GL_RED, GL_FLOAT, GLsizei(n * sizeof(float)),
                    r.aliasing.data());
  r.texel.resize(n);
  glGetTextureImage(t.texel.id(), 0, GL_RG, GL_FLOAT, GLsizei(n * sizeof(glm::vec2)),
                    r.texel.data());
  r.mapIndex.resize(n);
  glGetTextureImage(t.mapIndex.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, GLsizei(n),
                    r.mapIndex.data());
  r.color.width = t.width;
  r.color.height = t.height;
  r.color.pixels.resize(n * 4);
  glGetTextureImage(t.color.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(n * 4),
                    r.color.pixels.data());
  // Everything top row first, like the colour image (GL textures are bottom row first).
  flipVertically(r.color);
  if (s_->lastFrameOutside && s_->outsideTargets.width == t.width &&
      s_->outsideTargets.height == t.height) {
    r.outside.width = t.width;
    r.outside.height = t.height;
    r.outside.pixels.resize(n * 4);
    glGetTextureImage(s_->outsideTargets.color.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(n * 4),
                      r.outside.pixels.data());
    flipVertically(r.outside);
  }
  auto flip = [&](auto& v) {
    std::span<std::uint8_t> bytes(reinterpret_cast<std::uint8_t*>(v.data()),
                                  v.size() * sizeof(v[0]));
    flipRowsVertically(bytes, size_t(t.width) * sizeof(v[0]), t.height);
  };
  flip(r.positions);
  flip(r.normals);
  flip(r.hardMask);
  flip(r.aliasing);
  flip(r.texel);
  flip(r.mapIndex);
  return r;
}

Renderer::ReferenceSnapshot Renderer::snapshotForReference() const {
  ReferenceSnapshot snap;
  snap.frame = readback();
  snap.light = s_->light;
  snap.frameSignature = s_->frameSignature;
  if (!s_->scene || snap.frame.width == 0 || !ShadowReference::available()) return snap;
  if (!s_->reference || s_->referenceScene != s_->scene.get()) {
    s_->reference = std::make_shared<ShadowReference>(*s_->scene);
    s_->referenceScene = s_->scene.get();
  }
  snap.reference = s_->reference;
  return snap;
}

std::optional<Renderer::ErrorResult> Renderer::traceReference(ReferenceSnapshot snap,
                                                              const std::atomic<bool>* cancelled) {
  if (snap.frame.cancelled) return std::nullopt;  // a stopped frame is not measured
  ErrorResult res;
  res.frame = std::move(snap.frame);
  if (!snap.reference) return res;
  const FrameReadback& f = res.frame;
  const std::size_t n = f.positions.size();
  if (f.normals.size() != n || f.hardMask.size() != n)
    throw std::invalid_argument("traceReference: positions, normals and mask differ in size");
  // Bands of rows, so that a cancel (scene changed, window closed) is seen soon.
  const std::size_t band = std::size_t(std::max(1, f.width)) * 64;
  res.referenceMask.resize(n);
  std::vector<std::uint8_t> part;
  for (std::size_t begin = 0; begin < n; begin += band) {
    if (cancelled && cancelled->load()) return std::nullopt;
    const std::size_t count = std::min(band, n - begin);
    snap.reference->evaluate(std::span(f.positions).subspan(begin, count),
                             std::span(f.normals).subspan(begin, count), snap.light, part);
    std::copy(part.begin(), part.end(), res.referenceMask.begin() + std::ptrdiff_t(begin));
  }
  res.stats = compareShadowMasks(f.hardMask, res.referenceMask);
  return res;
}

namespace {
/// Keeps a traced reference mask (row 0 = top) for the error overlay of `frameSignature`.
bool uploadReferenceMask(RendererState& s, const std::string& frameSignature,
                         std::span<const std::uint8_t> mask, int width, int height) {
  const Targets& t = s.targets;
  if (width != t.width || height != t.height ||
      mask.size() != std::size_t(t.width) * std::size_t(t.height) || mask.empty())
    return false;
  std::vector<std::uint8_t> glOrder(mask.begin(), mask.end());  // GL: bottom row first
  flipRowsVertically(glOrder, size_t(t.width), t.height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(t.reference.id(), 0, 0, 0, t.width, t.height, GL_RED_INTEGER,
                      GL_UNSIGNED_BYTE, glOrder.data());
  s.referenceSignature = frameSignature;
  return true;
}
}  // namespace

bool Renderer::setReferenceMask(const std::string& frameSignature,
                                std::span<const std::uint8_t> mask, int width, int height) {
  return uploadReferenceMask(*s_, frameSignature, mask, width, height);
}

const std::string& Renderer::frameSignature() const {
  return s_->frameSignature;
}

Renderer::ErrorResult Renderer::computeError() const {
  if (s_->lastFrameCancelled)
    throw std::runtime_error(
        "computeError: the last frame was cancelled before it was complete (setCancelFlag); "
        "render a complete frame to measure its error");
  ReferenceSnapshot snap = snapshotForReference();
  const std::string signature = snap.frameSignature;
  ErrorResult res = *traceReference(std::move(snap));  // not cancellable: always a result
  // Keep it for the error overlay of this frame.
  uploadReferenceMask(*s_, signature, res.referenceMask, res.frame.width, res.frame.height);
  return res;
}

}  // namespace sl
