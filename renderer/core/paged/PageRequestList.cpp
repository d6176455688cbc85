// The GPU side of a paged map's page requests (PageRequestList.h).
#include "PageRequestList.h"

#include <algorithm>

#include "common/shared_constants.h"

namespace sl {

std::vector<pages::PageKey> readPageKeys(const gl::Buffer& buffer, GLintptr offset, std::size_t n) {
  std::vector<pages::PageKey> keys(n, 0u);
  if (n > 0) glGetNamedBufferSubData(buffer.id(), offset, GLsizeiptr(4 * n), keys.data());
  return keys;
}

PageRequestList::PageRequestList(const gl::ShaderLibrary& lib, const std::string& name)
    : compact_(lib, {name, {{GL_COMPUTE_SHADER, "common/paged/compact.comp"}}, {}, {}}) {}

void PageRequestList::ensure(int width, int height) {
  if (image_ && image_.width() == width && image_.height() == height) return;
  image_ = gl::Texture::create2D(GL_R32UI, width, height);
  list_ = gl::Buffer::create(GLsizeiptr(4) * (1 + GLsizeiptr(width) * height), nullptr);
}

void PageRequestList::compact() const {
  const GLuint gx = GLuint((image_.width() + SL_RMSM_GROUP - 1) / SL_RMSM_GROUP);
  const GLuint gy = GLuint((image_.height() + SL_RMSM_GROUP - 1) / SL_RMSM_GROUP);
  const std::uint32_t zero = 0;
  glNamedBufferSubData(list_.id(), 0, 4, &zero);
  compact_.use();
  glBindImageTexture(SL_RMSM_IMAGE_REQUESTS, image_.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SL_RMSM_BUFFER_REQUESTS, list_.id());
  glDispatchCompute(gx, gy, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

std::uint32_t PageRequestList::count() const {
  std::uint32_t count = 0;
  glGetNamedBufferSubData(list_.id(), 0, 4, &count);
  return std::min(count, std::uint32_t(list_.size() / 4 - 1));
}

void PageRequestList::addMemory(MemoryStats& m, const std::string& imageName) const {
  if (image_) m.add(imageName, "R32UI", image_.width(), image_.height(), 1, 4);
  if (list_) m.add("compacted requests (count + keys)", "R32UI", int(list_.size() / 4), 1, 1, 4);
}

}  // namespace sl
