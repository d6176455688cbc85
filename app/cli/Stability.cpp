// `shadowlab-cli stability`: temporal behaviour frame by frame (issues 3 and 5).
//  - one technique: per-frame rotation (DA-RTW's accumulated angle, e_x, whether the
//    vibration threshold held it) and the share of pixels whose hard mask changed since
//    the previous frame, with a summary; static camera or a slow orbit;
//  - `--suite FILE.json`: purpose-built failure cases with expectations (Suite.cpp).
#include <algorithm>
#include <cstdio>

#include "Commands.h"
#include "StabilityRun.h"
#include "gl/EglContext.h"

using nlohmann::json;

namespace sl::cli {

const char* const kStabilityUsage =
    "       shadowlab-cli stability --scene NAME|FILE --technique ID [--set KEY=VALUE]...\n"
    "                               [--frames N] [--orbit DEG_PER_FRAME] [--camera NAME|INDEX]\n"
    "                               [--light LIGHT] [--size WxH] [--warmup N]\n"
    "                               [--reference] --json FILE.json\n"
    "       shadowlab-cli stability --suite FILE.json [--frames-scale S] [--size WxH]\n"
    "                               [--case NAME]... [--techniques ID,ID...] [--json FILE.json]\n";

namespace {

// ---------------------------------------------------------------- one technique

int runSingle(Args& a) {
  std::string sceneName, technique, jsonPath, camera;
  std::vector<std::string> sets;
  int frames = 100, warmup = 0, width = 640, height = 360;
  double orbit = 0.0;
  bool withReference = false;
  std::optional<Light> light;
  for (std::size_t i = 1; i < a.rest.size(); ++i) {
    const std::string& o = a.rest[i];
    if (o == "--scene")
      sceneName = a.take(i, o);
    else if (o == "--technique")
      technique = a.take(i, o);
    else if (o == "--set")
      sets.push_back(a.take(i, o));
    else if (o == "--frames")
      frames = parseInt(o, a.take(i, o), 1, 100000);
    else if (o == "--warmup")
      warmup = parseInt(o, a.take(i, o), 0, 100000);
    else if (o == "--orbit")
      orbit = parseDouble(o, a.take(i, o), -kMaxOrbitDegPerFrame, kMaxOrbitDegPerFrame);
    else if (o == "--camera")
      camera = a.take(i, o);
    else if (o == "--light")
      light = parseLight(o, a.take(i, o));
    else if (o == "--size")
      std::tie(width, height) = parseSize(a.take(i, o));
    else if (o == "--reference")
      withReference = true;
    else if (o == "--json")
      jsonPath = a.take(i, o);
    else
      throw UsageError("unknown option '" + o + "' (stability options: see shadowlab-cli --help)");
  }
  if (sceneName.empty()) throw UsageError("--scene: missing (which scene)");
  if (technique.empty()) throw UsageError("--technique: missing (which technique)");
  if (jsonPath.empty()) throw UsageError("--json: missing (where to write the frames)");
  if (warmup >= frames)
    throw UsageError("--warmup: " + std::to_string(warmup) + " of --frames " +
                     std::to_string(frames) +
                     " leaves no frame to measure (warm-up frames are not counted)");
  checkOutputs({{"--json", jsonPath}}, {{"--scene", sceneName}});

  ConfigSpec spec;
  spec.techniqueId = technique;
  for (const std::string& kv : sets) {
    auto eq = kv.find('=');
    if (eq == std::string::npos || eq == 0)
      throw UsageError("--set: expected KEY=VALUE, got '" + kv + "'");
    spec.sets.push_back({kv.substr(0, eq), kv.substr(eq + 1)});
  }
  spec.label = technique + (spec.sets.empty() ? "" : " " + spec.paramsText());
  if (auto e = validateConfig(spec))
    throw UsageError((e->rfind("unknown technique", 0) == 0 ? "--technique: " : "--set: ") + *e);

  std::shared_ptr<Scene> scene = loadScene(sceneName);
  checkOutputsAgainstScene({{"--json", jsonPath}}, *scene);
  Camera cam = pickCamera(*scene, camera);
  if (orbit != 0.0) cam = orbitCentred(cam, *scene);
  std::vector<Camera> cameras;
  for (int f = 0; f < frames; ++f) {
    cameras.push_back(cam);
    cam.orbit(float(orbit), 0.0f);
  }

  std::vector<std::vector<StabilityFrame>> result;
  int referenceEvaluations = 0;
  {
    gl::EglContext ctx;
    checkFrameSize(width, height);
    std::vector<std::unique_ptr<ConfigRunner>> runners;
    runners.push_back(std::make_unique<ConfigRunner>(spec, scene, light));
    std::unique_ptr<ReferenceCache> reference;
    if (withReference) reference = std::make_unique<ReferenceCache>(*scene);
    MeasureOptions opts;
    opts.width = width;
    opts.height = height;
    opts.publishing = true;
    ProgressBar progress("stability", std::size_t(frames));
    result = runFrames(runners, cameras, opts, reference.get(), progress);
    progress.finish();
    if (reference) referenceEvaluations = reference->evaluations();
  }
  const std::vector<StabilityFrame>& fr = result.front();
  StabilitySummary sum = summariseStability(fr, warmup);
  json j;
  j["scene"] = scene->name;
  j["technique"] = technique;
  json params = json::object();
  for (const auto& [k, v] : spec.sets) params[k] = v;
  j["params"] = params;
  j["size"] = {width, height};
  j["frames"] = frames;
  j["warmup"] = warmup;
  j["orbit_deg_per_frame"] = orbit;
  j["camera"] = camera.empty() ? "(first bookmark)" : camera;
  j["has_rotation"] = sum.hasRotation;
  json perFrame = json::array();
  for (std::size_t k = 0; k < fr.size(); ++k) perFrame.push_back(frameJson(k, fr[k]));
  j["per_frame"] = perFrame;
  j["summary"] = summaryJson(sum);
  if (withReference) j["reference_evaluations"] = referenceEvaluations;
  writeText(jsonPath, j.dump(2, ' ', false, json::error_handler_t::replace));
  // Changes between frames: "n/a (fewer than 2 frames ...)" when nothing was compared.
  const std::string rotation =
      sum.rotationStepsMeasured
          ? std::to_string(sum.rotationChanges) + " (max step " + fmt(sum.maxRotationStepDeg) +
                " deg, last at frame " + std::to_string(sum.lastRotationChangeFrame) + ")"
          : "n/a (" + StabilitySummary::notMeasuredReason("rotation_changes") + ")";
  const std::string mask =
      sum.maskChangesMeasured
          ? std::to_string(sum.maskChangeFrames) + " (max " + fmt(sum.maxMaskChangedPct) +
                "%, last at frame " + std::to_string(sum.lastMaskChangeFrame) + ")"
          : "n/a (" + StabilitySummary::notMeasuredReason("mask_change_frames") + ")";
  std::printf("%s on %s, %d frames%s: rotation_changes %s, mask_change_frames %s%s -> %s\n",
              spec.label.c_str(), scene->name.c_str(), frames,
              orbit != 0.0 ? (", orbit " + fmt(orbit) + " deg/frame").c_str() : " (static)",
              rotation.c_str(), mask.c_str(),
              sum.hasRotation ? "" : " [no rotation: reported as 0 deg, e_x 1, held]",
              jsonPath.c_str());
  if (sum.failed())
    std::fprintf(stderr, "shadowlab-cli: %s: %d of %d frames failed (not measured), first %s\n",
                 spec.label.c_str(), sum.renderErrors, frames, sum.failure.c_str());
  return (sum.renderErrors || sum.glErrors) ? 1 : 0;
}

}  // namespace

int cmdStability(Args& a) {
  std::string suite, jsonPath;
  double framesScale = 1.0;
  std::optional<std::pair<int, int>> size;
  std::vector<std::string> onlyCases, onlyTechniques;
  bool suiteMode = false;
  for (const std::string& o : a.rest) suiteMode = suiteMode || o == "--suite";
  if (!suiteMode) return runSingle(a);
  for (std::size_t i = 1; i < a.rest.size(); ++i) {
    const std::string& o = a.rest[i];
    if (o == "--suite")
      suite = a.take(i, o);
    else if (o == "--frames-scale")
      framesScale = parseDouble(o, a.take(i, o), 1e-3, 100.0);
    else if (o == "--size")
      size = parseSize(a.take(i, o));
    else if (o == "--case")
      onlyCases.push_back(a.take(i, o));
    else if (o == "--techniques") {
      std::string list = a.take(i, o);
      std::size_t start = 0;
      while (start <= list.size()) {
        std::size_t comma = std::min(list.find(',', start), list.size());
        std::string id = list.substr(start, comma - start);
        if (!Renderer::findTechnique(id))
          throw UsageError("--techniques: unknown technique '" + id + "'");
        onlyTechniques.push_back(id);
        start = comma + 1;
      }
    } else if (o == "--json")
      jsonPath = a.take(i, o);
    else
      throw UsageError("unknown option '" + o +
                       "' (stability --suite options: see shadowlab-cli --help)");
  }
  checkOutputs({{"--json", jsonPath}}, {{"--suite", suite}});
  if (size) {  // refused before any case runs
    gl::EglContext ctx;
    checkFrameSize(size->first, size->second);
  }
  return runSuite(suite, framesScale, size, onlyCases, onlyTechniques, jsonPath);
}

}  // namespace sl::cli
