// The shared depth pass, the per-map lookup binding and depth publishing (ShadowPass.h).
#include "ShadowPass.h"

#include <stdexcept>

#include "algo/warp/PerspectiveWarp.h"
#include "common/shared_constants.h"
#include "core/Publish.h"
#include "core/SceneGpu.h"

namespace sl {

gl::ProgramDesc depthProgramDesc(bool opaque) {
  gl::ProgramDesc d{
      opaque ? "common/depth (opaque)" : "common/depth",
      {{GL_VERTEX_SHADER, "common/depth.vert"}, {GL_FRAGMENT_SHADER, "common/depth.frag"}},
      {},
      {}};
  if (opaque) d.defines.push_back("SL_DEPTH_OPAQUE");
  return d;
}

DepthProgram::DepthProgram(const gl::ShaderLibrary& lib)
    : masked_(lib, depthProgramDesc(false)), opaque_(lib, depthProgramDesc(true)) {}

void DepthProgram::draw(const SceneGpu& scene) const {
  scene.draw(masked_, SL_UNIT_MATERIAL, false, SceneGpu::Geometry::AsLoaded, &opaque_);
}

std::optional<std::string> DepthProgram::rebuild(const gl::ShaderLibrary& lib) {
  if (auto e = masked_.rebuild(lib)) return e;
  return opaque_.rebuild(lib);
}

void beginDepthPass(GLuint framebuffer, int width, int height, bool clear) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, width, height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  if (!clear) return;
  const float one = 1.0f;
  glClearNamedFramebufferfv(framebuffer, GL_DEPTH, 0, &one);
}

void renderDepth(const FrameContext& ctx, const DepthProgram& program, GLuint framebuffer,
                 int width, int height, const glm::mat4& lightViewProj) {
  renderDepth(ctx.sceneGpu, program, framebuffer, width, height, lightViewProj);
}

void renderDepth(const FrameContext& ctx, const gl::Program& program, GLuint framebuffer, int width,
                 int height, const glm::mat4& lightViewProj) {
  beginDepthPass(framebuffer, width, height);
  program.use();
  program.set("u_lightViewProj", lightViewProj);
  ctx.sceneGpu.draw(program, SL_UNIT_MATERIAL);
}

void renderDepth(const SceneGpu& scene, const DepthProgram& program, GLuint framebuffer, int width,
                 int height, const glm::mat4& lightViewProj) {
  beginDepthPass(framebuffer, width, height);
  program.use();
  program.set("u_lightViewProj", lightViewProj);
  program.draw(scene);
}

DepthMapView subRectView(const DepthMapView& full, glm::dvec2 uvMin, glm::dvec2 uvMax) {
  DepthMapView v = full;
  v.lightViewProj = glm::mat4(warp::uvRectCrop(uvMin, uvMax)) * full.lightViewProj;
  v.extentM = full.extentM * glm::vec2(uvMax - uvMin);
  return v;
}

DepthMapView focusedMapView(const FrameContext& ctx, const LightFit& fit, bool lispsm) {
  if (!lispsm) return depthMapView(fit);
  warp::WarpSettings settings;
  settings.kind = warp::WarpKind::Lispsm;
  warp::WarpFit warpFit;
  if (auto err =
          warp::fitFocusedWarp(ctx.camera, ctx.aspect, ctx.scene.bounds,
                               glm::dvec3(ctx.light.directionalTowards()), settings, warpFit))
    throw std::runtime_error(*err);
  return warpFit.warped() ? depthMapView(warpFit.mapFrame()) : depthMapView(fit);
}

float DepthMapView::depthPerMAtUnitW() const {
  if (depthPerMOverride > 0.0f) return depthPerMOverride;
  return sl::depthPerMAtUnitW(perspective, depthRangeM, nearM, farM);
}

DepthMapView depthMapView(const LightFit& fit) {
  DepthMapView v;
  v.lightViewProj = fit.viewProj;
  v.extentM = fit.extentM;
  v.depthRangeM = fit.depthRangeM > 0.0f ? fit.depthRangeM : 1.0f;
  v.perspective = fit.perspective;
  v.nearM = fit.nearM;
  v.farM = fit.farM;
  return v;
}

DepthMapView depthMapView(const DepthMapFrame& frame) {
  DepthMapView v;
  v.lightViewProj = frame.viewProj;
  v.perspective = true;
  v.extentM = frame.extentM;
  v.extentWPower = frame.extentWPower;
  v.depthPerMOverride = frame.depthPerM;
  v.depthWPower = frame.depthWPower;
  v.projective = frame.projective;
  return v;
}

void bindDepthLookup(const gl::Program& resolve, std::span<const DepthMapView> maps) {
  if (maps.size() > SL_MAX_DEPTH_MAPS)
    throw std::logic_error("a depth lookup over " + std::to_string(maps.size()) +
                           " maps; shaders/common/depth_map_test.glsl holds SL_MAX_DEPTH_MAPS = " +
                           std::to_string(SL_MAX_DEPTH_MAPS));
  for (size_t i = 0; i < maps.size(); ++i) {
    const std::string at = "[" + std::to_string(i) + "]";
    const DepthMapView& m = maps[i];
    const LightPlaneMatrix plane = lightPlaneMatrix(m.lightViewProj);
    resolve.set(("u_mapViewProj" + at).c_str(), m.lightViewProj);
    resolve.set(("u_mapNormalMatrix" + at).c_str(), plane.normal);
    resolve.set(("u_mapPlaneOffset" + at).c_str(), plane.offset);
    resolve.set(("u_mapExtentM" + at).c_str(), m.extentM);
    resolve.set(("u_mapDepthPerM" + at).c_str(), m.depthPerMAtUnitW());
    resolve.set(("u_mapExtentWPower" + at).c_str(), m.extentWPower);
    resolve.set(("u_mapDepthWPower" + at).c_str(), m.depthWPower);
    resolve.set(("u_mapProjective" + at).c_str(), m.projective ? 1 : 0);
  }
}

std::optional<std::string> DepthMapArray::sizeError(int resolution, int layers,
                                                    const std::string& what,
                                                    const std::string& lower) {
  const std::uint64_t bytes =
      4ull * std::uint64_t(resolution) * std::uint64_t(resolution) * std::uint64_t(layers);
  if (bytes <= kMaxDepthMapArrayBytes) return std::nullopt;
  return what + " of " + std::to_string(resolution) + "^2 need " + std::to_string(bytes >> 20) +
         " MiB of depth maps, more than the " + std::to_string(kMaxDepthMapArrayBytes >> 20) +
         " MiB one array may take (kMaxDepthMapArrayBytes); lower " + lower;
}

void DepthMapArray::ensure(int resolution, int layers, const std::string& what,
                           const std::string& lower) {
  if (maps_ && maps_.width() == resolution && maps_.layers() == layers) return;
  if (auto e = sizeError(resolution, layers, what, lower)) throw std::runtime_error(*e);
  maps_ = {};  // the old array goes before the new one comes
  layerFbos_.clear();
  layeredFbo_ = {};
  maps_ = gl::Texture::create2DArray(GL_DEPTH_COMPONENT32F, resolution, resolution, layers);
  for (int i = 0; i < layers; ++i) {
    gl::Framebuffer f = gl::Framebuffer::create();
    f.attachLayer(GL_DEPTH_ATTACHMENT, maps_, i);
    f.setDrawBuffers(0);
    f.checkComplete(what + ", layer " + std::to_string(i));
    layerFbos_.push_back(std::move(f));
  }
  layeredFbo_ = gl::Framebuffer::create();
  layeredFbo_.attach(GL_DEPTH_ATTACHMENT, maps_);
  layeredFbo_.setDrawBuffers(0);
  layeredFbo_.checkComplete(what + " (layered)");
}

void DepthMapArray::addMemory(MemoryStats& m, const std::string& label) const {
  if (maps_)
    m.add(label, gl::formatName(maps_.format()), maps_.width(), maps_.height(), maps_.layers(),
          gl::bytesPerTexel(maps_.format()));
}

SingleDepthMap::SingleDepthMap(const gl::ShaderLibrary& lib, std::string label)
    : label_(std::move(label)), program_(lib) {}

void SingleDepthMap::render(FrameContext& ctx, int resolution, const DepthMapView& view,
                            bool outline) {
  view_ = view;
  if (outline) ctx.addOutline(view.lightViewProj, OutlineRole::LightMap);
  if (!map_ || map_.width() != resolution) {
    map_ = gl::Texture::create2D(GL_DEPTH_COMPONENT32F, resolution, resolution);
    fbo_ = gl::Framebuffer::create();
    fbo_.attach(GL_DEPTH_ATTACHMENT, map_);
    fbo_.setDrawBuffers(0);
    fbo_.checkComplete(label_);
  }
  renderDepth(ctx, program_, fbo_.id(), resolution, resolution, view_.lightViewProj);
  publishDepth(ctx, "shadow map", map_);
}

void SingleDepthMap::bindLookup(const gl::Program& resolve, int firstUnit) const {
  bindDepthLookup(resolve, std::span(&view_, 1));
  glBindTextureUnit(GLuint(firstUnit), map_.id());
  resolve.set("u_shadowMap", firstUnit);
}

MemoryStats SingleDepthMap::memory() const {
  MemoryStats m;
  if (map_)
    m.add("shadow map", gl::formatName(map_.format()), map_.width(), map_.height(), 1,
          gl::bytesPerTexel(map_.format()));
  return m;
}

std::optional<std::string> SingleDepthMap::reloadShaders(const gl::ShaderLibrary& lib) {
  return program_.rebuild(lib);
}

}  // namespace sl
