// shadowlab-cli: the headless front end (surfaceless EGL, no display needed).
//   list      scenes, techniques and their parameters
//   render    one configuration -> PNG, metrics JSON, error image
//   compare   every technique on one scene -> a folder of images and metrics
//   bench     speed against accuracy: sweeps along a camera path -> CSV and chart (Bench.cpp)
//   chart     the chart again from a bench CSV, x = time or memory (Bench.cpp)
//   stability frame-to-frame stability, one technique or a suite of failure cases
//             (Stability.cpp)
//   storage   the storage factor of warped and partitioned shadow maps, Figs. 6-7 of
//             Lloyd et al. 2006 (Storage.cpp)
//   reproduce every claim of the papers measured, one verdict each -> REPORT.md
//             (Reproduce.cpp)
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "CliCommon.h"
#include "Commands.h"
#include "measure/Measure.h"
#include "Montage.h"
#include "core/JsonNumber.h"
#include "algo/InputFile.h"
#include "algo/metrics/BenchStats.h"
#include "core/Preset.h"
#include "core/Renderer.h"
#include "gl/EglContext.h"
#include "gl/ShaderLibrary.h"
#include "metrics/Image.h"
#include "metrics/ShadowReference.h"
#include "scene/GltfLoader.h"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

using namespace sl::cli;

const char* kUsage =
    "usage: shadowlab-cli list [--format text|markdown]   (markdown: the parameter reference)\n"
    "       shadowlab-cli version   (the version, where data is read from, what this build has)\n"
    "       shadowlab-cli render --scene NAME|FILE --technique ID [--set KEY=VALUE]...\n"
    "                            [--size WxH] [--frames N] [--camera NAME|INDEX]\n"
    "                            [--path NAME|INDEX [--path-at FRACTION (0)]]\n"
    "                            [--light LIGHT] [--preset FILE.json]\n"
    "                            --out FILE.png [--metrics FILE.json] [--error-image FILE.png]\n"
    "                            [--wrong-pixels FILE.csv] [--publish CURVE]... [--no-reference]\n"
    "         (--wrong-pixels: one line per pixel whose hard test disagrees with the reference:\n"
    "          where it is, its surface, m, the map and uv its lookup used;\n"
    "          --publish: a curve the technique publishes, into --metrics' published_curves;\n"
    "          --no-reference: no ray-traced reference, timings only: the error is n/a)\n"
    "       shadowlab-cli compare [--scene NAME|FILE] [--technique ID[:KEY=V1,V2...]]...\n"
    "                            [--set KEY=VALUE]... [--size WxH] [--camera NAME|INDEX]\n"
    "                            [--light LIGHT] --out-dir DIR [--montage FILE.png]\n"
    "                            [--dilate PX (1)] [--columns N] [--inset X,Y,W,H[,ZOOM]]\n"
    "         (no --technique: every technique at its defaults)\n"
    "  LIGHT: AZ,EL or dir:AZ,EL (degrees) | point:X,Y,Z[,RANGE] |\n"
    "         spot:X,Y,Z,DX,DY,DZ,OUTER_DEG[,INNER_DEG[,RANGE]] (metres; range 0 = infinite)\n";

struct RenderConfig {
  std::string scene = "default";
  std::string technique = sl::Renderer::baselineTechniqueId();
  std::vector<std::string> sets;
  int width = 1280, height = 720;
  int frames = 1;
  std::string camera;
  std::optional<sl::Camera> presetCamera;  ///< a --preset's camera (a later --camera wins)
  std::string preset;                      ///< the --preset file (an input)
  /// A camera path: the camera a fraction pathAt of the way from its first key to its last
  /// (bench's frames spread over the same span).
  std::string path;
  double pathAt = 0.0;  ///< 0 = the path's start, 1 = its end
  std::optional<sl::Light> light;
  std::string out, metrics, errorImage, wrongPixels;
  std::vector<std::string> publish;  ///< curves to add to --metrics (published_curves)
  /// The Embree reference (the error). Off with --no-reference, and in a build without it
  /// (SHADOWLAB_REFERENCE=OFF): timings only, the error n/a.
  bool reference = true;
};

/// Techniques whose shadow map depends on earlier frames through a rotation (DA-RTW's R_k
/// from the previous frame's IM; TechniqueInfo::temporalRotation): a single frame of
/// DA-RTW is rtw-backward with R = I, so unmeasured frames come first.
constexpr int kMaxRotationWarmup = 32;

struct Warmup {
  int frames = 0;         ///< unmeasured frames rendered before the measured ones
  bool settled = true;    ///< the rotation stopped changing (held, or nothing to rotate by)
  bool temporal = false;  ///< the technique has a temporal rotation
};

/// For a technique with a temporal rotation: unmeasured frames (its settleKeys requested)
/// until its settled rule says so, at most kMaxRotationWarmup. The measured frames then run
/// without publishing.
Warmup warmUpRotation(sl::Renderer& r, const RenderConfig& cfg) {
  Warmup w;
  const sl::TechniqueInfo* info = sl::Renderer::findTechnique(r.techniqueId());
  if (!info || !info->temporalRotation || !info->settled) return w;
  w.temporal = true;
  w.settled = false;
  r.requestPublications(info->settleKeys);
  while (w.frames < kMaxRotationWarmup && !w.settled) {
    if (auto e = r.renderFrame(cfg.width, cfg.height, 0)) {
      r.requestPublications({});
      throw std::runtime_error(*e);
    }
    ++w.frames;
    // The technique's own rule (TechniqueInfo::settled); nothing: no estimate this frame.
    w.settled = info->settled(r.publication()).value_or(false);
  }
  r.requestPublications({});
  return w;
}

/// Renders `frames` frames and returns the metrics JSON (medians over frames). With
/// `showProgress` and more than one frame, a progress bar on stderr (`--frames 100000`).
json renderAndMeasure(sl::Renderer& r, const RenderConfig& cfg, sl::Renderer::ErrorResult& err,
                      bool showProgress = false) {
  const Warmup warm = warmUpRotation(r, cfg);
  std::optional<ProgressBar> progress;
  if (showProgress && cfg.frames > 1) progress.emplace("render", std::size_t(cfg.frames));
  std::map<std::string, std::vector<double>> passMs;
  std::vector<std::string> passOrder;
  std::vector<double> totals;
  // The technique's published numbers (no image or curve: nothing read back for them), and
  // the curves --publish asks for.
  std::set<std::string> numberKeys;
  if (const sl::TechniqueInfo* info = sl::Renderer::findTechnique(r.techniqueId())) {
    for (const sl::PublicationDecl& d : info->publications)
      if (d.kind == sl::PublicationKind::Number) numberKeys.insert(d.key);
    for (const std::string& key : cfg.publish) {
      const auto it = std::find_if(info->publications.begin(), info->publications.end(),
                                   [&](const sl::PublicationDecl& d) { return d.key == key; });
      if (it == info->publications.end() || it->kind != sl::PublicationKind::Curve) {
        std::string curves;
        for (const sl::PublicationDecl& d : info->publications)
          if (d.kind == sl::PublicationKind::Curve) curves += (curves.empty() ? "" : ", ") + d.key;
        throw UsageError("--publish: '" + key + "' is not a curve " + r.techniqueId() +
                         " publishes (its curves: " + (curves.empty() ? "none" : curves) + ")");
      }
      numberKeys.insert(key);
    }
  }
  r.requestPublications(numberKeys);
  for (int f = 0; f < cfg.frames; ++f) {
    // A refused frame measures nothing: no metrics are written, the frame is named.
    if (auto e = r.renderFrame(cfg.width, cfg.height, 0))
      throw std::runtime_error(cfg.frames > 1 ? "frame " + std::to_string(f) + ": " + *e : *e);
    for (const auto& p : r.stats().passes) {
      if (!passMs.count(p.name)) passOrder.push_back(p.name);
      passMs[p.name].push_back(p.ms);
    }
    totals.push_back(r.stats().totalMs);
    if (progress)
      progress->step("frame " + std::to_string(f + 1) + "/" + std::to_string(cfg.frames), true);
  }
  if (progress) progress->finish();
  for (const std::string& e : r.takeGlErrors()) throw std::runtime_error("GL error: " + e);
  if (cfg.reference) {
    err = r.computeError();
  } else {
    err = {};
    err.frame = r.readback();
  }
  const sl::FrameStats& st = r.stats();
  json j;
  j["scene"] = r.scene()->name;
  j["technique"] = r.techniqueId();
  json params = json::object();
  for (const auto& d : r.params().decls()) params[d.key] = r.params().format(d.key);
  j["params"] = params;
  j["size"] = {cfg.width, cfg.height};
  j["frames"] = cfg.frames;
  j["warmup_frames"] = warm.frames;
  if (warm.temporal) j["rotation_settled"] = warm.settled;
  j["timing_method"] = st.timingMethod;
  j["total_ms"] = sl::median(totals);
  json passes = json::array();
  for (const auto& name : passOrder)
    passes.push_back(
        {{"name", name}, {"ms", sl::median(passMs[name])}, {"method", st.timingMethod}});
  j["passes"] = passes;
  j["texels"] = st.memory.texels();
  j["bytes"] = st.memory.bytes();
  json published = json::object();  // the last frame's
  for (const auto& [k, v] : r.publication().numbers) published[k] = sl::jsonNumber(v);
  j["published"] = published;
  json curves = json::object();  // the last frame's, those --publish asked for
  for (const auto& [k, v] : r.publication().curves) curves[k] = v;
  j["published_curves"] = curves;
  r.requestPublications({});
  json res = json::array();
  for (const auto& m : st.memory.resources)
    res.push_back({{"name", m.name},
                   {"format", m.format},
                   {"width", m.width},
                   {"height", m.height},
                   {"layers", m.layers},
                   {"texels", m.texels},
                   {"bytes", m.bytes}});
  j["resources"] = res;
  j["covered_pixels"] = err.stats.covered;
  j["reference"] = cfg.reference;
  if (!cfg.reference)
    j["error_unmeasured"] = sl::ShadowReference::available()
                                ? "--no-reference: no ray-traced reference, timings only"
                                : sl::ShadowReference::unavailableReason();
  // No covered pixel or no reference: nothing was measured (null, not 0).
  const bool measured = cfg.reference && err.stats.covered > 0;
  j["error_pct"] = measured ? json(err.stats.errorPct) : json(nullptr);
  j["false_lit_pct"] = measured ? json(err.stats.falseLitPct) : json(nullptr);
  j["false_shadow_pct"] = measured ? json(err.stats.falseShadowPct) : json(nullptr);
  j["gl"] = r.glDescription();
  const sl::Renderer::GlStrings gl = r.glStrings();
  j["gl_vendor"] = gl.vendor;
  j["gl_renderer"] = gl.renderer;
  j["gl_version"] = gl.version;
  return j;
}

/// One line (no newline) about the warm-up in `j`, empty when none ran.
std::string describeWarmup(const json& j) {
  if (!j.contains("rotation_settled")) return "";
  const int n = j["warmup_frames"].get<int>();
  if (j["rotation_settled"].get<bool>())
    return j["technique"].get<std::string>() + ": " + std::to_string(n) +
           " unmeasured warm-up frame(s) until the rotation settled";
  return "note: " + j["technique"].get<std::string>() + ": the rotation still changed after " +
         std::to_string(n) + " unmeasured warm-up frames; measured with the rotation so far";
}

/// "error 0.123% (false lit ..., false shadow ...)" or "error n/a (no covered pixel)".
std::string describeError(const sl::ShadowErrorStats& e) {
  if (e.covered == 0) return "error n/a (no covered pixel)";
  char buf[160];
  std::snprintf(buf, sizeof buf, "error %.3f%% (false lit %.3f%%, false shadow %.3f%%)", e.errorPct,
                e.falseLitPct, e.falseShadowPct);
  return buf;
}

/// The pixels whose hard test disagrees with the reference, one CSV line each (row 0 = top):
/// what was wrong, the surface there, the aliasing m, the map the lookup selected and the uv
/// it looked up in it (render --wrong-pixels).
std::string wrongPixelsCsv(const sl::Renderer::ErrorResult& err) {
  const sl::FrameReadback& f = err.frame;
  std::string out = "x,y,wrong,px,py,pz,nx,ny,nz,m,map,u,v\n";
  char line[320];
  for (int y = 0; y < f.height; ++y) {
    for (int x = 0; x < f.width; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(f.width) + std::size_t(x);
      const std::uint8_t tech = f.hardMask[i], ref = err.referenceMask[i];
      if (tech == sl::kMaskUncovered || ref == sl::kMaskUncovered) continue;
      const bool techLit = tech != sl::kMaskShadowed, refLit = ref != sl::kMaskShadowed;
      if (techLit == refLit) continue;
      const glm::vec4 p = f.positions[i], n = f.normals[i];
      std::snprintf(line, sizeof line, "%d,%d,%s,%.6f,%.6f,%.6f,%.5f,%.5f,%.5f,%.5f,%d,%.8f,%.8f\n",
                    x, y, techLit ? "false_lit" : "false_shadow", p.x, p.y, p.z, n.x, n.y, n.z,
                    f.aliasing[i], int(f.mapIndex[i]), f.texel[i].x, f.texel[i].y);
      out += line;
    }
  }
  return out;
}

void configure(sl::Renderer& r, const RenderConfig& cfg, const std::shared_ptr<sl::Scene>& scene) {
  r.setScene(scene);
  if (auto e = r.setTechnique(cfg.technique)) throw UsageError("--technique: " + *e);
  for (const std::string& kv : cfg.sets) {
    // Shared renderer parameters (shading.*) and the technique's own.
    auto eq = kv.find('=');
    std::string key = eq == std::string::npos ? kv : kv.substr(0, eq);
    sl::ParamSet& set = r.rendererParams().has(key) ? r.rendererParams() : r.params();
    if (auto e = set.assign(kv)) throw UsageError("--set: " + *e);
  }
  if (const sl::TechniqueInfo* info = sl::Renderer::findTechnique(r.techniqueId()))
    if (auto e = sl::checkTechniqueParams(*info, r.params()))
      throw UsageError("--set: technique '" + r.techniqueId() + "': " + *e);
  if (!cfg.path.empty()) {
    const sl::CameraPath& path = pickPath(*scene, cfg.path);
    r.setCamera(path.sampleFraction(float(cfg.pathAt)));
  } else {
    r.setCamera(cfg.presetCamera ? *cfg.presetCamera : pickCamera(*scene, cfg.camera));
  }
  if (cfg.light) r.setLight(*cfg.light);
  // A light the technique cannot render: exit 2 with the renderer's own message.
  if (const sl::TechniqueInfo* info = sl::Renderer::findTechnique(r.techniqueId()))
    if (auto e = sl::checkLightSupport(*info, r.light().type)) throw UsageError(*e);
}

/// `|` and line breaks would end a Markdown table cell.
std::string markdownCell(std::string text) {
  std::string out;
  for (char c : text) {
    if (c == '|')
      out += "\\|";
    else if (c == '\n')
      out += ' ';
    else
      out += c;
  }
  return out;
}

/// `list --format markdown`: the parameter reference (docs/user-guide/parameters.md is this
/// output; tests/cli/parameter_reference.sh fails when the committed page is stale).
int cmdListMarkdown() {
  std::cout << "# Parameter reference\n\n"
               "Generated from the parameter declarations by `shadowlab-cli list --format "
               "markdown`; do not edit by hand. Every parameter can be set with `--set "
               "KEY=VALUE` (CLI), in a preset's or lesson's `params`, and in the GUI's "
               "Parameters panel; values outside the range are refused with the range.\n\n"
               "Built-in scenes: ";
  const std::vector<std::string> scenes = sl::builtinSceneNames();
  for (std::size_t i = 0; i < scenes.size(); ++i)
    std::cout << (i ? ", " : "") << "`" << scenes[i] << "`";
  std::cout << ".\n\n## Techniques\n\n";
  for (const auto& t : sl::Renderer::techniques())
    std::cout << "- [`" << t.id << "`](#" << t.id << ") — " << markdownCell(t.name) << "\n";
  auto table = [](const std::vector<sl::ParamDecl>& decls) {
    if (decls.empty()) {
      std::cout << "No parameters of its own.\n\n";
      return;
    }
    std::cout << "| parameter | default | range | what it does |\n|---|---|---|---|\n";
    for (const auto& d : decls) {
      sl::ParamSet tmp({d});
      std::cout << "| `" << d.key << "` | `" << markdownCell(tmp.format(d.key)) << "` | "
                << markdownCell(sl::describeRange(d)) << " | " << markdownCell(d.help) << " |\n";
    }
    std::cout << "\n";
  };
  for (const auto& t : sl::Renderer::techniques()) {
    std::cout << "\n## " << t.id << "\n\n**" << markdownCell(t.name) << "**. "
              << markdownCell(t.description) << "\n\n";
    table(t.params);
  }
  std::cout << "\n## Shared parameters\n\nEvery technique has these (shading, overlays, the "
               "outside view).\n\n";
  table(sl::rendererParamDecls());
  return 0;
}

int cmdList(Args& a) {
  std::string format = "text";
  for (size_t i = 1; i < a.rest.size(); ++i) {
    const std::string& o = a.rest[i];
    if (o == "--format") {
      format = a.take(i, o);
      if (format != "text" && format != "markdown")
        throw UsageError("--format: expected text or markdown, got '" + format + "'");
    } else {
      throw UsageError("unknown option '" + o + "' (list options: --format text|markdown)");
    }
  }
  if (format == "markdown") return cmdListMarkdown();
  std::cout << "Scenes (" << sl::builtinSceneDir().string() << "):\n";
  for (const std::string& n : sl::builtinSceneNames()) std::cout << "  " << n << "\n";
  // The presets that ship: lessons and the papers' methods as written (render --preset FILE).
  for (const char* folder : {"lessons", "papers"}) {
    const std::filesystem::path dir = sl::builtinSceneDir() / folder;
    std::cout << "\nPresets in " << dir.string() << " (render --preset FILE):\n";
    std::vector<std::filesystem::path> files;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(dir, ec))
      if (e.path().extension() == ".json") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const auto& f : files) {
      std::string error;
      const std::optional<sl::Preset> p = sl::loadPreset(f, &error);
      std::cout << "  " << f.filename().string() << " - "
                << (p ? p->title : "cannot be read: " + error);
      if (p && !p->cases.empty()) std::cout << " (" << p->cases.size() << " cases)";
      std::cout << "\n";
    }
  }
  std::cout << "\nTechniques:\n";
  auto printParams = [](const std::vector<sl::ParamDecl>& decls) {
    for (const auto& d : decls) {
      sl::ParamSet tmp({d});
      std::cout << "      " << d.key << " = " << tmp.format(d.key) << "  [" << sl::describeRange(d)
                << "]  " << d.help << "\n";
    }
  };
  for (const auto& t : sl::Renderer::techniques()) {
    std::cout << "  " << t.id << " - " << t.name << "\n      " << t.description << "\n";
    printParams(t.params);
  }
  std::cout << "\nShared parameters (every technique):\n";
  printParams(sl::rendererParamDecls());
  return 0;
}

/// The version, the data folders this program reads (scene/DataDir.h: an installed tree finds
/// its own, wherever it was moved) and what this build can do.
int cmdVersion() {
  std::cout << "shadowlab-cli " << SHADOWLAB_VERSION << "\n"
            << "shaders: " << sl::gl::ShaderLibrary::defaultRoot().string() << "\n"
            << "scenes: " << sl::builtinSceneDir().string() << "\n"
            << "reference: "
            << (sl::ShadowReference::available() ? std::string("Embree ray tracer")
                                                 : sl::ShadowReference::unavailableReason())
            << "\n"
            << "images: " << (SHADOWLAB_CLI_IMAGES_OIIO ? "OpenImageIO" : "PNG (stb)") << "\n"
            << "charts: " << (SHADOWLAB_CLI_CHARTS ? "Qt Charts" : "none (built without Qt)")
            << "\n";
  return 0;
}

RenderConfig parseRender(Args& a, size_t start, bool needOut) {
  RenderConfig cfg;
  bool pathAtGiven = false;
  for (size_t i = start; i < a.rest.size(); ++i) {
    const std::string& o = a.rest[i];
    if (o == "--scene")
      cfg.scene = a.take(i, o);
    else if (o == "--technique")
      cfg.technique = a.take(i, o);
    else if (o == "--set")
      cfg.sets.push_back(a.take(i, o));
    else if (o == "--size")
      std::tie(cfg.width, cfg.height) = parseSize(a.take(i, o));
    else if (o == "--frames")
      cfg.frames = parseInt(o, a.take(i, o), 1, 100000);
    else if (o == "--camera") {
      cfg.camera = a.take(i, o);
      cfg.presetCamera.reset();
    } else if (o == "--path")
      cfg.path = a.take(i, o);
    else if (o == "--path-at") {
      cfg.pathAt = parseDouble(o, a.take(i, o), 0.0, 1.0);
      pathAtGiven = true;
    } else if (o == "--out" || o == "--out-dir")
      cfg.out = a.take(i, o);
    else if (o == "--metrics")
      cfg.metrics = a.take(i, o);
    else if (o == "--error-image")
      cfg.errorImage = a.take(i, o);
    else if (o == "--wrong-pixels")
      cfg.wrongPixels = a.take(i, o);
    else if (o == "--publish")
      cfg.publish.push_back(a.take(i, o));
    else if (o == "--no-reference")
      cfg.reference = false;
    else if (o == "--light")
      cfg.light = parseLight(o, a.take(i, o));
    else if (o == "--preset") {
      std::string err;
      cfg.preset = a.take(i, o);
      auto p = sl::loadPreset(cfg.preset, &err);
      if (!p) throw UsageError("--preset: " + err);
      if (!p->scene.empty()) cfg.scene = p->scene;
      if (!p->technique.empty()) cfg.technique = p->technique;
      for (const auto& [k, v] : p->params) cfg.sets.push_back(k + "=" + v);
      if (p->light) cfg.light = p->light;
      if (p->camera) {
        cfg.presetCamera = p->camera;
        cfg.camera.clear();
      }
    } else {
      throw UsageError("unknown option '" + o + "'");
    }
  }
  if (needOut && cfg.out.empty()) throw UsageError("--out: missing (where to write the image)");
  if (!cfg.path.empty() && (!cfg.camera.empty() || cfg.presetCamera))
    throw UsageError("--path: give either a camera path (--path) or a camera (--camera, --preset)");
  if (cfg.path.empty() && pathAtGiven)
    throw UsageError("--path-at: needs --path (the camera path it is a fraction of)");
  if (!cfg.reference && !cfg.errorImage.empty())
    throw UsageError("--error-image: needs the ray-traced reference (not with --no-reference)");
  if (!cfg.reference && !cfg.wrongPixels.empty())
    throw UsageError("--wrong-pixels: needs the ray-traced reference (not with --no-reference)");
  if (cfg.reference && !sl::ShadowReference::available()) {
    if (!cfg.errorImage.empty() || !cfg.wrongPixels.empty())
      throw UsageError(std::string(!cfg.errorImage.empty() ? "--error-image" : "--wrong-pixels") +
                       ": " + sl::ShadowReference::unavailableReason());
    std::fprintf(stderr, "note: %s (error n/a)\n", sl::ShadowReference::unavailableReason());
    cfg.reference = false;
  }
  return cfg;
}

int cmdRender(Args& a) {
  RenderConfig cfg = parseRender(a, 1, true);
  const std::vector<OutputFile> outputs = {{"--out", cfg.out},
                                           {"--metrics", cfg.metrics},
                                           {"--error-image", cfg.errorImage},
                                           {"--wrong-pixels", cfg.wrongPixels}};
  // The image formats before any work (a name without an extension failed after the frames).
  for (const OutputFile& o : {outputs[0], outputs[2]}) {
    std::error_code ec;
    const fs::file_status st = fs::status(o.path, ec);
    if (o.path.empty() || (fs::exists(st) && !fs::is_regular_file(st))) continue;  // /dev/null
    if (auto e = sl::checkImageFormat(o.path)) throw UsageError(o.name + ": " + *e);
  }
  checkOutputs(outputs, {{"--scene", cfg.scene}, {"--preset", cfg.preset}});
  const std::shared_ptr<sl::Scene> scene = loadScene(cfg.scene);
  checkOutputsAgainstScene(outputs, *scene);
  sl::gl::EglContext ctx;
  checkFrameSize(cfg.width, cfg.height);
  sl::Renderer r;
  configure(r, cfg, scene);
  sl::Renderer::ErrorResult err;
  json j = renderAndMeasure(r, cfg, err, /*showProgress=*/true);
  // view.outside=on: --out is the outside view (what a host shows); the error image and the
  // metrics stay the main camera's.
  writePng(cfg.out, err.frame.outside.pixels.empty() ? err.frame.color : err.frame.outside);
  if (!cfg.metrics.empty())
    writeText(cfg.metrics, j.dump(2, ' ', false, json::error_handler_t::replace));
  if (!cfg.errorImage.empty())
    writePng(cfg.errorImage,
             sl::makeErrorImage(err.frame.color, err.frame.hardMask, err.referenceMask));
  if (!cfg.wrongPixels.empty()) writeText(cfg.wrongPixels, wrongPixelsCsv(err));
  if (std::string w = describeWarmup(j); !w.empty())
    std::fprintf(w.rfind("note:", 0) == 0 ? stderr : stdout, "%s\n", w.c_str());
  // ASM's refinement loop stopped by its iteration cap is never silent (the metrics JSON has
  // asm.cap.stops, asm.stop and asm.requests.left too).
  if (const json& pub = j["published"]; pub.contains("asm.cap.stops") &&
                                        pub["asm.cap.stops"].is_number() &&
                                        pub["asm.cap.stops"].get<double>() > 0.0)
    std::fprintf(stderr,
                 "note: asm: the iteration cap stopped the refinement loop in %g of the frames "
                 "rendered (published asm.cap.stops); the last frame: asm.stop %g, %g pages "
                 "still requested (asm.requests.left)\n",
                 pub["asm.cap.stops"].get<double>(), pub.value("asm.stop", 0.0),
                 pub.value("asm.requests.left", 0.0));
  std::printf("%s on %s: %.2f ms (%s), %llu texels, %s -> %s\n", r.techniqueId().c_str(),
              r.scene()->name.c_str(), j["total_ms"].get<double>(), r.stats().timingMethod.c_str(),
              (unsigned long long)r.stats().memory.texels(),
              cfg.reference ? describeError(err.stats).c_str() : "error n/a (no reference)",
              cfg.out.c_str());
  return 0;
}

int cmdCompare(Args& a) {
  // Options of compare's own; the rest are render's (scene, size, frames, camera, light,
  // --set for every configuration, preset).
  std::vector<std::string> techniqueSpecs;
  std::string montage;
  int dilate = 1, columns = 0;
  std::optional<sl::ui::FigureInset> inset;
  Args rest;
  rest.rest.push_back(a.rest[0]);
  for (size_t i = 1; i < a.rest.size(); ++i) {
    const std::string& o = a.rest[i];
    if (o == "--technique")
      techniqueSpecs.push_back(a.take(i, o));
    else if (o == "--montage")
      montage = a.take(i, o);
    else if (o == "--dilate")
      dilate = parseInt(o, a.take(i, o), 0, 16);
    else if (o == "--columns")
      columns = parseInt(o, a.take(i, o), 0, 64);
    else if (o == "--inset") {
      // X,Y,W,H as fractions of the image (x right, y down), optionally ,ZOOM
      const std::string text = a.take(i, o);
      std::vector<double> v;
      std::stringstream ss(text);
      for (std::string part; std::getline(ss, part, ',');)
        v.push_back(parseDouble(o, part, 0.0, 16.0));
      if (v.size() != 4 && v.size() != 5)
        throw UsageError("--inset: expected X,Y,W,H[,ZOOM] (fractions of the image), got '" + text +
                         "'");
      if (v[2] <= 0.0 || v[3] <= 0.0 || v[0] + v[2] > 1.0 || v[1] + v[3] > 1.0)
        throw UsageError("--inset: the region " + text +
                         " must lie inside the image (X + W <= 1, Y + H <= 1, W, H > 0)");
      const int zoom = v.size() == 5 ? int(v[4]) : 3;
      if (zoom < 2 || zoom > 8 || v[2] * zoom > 0.9 || v[3] * zoom > 0.9)
        throw UsageError(
            "--inset: zoom " + std::to_string(zoom) +
            " must be 2..8 and the zoomed region fit the image (W x ZOOM, H x ZOOM <= 0.9)");
      inset = sl::ui::FigureInset{v[0], v[1], v[2], v[3], zoom};
    } else
      rest.rest.push_back(o);
  }
  RenderConfig base = parseRender(rest, 1, false);
  if (!montage.empty())
    if (auto e = sl::cli::montageUnavailable()) throw UsageError(*e);
  if (!base.reference)
    throw UsageError(sl::ShadowReference::available()
                         ? "--no-reference: compare draws error images; it needs the ray-traced "
                           "reference (render and bench measure time without it)"
                         : std::string("compare: ") + sl::ShadowReference::unavailableReason());
  if (!base.wrongPixels.empty())
    throw UsageError("--wrong-pixels: a render option (one configuration), not compare's");
  // compare's images and errors are the main camera's: an outside view would be ignored.
  for (const std::string& kv : base.sets) {
    const auto eq = kv.find('=');
    if (kv.substr(0, eq) == "view.outside" && eq != std::string::npos &&
        kv.substr(eq + 1) != "off" && kv.substr(eq + 1) != "0" && kv.substr(eq + 1) != "false")
      throw UsageError(
          "--set view.outside: compare writes the main camera's images and errors, "
          "not the outside view (render --set view.outside=on draws it)");
  }
  if (base.out.empty()) base.out = "shadowlab-out";
  checkOutputFolder("--out-dir", base.out);
  // The configurations: each --technique ID[:KEY=V1,V2...] expanded (as bench does), or every
  // technique at its defaults.
  std::vector<sl::cli::ConfigSpec> specs;
  for (const std::string& t : techniqueSpecs)
    for (sl::cli::ConfigSpec& c : sl::cli::expandTechniqueSweep(t)) specs.push_back(std::move(c));
  const bool all = specs.empty();
  if (all)
    for (const auto& t : sl::Renderer::techniques()) specs.push_back({t.id, {}, t.id});
  {  // The same configuration listed twice gets its own name (and files).
    std::map<std::string, int> seen;
    for (sl::cli::ConfigSpec& c : specs)
      if (int n = ++seen[c.label]; n > 1) c.label += " #" + std::to_string(n);
  }
  // Every file compare writes, checked against each other and the inputs before any work:
  // per configuration <stem>.png, <stem>.error.png, <stem>.json, then summary.json and the
  // montage.
  auto stemOf = [&](const std::string& label) {
    std::string file = label;
    for (char& ch : file)
      if (ch == ' ' || ch == '/' || ch == ':' || ch == '#') ch = '_';
    return (fs::path(base.out) / file).string();
  };
  std::vector<OutputFile> outputs;
  for (const sl::cli::ConfigSpec& spec : specs)
    for (const char* ext : {".png", ".error.png", ".json"})
      outputs.push_back({"--out-dir (" + spec.label + ")", stemOf(spec.label) + ext, false});
  outputs.push_back({"--out-dir (summary)", (fs::path(base.out) / "summary.json").string(), false});
  if (!montage.empty()) outputs.push_back({"--montage", montage});
  checkOutputs(outputs, {{"--scene", base.scene}, {"--preset", base.preset}});
  const std::shared_ptr<sl::Scene> scene = loadScene(base.scene);  // once: its warnings once
  checkOutputsAgainstScene(outputs, *scene);
  sl::gl::EglContext ctx;
  checkFrameSize(base.width, base.height);
  sl::Renderer r;
  json summary = json::array();
  std::vector<sl::ui::FigureCell> cells;
  r.setScene(scene);  // the scene's light, or --light's
  if (base.light) r.setLight(*base.light);
  const sl::LightType lightType = r.light().type;
  if (!all)  // every asked-for configuration must render this light: refused before any work
    for (const sl::cli::ConfigSpec& spec : specs)
      if (const sl::TechniqueInfo* info = sl::Renderer::findTechnique(spec.techniqueId))
        if (auto e = sl::checkLightSupport(*info, lightType))
          throw UsageError("--technique " + spec.techniqueId + ": " + *e);
  // --set (and a preset's parameters) apply to every configuration that renders: each must
  // have the key and take the value, checked before anything renders.
  for (const sl::cli::ConfigSpec& spec : specs) {
    const sl::TechniqueInfo* info = sl::Renderer::findTechnique(spec.techniqueId);
    if (info && sl::checkLightSupport(*info, lightType)) continue;  // skipped below
    sl::cli::ConfigSpec trial = spec;
    for (const std::string& kv : base.sets) {
      auto eq = kv.find('=');
      if (eq == std::string::npos || eq == 0)
        throw UsageError("--set: expected KEY=VALUE, got '" + kv + "'");
      bool swept = false;  // a --technique sweep's own value wins
      for (const auto& [k, v] : spec.sets) swept = swept || k == kv.substr(0, eq);
      if (!swept) trial.sets.push_back({kv.substr(0, eq), kv.substr(eq + 1)});
    }
    if (auto e = sl::cli::validateConfig(trial))
      throw UsageError("--set: " + *e +
                       (all ? " (compare renders every technique: name the "
                              "ones to compare with --technique)"
                            : ""));
  }
  std::size_t failed = 0;  // configurations whose frames the renderer refused
  std::printf("%-28s %10s %12s %10s %10s %10s\n", "configuration", "total ms", "texels", "error %",
              "false lit", "false shd");
  for (const sl::cli::ConfigSpec& spec : specs) {
    // A technique that cannot render this light (cube: no directional) gets a row saying
    // so, not a wrong picture; the others go on.
    const sl::TechniqueInfo* info = sl::Renderer::findTechnique(spec.techniqueId);
    if (auto e = info ? sl::checkLightSupport(*info, lightType) : std::nullopt) {
      std::printf("%-28s skipped: %s\n", spec.label.c_str(), e->c_str());
      continue;
    }
    RenderConfig cfg = base;
    cfg.technique = spec.techniqueId;
    for (const auto& [k, v] : spec.sets) cfg.sets.push_back(k + "=" + v);
    cfg.frames = std::max(cfg.frames, 3);
    configure(r, cfg, scene);
    sl::Renderer::ErrorResult err;
    json j;
    try {
      j = renderAndMeasure(r, cfg, err);
    } catch (const UsageError&) {
      throw;
    } catch (const std::runtime_error& e) {
      // A frame the renderer refused measured nothing: a failed row, no image; the others
      // go on.
      const std::string why = sl::cutText(e.what());
      std::printf("%-28s failed: %s\n", spec.label.c_str(), why.c_str());
      summary.push_back({{"configuration", spec.label}, {"failure", why}});
      ++failed;
      continue;
    }
    j["configuration"] = spec.label;
    const std::string stem = stemOf(spec.label);
    // Files compare names in --out-dir: only regular files are replaced there.
    auto inOutDir = [](const std::string& path) { return OutputFile{path, path, false}; };
    writePng(inOutDir(stem + ".png"), err.frame.color);
    writePng(inOutDir(stem + ".error.png"),
             sl::makeErrorImage(err.frame.color, err.frame.hardMask, err.referenceMask));
    writeText(inOutDir(stem + ".json"), j.dump(2, ' ', false, json::error_handler_t::replace));
    summary.push_back(j);
    const double ms = j["total_ms"].get<double>();
    const auto texels = j["texels"].get<std::uint64_t>();
    if (err.stats.covered == 0)
      std::printf("%-28s %10.2f %12llu n/a (no covered pixel)\n", spec.label.c_str(), ms,
                  (unsigned long long)texels);
    else
      std::printf("%-28s %10.2f %12llu %10.3f %10.3f %10.3f\n", spec.label.c_str(), ms,
                  (unsigned long long)texels, err.stats.errorPct, err.stats.falseLitPct,
                  err.stats.falseShadowPct);
    if (std::string w = describeWarmup(j); !w.empty() && w.rfind("note:", 0) == 0)
      std::fprintf(stderr, "%s\n", w.c_str());
    if (!montage.empty()) {
      char facts[160];
      const double mib = double(j["bytes"].get<std::uint64_t>()) / double(1 << 20);
      if (err.stats.covered == 0)
        std::snprintf(facts, sizeof facts, "%.3g M texels (%.3g MiB), error n/a, %.1f ms",
                      double(texels) / 1e6, mib, ms);
      else
        std::snprintf(facts, sizeof facts, "%.3g M texels (%.3g MiB), error %.3f %%, %.1f ms",
                      double(texels) / 1e6, mib, err.stats.errorPct, ms);
      cells.push_back(
          {spec.label, facts, err.frame.color,
           sl::makeErrorImage(err.frame.color, err.frame.hardMask, err.referenceMask, dilate)});
    }
  }
  const std::string summaryPath = (fs::path(base.out) / "summary.json").string();
  writeText(OutputFile{summaryPath, summaryPath, false},
            summary.dump(2, ' ', false, json::error_handler_t::replace));
  std::printf(
      "wrote images (<configuration>.png, <configuration>.error.png) and metrics (*.json, "
      "summary.json) to %s\n",
      fs::absolute(base.out).string().c_str());
  if (!montage.empty() && cells.empty())
    std::fprintf(stderr, "note: %s not written: no configuration rendered\n", montage.c_str());
  if (!montage.empty() && !cells.empty()) {
    char title[256];
    std::snprintf(title, sizeof title,
                  "%s, %dx%d, %s light; below each image its errors against the exact reference "
                  "(magenta: wrongly lit, cyan: wrongly shadowed; drawn %d px wider)",
                  scene->name.c_str(), base.width, base.height,
                  lightType == sl::LightType::Directional ? "directional"
                  : lightType == sl::LightType::Spot      ? "spot"
                                                          : "point",
                  dilate);
    sl::cli::writeMontage(cells, title, columns, inset, montage);  // a write error: exit 1
    std::printf("wrote the montage %s\n", montage.c_str());
  }
  if (failed)
    std::fprintf(stderr, "shadowlab-cli: %zu configuration%s failed (see \"failure\" in %s)\n",
                 failed, failed == 1 ? "" : "s",
                 (fs::path(base.out) / "summary.json").string().c_str());
  return failed ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; ++i) a.rest.emplace_back(argv[i]);
  try {
    // No command is bad input: one line on stderr, exit 2 (the usage is --help's, on stdout).
    if (a.rest.empty())
      throw UsageError(
          "no command (commands: list, version, render, compare, bench, chart, stability, "
          "storage, reproduce; shadowlab-cli --help shows the usage)");
    if (a.rest[0] == "--help" || a.rest[0] == "-h") {
      std::cout << kUsage << kBenchUsage << kChartUsage << kStabilityUsage << kStorageUsage
                << kReproduceUsage;
      return 0;
    }
    const std::string& cmd = a.rest[0];
    // `shadowlab-cli COMMAND --help`: that command's usage, exit 0.
    if (std::find_if(a.rest.begin() + 1, a.rest.end(), [](const std::string& s) {
          return s == "--help" || s == "-h";
        }) != a.rest.end()) {
      if (cmd == "bench")
        std::cout << kBenchUsage;
      else if (cmd == "chart")
        std::cout << kChartUsage;
      else if (cmd == "stability")
        std::cout << kStabilityUsage;
      else if (cmd == "storage")
        std::cout << kStorageUsage;
      else if (cmd == "reproduce")
        std::cout << kReproduceUsage;
      else
        std::cout << kUsage;
      return 0;
    }
    if (cmd == "list") return cmdList(a);
    if (cmd == "version" || cmd == "--version") return cmdVersion();
    if (cmd == "render") return cmdRender(a);
    if (cmd == "compare") return cmdCompare(a);
    if (cmd == "bench") return cmdBench(a);
    if (cmd == "stability") return cmdStability(a);
    if (cmd == "chart") return cmdChart(a);
    if (cmd == "storage") return cmdStorage(a);
    if (cmd == "reproduce") return cmdReproduce(a);
    throw UsageError(
        "unknown command '" + cmd +
        "' (commands: list, version, render, compare, bench, chart, stability, storage, "
        "reproduce)");
  } catch (const UsageError& e) {
    std::cerr << "shadowlab-cli: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::string msg = e.what();
    std::replace(msg.begin(), msg.end(), '\n', ' ');
    std::cerr << "shadowlab-cli: " << msg << "\n";
    return 1;
  }
}
