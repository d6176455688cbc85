// Measuring configurations frame by frame; see Measure.h.
#include "Measure.h"

#include <cmath>
#include <cstring>
#include <vector>

#include "CliCommon.h"
#include "algo/InputFile.h"
#include "metrics/ErrorMetrics.h"

namespace sl::cli {

static_assert(kStatsMaskShadowed == kMaskShadowed && kStatsMaskUncovered == kMaskUncovered,
              "BenchStats and ErrorMetrics must read masks alike");

namespace {

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    std::size_t p = text.find(sep, start);
    out.push_back(text.substr(start, p == std::string::npos ? std::string::npos : p - start));
    if (p == std::string::npos) return out;
    start = p + 1;
  }
}

/// The parameter set a key belongs to: the technique's own, else the shared renderer's.
ParamSet* paramSetFor(Renderer& r, const std::string& key) {
  if (r.params().has(key)) return &r.params();
  if (r.rendererParams().has(key)) return &r.rendererParams();
  return nullptr;
}

/// Every live runner's renderer. Renderers on one context share GL's single debug callback
/// (the last one created receives every message), so a frame's GL errors are collected
/// from all of them.
std::vector<Renderer*>& liveRenderers() {
  static std::vector<Renderer*> list;
  return list;
}

std::vector<std::string> drainGlErrors() {
  std::vector<std::string> all;
  for (Renderer* r : liveRenderers())
    for (std::string& e : r->takeGlErrors()) all.push_back(std::move(e));
  return all;
}

}  // namespace

std::string firstFailureText(const std::vector<const FrameSample*>& frames) {
  for (std::size_t k = 0; k < frames.size(); ++k)
    if (frames[k]->failed())
      return cutText("frame " + std::to_string(k) + ": " + frames[k]->renderError);
  return "";
}

std::string ConfigSpec::paramsText() const {
  std::string out;
  for (const auto& [k, v] : sets) out += (out.empty() ? "" : " ") + k + "=" + v;
  return out;
}

std::optional<std::string> validateConfig(const ConfigSpec& spec) {
  const TechniqueInfo* info = Renderer::findTechnique(spec.techniqueId);
  if (!info) {
    std::string known;
    for (const TechniqueInfo& t : Renderer::techniques())
      known += (known.empty() ? "" : ", ") + t.id;
    return "unknown technique '" + spec.techniqueId + "' (known: " + known + ")";
  }
  ParamSet own(info->params), shared(rendererParamDecls());
  for (const auto& [k, v] : spec.sets) {
    ParamSet* set = own.has(k) ? &own : shared.has(k) ? &shared : nullptr;
    if (!set) return "technique '" + spec.techniqueId + "' has no parameter '" + k + "'";
    if (auto e = set->setFromString(k, v)) return *e;
  }
  // Values in range that the technique cannot render together (fvsm.grid=3).
  if (auto e = checkTechniqueParams(*info, own))
    return "technique '" + spec.techniqueId + "': " + *e;
  return std::nullopt;
}

std::vector<ConfigSpec> expandTechniqueSweep(const std::string& text, const std::string& opt) {
  std::vector<std::string> parts = split(text, ':');
  if (parts[0].empty())
    throw UsageError(opt + ": expected ID[:KEY=V1,V2,...]..., got '" + text + "'");
  std::vector<std::pair<std::string, std::vector<std::string>>> axes;
  for (std::size_t i = 1; i < parts.size(); ++i) {
    auto eq = parts[i].find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == parts[i].size())
      throw UsageError(opt + ": expected KEY=V1,V2,... after ':', got '" + parts[i] + "'");
    std::vector<std::string> values = split(parts[i].substr(eq + 1), ',');
    for (const std::string& v : values)
      if (v.empty()) throw UsageError(opt + ": empty value in '" + parts[i] + "'");
    axes.push_back({parts[i].substr(0, eq), values});
  }
  std::vector<ConfigSpec> out;
  std::vector<std::size_t> idx(axes.size(), 0);
  while (true) {
    ConfigSpec c;
    c.techniqueId = parts[0];
    for (std::size_t a = 0; a < axes.size(); ++a)
      c.sets.push_back({axes[a].first, axes[a].second[idx[a]]});
    c.label = c.techniqueId + (c.sets.empty() ? "" : " " + c.paramsText());
    if (auto e = validateConfig(c)) throw UsageError(opt + ": " + *e);
    out.push_back(std::move(c));
    // Odometer: the last key varies fastest.
    std::size_t a = axes.size();
    while (a > 0 && ++idx[a - 1] == axes[a - 1].second.size()) idx[--a] = 0;
    if (a == 0) break;
  }
  return out;
}

const std::vector<std::uint8_t>& ReferenceCache::evaluate(const FrameReadback& frame,
                                                          const Light& light) {
  auto same = [](const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(glm::vec4)) == 0);
  };
  if (valid_ && light_ == light && same(positions_, frame.positions) &&
      same(normals_, frame.normals))
    return mask_;
  reference_.evaluate(frame.positions, frame.normals, light, mask_);
  positions_ = frame.positions;
  normals_ = frame.normals;
  light_ = light;
  valid_ = true;
  ++evaluations_;
  return mask_;
}

ConfigRunner::ConfigRunner(ConfigSpec spec, std::shared_ptr<const Scene> scene,
                           const std::optional<Light>& light)
    : spec_(std::move(spec)), renderer_(std::make_unique<Renderer>()) {
  liveRenderers().push_back(renderer_.get());
  renderer_->setScene(std::move(scene));
  if (light) renderer_->setLight(*light);
  if (auto e = renderer_->setTechnique(spec_.techniqueId)) throw UsageError(*e);
  // A light the technique cannot render is refused up front (renderFrame would too).
  if (const TechniqueInfo* info = Renderer::findTechnique(spec_.techniqueId))
    if (auto e = checkLightSupport(*info, renderer_->light().type)) throw UsageError(*e);
  for (const auto& [k, v] : spec_.sets) {
    ParamSet* set = paramSetFor(*renderer_, k);
    if (!set)
      throw UsageError("technique '" + spec_.techniqueId + "' has no parameter '" + k + "'");
    if (auto e = set->setFromString(k, v)) throw UsageError(*e);
  }
}

ConfigRunner::~ConfigRunner() {
  std::erase(liveRenderers(), renderer_.get());
}

void ConfigRunner::forgetPreviousFrame() {
  previousMask_.clear();
  previousReference_.clear();
}

FrameSample ConfigRunner::renderAndMeasure(const Camera& camera, const MeasureOptions& options,
                                           ReferenceCache* reference) {
  FrameSample s;
  Renderer& r = *renderer_;
  r.setCamera(camera);
  // Only the numbers (rotation, PCA): no image or curve is read back while measuring.
  std::set<std::string> numberKeys;
  if (options.publishing && publishingWanted_)
    if (const TechniqueInfo* info = Renderer::findTechnique(r.techniqueId()))
      for (const PublicationDecl& d : info->publications)
        if (d.kind == PublicationKind::Number) numberKeys.insert(d.key);
  r.requestPublications(std::move(numberKeys));
  auto collectGlErrors = [&s] {
    for (std::string& e : drainGlErrors()) s.glErrors.push_back(std::move(e));
  };
  collectGlErrors();  // anything since the last frame (set-up) counts against this one
  if (auto e = r.renderFrame(options.width, options.height, 0)) s.renderError = *e;
  collectGlErrors();
  if (s.failed()) {
    // Nothing was measured: the renderer drew a neutral frame and its stats, readback and
    // publication are an older frame's. The next frame has no previous one to compare with.
    forgetPreviousFrame();
    return s;
  }
  const FrameStats& st = r.stats();
  s.totalMs = st.totalMs;
  s.passes = st.passes;
  s.timingMethod = st.timingMethod;
  s.texels = st.memory.texels();
  s.bytes = st.memory.bytes();

  if (options.publishing && publishingWanted_) {
    const auto& numbers = r.publication().numbers;
    for (const auto& [k, v] : numbers)
      if (!std::isfinite(v)) s.nonFiniteNumbers.push_back(k);
    auto numberOr = [&numbers](const char* key, double fallback) {
      auto n = numbers.find(key);
      return n == numbers.end() ? fallback : n->second;
    };
    s.lightAreaM2 = numberOr("light.area", s.lightAreaM2);
    s.halfMassX = numberOr("importance.halfmass.x", s.halfMassX);
    s.halfMassY = numberOr("importance.halfmass.y", s.halfMassY);
    s.anisotropy = numberOr("pca.anisotropy", s.anisotropy);
    auto it = numbers.find("rotation.deg");
    if (it != numbers.end()) {
      s.hasRotation = true;
      s.rotationDeg = it->second;
      if (auto e = numbers.find("e_x"); e != numbers.end()) s.ex = e->second;
      if (auto h = numbers.find("rotation.held"); h != numbers.end()) s.held = h->second != 0.0;
    } else if (numbers.empty()) {
      publishingWanted_ = false;  // nothing to read from this technique: stop paying for it
    }
  }

  FrameReadback frame = r.readback();
  s.aliasing = computeAliasingStats(frame.aliasing, frame.hardMask);
  if (!previousMask_.empty() && previousMask_.size() == frame.hardMask.size())
    s.maskChange = compareConsecutiveMasks(previousMask_, frame.hardMask);
  if (reference) {
    const std::vector<std::uint8_t>& ref = reference->evaluate(frame, r.light());
    s.hasReference = true;
    s.error = compareShadowMasks(frame.hardMask, ref);
    if (!previousReference_.empty() && previousReference_.size() == ref.size() &&
        previousMask_.size() == ref.size())
      s.flicker = computeFlicker(previousMask_, frame.hardMask, previousReference_, ref);
    previousReference_ = ref;
  } else {
    previousReference_.clear();
  }
  previousMask_ = std::move(frame.hardMask);
  collectGlErrors();
  return s;
}

}  // namespace sl::cli
