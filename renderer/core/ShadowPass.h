// Helpers shared by the shadow-map techniques: the depth-only light pass (exact depth at
// texel centres, alpha-tested casters), the per-map binding of the one bias model of every
// lookup (shaders/common/depth_map_test.glsl). Publishing: core/Publish.h.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "algo/Focus.h"
#include "algo/ShadowBias.h"
#include "core/Technique.h"

namespace sl {

/// shaders/common/depth.vert + depth.frag: transforms by u_lightViewProj, alpha test.
/// `opaque`: built with SL_DEPTH_OPAQUE, no alpha test (an empty fragment shader).
gl::ProgramDesc depthProgramDesc(bool opaque = false);

/// The depth-only light pass's program, built twice: with the alpha test, for primitives
/// whose material is alpha-tested (MASK), and without it for all others. A fragment shader
/// that may discard keeps the rasteriser from testing depth before shading; on llvmpipe the
/// opaque build renders fvsm's tile depth 2.3x faster (docs/techniques/fvsm.md).
/// Every uniform is set on both builds.
class DepthProgram {
 public:
  explicit DepthProgram(const gl::ShaderLibrary& lib);
  template <class T>
  void set(const char* name, const T& value) const {
    masked_.set(name, value);
    opaque_.set(name, value);
  }
  /// Binds the alpha-tested build (SceneGpu::draw switches per primitive).
  void use() const { masked_.use(); }
  /// Draws the scene: alpha-tested primitives with the masked build, the rest opaque.
  void draw(const SceneGpu& scene) const;
  std::vector<const gl::Program*> programs() const { return {&masked_, &opaque_}; }
  std::optional<std::string> rebuild(const gl::ShaderLibrary& lib);

 private:
  gl::Program masked_, opaque_;
};

/// Binds `framebuffer`, sets the viewport and the depth-only state (less, write, no
/// culling) and clears depth to 1 (unless `clear` is false: a page pool keeping its cache):
/// the start of every depth pass.
void beginDepthPass(GLuint framebuffer, int width, int height, bool clear = true);

/// Clears and renders the scene's depth into `framebuffer` (width x height). No bias: the
/// map holds the exact depth at each texel centre; the lookup applies the bias model.
void renderDepth(const FrameContext& ctx, const DepthProgram& program, GLuint framebuffer,
                 int width, int height, const glm::mat4& lightViewProj);
/// The same with a technique's own depth program (the cube's distance), one build for all.
void renderDepth(const FrameContext& ctx, const gl::Program& program, GLuint framebuffer, int width,
                 int height, const glm::mat4& lightViewProj);
/// The same for a technique that renders maps outside renderShadows (ResolveTargets::sceneGpu).
void renderDepth(const SceneGpu& scene, const DepthProgram& program, GLuint framebuffer, int width,
                 int height, const glm::mat4& lightViewProj);

/// One depth map of a lookup (common/depth_map_test.glsl): its own light matrix and
/// extent. A technique with several maps (an array, an atlas, cascades, faces) has one view
/// per map; its GLSL selection function picks the index. The matrix may be orthographic
/// (directional) or perspective (a spot's frustum, a cube face): the lookup divides by the
/// map's clip w.
struct DepthMapView {
  glm::mat4 lightViewProj{1.0f};    ///< world -> the map's clip space
  glm::vec2 extentM{1.0f};          ///< metres per unit of the map's light uv, at clip w = 1
  float depthRangeM = 1.0f;         ///< orthographic: metres per unit of window depth
  bool perspective = false;         ///< a perspective map (sl::LightFit::perspective)
  float nearM = 0.0f, farM = 0.0f;  ///< perspective: the frustum's near and far planes
  /// Set instead of nearM/farM by a map whose depth is not glm's perspective depth (a
  /// light-space warp): window depth per metre at clip w = 1; 0 = derive it.
  float depthPerMOverride = 0.0f;
  /// How metres per uv and depth per metre scale with clip w (sl::DepthMapFrame).
  glm::vec2 extentWPower{1.0f};
  float depthWPower = 2.0f;
  /// A general projective map (sl::DepthMapFrame::projective): local texel and depth per
  /// metre from the matrix's derivatives at the receiver.
  bool projective = false;
  /// Window depth per metre along the light at clip w = 1 (sl::depthPerMAtUnitW).
  float depthPerMAtUnitW() const;
};
/// The view of one map covering this frame's fit.
DepthMapView depthMapView(const LightFit& fit);
/// The map covering only light uv [uvMin, uvMax] of `full` (a tile of a virtual map; uv
/// may leave [0, 1] for an overlap): clip' = s clip with s = warp::uvRectCrop (scaling and
/// shifting x and y, the shift times w, so it holds for orthographic and perspective
/// matrices: a LiSPSM-warped map's tiles); the same depth, extentM times the rectangle's
/// size.
DepthMapView subRectView(const DepthMapView& full, glm::dvec2 uvMin, glm::dvec2 uvMax);
/// The view of a map rendered through a light-space warp (sl::DepthMapFrame: PSM, LiSPSM,
/// TSM, warped cascades): perspective, its own w powers and depth per metre.
DepthMapView depthMapView(const DepthMapFrame& frame);
/// A directional light's focused map: `fit` itself (orthographic), or with `lispsm` the
/// LiSPSM warp around view frustum ∩ scene (algo/warp fitFocusedWarp: what `lispsm` renders,
/// n' = n'_LiSPSM) — the virtual map of fvsm and virtual-tiled with their warp = lispsm
/// (Giegl & Wimmer 2007 use it in all their results). Where LiSPSM falls back to uniform
/// (the light nearly along the view), `fit`. Throws std::runtime_error with the fit's error.
DepthMapView focusedMapView(const FrameContext& ctx, const LightFit& fit, bool lispsm);
/// Sets the per-map uniforms of common/depth_map_test.glsl (u_map*[i] for map i). The
/// maps' textures and the shared parameters (bias.*, pcf: bindParams) are bound elsewhere.
/// Throws std::logic_error for more than SL_MAX_DEPTH_MAPS maps.
void bindDepthLookup(const gl::Program& resolve, std::span<const DepthMapView> maps);

/// The largest array of depth maps a technique allocates (DepthMapArray): Mesa's llvmpipe
/// completes the framebuffer of a 2 GiB array (cascades, 2 x 16384^2) and not of a 3 GiB one
/// (3 x 16384^2: incomplete attachment, status 0x36054).
inline constexpr std::uint64_t kMaxDepthMapArrayBytes = 2ull << 30;

/// An array of square depth maps (DEPTH_COMPONENT32F, one layer per map: cascades, faces,
/// cube faces, paraboloid halves) with a framebuffer per layer and one over every layer (for
/// layered rendering), reallocated only when the resolution or the layer count changes.
class DepthMapArray {
 public:
  /// "<what> of <res>^2 need <N> MiB of depth maps, more than the <M> MiB one array may take
  /// (kMaxDepthMapArrayBytes); lower <lower>" when `layers` maps of `resolution`^2 exceed
  /// kMaxDepthMapArrayBytes, else nothing. No GL: a technique's checkParams refuses the parameters
  /// with it before the first frame (the worst case of its maps), and ensure() before allocating.
  static std::optional<std::string> sizeError(int resolution, int layers, const std::string& what,
                                              const std::string& lower);

  /// (Re)allocates `layers` maps of `resolution`^2. `what` names them in messages and
  /// framebuffer labels ("cascades: 4 partitions"); `lower` says what to lower when the
  /// array would exceed kMaxDepthMapArrayBytes ("resolution or partitions"): std::runtime_error
  /// with sizeError's message.
  void ensure(int resolution, int layers, const std::string& what, const std::string& lower);
  explicit operator bool() const { return bool(maps_); }
  const gl::Texture& texture() const { return maps_; }
  GLuint layerFramebuffer(int layer) const { return layerFbos_.at(std::size_t(layer)).id(); }
  GLuint layeredFramebuffer() const { return layeredFbo_.id(); }
  /// Adds the array to `m` as `label` (every byte: resolution^2 x layers x 4 B).
  void addMemory(MemoryStats& m, const std::string& label) const;

 private:
  gl::Texture maps_;
  std::vector<gl::Framebuffer> layerFbos_;
  gl::Framebuffer layeredFbo_;
};

/// One square depth map with its framebuffer and depth program, looked up by
/// shaders/common/single_depth_map.glsl: what `uniform` and the perspective warps share.
class SingleDepthMap {
 public:
  /// `label` names the map in framebuffer errors.
  SingleDepthMap(const gl::ShaderLibrary& lib, std::string label);
  /// (Re)allocates the map when `resolution` changes, renders the scene's exact depth
  /// through view.lightViewProj and publishes it as "shadow map" when that key is requested.
  /// With `outline`, adds the map's frustum (the inverse of its matrix) to the outside view.
  void render(FrameContext& ctx, int resolution, const DepthMapView& view, bool outline = true);
  /// The lookup's per-map uniforms and the map on `firstUnit` (as u_shadowMap).
  void bindLookup(const gl::Program& resolve, int firstUnit) const;
  MemoryStats memory() const;
  std::optional<std::string> reloadShaders(const gl::ShaderLibrary& lib);
  const DepthProgram& program() const { return program_; }

 private:
  std::string label_;
  DepthProgram program_;
  gl::Texture map_;
  gl::Framebuffer fbo_;
  DepthMapView view_;
};

/// A technique whose lookup is one SingleDepthMap (uniform, the perspective warps): it fits
/// a view and calls map_.render(); the lookup binding, programs, memory and reload are these.
class SingleDepthMapTechnique : public Technique {
 public:
  void bindLookup(const gl::Program& resolve, int firstUnit) const override {
    map_.bindLookup(resolve, firstUnit);
  }
  std::vector<const gl::Program*> programs() const override { return map_.program().programs(); }
  MemoryStats memory() const override { return map_.memory(); }
  std::optional<std::string> reloadShaders(const gl::ShaderLibrary& lib) override {
    return map_.reloadShaders(lib);
  }

 protected:
  SingleDepthMapTechnique(const gl::ShaderLibrary& lib, std::string label)
      : map_(lib, std::move(label)) {}
  SingleDepthMap map_;
};

}  // namespace sl
