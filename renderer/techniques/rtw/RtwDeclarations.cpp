// What RTW and DA-RTW do each frame and what they publish, declared without GL: the passes
// in frame order (ids = the gl::GpuTimer scopes of RtwShadowMap.cpp) with the explanation
// pass stepping shows, and every publication key with its readback cost.
#include <cstdint>

#include "RtwShadowMap.h"

namespace sl {

namespace {
std::uint64_t imRes(const ParamSet& p) {
  return std::uint64_t(p.getInt("im.resolution"));
}
std::uint64_t smRes(const ParamSet& p) {
  return std::uint64_t(p.getInt("resolution"));
}
std::uint64_t momentRes(const ParamSet& p) {
  return std::uint64_t(RtwShadowMap::momentResolution(p, int(imRes(p))));
}
/// Texels of every level of the moment chain of an m x m IM (sizes halve, rounding up).
std::uint64_t momentChainTexels(std::uint64_t m) {
  std::uint64_t texels = 0;
  for (std::uint64_t s = m;; s = (s + 1) / 2) {
    texels += s * s;
    if (s == 1) break;
  }
  return texels;
}
}  // namespace

std::vector<PassDecl> RtwShadowMap::passDecls(const std::string& id) {
  const bool da = id == "da-rtw";
  const bool backward = id == "rtw-backward" || da;
  std::vector<PassDecl> passes;
  if (da)
    passes.push_back(
        {"rotation estimate", "PCA, prediction and rotation",
         "DA-RTW: the moment sums of the last frame's importance (read behind a fence, no "
         "stall) give its mean and covariance and the principal axis (orange). rotation.mode = "
         "pca turns the light's image plane so the axis lies on the shadow map's x axis, unless "
         "e_x is above the vibration threshold. predicted: the last frame's importance is "
         "resampled into a dozen candidate turns, each turn's warp is built as this frame "
         "would build it, and the turn with the fewest expected wrong pixels at the last "
         "frame's shadow edges is taken when it beats the current frame by the margin.",
         "covariance"});
  passes.push_back({"focus", "Focus the light frustum",
                    da ? "The light's orthographic frustum, rotated by R, fitted to what the "
                         "camera sees of the scene."
                       : "The light's orthographic frustum fitted to what the camera sees of "
                         "the scene: the square the importance map and the warp cover.",
                    ""});
  passes.push_back(
      {"importance", "Importance map",
       backward
           ? "The camera's needs in light space: every camera pixel (every importance.stride-th) "
             "scatters the shadow-map density it wants (eye distance, orientation, shadow "
             "edges) into light space with atomicMax — straight into the two 1D maps (the max "
             "per column and row), and into the 2D IM only while a panel shows it. Bright = "
             "needs many texels."
           : "The camera's needs in light space: the scene rendered from the light, every "
             "texel projected into the camera for the density it wants there" +
                 std::string(id == "rtw-hybrid"
                                 ? " (hidden surfaces, behind the camera's G-buffer, get none)."
                                 : ".") +
                 " Bright = needs many texels.",
       "importance"});
  if (da)
    passes.push_back(
        {"moments", "Moment mip chain",
         "DA-RTW: the importance map (pca.source = im) or its block maxima (at most 128², "
         "block-max) into six textures I, xI, yI, x²I, y²I, xyI, summed 2×2 per level down to 1×1: "
         "the top holds the sums that give the mean and "
         "covariance of the importance (the next frame's rotation estimate reads it).",
         "moments"});
  if (!backward)
    passes.push_back(
        {"collapse", "Collapse to 1D",
         "The max over every column (x map) and row (y map) of the IM. A rectilinear warp can "
         "only give the separable density Ix·Iy: compare it with the raw IM.",
         "importance"});
  passes.push_back({"blur", "Blur and floor",
                    "A Gaussian blur of each 1D map (no abrupt steps in the warp) and a floor so "
                    "that no region collapses to zero texels: orange curves in Warp functions.",
                    "warp"});
  passes.push_back({"scan + warp", "Prefix sum → warp maps",
                    "A Blelloch scan of each 1D map; its normalised cumulative sum is the warp: "
                    "u' = u + warp(u). Its slope is the magnification; the dashed line is the "
                    "uniform map. Then the inverse tables: the unwarped light coordinate of "
                    "every warped texel centre.",
                    "warp"});
  passes.push_back(
      {"warped shadow map", "Warped shadow map",
       "Depth from the light, warped: important regions get more texels (large grid cells), "
       "beside the unwarped map for contrast. Each texel stores its triangle's depth plane at "
       "the texel's unwarped centre (exact whatever the tessellation); tessellation bends the "
       "silhouettes with the warp.",
       "shadowmap"});
  return passes;
}

std::vector<PublicationDecl> RtwShadowMap::publicationDecls(const std::string& id) {
  const bool da = id == "da-rtw";
  using K = PublicationKind;
  auto floats = [](std::uint64_t (*count)(const ParamSet&)) {
    return [count](const ParamSet& p) { return 4 * count(p); };
  };
  std::vector<PublicationDecl> d;
  d.push_back(shadowMapPublicationDecl());
  d.back().what = "The warped shadow map as rendered (depth 0..1).";
  d.push_back({"shadow map.uniform", K::Image,
               "An unwarped map of the same size, for contrast (rendered only while asked for).",
               "4 B x min(resolution, 2048)^2", [](const ParamSet& p) {
                 return publishedImageBytes(int(smRes(p)), int(smRes(p)));
               }});
  d.push_back({"importance", K::Image,
               "The 2D importance map before the collapse (backward analysis builds it only "
               "while asked for).",
               "4 B x im.resolution^2",
               floats([](const ParamSet& p) { return imRes(p) * imRes(p); })});
  for (const char* axis : {"x", "y"}) {
    const std::string a(axis);
    d.push_back({"importance." + a, K::Curve, "Collapsed 1D importance (max), before the blur.",
                 "4 B x im.resolution", floats(imRes)});
    d.push_back({"importance." + a + ".blurred", K::Curve, "1D importance after blur and floor.",
                 "4 B x im.resolution", floats(imRes)});
    d.push_back({"warp." + a, K::Curve, "Warp at the n+1 texel edges: u' = u + warp(u).",
                 "4 B x (im.resolution + 1)",
                 floats([](const ParamSet& p) { return imRes(p) + 1; })});
    d.push_back({"inverse." + a, K::Curve,
                 "Unwarped light coordinate of every warped texel centre.", "4 B x resolution",
                 floats(smRes)});
  }
  d.push_back({"light.extent.x", K::Number, "Light frustum width (m).", "", {}});
  d.push_back({"light.extent.y", K::Number, "Light frustum height (m).", "", {}});
  d.push_back({"light.area",
               K::Number,
               "Light frustum area, width x height (m^2): the texels per m^2 of the map are "
               "resolution^2 / light.area.",
               "",
               {}});
  for (const char* axis : {"x", "y"})
    d.push_back({"importance.halfmass." + std::string(axis), K::Number,
                 "Half-mass width of the collapsed " + std::string(axis) +
                     " importance: the shortest run of texels holding half its sum, as a share "
                     "of the map's side (small = sharp; after DA-RTW's rotation y lies across "
                     "the principal axis).",
                 "4 B x im.resolution", floats(imRes)});
  if (!da) return d;
  d.push_back({"importance.moments", K::Image,
               "The IM the PCA reads: the IM itself or its block maxima (≤ 128²), by pca.source.",
               "4 B x (im.resolution or min(im.resolution, 128))^2",
               floats([](const ParamSet& p) { return momentRes(p) * momentRes(p); })});
  d.push_back({"moment.*.*", K::ImageSet,
               "The moment chain: channel I, xI, yI, xxI, yyI, xyI at every level (0 = full).",
               "4 B x 6 x (texels of every level of the chain of the PCA's IM)",
               floats([](const ParamSet& p) { return 6 * momentChainTexels(momentRes(p)); })});
  d.push_back({"prediction.curve",
               K::Curve,
               "The predicted score (expected wrong pixels, relative units) of the turn to every "
               "angle from -90 to 90 degrees in 5-degree steps (37 values; 0 = no prediction).",
               "",
               {}});
  d.push_back({"prediction.searched",
               K::Curve,
               "The turns the prediction scored this frame: angle (degrees), score, pairs.",
               "",
               {}});
  for (const char* n :
       {"prediction.valid", "prediction.reason", "prediction.current_deg", "prediction.best_deg",
        "prediction.gain", "prediction.margin", "prediction.score.current", "prediction.score.best",
        "prediction.undersampled.current", "prediction.undersampled.best", "prediction.weight",
        "prediction.candidates", "prediction.m.p50", "prediction.m.p95", "prediction.ms",
        "prediction.pixels", "prediction.edge_pixels"})
    d.push_back(
        {n,
         K::Number,
         "The turn prediction from the last frame's importance (algo/rtw/TurnPrediction.h).",
         "",
         {}});
  d.push_back({"pca.scale.x",
               K::Number,
               "Scale of the PCA's x (metres per centred IM unit: the half extent of the frustum "
               "the moments were taken in; 1 with pca.metric = im-units).",
               "",
               {}});
  d.push_back({"pca.scale.y", K::Number, "Scale of the PCA's y (as pca.scale.x).", "", {}});
  for (const char* n : {"moment.I",
                        "moment.xI",
                        "moment.yI",
                        "moment.xxI",
                        "moment.yyI",
                        "moment.xyI",
                        "mean.x",
                        "mean.y",
                        "cov.xx",
                        "cov.xy",
                        "cov.yy",
                        "eigen.1",
                        "eigen.2",
                        "pca.valid",
                        "e_x",
                        "e_y",
                        "rotation.held",
                        "rotation.too_round",
                        "rotation.too_concentrated",
                        "pca.anisotropy",
                        "pca.spread",
                        "rotation.deg",
                        "rotation.step_deg",
                        "rotation.changes",
                        rtw::kHoldThresholdKey,
                        "pca.min_anisotropy",
                        "pca.min_spread",
                        "pca.axis_deg",
                        "rotation.mode",
                        "rotation.frames"})
    d.push_back({n, K::Number, "PCA and rotation (the last frame's moments).", "", {}});
  return d;
}

}  // namespace sl
