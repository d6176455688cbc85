#include "SceneGpu.h"

#include <cmath>

#include "algo/MeshSplit.h"

namespace sl {

namespace {
struct Vertex {
  float px, py, pz;
  float nx, ny, nz;
  float u, v;
};
}  // namespace

SceneGpu::Mesh SceneGpu::upload(const Scene& scene, float splitEdgeM) const {
  Mesh mesh;
  std::vector<Vertex> verts;
  std::vector<std::uint32_t> idx;
  for (const MeshPrimitive& prim : scene.primitives) {
    TriangleMesh src{prim.positions, prim.normals, prim.uvs, prim.indices};
    TriangleMesh m = splitEdgeM > 0.0f ? splitLongTriangles(src, splitEdgeM) : std::move(src);
    std::uint32_t base = std::uint32_t(verts.size());
    for (size_t i = 0; i < m.positions.size(); ++i) {
      const glm::vec3& p = m.positions[i];
      glm::vec3 n = i < m.normals.size() ? m.normals[i] : glm::vec3(0, 1, 0);
      glm::vec2 uv = i < m.uvs.size() ? m.uvs[i] : glm::vec2(0.0f);
      verts.push_back({p.x, p.y, p.z, n.x, n.y, n.z, uv.x, uv.y});
    }
    Draw d;
    d.firstIndex = idx.size();
    d.indexCount = GLsizei(m.indices.size());
    d.material = prim.material;
    for (std::uint32_t i : m.indices) idx.push_back(base + i);
    if (d.indexCount > 0) mesh.draws.push_back(d);
    mesh.triangles += m.indices.size() / 3;
  }
  mesh.vertices = gl::Buffer::create(GLsizeiptr(verts.size() * sizeof(Vertex)), verts.data(), 0);
  mesh.indices = gl::Buffer::create(GLsizeiptr(idx.size() * sizeof(std::uint32_t)), idx.data(), 0);
  mesh.vao = gl::createVertexArray();
  GLuint vao = mesh.vao.id();
  glVertexArrayVertexBuffer(vao, 0, mesh.vertices.id(), 0, sizeof(Vertex));
  glVertexArrayElementBuffer(vao, mesh.indices.id());
  for (GLuint a = 0; a < 3; ++a) {
    glEnableVertexArrayAttrib(vao, a);
    glVertexArrayAttribBinding(vao, a, 0);
  }
  glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, offsetof(Vertex, px));
  glVertexArrayAttribFormat(vao, 1, 3, GL_FLOAT, GL_FALSE, offsetof(Vertex, nx));
  glVertexArrayAttribFormat(vao, 2, 2, GL_FLOAT, GL_FALSE, offsetof(Vertex, u));
  return mesh;
}

SceneGpu::SceneGpu(const Scene& scene) : materials_(scene.materials) {
  const glm::vec3 diagonal = scene.bounds.max - scene.bounds.min;
  const float length = glm::length(diagonal);
  splitEdgeM_ = std::isfinite(length) && length > 0.0f ? length / kSplitEdgeDivisor : 0.0f;
  meshes_[0] = upload(scene, 0.0f);
  meshes_[1] = upload(scene, splitEdgeM_);

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

void SceneGpu::draw(const gl::Program& program, int textureUnit, bool patches, Geometry geometry,
                    const gl::Program* opaque) const {
  const Mesh& mesh = meshes_[geometry == Geometry::AsLoaded ? 0 : 1];
  glBindVertexArray(mesh.vao.id());
  if (patches) glPatchParameteri(GL_PATCH_VERTICES, 3);
  program.set("u_baseColorTex", textureUnit);
  static const Material kDefault{};
  const gl::Program* bound = &program;  // the caller bound it
  for (const Draw& d : mesh.draws) {
    const Material& m = d.material >= 0 && size_t(d.material) < materials_.size()
                            ? materials_[d.material]
                            : kDefault;
    const gl::Program* use = opaque && m.alphaMode != AlphaMode::Mask ? opaque : &program;
    if (use != bound) {
      use->use();
      bound = use;
    }
    if (use == opaque) {
      glDrawElements(patches ? GL_PATCHES : GL_TRIANGLES, d.indexCount, GL_UNSIGNED_INT,
                     reinterpret_cast<const void*>(d.firstIndex * sizeof(std::uint32_t)));
      continue;
    }
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
  if (bound != &program) program.use();
  glBindVertexArray(0);
}

}  // namespace sl
