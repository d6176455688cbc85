// The GPU side of a paged map's page requests, shared by `rmsm` and `asm`: the per-pixel
// request keys (R32UI, the camera's size; written by the technique's own pass:
// rmsm/requests.comp, asm/edges.comp), their dedup and compaction into one list
// (common/paged/compact.comp: a count, then the keys) and its read-back.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "algo/pages/VirtualPages.h"
#include "core/Technique.h"
#include "gl/Gl.h"

namespace sl {

/// `n` page keys of `buffer` from byte `offset` on (read back; empty when n is 0).
std::vector<pages::PageKey> readPageKeys(const gl::Buffer& buffer, GLintptr offset, std::size_t n);

class PageRequestList {
 public:
  /// `name` labels the compaction program ("rmsm/compact").
  PageRequestList(const gl::ShaderLibrary& lib, const std::string& name);

  /// (Re)allocates the image and the list (one key per pixel) for width x height pixels.
  void ensure(int width, int height);
  /// The per-pixel keys (R32UI), bound by the technique's request pass.
  const gl::Texture& image() const { return image_; }
  /// The compacted list: a count, then the keys.
  const gl::Buffer& list() const { return list_; }
  /// Dedup + compaction of image() into list() (its count zeroed first): a request stays only
  /// when its left and lower neighbours ask for a different page.
  void compact() const;
  /// The list's length, clamped to its capacity (4 bytes read back).
  std::uint32_t count() const;
  /// The first `n` keys of the list (read back).
  std::vector<pages::PageKey> keys(std::size_t n) const { return readPageKeys(list_, 4, n); }
  /// The whole compacted list (count() keys).
  std::vector<pages::PageKey> compacted() const { return keys(count()); }
  /// Technique::memory()'s lines: image() as `imageName`, then the list.
  void addMemory(MemoryStats& m, const std::string& imageName) const;
  const gl::Program& program() const { return compact_; }
  std::optional<std::string> reloadShaders(const gl::ShaderLibrary& lib) {
    return compact_.rebuild(lib);
  }

 private:
  gl::Program compact_;
  gl::Texture image_;  ///< R32UI per camera pixel
  gl::Buffer list_;    ///< count + one key per pixel
};

}  // namespace sl
