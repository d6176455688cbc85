// PSM / LiSPSM / TSM (PerspectiveShadowMap.h): fit the warp around view frustum ∩ scene,
// render exact depth through it, look up one perspective map.
#include "PerspectiveShadowMap.h"

#include <algorithm>
#include <stdexcept>

#include "algo/Focus.h"
#include "core/Publish.h"
#include "core/SceneGpu.h"

namespace sl {

ParamDecl warpEtaDecl(double defaultEta) {
  return {.key = "warp.eta",
          .label = "Warp eta",
          .group = "Warp",
          .type = ParamType::Float,
          .defaultValue = defaultEta,
          .minValue = -1.0,
          .maxValue = 1.0,
          .step = 0.05,
          .help =
              "Lloyd et al.'s eq. 11: -1 uniform (n' infinite), 0 LiSPSM (n' = n + sqrt(f n)), "
              "1 PSM (n' = n). Shared by psm, lispsm (which differ only in the default) and "
              "cascades with partition.warp (per partition: n and f of its slice) and "
              "face-partition (one warp per face); tsm derives it from warp.focus and publishes "
              "it (warp.eta)."};
}

namespace {

ParamDecl focusDecl() {
  return {.key = "warp.focus",
          .label = "TSM focus",
          .group = "Warp",
          .type = ParamType::Float,
          .defaultValue = 0.5,
          .minValue = 0.0,
          .maxValue = 1.0,
          .step = 0.05,
          .help =
              "TSM's focus point on the view axis at near + this share of (far - near); the "
              "warp maps it to the 80 % line of the map (Martin and Tan 2004). That is one "
              "warp with some n', i.e. some eta (Lloyd et al. 2006): published as warp.n_prime "
              "and warp.eta and analysed as such; to set eta itself use lispsm or psm."};
}

}  // namespace

TechniqueInfo PerspectiveShadowMap::info(const std::string& id) {
  std::vector<ParamDecl> params = shadowMapParamDecls(2048);
  std::string name, description;
  if (id == "psm") {
    name = "Perspective shadow map (PSM)";
    description =
        "Stamminger and Drettakis 2002 in the light space of Lloyd et al. 2006: one depth map "
        "warped by a perspective along light-space z with n' = n (warp.eta = 1); the "
        "singularity clamped (Kozlov).";
    params.insert(params.begin(), warpEtaDecl(1.0));
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
  info.lights = {LightType::Directional};
  return info;
}

PerspectiveShadowMap::PerspectiveShadowMap(const gl::ShaderLibrary& lib, Kind kind)
    : SingleDepthMapTechnique(lib, "perspective shadow map"), kind_(kind) {}

void addWarpOutlines(const warp::WarpFit& fit, FrameOutlines& out, int map) {
  // Light space (algo/warp): x across, y along the light (depth), z the warp's axis. The box
  // the warp was fitted in is the light's (unwarped) frustum; the warping frustum is the
  // wedge |x - cx| <= tanHalfX z' for z' = z - lo.z + n' in [n', n' + L], its side edges
  // meeting at the apex line z' = 0 (paper's Fig. 3).
  const glm::dvec3 X = fit.space.x, Y = fit.space.y, Z = fit.space.z;
  auto world = [&](double x, double y, double z) { return glm::vec3(x * X + y * Y + z * Z); };
  FrustumOutline box, warp;
  box.role = OutlineRole::LightMap;
  warp.role = OutlineRole::Warp;
  box.map = warp.map = map;
  std::array<glm::vec3, 4> apex;
  for (int i = 0; i < 8; ++i) {
    const int face = i & 3;
    const double sx = (face == 1 || face == 2) ? 1.0 : -1.0;
    const double y = face >= 2 ? fit.hi.y : fit.lo.y;
    const double z = i < 4 ? fit.lo.z : fit.hi.z;
    box.corners[size_t(i)] = world(sx > 0 ? fit.hi.x : fit.lo.x, y, z);
    const double zPrime = z - fit.lo.z + fit.nPrime;
    warp.corners[size_t(i)] = world(fit.cx + sx * fit.tanHalfX * zPrime, y, z);
    if (i < 4) apex[size_t(i)] = world(fit.cx, y, fit.lo.z - fit.nPrime);
  }
  warp.apex = apex;
  out.frusta.push_back(box);
  out.frusta.push_back(warp);
}

void PerspectiveShadowMap::renderShadows(FrameContext& ctx) {
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
      // The uniform map exactly as `uniform` renders it: eta = -1 and the fallback are it.
      LightFit uniformFit;
      if (auto err = fitDirectionalLight(ctx.camera, ctx.aspect, ctx.scene.bounds, towards,
                                         FocusSettings{}, uniformFit))
        throw std::runtime_error(*err);
      mapView = depthMapView(uniformFit);
    } else {
      mapView = depthMapView(fit_.mapFrame());
    }
  }
  publishNumber(ctx, "warp.n_prime", fit_.nPrime);
  publishNumber(ctx, "warp.eta", fit_.eta);
  publishNumber(ctx, "warp.fallback", fit_.fallback ? 1.0 : 0.0);
  publishNumber(ctx, "warp.fallback_cause", double(int(fit_.fallbackCause)));

  if (fit_.warped() && ctx.outlines) addWarpOutlines(fit_, *ctx.outlines);
  auto pass = ctx.timer.scope("shadow map");
  map_.render(ctx, ctx.params.getInt("resolution"), mapView, /*outline=*/!fit_.warped());
}

}  // namespace sl
