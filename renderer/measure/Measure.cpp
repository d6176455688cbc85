// Measuring configurations frame by frame; see Measure.h.
#include "measure/Measure.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdio>
#include <cstring>
#include <vector>

#include "algo/InputFile.h"
#include "measure/SceneCameras.h"
#include "metrics/ErrorMetrics.h"
#include "metrics/Image.h"

namespace sl::measure {

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

std::vector<TechniqueEntry>& extraTechniques() {
  static std::vector<TechniqueEntry> list;
  return list;
}

std::vector<std::string> drainGlErrors() {
  std::vector<std::string> all;
  for (Renderer* r : liveRenderers())
    for (std::string& e : r->takeGlErrors()) all.push_back(std::move(e));
  return all;
}

}  // namespace

void addExtraTechnique(TechniqueEntry entry) {
  extraTechniques().push_back(std::move(entry));
}

const TechniqueInfo* findTechniqueInfo(const std::string& id) {
  if (const TechniqueInfo* info = Renderer::findTechnique(id)) return info;
  for (const TechniqueEntry& e : extraTechniques())
    if (e.info.id == id) return &e.info;
  return nullptr;
}

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
  const TechniqueInfo* info = findTechniqueInfo(spec.techniqueId);
  if (!info) {
    std::string known;
    for (const TechniqueInfo& t : Renderer::techniques())
      known += (known.empty() ? "" : ", ") + t.id;
    for (const TechniqueEntry& e : extraTechniques()) known += ", " + e.info.id;
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
    : spec_(std::move(spec)) {
  RendererOptions options;
  options.extraTechniques = extraTechniques();
  renderer_ = std::make_unique<Renderer>(options);
  liveRenderers().push_back(renderer_.get());
  renderer_->setScene(std::move(scene));
  if (light) renderer_->setLight(*light);
  if (auto e = renderer_->setTechnique(spec_.techniqueId)) throw UsageError(*e);
  // A light the technique cannot render is refused up front (renderFrame would too).
  if (const TechniqueInfo* info = findTechniqueInfo(spec_.techniqueId))
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

std::set<std::string> ConfigRunner::numberKeys(const MeasureOptions& options) const {
  // Only the numbers (rotation, PCA): no image or curve is read back while measuring.
  std::set<std::string> keys;
  if (options.publishing && publishingWanted_)
    if (const TechniqueInfo* info = findTechniqueInfo(renderer_->techniqueId()))
      for (const PublicationDecl& d : info->publications)
        if (d.kind == PublicationKind::Number) keys.insert(d.key);
  return keys;
}

std::optional<std::string> ConfigRunner::renderUnmeasured(const Camera& camera,
                                                          const MeasureOptions& options) {
  Renderer& r = *renderer_;
  r.setCamera(camera);
  // The same request as a measured frame: a technique that computes more when asked does the
  // same work in every frame.
  r.requestPublications(numberKeys(options));
  ++framesRendered_;
  return r.renderFrame(options.width, options.height, 0);
}

FrameSample ConfigRunner::renderAndMeasure(const Camera& camera, const MeasureOptions& options,
                                           ReferenceCache* reference) {
  FrameSample s;
  Renderer& r = *renderer_;
  r.setCamera(camera);
  r.requestPublications(numberKeys(options));
  auto collectGlErrors = [&s] {
    for (std::string& e : drainGlErrors()) s.glErrors.push_back(std::move(e));
  };
  // Anything since the last measured frame (set-up, in-between frames) counts against this one.
  collectGlErrors();
  ++framesRendered_;
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
    s.numbers = std::map<std::string, double>(numbers.begin(), numbers.end());
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
    s.errorByDistance =
        splitErrorByDistance(frame.hardMask, ref, frame.positions, r.camera().position);
    if (options.keepImages) {
      s.color = frame.color;
      s.errorImage = makeErrorImage(frame.color, frame.hardMask, ref);
    }
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

ConfigSummary summarise(const std::vector<FrameSample>& all) {
  ConfigSummary s;
  std::vector<const FrameSample*> order;
  for (const FrameSample& f : all) order.push_back(&f);
  s.failure = firstFailureText(order);
  std::vector<FrameSample> frames;  // the frames that rendered: the only ones measured
  for (const FrameSample& f : all) {
    s.frameMs.push_back(f.failed() ? std::numeric_limits<double>::quiet_NaN() : f.totalMs);
    s.renderErrors += f.failed() ? 1 : 0;
    s.glErrors += f.glErrors.size();
    if (!f.failed()) frames.push_back(f);
  }
  if (frames.empty()) {  // a failed configuration: nothing measured
    const double nan = std::numeric_limits<double>::quiet_NaN();
    s.totalMs = s.texels = s.bytes = s.covered = nan;
    s.errorPct = s.falseLitPct = s.falseShadowPct = s.errorNearPct = s.errorFarPct = nan;
    s.aliasingMean = s.aliasingP95 = s.aliasingMax = s.flickerPct = nan;
    s.lightAreaM2 = s.halfMassX = s.halfMassY = s.rotationDeg = s.anisotropy = nan;
    return s;
  }
  // A value over the frames that measured it (`measured`); none: NaN (not measured, an empty
  // cell), never 0.
  auto medOver = [&](auto measured, auto get) {
    std::vector<double> v;
    for (const FrameSample& f : frames)
      if (measured(f)) v.push_back(double(get(f)));
    return v.empty() ? std::numeric_limits<double>::quiet_NaN() : median(v);
  };
  auto med = [&](auto get) { return medOver([](const FrameSample&) { return true; }, get); };
  s.totalMs = med([](const FrameSample& f) { return f.totalMs; });
  std::map<std::string, std::vector<double>> passes;
  for (const FrameSample& f : frames)
    for (const PassTiming& p : f.passes) passes[p.name].push_back(p.ms);
  for (const auto& [name, v] : passes) s.passMs[name] = median(v);
  s.timingMethod = frames.back().timingMethod;
  s.texels = med([](const FrameSample& f) { return f.texels; });
  s.bytes = med([](const FrameSample& f) { return f.bytes; });
  // The error over the frames with a covered pixel; covered over the same frames, so it is 0
  // exactly when the error was measured on none.
  auto hasCovered = [](const FrameSample& f) { return f.error.covered > 0; };
  s.errorPct = medOver(hasCovered, [](const FrameSample& f) { return f.error.errorPct; });
  s.falseLitPct = medOver(hasCovered, [](const FrameSample& f) { return f.error.falseLitPct; });
  s.falseShadowPct =
      medOver(hasCovered, [](const FrameSample& f) { return f.error.falseShadowPct; });
  s.covered = medOver(hasCovered, [](const FrameSample& f) { return f.error.covered; });
  s.errorNearPct = medOver([](const FrameSample& f) { return f.errorByDistance.nearCovered > 0; },
                           [](const FrameSample& f) { return f.errorByDistance.nearErrorPct; });
  s.errorFarPct = medOver([](const FrameSample& f) { return f.errorByDistance.farCovered > 0; },
                          [](const FrameSample& f) { return f.errorByDistance.farErrorPct; });
  if (!std::isfinite(s.covered)) s.covered = 0.0;
  // Aliasing over the frames with a pixel to summarise, flicker over the consecutive frames
  // that compared one.
  auto hasAliasing = [](const FrameSample& f) { return f.aliasing.pixels > 0; };
  s.aliasingMean = medOver(hasAliasing, [](const FrameSample& f) { return f.aliasing.mean; });
  s.aliasingP95 = medOver(hasAliasing, [](const FrameSample& f) { return f.aliasing.p95; });
  s.aliasingMax = medOver(hasAliasing, [](const FrameSample& f) { return f.aliasing.max; });
  s.flickerPct = medOver([](const FrameSample& f) { return f.flicker && f.flicker->compared > 0; },
                         [](const FrameSample& f) { return f.flicker->pct; });
  auto medPublished = [&](auto get) {
    return medOver([&](const FrameSample& f) { return std::isfinite(get(f)); }, get);
  };
  s.lightAreaM2 = medPublished([](const FrameSample& f) { return f.lightAreaM2; });
  s.halfMassX = medPublished([](const FrameSample& f) { return f.halfMassX; });
  s.halfMassY = medPublished([](const FrameSample& f) { return f.halfMassY; });
  s.anisotropy = medPublished([](const FrameSample& f) { return f.anisotropy; });
  s.rotationDeg = medPublished([](const FrameSample& f) {
    return f.hasRotation ? f.rotationDeg : std::numeric_limits<double>::quiet_NaN();
  });
  return s;
}

std::size_t MeasureCameras::betweenCount() const {
  std::size_t n = 0;
  for (const std::vector<Camera>& b : between) n += b.size();
  return n;
}

MeasureCameras pathCameras(const CameraPath& path, int frames, double hz, const std::string& opt) {
  MeasureCameras out;
  out.pathHz = hz;
  out.alongPath = true;
  const double start = path.startS(), end = path.durationS();
  auto timeOf = [&](int f) {
    return frames > 1 ? start + (end - start) * double(f) / double(frames - 1) : start;
  };
  // In-between frames before frame f: k = 1, 2, ... with t_f - k / hz > t_{f-1}, i.e.
  // k < gap * hz (a frame landing on t_{f-1} within float noise is that measured frame).
  auto countBefore = [&](int f) -> double {
    if (hz <= 0.0 || f == 0) return 0.0;
    return std::max(0.0, std::ceil((timeOf(f) - timeOf(f - 1)) * hz - 1e-6) - 1.0);
  };
  double total = 0.0;
  for (int f = 0; f < frames; ++f) total += countBefore(f);
  if (total > double(kMaxInBetweenFrames)) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "%s: %g Hz along path '%s' (%g s) is %.0f frames between the measured ones, "
                  "over the limit of %zu (kMaxInBetweenFrames); use a lower rate or 0",
                  opt.c_str(), hz, cutText(path.name, 60).c_str(), end - start, total,
                  kMaxInBetweenFrames);
    throw UsageError(text);
  }
  for (int f = 0; f < frames; ++f) {
    out.measured.push_back(path.sampleFrame(f, frames));
    std::vector<Camera> before;
    const int n = int(countBefore(f));
    for (int k = n; k >= 1; --k) before.push_back(path.sample(float(timeOf(f) - double(k) / hz)));
    out.between.push_back(std::move(before));
  }
  return out;
}

MeasureCameras measureCameras(const Scene& scene, const std::string& path,
                              const std::string& camera, int frames, double pathHz,
                              std::string& cameraText) {
  if (!path.empty() && !camera.empty())
    throw UsageError("--camera: give either a camera path (--path) or a bookmark (--camera)");
  if (camera.empty() && !scene.paths.empty()) {
    const CameraPath& p = pickPath(scene, path);
    cameraText = cutText("path " + p.name);  // a glTF animation name: any length
    return pathCameras(p, frames, pathHz);
  }
  if (!path.empty()) (void)pickPath(scene, path);  // names the missing path
  MeasureCameras out;
  out.measured.assign(std::size_t(frames), pickCamera(scene, camera));
  out.between.resize(std::size_t(frames));
  cameraText = cutText("camera " + (camera.empty() ? std::string("(first bookmark)") : camera));
  return out;
}

FrameSample renderBetweenAndMeasure(ConfigRunner& runner, const std::vector<Camera>& between,
                                    const Camera& camera, const MeasureOptions& options,
                                    ReferenceCache* reference) {
  for (std::size_t k = 0; k < between.size(); ++k)
    if (auto e = runner.renderUnmeasured(between[k], options)) {
      FrameSample s;
      s.renderError = "in-between frame " + std::to_string(k + 1) + " of " +
                      std::to_string(between.size()) + " before it: " + *e;
      runner.forgetPreviousFrame();
      return s;
    }
  return runner.renderAndMeasure(camera, options, reference);
}

std::vector<std::vector<FrameSample>> runInterleaved(
    const std::vector<std::unique_ptr<ConfigRunner>>& runners, const MeasureCameras& cameras,
    const MeasureOptions& options, ReferenceCache* reference, int warmup,
    const std::function<void(std::size_t, int, const FrameSample&)>& onSample) {
  std::vector<std::vector<FrameSample>> samples(runners.size());
  if (runners.empty() || cameras.measured.empty()) return samples;
  MeasureOptions warm = options;
  warm.keepImages = false;
  for (int w = 0; w < warmup; ++w)
    for (const auto& r : runners)
      (void)r->renderAndMeasure(cameras.measured.front(), warm, nullptr);
  for (const auto& r : runners) r->forgetPreviousFrame();
  const int frames = int(cameras.measured.size());
  static const std::vector<Camera> kNone;
  for (int f = 0; f < frames; ++f) {
    MeasureOptions o = options;
    o.keepImages = options.keepImages && f + 1 == frames;  // the last frame's images only
    const std::vector<Camera>& between =
        std::size_t(f) < cameras.between.size() ? cameras.between[std::size_t(f)] : kNone;
    for (std::size_t k = 0; k < runners.size(); ++k) {
      const std::size_t i = (k + std::size_t(f)) % runners.size();
      // This configuration's in-between frames right before its measured frame: the other
      // configurations' frames between them touch none of its state.
      FrameSample s = renderBetweenAndMeasure(*runners[i], between,
                                              cameras.measured[std::size_t(f)], o, reference);
      if (onSample) onSample(i, f, s);
      samples[i].push_back(std::move(s));
    }
  }
  return samples;
}

}  // namespace sl::measure
