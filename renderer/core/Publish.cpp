// Readback helpers of core/Publish.h: the only place publication bytes are read and counted.
#include "core/Publish.h"

#include "gl/Gl.h"

namespace sl {

namespace {
FloatImage readImage(FrameContext& ctx, const gl::Texture& texture, GLenum format, GLenum type,
                     int layer = -1) {
  FloatImage img;
  img.width = texture.width();
  img.height = texture.height();
  img.values.resize(std::size_t(img.width) * std::size_t(img.height));
  const std::size_t bytes = img.values.size() * sizeof(float);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  if (layer < 0)
    glGetTextureImage(texture.id(), 0, format, type, GLsizei(bytes), img.values.data());
  else  // one layer of an array
    glGetTextureSubImage(texture.id(), 0, 0, 0, layer, img.width, img.height, 1, format, type,
                         GLsizei(bytes), img.values.data());
  ctx.publication->readbackBytes += bytes;
  return img;
}
/// A depth texture (or one layer of an array) as a float image of at most
/// kMaxPublishedImageSide per side: a larger one is blitted nearest-sampled into a temporary
/// depth texture of publishedImageSize and that is read back (a 16384² map read whole took
/// 1 GiB for one panel).
FloatImage readDepth(FrameContext& ctx, const gl::Texture& depth, int layer) {
  const int w = depth.width(), h = depth.height();
  const auto [sw, sh] = publishedImageSize(w, h);
  if (sw == w && sh == h) return readImage(ctx, depth, GL_DEPTH_COMPONENT, GL_FLOAT, layer);
  const gl::Texture small = gl::Texture::create2D(depth.format(), sw, sh);
  gl::Framebuffer from = gl::Framebuffer::create(), to = gl::Framebuffer::create();
  if (layer < 0)
    from.attach(GL_DEPTH_ATTACHMENT, depth);
  else
    from.attachLayer(GL_DEPTH_ATTACHMENT, depth, layer);
  to.attach(GL_DEPTH_ATTACHMENT, small);
  for (const gl::Framebuffer* f : {&from, &to}) {
    glNamedFramebufferDrawBuffer(f->id(), GL_NONE);
    glNamedFramebufferReadBuffer(f->id(), GL_NONE);
  }
  glBlitNamedFramebuffer(from.id(), to.id(), 0, 0, w, h, 0, 0, sw, sh, GL_DEPTH_BUFFER_BIT,
                         GL_NEAREST);
  FloatImage img = readImage(ctx, small, GL_DEPTH_COMPONENT, GL_FLOAT);
  img.sourceWidth = w;
  img.sourceHeight = h;
  return img;
}
}  // namespace

bool publishDepthLayer(FrameContext& ctx, const std::string& key, const gl::Texture& depth,
                       int layer) {
  if (!ctx.wants(key)) return false;
  ctx.publication->images[key] = readDepth(ctx, depth, layer);
  return true;
}

bool publishDepth(FrameContext& ctx, const std::string& key, const gl::Texture& depth) {
  if (!ctx.wants(key)) return false;
  ctx.publication->images[key] = readDepth(ctx, depth, -1);
  return true;
}

bool publishRed(FrameContext& ctx, const std::string& key, const gl::Texture& texture) {
  if (!ctx.wants(key)) return false;
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
  ctx.publication->images[key] = readImage(ctx, texture, GL_RED, GL_FLOAT);
  return true;
}

bool publishFloatBits(FrameContext& ctx, const std::string& key, const gl::Texture& texture) {
  if (!ctx.wants(key)) return false;
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
  ctx.publication->images[key] = readImage(ctx, texture, GL_RED_INTEGER, GL_UNSIGNED_INT);
  return true;
}

std::vector<float> readPublishedFloats(FrameContext& ctx, const gl::Buffer& buffer,
                                       std::size_t offset, std::size_t count) {
  std::vector<float> v(count);
  if (!ctx.publication || count == 0) return v;
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(buffer.id(), GLintptr(offset * sizeof(float)),
                          GLsizeiptr(count * sizeof(float)), v.data());
  ctx.publication->readbackBytes += count * sizeof(float);
  return v;
}

bool publishCurve(FrameContext& ctx, const std::string& key, const gl::Buffer& buffer,
                  std::size_t offset, std::size_t count) {
  if (!ctx.wants(key)) return false;
  ctx.publication->curves[key] = readPublishedFloats(ctx, buffer, offset, count);
  return true;
}

bool publishValues(FrameContext& ctx, const std::string& key, std::vector<float> values) {
  if (!ctx.wants(key)) return false;
  ctx.publication->curves[key] = std::move(values);
  return true;
}

bool publishImage(FrameContext& ctx, const std::string& key, int width, int height,
                  std::vector<float> values) {
  if (!ctx.wants(key)) return false;
  FloatImage& image = ctx.publication->images[key];
  image.width = width;
  image.height = height;
  image.channels = 1;
  image.values = std::move(values);
  return true;
}

bool publishNumber(FrameContext& ctx, const std::string& key, double value) {
  if (!ctx.wants(key)) return false;
  ctx.publication->numbers[key] = value;
  return true;
}

}  // namespace sl
