// The two-half omni maps' base (OmniRayMap.h).
#include "OmniRayMap.h"

#include <algorithm>
#include <stdexcept>

#include "core/Publish.h"

namespace sl {

OmniRayMap::OmniRayMap(const gl::ShaderLibrary& lib, const gl::ProgramDesc& depth,
                       std::string mapsLabel)
    : depthProgram_(lib, depth), mapsLabel_(std::move(mapsLabel)) {}

void OmniRayMap::fitFrame(const FrameContext& ctx, const glm::dvec3& x, const glm::dvec3& y,
                          const glm::dvec3& axis) {
  if (auto err = ctx.light.validate()) throw std::runtime_error(*err);
  if (!ctx.scene.bounds.valid()) throw std::runtime_error("scene: empty bounds (no geometry)");
  lightPosM_ = ctx.light.positionM;
  x_ = glm::vec3(x);
  y_ = glm::vec3(y);
  axis_ = glm::vec3(axis);
  float far = 0.0f;
  for (const glm::vec3& c : ctx.scene.bounds.corners())
    far = std::max(far, glm::length(c - lightPosM_));
  if (ctx.light.rangeM > 0.0f) far = std::min(far, ctx.light.rangeM);
  nearM_ = 0.0f;
  farM_ = 1.01f * std::max(far, 1e-3f);
}

void OmniRayMap::ensureHalves(int resolution, int halves, const std::string& what) {
  maps_.ensure(resolution, halves, what, "resolution");
}

void OmniRayMap::beginHalf(int half, int resolution) const {
  beginDepthPass(maps_.layerFramebuffer(half), resolution, resolution);
  depthProgram_.use();
  setMapping(depthProgram_);
}

void OmniRayMap::setMapping(const gl::Program& program) const {
  program.set("u_omniLight", lightPosM_);
  program.set("u_omniX", x_);
  program.set("u_omniY", y_);
  program.set("u_omniAxis", axis_);
  program.set("u_omniNearM", nearM_);
  program.set("u_omniFarM", farM_);
}

void OmniRayMap::publishHalves(FrameContext& ctx, const std::string& farKey,
                               const std::string& mapPrefix, int halves) const {
  publishNumber(ctx, farKey, farM_);
  for (int i = 0; i < halves; ++i)
    publishDepthLayer(ctx, mapPrefix + std::to_string(i) + ".map", maps_.texture(), i);
}

void OmniRayMap::bindHalves(const gl::Program& resolve, int firstUnit, const char* sampler) const {
  glBindTextureUnit(GLuint(firstUnit), maps_.texture().id());
  resolve.set(sampler, firstUnit);
  setMapping(resolve);
}

MemoryStats OmniRayMap::memory() const {
  MemoryStats m;
  maps_.addMemory(m, mapsLabel_);
  return m;
}

std::optional<std::string> OmniRayMap::reloadShaders(const gl::ShaderLibrary& lib) {
  return depthProgram_.rebuild(lib);
}

}  // namespace sl
