// The scene uploaded to the GPU: one interleaved vertex buffer (position, normal, uv),
// one index buffer, the material textures, and a draw list — twice: as loaded, and with
// its long triangles split (algo/MeshSplit) for the non-linear (warped) light passes.
#pragma once

#include <vector>

#include "gl/Gl.h"
#include "gl/ShaderLibrary.h"
#include "scene/Scene.h"

namespace sl {

class SceneGpu {
 public:
  /// Longest edge of the split geometry: the scene bounds' diagonal / kSplitEdgeDivisor.
  static constexpr float kSplitEdgeDivisor = 32.0f;
  enum class Geometry { AsLoaded, SplitLongTriangles };

  explicit SceneGpu(const Scene& scene);
  /// Draws every primitive with `program` bound; sets u_baseColor (vec4), u_alphaMask
  /// (int 0/1), u_alphaCutoff, u_hasTexture and binds the base colour texture to unit
  /// `textureUnit` (the program's u_baseColorTex must use that unit).
  /// `patches`: draws GL_PATCHES (3 vertices) for tessellation programs.
  /// `opaque` (optional, already holding the pass's uniforms): drawn instead of `program`
  /// for every primitive whose material is not alpha-tested (alphaMode MASK), with no
  /// material uniforms set; `program` is bound again at the end.
  void draw(const gl::Program& program, int textureUnit = 0, bool patches = false,
            Geometry geometry = Geometry::AsLoaded, const gl::Program* opaque = nullptr) const;
  std::size_t triangleCount() const { return meshes_[0].triangles; }
  std::size_t splitTriangleCount() const { return meshes_[1].triangles; }
  float splitEdgeM() const { return splitEdgeM_; }

 private:
  struct Draw {
    GLsizei indexCount = 0;
    std::size_t firstIndex = 0;
    int material = -1;
  };
  struct Mesh {
    gl::VertexArray vao;
    gl::Buffer vertices, indices;
    std::vector<Draw> draws;
    std::size_t triangles = 0;
  };
  Mesh upload(const Scene& scene, float splitEdgeM) const;
  Mesh meshes_[2];
  float splitEdgeM_ = 0.0f;
  std::vector<gl::Texture> textures_;
  std::vector<Material> materials_;
};

}  // namespace sl
