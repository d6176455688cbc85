#include "SceneGpu.h"

namespace sl {

namespace {
struct Vertex {
  float px, py, pz;
  float nx, ny, nz;
  float u, v;
};
}  // namespace

SceneGpu::SceneGpu(const Scene& scene) : materials_(scene.materials) {
  std::vector<Vertex> verts;
  std::vector<std::uint32_t> idx;
  for (const MeshPrimitive& prim : scene.primitives) {
    std::uint32_t base = std::uint32_t(verts.size());
    for (size_t i = 0; i < prim.positions.size(); ++i) {
      const glm::vec3& p = prim.positions[i];
      glm::vec3 n = i < prim.normals.size() ? prim.normals[i] : glm::vec3(0, 1, 0);
      glm::vec2 uv = i < prim.uvs.size() ? prim.uvs[i] : glm::vec2(0.0f);
      verts.push_back({p.x, p.y, p.z, n.x, n.y, n.z, uv.x, uv.y});
    }
    Draw d;
    d.firstIndex = idx.size();
    d.indexCount = GLsizei(prim.indices.size());
    d.material = prim.material;
    for (std::uint32_t i : prim.indices) idx.push_back(base + i);
    if (d.indexCount > 0) draws_.push_back(d);
    triangles_ += prim.indices.size() / 3;
  }
  vertices_ = gl::Buffer::create(GLsizeiptr(verts.size() * sizeof(Vertex)), verts.data(), 0);
  indices_ = gl::Buffer::create(GLsizeiptr(idx.size() * sizeof(std::uint32_t)), idx.data(), 0);
  vao_ = gl::createVertexArray();
  GLuint vao = vao_.id();
  glVertexArrayVertexBuffer(vao, 0, vertices_.id(), 0, sizeof(Vertex));
  glVertexArrayElementBuffer(vao, indices_.id());
  for (GLuint a = 0; a < 3; ++a) {
    glEnableVertexArrayAttrib(vao, a);
    glVertexArrayAttribBinding(vao, a, 0);
  }
  glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, offsetof(Vertex, px));
  glVertexArrayAttribFormat(vao, 1, 3, GL_FLOAT, GL_FALSE, offsetof(Vertex, nx));
  glVertexArrayAttribFormat(vao, 2, 2, GL_FLOAT, GL_FALSE, offsetof(Vertex, u));

  for (const SceneImage& img : scene.images) {
    if (img.width <= 0 || img.height <= 0 ||
        img.rgba.size() < size_t(img.width) * size_t(img.height) * 4) {
      textures_.emplace_back();
      continue;
    }
    int levels = 1;
    for (int s = std::max(img.width, img.height); s > 1; s >>= 1) ++levels;
    gl::Texture t = gl::Texture::create2D(GL_RGBA8, img.width, img.height, levels);
    glTextureSubImage2D(t.id(), 0, 0, 0, img.width, img.height, GL_RGBA, GL_UNSIGNED_BYTE,
                        img.rgba.data());
    glGenerateTextureMipmap(t.id());
    t.setFilter(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
    t.setWrap(GL_REPEAT);
    textures_.push_back(std::move(t));
  }
}

void SceneGpu::draw(const gl::Program& program, int textureUnit, bool patches) const {
  glBindVertexArray(vao_.id());
  if (patches) glPatchParameteri(GL_PATCH_VERTICES, 3);
  program.set("u_baseColorTex", textureUnit);
  static const Material kDefault{};
  for (const Draw& d : draws_) {
    const Material& m = d.material >= 0 && size_t(d.material) < materials_.size()
                            ? materials_[d.material]
                            : kDefault;
    const gl::Texture* tex = nullptr;
    if (m.baseColorTexture >= 0 && size_t(m.baseColorTexture) < textures_.size() &&
        textures_[m.baseColorTexture])
      tex = &textures_[m.baseColorTexture];
    program.set("u_baseColor", m.baseColorFactor);
    program.set("u_alphaMask", m.alphaMode == AlphaMode::Mask ? 1 : 0);
    program.set("u_alphaCutoff", m.alphaCutoff);
    program.set("u_hasTexture", tex ? 1 : 0);
    glBindTextureUnit(GLuint(textureUnit), tex ? tex->id() : 0);
    glDrawElements(patches ? GL_PATCHES : GL_TRIANGLES, d.indexCount, GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(d.firstIndex * sizeof(std::uint32_t)));
  }
  glBindVertexArray(0);
}

}  // namespace sl
