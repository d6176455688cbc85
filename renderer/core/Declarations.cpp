// GL-free declarations of what a frame does and publishes (core/Renderer.h): the renderer's
// own passes, key patterns, and the declared cost of a publication request.
#include <algorithm>

#include "common/shared_constants.h"
#include "core/Renderer.h"
#include "core/Technique.h"

namespace sl {

const char* publicationKindName(PublicationKind kind) {
  switch (kind) {
    case PublicationKind::Image:
      return "image";
    case PublicationKind::ImageSet:
      return "image set";
    case PublicationKind::Curve:
      return "curve";
    case PublicationKind::Number:
      return "number";
  }
  return "?";
}

bool publicationKeyMatches(std::string_view pattern, std::string_view key) {
  // Glob with '*' only, iterative with one backtrack point (linear in practice).
  std::size_t p = 0, k = 0, star = std::string_view::npos, mark = 0;
  while (k < key.size()) {
    if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      mark = k;
    } else if (p < pattern.size() && pattern[p] == key[k]) {
      ++p, ++k;
    } else if (star != std::string_view::npos) {
      p = star + 1;
      k = ++mark;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

bool Publication::wants(std::string_view key) const {
  return std::any_of(requested.begin(), requested.end(), [key](const std::string& pattern) {
    return publicationKeyMatches(pattern, key);
  });
}

double Publication::number(const std::string& key, double fallback) const {
  const auto it = numbers.find(key);
  return it == numbers.end() ? fallback : it->second;
}

const PublicationDecl* TechniqueInfo::findPublication(std::string_view key) const {
  for (const PublicationDecl& d : publications)
    if (publicationKeyMatches(d.key, key)) return &d;
  return nullptr;
}

std::vector<PassDecl> rendererPassDecls() {
  return {
      {"gbuffer", "Camera G-buffer",
       "The scene from the camera: world position, normal and albedo of every pixel. Every "
       "later pass reads it (backward importance analysis, the lookup, the shading).",
       ""},
      {"resolve", "Lookup (resolve)",
       "Every pixel finds its light-space position, goes through the technique's lookup (the "
       "same warp or partition the map was built with) and compares its own plane, carried to "
       "the sampled texel's centre, with the depth stored there: the hard mask and the "
       "filtered visibility. Try the overlays (O): error against the exact reference, texels "
       "per pixel, the shadow-map grid on the scene.",
       ""},
      {"composite", "Shade and composite",
       "Lambert shading with the filtered visibility and sky ambient, and the overlay chosen "
       "in the Teaching bar drawn over it.",
       ""},
  };
}

std::vector<PassDecl> framePassDecls(const TechniqueInfo& technique) {
  std::vector<PassDecl> renderer = rendererPassDecls();
  std::vector<PassDecl> out{renderer.front()};
  for (const PassDecl& p : technique.passes)
    if (!p.duringResolve) out.push_back(p);
  out.push_back(renderer[1]);  // resolve
  for (const PassDecl& p : technique.passes)
    if (p.duringResolve) out.push_back(p);
  out.insert(out.end(), renderer.begin() + 2, renderer.end());
  return out;
}

std::vector<PassDecl> framePassDecls(const TechniqueInfo& technique, const ParamSet& params) {
  std::vector<PassDecl> out;
  for (PassDecl& p : framePassDecls(technique))
    if (p.onlyWhenParam.empty() || params.getInt(p.onlyWhenParam) == p.onlyWhenValue)
      out.push_back(std::move(p));
  return out;
}

const std::vector<PublicationDecl>& rendererPublicationDecls() {
  static const std::vector<PublicationDecl> decls = {
      {"aliasing.*", PublicationKind::Number,
       "Perspective aliasing m over the covered pixels: p50, p95 (from a GPU histogram of log2 "
       "m, " +
           std::to_string(SL_ALIASING_BINS_PER_OCTAVE) +
           " bins per octave: within half a bin), the exact max, the pixel count, the bin width "
           "in octaves. Without a covered pixel (pixel count 0) p50, p95 and max are not "
           "measured: absent, never 0.",
       "4 B x (4 + " + std::to_string(SL_ALIASING_BINS) + " bins)",
       [](const ParamSet&) { return std::uint64_t(4 * (4 + SL_ALIASING_BINS)); }},
      {"mask.*", PublicationKind::Number,
       "The hard mask's change since the previous frame (GPU count, CPU mirror "
       "compareConsecutiveMasks): changed_pixels (lit in one frame, shadowed in the other), "
       "compared_pixels (covered in both); absent on the first frame of a size.",
       "4 B x 2", [](const ParamSet&) { return std::uint64_t(8); }},
      {"camera.*", PublicationKind::Number,
       "The frame's camera: near_m, far_m, fov_deg (full vertical), aspect, height_px, "
       "forward.{x,y,z}, "
       "up.{x,y,z}.",
       "", nullptr},
      {"light.type", PublicationKind::Number,
       "The frame's light: its kind (0 directional, 1 spot, 2 point).", "", nullptr},
      {"light.azimuth_deg", PublicationKind::Number,
       "The frame's directional light: azimuth (degrees); absent for spot and point lights.", "",
       nullptr},
      {"light.elevation_deg", PublicationKind::Number,
       "The frame's directional light: elevation above the horizon (degrees); absent for spot "
       "and point lights.",
       "", nullptr},
      {"param.*", PublicationKind::Number,
       "The technique's parameter values of this frame, by key (enums as their index).", "",
       nullptr},
  };
  return decls;
}

const PublicationDecl* findFramePublication(const TechniqueInfo& technique, std::string_view key) {
  for (const PublicationDecl& d : rendererPublicationDecls())
    if (publicationKeyMatches(d.key, key)) return &d;
  return technique.findPublication(key);
}

std::uint64_t declaredPublicationBytes(const TechniqueInfo& technique, const ParamSet& params,
                                       const std::set<std::string>& requested) {
  std::uint64_t bytes = 0;
  std::vector<const PublicationDecl*> decls;
  for (const PublicationDecl& d : rendererPublicationDecls()) decls.push_back(&d);
  for (const PublicationDecl& d : technique.publications) decls.push_back(&d);
  for (const PublicationDecl* dp : decls) {
    const PublicationDecl& d = *dp;
    // A declaration is read when a requested pattern matches its key, or (for a declared
    // pattern such as "moment.*.*") when the two overlap: checked both ways.
    const bool asked = std::any_of(requested.begin(), requested.end(), [&](const std::string& r) {
      return publicationKeyMatches(r, d.key) || publicationKeyMatches(d.key, r);
    });
    if (asked && d.bytes) bytes += d.bytes(params);
  }
  return bytes;
}

std::pair<int, int> publishedImageSize(int width, int height) {
  const int n = (std::max(width, height) + kMaxPublishedImageSide - 1) / kMaxPublishedImageSide;
  if (n <= 1) return {width, height};
  return {(width + n - 1) / n, (height + n - 1) / n};
}

std::uint64_t publishedImageBytes(int width, int height) {
  const auto [w, h] = publishedImageSize(width, height);
  return 4 * std::uint64_t(w) * std::uint64_t(h);
}

PublicationDecl shadowMapPublicationDecl() {
  return {"shadow map", PublicationKind::Image,
          "The shadow map as rendered (depth 0..1; nearest-sampled to at most 2048 per side).",
          "4 B x min(resolution, 2048)^2", [](const ParamSet& p) {
            const int r = p.getInt("resolution");
            return publishedImageBytes(r, r);
          }};
}

}  // namespace sl
