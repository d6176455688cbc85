// The steps of a frame but the resolve and its statistics (FrameSteps.h): G-buffer, shadows,
// composite, outside view, present; and the end of a frame's transaction.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <mutex>
#include <span>
#include <stdexcept>
#include <utility>

#include "common/shared_constants.h"
#include "core/LightBinding.h"
#include "core/ParamBinding.h"
#include "core/SceneGpu.h"
#include "core/Technique.h"
#include "algo/metrics/BenchStats.h"
#include "gl/Gl.h"
#include "metrics/ShadowReference.h"
#include "core/FrameSteps.h"

namespace sl::frame {
namespace {

/// The outline segments as lines two pixels wide over `t`'s composite, on top (no depth
/// test: a frustum is never hidden by the scene).
void drawOutlines(RendererState& s, const Targets& t, const glm::mat4& viewProj,
                  const std::vector<OutlineSegment>& segments) {
  if (segments.empty()) return;
  struct Vertex {
    glm::vec3 position, colour;
  };
  std::vector<Vertex> vertices;
  vertices.reserve(segments.size() * 2);
  for (const OutlineSegment& seg : segments) {
    vertices.push_back({seg.a, seg.colour});
    vertices.push_back({seg.b, seg.colour});
  }
  const gl::Buffer buffer =
      gl::Buffer::create(GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(), 0);
  const gl::VertexArray vao = gl::createVertexArray();
  glVertexArrayVertexBuffer(vao.id(), 0, buffer.id(), 0, sizeof(Vertex));
  glEnableVertexArrayAttrib(vao.id(), 0);
  glEnableVertexArrayAttrib(vao.id(), 1);
  glVertexArrayAttribFormat(vao.id(), 0, 3, GL_FLOAT, GL_FALSE, offsetof(Vertex, position));
  glVertexArrayAttribFormat(vao.id(), 1, 3, GL_FLOAT, GL_FALSE, offsetof(Vertex, colour));
  glVertexArrayAttribBinding(vao.id(), 0, 0);
  glVertexArrayAttribBinding(vao.id(), 1, 0);

  glBindFramebuffer(GL_FRAMEBUFFER, t.composite.id());
  glViewport(0, 0, t.width, t.height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  s.outlineProgram.use();
  s.outlineProgram.set("u_viewProj", viewProj);
  glBindVertexArray(vao.id());
  const glm::vec2 pixel(2.0f / float(t.width), 2.0f / float(t.height));
  for (const glm::vec2 offset :
       {glm::vec2(0.0f), glm::vec2(pixel.x, 0.0f), glm::vec2(0.0f, pixel.y)}) {
    s.outlineProgram.set("u_pixelOffset", offset);
    glDrawArrays(GL_LINES, 0, GLsizei(vertices.size()));
  }
  glBindVertexArray(0);
}

}  // namespace

void gbufferStep(RendererState& s, Frame& f) {
  const CameraPass& c = *f.camera;
  Targets& t = c.targets;
  glBindFramebuffer(GL_FRAMEBUFFER, t.gbuffer.id());
  glViewport(0, 0, t.width, t.height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  const float zero[4] = {0, 0, 0, 0}, one = 1.0f;
  for (int i = 0; i < 3; ++i) glClearNamedFramebufferfv(t.gbuffer.id(), GL_COLOR, i, zero);
  glClearNamedFramebufferfv(t.gbuffer.id(), GL_DEPTH, 0, &one);
  s.gbufferProgram.use();
  s.gbufferProgram.set("u_viewProj", c.proj * c.view);
  s.gbufferProgram.set("u_cameraPos", c.eye);
  s.sceneGpu->draw(s.gbufferProgram, SL_UNIT_MATERIAL);
}

void shadowsStep(RendererState& s, Frame& f) {
  const ParamSet& params = paramsFor(s, s.techniqueId);
  const FrameSetup& setup = f.setup;
  const Targets& t = f.mainCamera.targets;
  FrameContext ctx{
      .scene = *s.scene,
      .sceneGpu = *s.sceneGpu,
      .camera = s.camera,
      .aspect = setup.aspect,
      .cameraView = f.mainCamera.view,
      .cameraProj = f.mainCamera.proj,
      .light = s.light,
      .width = setup.width,
      .height = setup.height,
      .gbuffer = {.position = t.position, .normal = t.normal},
      .previous = {.hard = t.prevHard, .aliasing = t.prevAliasing, .mapIndex = t.prevMapIndex},
      .params = params,
      .timer = *s.timer,
      .shaders = s.shaders,
      .frameIndex = s.frameIndex,
      .publication = setup.publishing ? &s.publication : nullptr,
      .outlines = &f.results.outlines,
  };
  for (const gl::Program* p : s.technique->programs()) bindParams(*p, params);
  s.technique->renderShadows(ctx);
}

void compositeStep(RendererState& s, Frame& f) {
  const CameraPass& cam = *f.camera;
  const Targets& t = cam.targets;
  glBindFramebuffer(GL_FRAMEBUFFER, t.composite.id());
  glViewport(0, 0, t.width, t.height);
  const gl::Program& c = s.compositeProgram;
  c.use();
  // Samplers: layout(binding = SL_UNIT_*) in composite.frag.
  glBindTextureUnit(SL_UNIT_G_POSITION, t.position.id());
  glBindTextureUnit(SL_UNIT_G_NORMAL, t.normal.id());
  glBindTextureUnit(SL_UNIT_G_ALBEDO, t.albedo.id());
  glBindTextureUnit(SL_UNIT_VISIBILITY, t.filtered.id());
  glBindTextureUnit(SL_UNIT_HARD, t.hard.id());
  glBindTextureUnit(SL_UNIT_REFERENCE, t.reference.id());
  glBindTextureUnit(SL_UNIT_ALIASING, t.aliasing.id());
  glBindTextureUnit(SL_UNIT_TEXEL, t.texel.id());
  glBindTextureUnit(SL_UNIT_MAP_INDEX, t.mapIndex.id());
  // The changed overlay: against the last complete frame's mask (none yet: against itself, empty).
  const bool hasPrevious = cam.mainCamera && f.setup.hadMask;
  glBindTextureUnit(SL_UNIT_PREV_HARD, hasPrevious ? t.prevHard.id() : t.hard.id());
  bindLight(c, s.light);
  c.set("u_cameraPos", cam.eye);
  bindParams(c, s.rendererParams);  // shading.ambient, view.overlay
  const int overlay = s.rendererParams.getInt("view.overlay");
  // The pages overlay's page grid per selectable map (none: 0), read by that overlay only:
  // not set (SL_MAX_DEPTH_MAPS uniforms) on every other frame.
  if (overlay == SL_OVERLAY_PAGES) {
    const std::vector<int> grid = s.technique ? s.technique->pageGrid() : std::vector<int>{};
    for (int i = 0; i < SL_MAX_DEPTH_MAPS; ++i)
      c.set(("u_pageCells[" + std::to_string(i) + "]").c_str(),
            i < int(grid.size()) ? grid[std::size_t(i)] : 0);
  }
  // A partial progressive frame draws no error pixels: its reference is of the whole frame.
  const bool shownComplete = !s.frameProgress || s.frameProgress->shownComplete;
  const bool referenceMatches =
      cam.mainCamera && shownComplete && s.referenceSignature == s.frameSignature;
  if (overlay == SL_OVERLAY_ERROR && !referenceMatches)
    c.set("u_overlay", SL_OVERLAY_NONE);  // no reference of this exact view
  if ((overlay == SL_OVERLAY_ALIASING || overlay == SL_OVERLAY_CHANGED) && !cam.mainCamera)
    c.set("u_overlay", SL_OVERLAY_NONE);  // m and the mask change of the main camera only
  glBindVertexArray(s.emptyVao.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
}

void outsideViewStep(RendererState& s, Frame& f) {
  const FrameSetup& setup = f.setup;
  const ParamSet& p = s.rendererParams;
  const std::vector<OutlineSegment> segments =
      outlineSegments(s.camera, setup.aspect, s.scene->bounds, f.results.outlines);
  const OutsideViewSettings settings{
      .azimuthDeg = float(p.get("view.outside.azimuth_deg")),
      .elevationDeg = float(p.get("view.outside.elevation_deg")),
      .zoom = float(p.get("view.outside.zoom")),
  };
  const Camera cam = fitOutsideCamera(s.camera, setup.aspect, segments, settings);
  if (auto err = cam.validate()) throw std::runtime_error(*err);
  s.ensureOutsideTargets(setup.width, setup.height);
  CameraPass outside{.targets = s.outsideTargets,
                     .view = cam.view(),
                     .proj = cam.projection(setup.aspect),
                     .eye = cam.position,
                     .mainCamera = false};
  f.camera = &outside;
  for (void (*step)(RendererState&, Frame&) : {gbufferStep, resolveStep, compositeStep}) {
    if (cancelRequested(s)) break;
    step(s, f);
  }
  f.camera = &f.mainCamera;
  if (cancelRequested(s)) return;  // renderFrame drops the frame
  drawOutlines(s, s.outsideTargets, outside.proj * outside.view, segments);
  f.results.outsideCamera = cam;
  s.lastFrameOutside = true;
}

void presentStep(RendererState& s, Frame& f) {
  const FrameSetup& setup = f.setup;
  const Targets& shown = s.lastFrameOutside ? s.outsideTargets : f.mainCamera.targets;
  const bool scaled = setup.presentWidth != setup.width || setup.presentHeight != setup.height;
  const unsigned target = setup.hostFramebuffer;
  if (glCheckNamedFramebufferStatus(target, GL_DRAW_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE)
    glBlitNamedFramebuffer(shown.composite.id(), target, 0, 0, setup.width, setup.height, 0, 0,
                           scaled ? setup.presentWidth : setup.width,
                           scaled ? setup.presentHeight : setup.height, GL_COLOR_BUFFER_BIT,
                           scaled ? GL_LINEAR : GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, target);
}

std::optional<std::string> stepFailureMessage(const RendererState& s, StepFailure failure,
                                              const std::exception& e) {
  switch (failure) {
    case StepFailure::NamesTechnique:
      return "technique '" + s.techniqueId + "': " + e.what();
    case StepFailure::NamesOutsideView:
      return std::string("outside view: ") + e.what();
    case StepFailure::Propagates:
      break;
  }
  return std::nullopt;
}

std::string frameSignatureOf(const RendererState& s, const ParamSet& params, int width,
                             int height) {
  const Camera& c = s.camera;
  char buf[512];
  std::snprintf(buf, sizeof buf, "%p|%s|%u|%d|%d|%g,%g,%g|%g,%g,%g|%g,%g,%g|%g|%s",
                static_cast<const void*>(s.scene.get()), s.techniqueId.c_str(), params.revision(),
                width, height, c.position.x, c.position.y, c.position.z, c.target.x, c.target.y,
                c.target.z, c.up.x, c.up.y, c.up.z, c.fovYDeg, s.light.describe().c_str());
  return buf;
}

void endFrame(RendererState& s, bool complete) {
  const TechniqueEntry* entry = findEntry(s, s.techniqueId);
  const bool carriesState = s.technique && entry && entry->info.temporalState;
  if (!complete) {
    if (carriesState) s.technique->discardFrame();
    return;
  }
  Targets& t = s.targets;
  for (auto [from, to] : {std::pair{&t.hard, &t.prevHard}, std::pair{&t.aliasing, &t.prevAliasing},
                          std::pair{&t.mapIndex, &t.prevMapIndex}})
    glCopyImageSubData(from->id(), GL_TEXTURE_2D, 0, 0, 0, 0, to->id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                       t.width, t.height, 1);
  t.committed = true;
  if (carriesState) s.technique->commitFrame();
}

}  // namespace sl::frame
