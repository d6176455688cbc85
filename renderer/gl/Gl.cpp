#include "Gl.h"

#include <algorithm>
#include <unordered_map>

#include <stdexcept>

namespace sl::gl {

namespace {
std::unordered_map<GLuint, std::uint64_t>& textureBytes() {
  static std::unordered_map<GLuint, std::uint64_t> m;
  return m;
}
std::unordered_map<GLuint, std::uint64_t>& bufferBytes() {
  static std::unordered_map<GLuint, std::uint64_t> m;
  return m;
}
std::uint64_t levelBytes(GLenum format, int width, int height, int levels) {
  std::uint64_t total = 0;
  for (int l = 0; l < levels; ++l, width = std::max(1, width / 2), height = std::max(1, height / 2))
    total += std::uint64_t(width) * std::uint64_t(height) * std::uint64_t(bytesPerTexel(format));
  return total;
}
}  // namespace

void TextureDeleter::operator()(GLuint id) const {
  textureBytes().erase(id);
  glDeleteTextures(1, &id);
}

void BufferDeleter::operator()(GLuint id) const {
  bufferBytes().erase(id);
  glDeleteBuffers(1, &id);
}

std::uint64_t allocatedBytes() {
  std::uint64_t total = 0;
  for (const auto& [id, bytes] : textureBytes()) total += bytes;
  for (const auto& [id, bytes] : bufferBytes()) total += bytes;
  return total;
}

Texture Texture::create2D(GLenum internalFormat, int width, int height, int levels) {
  Texture t;
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &id);
  t.h_ = Handle<TextureDeleter>(id);
  glTextureStorage2D(id, levels, internalFormat, width, height);
  textureBytes()[id] = levelBytes(internalFormat, width, height, levels);
  t.width_ = width;
  t.height_ = height;
  t.format_ = internalFormat;
  t.setFilter(levels > 1 ? GL_NEAREST_MIPMAP_NEAREST : GL_NEAREST, GL_NEAREST);
  t.setWrap(GL_CLAMP_TO_EDGE);
  return t;
}

Texture Texture::create2DArray(GLenum internalFormat, int width, int height, int layers) {
  Texture t;
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &id);
  t.h_ = Handle<TextureDeleter>(id);
  glTextureStorage3D(id, 1, internalFormat, width, height, layers);
  textureBytes()[id] = levelBytes(internalFormat, width, height, 1) * std::uint64_t(layers);
  t.width_ = width;
  t.height_ = height;
  t.layers_ = layers;
  t.format_ = internalFormat;
  t.setFilter(GL_NEAREST, GL_NEAREST);
  t.setWrap(GL_CLAMP_TO_EDGE);
  return t;
}

Texture Texture::createBufferView(GLenum internalFormat, const Buffer& buffer) {
  Texture t;
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_BUFFER, 1, &id);
  t.h_ = Handle<TextureDeleter>(id);
  glTextureBuffer(id, internalFormat, buffer.id());
  t.width_ = int(buffer.size() / bytesPerTexel(internalFormat));
  t.height_ = 1;
  t.format_ = internalFormat;
  return t;
}

Texture Texture::create1D(GLenum internalFormat, int width) {
  Texture t;
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_1D, 1, &id);
  t.h_ = Handle<TextureDeleter>(id);
  glTextureStorage1D(id, 1, internalFormat, width);
  textureBytes()[id] = levelBytes(internalFormat, width, 1, 1);
  t.width_ = width;
  t.height_ = 1;
  t.format_ = internalFormat;
  t.setFilter(GL_LINEAR, GL_LINEAR);
  t.setWrap(GL_CLAMP_TO_EDGE);
  return t;
}

void Texture::setFilter(GLenum minFilter, GLenum magFilter) {
  glTextureParameteri(id(), GL_TEXTURE_MIN_FILTER, GLint(minFilter));
  glTextureParameteri(id(), GL_TEXTURE_MAG_FILTER, GLint(magFilter));
}

void Texture::setWrap(GLenum wrap) {
  glTextureParameteri(id(), GL_TEXTURE_WRAP_S, GLint(wrap));
  glTextureParameteri(id(), GL_TEXTURE_WRAP_T, GLint(wrap));
}

void Texture::setCompare(bool on) {
  glTextureParameteri(id(), GL_TEXTURE_COMPARE_MODE, on ? GL_COMPARE_REF_TO_TEXTURE : GL_NONE);
  glTextureParameteri(id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
}

Buffer Buffer::create(GLsizeiptr bytes, const void* data, GLbitfield flags) {
  Buffer b;
  GLuint id = 0;
  glCreateBuffers(1, &id);
  b.h_ = Handle<BufferDeleter>(id);
  glNamedBufferStorage(id, bytes > 0 ? bytes : 4, data, flags);
  bufferBytes()[id] = std::uint64_t(bytes > 0 ? bytes : 4);
  b.size_ = bytes;
  return b;
}

Framebuffer Framebuffer::create() {
  Framebuffer f;
  GLuint id = 0;
  glCreateFramebuffers(1, &id);
  f.h_ = Handle<FramebufferDeleter>(id);
  return f;
}

void Framebuffer::attach(GLenum attachment, const Texture& texture, int level) {
  glNamedFramebufferTexture(id(), attachment, texture.id(), level);
}

void Framebuffer::attachLayer(GLenum attachment, const Texture& texture, int layer, int level) {
  glNamedFramebufferTextureLayer(id(), attachment, texture.id(), level, layer);
}

void Framebuffer::setDrawBuffers(int count) {
  GLenum bufs[8];
  for (int i = 0; i < count && i < 8; ++i) bufs[i] = GLenum(GL_COLOR_ATTACHMENT0 + i);
  if (count == 0) {
    glNamedFramebufferDrawBuffer(id(), GL_NONE);
    glNamedFramebufferReadBuffer(id(), GL_NONE);
  } else {
    glNamedFramebufferDrawBuffers(id(), count, bufs);
  }
}

void Framebuffer::checkComplete(const std::string& what) const {
  GLenum status = glCheckNamedFramebufferStatus(id(), GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("framebuffer '" + what + "' is incomplete (status 0x" +
                             std::to_string(status) + ")");
}

VertexArray createVertexArray() {
  GLuint id = 0;
  glCreateVertexArrays(1, &id);
  return VertexArray(id);
}

int bytesPerTexel(GLenum f) {
  switch (f) {
    case GL_R8:
      return 1;
    case GL_RG8:
    case GL_R16F:
    case GL_DEPTH_COMPONENT16:
      return 2;
    case GL_RGBA8:
    case GL_R32F:
    case GL_R32UI:
    case GL_RG16F:
    case GL_DEPTH_COMPONENT32F:
    case GL_DEPTH_COMPONENT24:
    case GL_DEPTH24_STENCIL8:
      return 4;
    case GL_RG32F:
    case GL_RGBA16F:
      return 8;
    case GL_RGBA32F:
    case GL_RGBA32UI:
      return 16;
    default:
      return 4;
  }
}

std::string formatName(GLenum f) {
  switch (f) {
    case GL_R8:
      return "R8";
    case GL_RGBA8:
      return "RGBA8";
    case GL_R16F:
      return "R16F";
    case GL_R32F:
      return "R32F";
    case GL_R32UI:
      return "R32UI";
    case GL_RG32F:
      return "RG32F";
    case GL_RGBA16F:
      return "RGBA16F";
    case GL_RGBA32F:
      return "RGBA32F";
    case GL_RGBA32UI:
      return "RGBA32UI";
    case GL_DEPTH_COMPONENT16:
      return "DEPTH_COMPONENT16";
    case GL_DEPTH_COMPONENT24:
      return "DEPTH_COMPONENT24";
    case GL_DEPTH_COMPONENT32F:
      return "DEPTH_COMPONENT32F";
    default:
      return "0x" + std::to_string(f);
  }
}

void Fence::place() {
  reset();
  sync_ = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
}

bool Fence::wait() {
  if (!sync_) return false;
  GLenum r = glClientWaitSync(sync_, GL_SYNC_FLUSH_COMMANDS_BIT, 0);
  while (r == GL_TIMEOUT_EXPIRED) r = glClientWaitSync(sync_, GL_SYNC_FLUSH_COMMANDS_BIT, 1000000);
  return r == GL_ALREADY_SIGNALED || r == GL_CONDITION_SATISFIED;
}

void Fence::reset() {
  if (sync_) glDeleteSync(sync_);
  sync_ = nullptr;
}

}  // namespace sl::gl
