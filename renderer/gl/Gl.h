// Thin RAII wrappers over OpenGL 4.5 objects (direct state access). Include this (it
// includes <epoxy/gl.h>) before any Qt OpenGL header.
#pragma once

#include <epoxy/gl.h>

#include <cstdint>
#include <string>
#include <utility>

namespace sl::gl {

/// Owns one GL name; deletes it with the given deleter. Movable, not copyable.
template <typename Deleter>
class Handle {
 public:
  Handle() = default;
  explicit Handle(GLuint id) : id_(id) {}
  ~Handle() { reset(); }
  Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
  Handle& operator=(Handle&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, 0);
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void reset() {
    if (id_) Deleter{}(id_);
    id_ = 0;
  }

 private:
  GLuint id_ = 0;
};

struct TextureDeleter {
  void operator()(GLuint id) const;  ///< also forgets the texture's bytes (allocatedBytes)
};
struct BufferDeleter {
  void operator()(GLuint id) const;  ///< also forgets the buffer's bytes (allocatedBytes)
};

/// Bytes of storage held by every Texture and Buffer alive in this process (all levels),
/// as allocated through these wrappers: lets tests check that a technique's memory()
/// reports all it allocated.
std::uint64_t allocatedBytes();
struct FramebufferDeleter {
  void operator()(GLuint id) const { glDeleteFramebuffers(1, &id); }
};
struct VertexArrayDeleter {
  void operator()(GLuint id) const { glDeleteVertexArrays(1, &id); }
};
struct ProgramDeleter {
  void operator()(GLuint id) const { glDeleteProgram(id); }
};
struct QueryDeleter {
  void operator()(GLuint id) const { glDeleteQueries(1, &id); }
};

/// A 2D texture (or array) with its size and format remembered.
class Texture {
 public:
  Texture() = default;
  /// Allocates immutable storage; `levels` mip levels.
  static Texture create2D(GLenum internalFormat, int width, int height, int levels = 1);
  static Texture create1D(GLenum internalFormat, int width);
  /// A 2D array texture of `layers` maps (one level): several shadow maps of one size.
  static Texture create2DArray(GLenum internalFormat, int width, int height, int layers);
  /// A buffer texture viewing `buffer` (no storage of its own): shaders texelFetch a
  /// samplerBuffer, which software rasterisers serve much faster than SSBO loads.
  static Texture createBufferView(GLenum internalFormat, const class Buffer& buffer);
  GLuint id() const { return h_.id(); }
  int width() const { return width_; }
  int height() const { return height_; }
  int layers() const { return layers_; }  ///< 1 unless an array
  GLenum format() const { return format_; }
  explicit operator bool() const { return bool(h_); }
  void setFilter(GLenum minFilter, GLenum magFilter);
  void setWrap(GLenum wrap);
  void setCompare(bool on);  ///< GL_COMPARE_REF_TO_TEXTURE with GL_LEQUAL

 private:
  Handle<TextureDeleter> h_;
  int width_ = 0, height_ = 0, layers_ = 1;
  GLenum format_ = 0;
};

class Buffer {
 public:
  Buffer() = default;
  static Buffer create(GLsizeiptr bytes, const void* data,
                       GLbitfield flags = GL_DYNAMIC_STORAGE_BIT);
  GLuint id() const { return h_.id(); }
  GLsizeiptr size() const { return size_; }
  explicit operator bool() const { return bool(h_); }

 private:
  Handle<BufferDeleter> h_;
  GLsizeiptr size_ = 0;
};

/// A fence after the commands issued so far: lets a result be read a frame later without
/// stalling the pipeline (glFenceSync / glClientWaitSync).
class Fence {
 public:
  Fence() = default;
  ~Fence() { reset(); }
  Fence(Fence&& o) noexcept : sync_(o.sync_) { o.sync_ = nullptr; }
  Fence& operator=(Fence&& o) noexcept {
    if (this != &o) reset(), sync_ = o.sync_, o.sync_ = nullptr;
    return *this;
  }
  Fence(const Fence&) = delete;
  Fence& operator=(const Fence&) = delete;
  /// Places a new fence after everything issued so far.
  void place();
  /// Waits (flushing first) until the commands before the fence are done; true at once
  /// when they already are. False when no fence is placed.
  bool wait();
  explicit operator bool() const { return sync_ != nullptr; }
  void reset();

 private:
  GLsync sync_ = nullptr;
};

class Framebuffer {
 public:
  Framebuffer() = default;
  static Framebuffer create();
  GLuint id() const { return h_.id(); }
  void attach(GLenum attachment, const Texture& texture, int level = 0);
  /// Attaches one layer of an array texture.
  void attachLayer(GLenum attachment, const Texture& texture, int layer, int level = 0);
  /// Sets draw buffers for the colour attachments 0..count-1 (0: none).
  void setDrawBuffers(int count);
  /// Throws std::runtime_error naming `what` when incomplete.
  void checkComplete(const std::string& what) const;

 private:
  Handle<FramebufferDeleter> h_;
};

using VertexArray = Handle<VertexArrayDeleter>;
VertexArray createVertexArray();

/// Bytes per texel of the sized internal formats ShadowLab uses (for memory accounting).
int bytesPerTexel(GLenum internalFormat);
std::string formatName(GLenum internalFormat);

}  // namespace sl::gl
