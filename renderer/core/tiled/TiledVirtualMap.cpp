// The GL side of a tiled virtual shadow map (TiledVirtualMap.h).
#include "TiledVirtualMap.h"

#include "common/shared_constants.h"
#include "core/LightBinding.h"

namespace sl {

gl::ProgramDesc applyTileProgramDesc() {
  return {"common/tiled/apply_tile", {{GL_COMPUTE_SHADER, "common/tiled/apply_tile.comp"}}, {}, {}};
}

void appendTileBiasParams(std::vector<ParamDecl>& params) {
  for (ParamDecl& d : shadowMapParamDecls(4096))
    if (d.key != "resolution") params.push_back(std::move(d));
}

void TileDepthTarget::ensure(glm::ivec2 size, const std::string& label) {
  if (texture && texture.width() == size.x && texture.height() == size.y) return;
  texture = gl::Texture::create2D(GL_DEPTH_COMPONENT32F, size.x, size.y);
  fbo = gl::Framebuffer::create();
  fbo.attach(GL_DEPTH_ATTACHMENT, texture);
  fbo.setDrawBuffers(0);
  fbo.checkComplete(label);
}

void TileDepthTarget::addMemory(MemoryStats& m, const std::string& name) const {
  if (texture)
    m.add(name, gl::formatName(texture.format()), texture.width(), texture.height(), 1,
          gl::bytesPerTexel(texture.format()));
}

void tileApplyRange(glm::dvec2 uvMin, glm::dvec2 uvMax, glm::dvec2& applyMin,
                    glm::dvec2& applyMax) {
  constexpr double beyond = 1e30;
  applyMin = {uvMin.x <= 0.0 ? -beyond : uvMin.x, uvMin.y <= 0.0 ? -beyond : uvMin.y};
  applyMax = {uvMax.x >= 1.0 ? beyond : uvMax.x, uvMax.y >= 1.0 ? beyond : uvMax.y};
}

void endTiles(const ResolveTargets& t) {
  if (t.timer) t.timer->begin("resolve");
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer);
  glViewport(0, 0, t.width, t.height);
}

void clearResolveTargets(const ResolveTargets& t) {
  const GLuint empty = SL_MASK_EMPTY;
  const float one = 1.0f, zero[2] = {0.0f, 0.0f};
  glClearTexImage(t.outputs.hard.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &empty);
  glClearTexImage(t.outputs.filtered.id(), 0, GL_RED, GL_FLOAT, &one);
  glClearTexImage(t.outputs.aliasing.id(), 0, GL_RED, GL_FLOAT, zero);
  glClearTexImage(t.outputs.texel.id(), 0, GL_RG, GL_FLOAT, zero);
}

void applyTile(const gl::Program& apply, const ResolveTargets& t, const EyeDepthBuffer& eyeDepth,
               const TileApply& tile) {
  t.bindForCompute();
  apply.use();
  bindLight(apply, t.light);
  eyeDepth.bind(apply);
  apply.set("u_size", glm::ivec2(t.width, t.height));
  apply.set("u_rectMin", tile.rectMin);
  apply.set("u_rectMax", tile.rectMax);
  apply.set("u_fullFromEye",
            glm::mat4(glm::dmat4(tile.full.lightViewProj) * glm::dmat4(eyeDepth.worldFromEye())));
  apply.set("u_tileUvMin", glm::vec2(tile.uvMin));
  apply.set("u_tileUvMax", glm::vec2(tile.uvMax));
  apply.set("u_texelsPerFullUv", tile.texelsPerFullUv);
  apply.set("u_mapIndex", tile.mapIndex);
  apply.set("u_onlyEmpty", tile.onlyEmpty ? 1 : 0);
  apply.set("u_clampToTile", tile.clampToTile ? 1 : 0);
  apply.set("u_tileTexels", tile.texels);
  if (tile.onlyEmpty) glBindTextureUnit(SL_UNIT_HARD, t.outputs.hard.id());
  bindDepthLookup(apply, std::span(&tile.tile, 1));
  glBindTextureUnit(SL_UNIT_LOOKUP_FIRST, tile.texture.id());
  apply.set("u_shadowMap", SL_UNIT_LOOKUP_FIRST);
  const glm::ivec2 size = glm::max(tile.rectMax - tile.rectMin, glm::ivec2(0));
  if (size.x == 0 || size.y == 0) return;
  glDispatchCompute(GLuint((size.x + 7) / 8), GLuint((size.y + 7) / 8), 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

}  // namespace sl
