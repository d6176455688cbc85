// PSM / LiSPSM / TSM (PerspectiveShadowMap.h): fit the warp around view frustum ∩ scene,
// render exact depth through it, look up one perspective map.
#include "PerspectiveShadowMap.h"

#include <algorithm>
#include <stdexcept>

#include "algo/Focus.h"
#include "algo/warp/PostPerspective.h"
#include "core/Publish.h"
#include "core/SceneGpu.h"

namespace sl {

namespace {

ParamDecl focusDecl() {
  return floatParam("warp.focus", "TSM focus", "Warp", 0.5, {0.0, 1.0, 0.05})
      .withHelp(
          "TSM's focus point on the view axis at near + this share of (far - near); the warp maps "
          "it to the 80 % line of the map (Martin and Tan 2004). That is one warp with some n', "
          "i.e. some eta (Lloyd et al. 2006): published as warp.n_prime and warp.eta and analysed "
          "as such; to set eta itself use lispsm or psm.");
}

/// The unwarped map exactly as the uniform shadow map renders it (focused on what the camera
/// sees): what a warp that degenerates falls back to.
DepthMapView unwarpedMapView(const FrameContext& ctx, glm::vec3 towards) {
  LightFit fit;
  if (auto err = fitDirectionalLight(ctx.camera, ctx.aspect, ctx.scene.bounds, towards,
                                     FocusSettings{}, fit))
    throw std::runtime_error(*err);
  return depthMapView(fit);
}

}  // namespace

TechniqueInfo PerspectiveShadowMap::info(const std::string& id) {
  std::vector<ParamDecl> params = shadowMapParamDecls(2048);
  std::string name, description;
  if (id == "psm") {
    name = "Perspective shadow map (PSM)";
    description =
        "Stamminger and Drettakis 2002 as they wrote it (psm.method = post-perspective): the "
        "scene and the light taken into the camera's post-perspective space, where the light is "
        "a point (in front of the viewer), a point beyond infinity with its projection inverted "
        "(behind) or directional (across), the virtual camera slid back over casters behind "
        "the viewer (Kozlov 2004); or Lloyd et al.'s light-space reading, eta = 1 "
        "(psm.method = lispsm-eta1).";
    params.insert(
        params.begin(),
        {choiceParam("psm.method", "PSM method", "Warp", {"post-perspective", "lispsm-eta1"})
             .withHelp("post-perspective: Stamminger and Drettakis' PSM, the shadow map fitted in "
                       "the camera's post-perspective space (the paper). lispsm-eta1: Lloyd et "
                       "al.'s light-space warp with n' = n (warp.eta, default 1), their stand-in "
                       "for PSM with an overhead light; warp.eta is read only by this method."),
         warpEtaDecl(1.0),
         floatParam("psm.slide", "PSM extra slide-back", "Warp", 0.0, {0.0, 1000.0, 0.5})
             .withHelp(
                 "post-perspective only: metres the virtual camera moves back beyond what the "
                 "casters behind the viewer need (the paper: 0; Kozlov's remedy for texels "
                 "crowded at the near plane, a weaker warp)."),
         floatParam("psm.near", "PSM near plane", "Warp", 0.0, {0.0, 1000.0, 0.1})
             .withHelp("post-perspective only: 0 = the near plane pushed to the nearest scene part "
                       "in view (each primitive's bounding box against the view frustum: the paper "
                       "pushes it as far as the scene allows); > 0 = at this many metres instead "
                       "(receivers nearer than it lose resolution).")});
  } else if (id == "lispsm") {
    name = "Light space perspective shadow map (LiSPSM)";
    description =
        "Wimmer et al. 2004: one depth map warped along light-space z with n' = n + sqrt(f n) "
        "(warp.eta = 0), error spread evenly over depth (Lloyd et al. 2006, eq. 11).";
    params.insert(params.begin(), warpEtaDecl(0.0));
  } else if (id == "tsm") {
    name = "Trapezoidal shadow map (TSM)";
    description =
        "Martin and Tan 2004 in the light space of Lloyd et al. 2006: the warp that maps a focus "
        "point on the view axis to the map's 80 % line, i.e. one warp with the eta (eq. 11) "
        "its focus gives at this light, published as warp.eta.";
    params.insert(params.begin(), focusDecl());
  } else {
    throw std::invalid_argument("perspective shadow map: unknown id '" + id +
                                "' (psm, lispsm, tsm)");
  }
  TechniqueInfo info{id, name, description, params};
  info.passes = {{"warp", "Fit the warp",
                  "Light space of Lloyd et al.'s Fig. 3 around view frustum ∩ scene bounds: z "
                  "along the view vector projected, the warping frustum's n' from warp.eta (or "
                  "TSM's focus). Where the frustum looks square from the light (light behind or "
                  "in front of the viewer) the warp falls back to the uniform map, published as "
                  "warp.fallback = 1 (the Perspective warp panel says why).",
                  "perspective"},
                 {"shadow map", "Shadow map",
                  "Render the scene's depth through the warp's perspective: texels dense near the "
                  "viewer, sparse far away (uniform when warp.fallback = 1).",
                  "shadowmap"}};
  info.publications = {
      shadowMapPublicationDecl(),
      {"warp.n_prime", PublicationKind::Number,
       "n': distance from the warp's projection centre to the body, metres (inf = uniform)", "",
       nullptr},
      {"warp.eta", PublicationKind::Number,
       "eta of the warp used (-1 = uniform); tsm: eq. 11 inverted for the n' its focus gives", "",
       nullptr},
      {"warp.fallback", PublicationKind::Number,
       "1 when a warp was asked for but the uniform map was used (frustum square from the light)",
       "", nullptr},
      {"warp.fallback_cause", PublicationKind::Number,
       "why: 0 none, 1 light behind the viewer, 2 light in front, 3 TSM focus beyond its line, "
       "4 degenerate",
       "", nullptr}};
  if (id == "psm") {
    info.publications.push_back(
        {"psm.case", PublicationKind::Number,
         "post-perspective: what the light became, 0 point (in front), 1 inverted (behind), 2 "
         "directional (across), 3 uniform (along the view axis); -1 for lispsm-eta1",
         "", nullptr});
    info.publications.push_back({"psm.slide_back", PublicationKind::Number,
                                 "post-perspective: metres the virtual camera slid back", "",
                                 nullptr});
    info.publications.push_back({"psm.near_m", PublicationKind::Number,
                                 "post-perspective: the near plane, metres from the real eye", "",
                                 nullptr});
  }
  info.lights = {LightType::Directional};
  return info;
}

PerspectiveShadowMap::PerspectiveShadowMap(const gl::ShaderLibrary& lib, Kind kind)
    : SingleDepthMapTechnique(lib, "perspective shadow map"), kind_(kind) {}

void PerspectiveShadowMap::renderShadows(FrameContext& ctx) {
  if (kind_ == Kind::Psm && ctx.params.getInt("psm.method") == 0) {
    renderPostPerspective(ctx);
    return;
  }
  const glm::vec3 towards = ctx.light.directionalTowards();
  DepthMapView mapView;
  {
    auto pass = ctx.timer.scope("warp");
    // The body: view frustum ∩ scene bounds (the whole scene when the camera sees none of it),
    // every caster toward the light widening the depth range (warp::focusedBody).
    warp::WarpSettings settings;
    if (kind_ == Kind::Tsm) {
      settings.kind = warp::WarpKind::Tsm;
      settings.tsmFocusFraction = ctx.params.get("warp.focus");
    } else {
      settings.kind = warp::WarpKind::Eta;
      settings.eta = ctx.params.get("warp.eta");
    }
    if (auto err = warp::fitFocusedWarp(ctx.camera, ctx.aspect, ctx.scene.bounds,
                                        glm::dvec3(towards), settings, fit_))
      throw std::runtime_error(*err);

    if (fit_.uniform) {
      mapView = unwarpedMapView(ctx, towards);  // eta = -1 and the fallback are it
    } else {
      mapView = depthMapView(fit_.mapFrame());
    }
  }
  publishNumber(ctx, "warp.n_prime", fit_.nPrime);
  publishNumber(ctx, "warp.eta", fit_.eta);
  publishNumber(ctx, "warp.fallback", fit_.fallback ? 1.0 : 0.0);
  publishNumber(ctx, "warp.fallback_cause", double(int(fit_.fallbackCause)));
  if (kind_ == Kind::Psm) {
    publishNumber(ctx, "psm.case", -1.0);
    publishNumber(ctx, "psm.slide_back", 0.0);
    publishNumber(ctx, "psm.near_m", 0.0);
  }

  if (fit_.warped() && ctx.outlines) addWarpOutlines(fit_, *ctx.outlines);
  auto pass = ctx.timer.scope("shadow map");
  map_.render(ctx, ctx.params.getInt("resolution"), mapView, /*outline=*/!fit_.warped());
}

std::optional<std::string> PerspectiveShadowMap::fitPostPerspectiveFor(
    const Scene& scene, const Camera& camera, float aspect, glm::vec3 towards,
    const ParamSet& params, warp::PsmFit& out) {
  // Receivers: view frustum ∩ scene bounds with the near plane pushed to the nearest scene
  // part in view (the whole scene when the camera sees none of it); casters: those points
  // and where their rays towards the light leave the bounds.
  const warp::ViewFrustum view = warp::ViewFrustum::fromCamera(camera, aspect);
  double nearM = params.get("psm.near");
  if (nearM <= 0.0) {
    std::vector<Aabb> boxes;
    for (const MeshPrimitive& prim : scene.primitives) {
      Aabb b;
      for (const glm::vec3& p : prim.positions) b.extend(p);
      boxes.push_back(b);
    }
    nearM = warp::nearestDepthInView(view, boxes).value_or(camera.nearM);
  }
  nearM = std::clamp(nearM, double(camera.nearM), double(camera.farM));
  std::vector<glm::vec3> focus = intersectFrustumWithBox(
      camera.frustumCorners(aspect, float(nearM), camera.farM), scene.bounds);
  const auto box = scene.bounds.corners();
  if (focus.empty()) focus.assign(box.begin(), box.end());
  const std::vector<glm::dvec3> body(focus.begin(), focus.end());
  const std::vector<glm::dvec3> casters = warp::castersTowardsLight(
      body, glm::dvec3(towards), glm::dvec3(scene.bounds.min), glm::dvec3(scene.bounds.max));
  warp::PsmSettings settings;
  settings.extraSlideM = params.get("psm.slide");
  return warp::fitPostPerspective(view, body, casters, glm::dvec3(towards), settings, out);
}

void PerspectiveShadowMap::renderPostPerspective(FrameContext& ctx) {
  const glm::vec3 towards = ctx.light.directionalTowards();
  DepthMapView mapView;
  {
    auto pass = ctx.timer.scope("warp");
    if (auto err =
            fitPostPerspectiveFor(ctx.scene, ctx.camera, ctx.aspect, towards, ctx.params, psmFit_))
      throw std::runtime_error(*err);
    if (psmFit_.uniform()) {
      mapView = unwarpedMapView(ctx, towards);
    } else {
      mapView = depthMapView(psmFit_.mapFrame());
    }
  }
  // The light-space analysis does not describe this map: no n' or eta is published, the
  // fallback only where the post-perspective map is replaced by the uniform one.
  fit_ = warp::WarpFit{};
  fit_.uniform = psmFit_.uniform();
  fit_.fallback = psmFit_.uniform();
  fit_.fallbackReason = psmFit_.reason;
  publishNumber(ctx, "warp.fallback", psmFit_.uniform() ? 1.0 : 0.0);
  publishNumber(ctx, "warp.fallback_cause",
                psmFit_.uniform() ? double(int(warp::FallbackCause::Degenerate)) : 0.0);
  publishNumber(ctx, "psm.case", double(int(psmFit_.lightCase)));
  publishNumber(ctx, "psm.slide_back", psmFit_.slideBackM);
  publishNumber(ctx, "psm.near_m", psmFit_.nearM - psmFit_.slideBackM);
  auto pass = ctx.timer.scope("shadow map");
  map_.render(ctx, ctx.params.getInt("resolution"), mapView, /*outline=*/psmFit_.uniform());
}

}  // namespace sl
