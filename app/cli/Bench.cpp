// `shadowlab-cli bench`: speed against accuracy (issue 5). Every configuration of the
// sweep renders every frame of a camera path, interleaved frame by frame (so machine
// drift hits all alike), and is measured against the exact Embree reference; the CSV has
// one row per configuration with medians over frames, the chart plots time (or, with
// `--x bytes`, shadow memory) against error.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string_view>

#include "Chart.h"
#include "ChartCsv.h"
#include "Commands.h"
#include "measure/Measure.h"
#include "algo/InputFile.h"
#include "gl/EglContext.h"

namespace sl::cli {

const char* const kBenchUsage =
    "       shadowlab-cli bench --scene NAME|FILE --technique ID[:KEY=V1,V2,...]...\n"
    "                           [--path NAME|INDEX [--path-hz HZ] | --camera NAME|INDEX]\n"
    "                           [--frames N] [--warmup N] [--size WxH] [--light LIGHT]\n"
    "                           [--set KEY=VALUE]... --csv FILE.csv [--chart FILE.png]\n"
    "                           [--chart-y auto|linear|log] [--x ms|bytes] [--no-reference]\n"
    "         (--no-reference: no ray-traced reference, timings only: the error cells empty)\n"
    "         (--path-hz: along a path each configuration also renders a frame every 1/HZ s\n"
    "          of path time between the measured ones; 0: none; see docs/user-guide/bench.md)\n";

namespace {

struct BenchConfig {
  std::string scene;
  std::vector<std::string> techniques;  ///< --technique texts
  std::vector<std::string> sets;        ///< --set for every configuration
  std::string path, camera;
  double pathHz = kDefaultPathHz;  ///< along a path: a frame every 1/HZ s (Measure.h)
  bool pathHzGiven = false;
  int frames = 12;
  int warmup = 3;
  int width = 640, height = 360;
  std::optional<Light> light;
  std::string csv, chart;
  std::string chartY = "auto";
  ChartX chartX = ChartX::TimeMs;  ///< the chart's x (the CSV has both)
  /// The Embree reference (error columns). Off with --no-reference, and in a build without
  /// it (SHADOWLAB_REFERENCE=OFF): timings only, the error cells empty.
  bool reference = true;
};

/// `--x ms|bytes`: what the chart's x axis and its Pareto front are against.
ChartX parseChartXOption(const std::string& value) {
  if (auto x = parseChartX(value)) return *x;
  throw UsageError("--x: expected ms or bytes, got '" + value + "'");
}

BenchConfig parseBench(Args& a) {
  BenchConfig c;
  for (std::size_t i = 1; i < a.rest.size(); ++i) {
    const std::string& o = a.rest[i];
    if (o == "--scene")
      c.scene = a.take(i, o);
    else if (o == "--technique")
      c.techniques.push_back(a.take(i, o));
    else if (o == "--set")
      c.sets.push_back(a.take(i, o));
    else if (o == "--path")
      c.path = a.take(i, o);
    else if (o == "--camera")
      c.camera = a.take(i, o);
    else if (o == "--path-hz") {
      c.pathHz = parsePathHz(o, a.take(i, o));
      c.pathHzGiven = true;
    } else if (o == "--frames")
      c.frames = parseInt(o, a.take(i, o), 1, 100000);
    else if (o == "--warmup")
      c.warmup = parseInt(o, a.take(i, o), 0, 1000);
    else if (o == "--size")
      std::tie(c.width, c.height) = parseSize(a.take(i, o));
    else if (o == "--light")
      c.light = parseLight(o, a.take(i, o));
    else if (o == "--csv")
      c.csv = a.take(i, o);
    else if (o == "--chart")
      c.chart = a.take(i, o);
    else if (o == "--chart-y") {
      c.chartY = a.take(i, o);
      if (c.chartY != "auto" && c.chartY != "linear" && c.chartY != "log")
        throw UsageError("--chart-y: expected auto, linear or log, got '" + c.chartY + "'");
    } else if (o == "--x")
      c.chartX = parseChartXOption(a.take(i, o));
    else if (o == "--no-reference")
      c.reference = false;
    else
      throw UsageError("unknown option '" + o + "' (bench options: see shadowlab-cli --help)");
  }
  if (c.scene.empty()) throw UsageError("--scene: missing (which scene to benchmark)");
  if (c.techniques.empty()) throw UsageError("--technique: missing (at least one configuration)");
  if (c.csv.empty()) throw UsageError("--csv: missing (where to write the results)");
  if (!c.path.empty() && !c.camera.empty())
    throw UsageError("--camera: give either a camera path (--path) or a bookmark (--camera)");
  if (c.pathHzGiven && !c.camera.empty())
    throw UsageError(
        "--path-hz: goes with a camera path, not --camera (a fixed camera renders "
        "no frames in between)");
  return c;
}

/// Adds the --set values to every configuration that has the key; a key that no
/// configuration (and no shared parameter) has is an error.
void applyCommonSets(std::vector<ConfigSpec>& configs, const std::vector<std::string>& sets) {
  for (const std::string& kv : sets) {
    auto eq = kv.find('=');
    if (eq == std::string::npos || eq == 0)
      throw UsageError("--set: expected KEY=VALUE, got '" + kv + "'");
    const std::string key = kv.substr(0, eq), value = kv.substr(eq + 1);
    bool used = false;
    for (ConfigSpec& c : configs) {
      bool swept = false;
      for (const auto& s : c.sets) swept = swept || s.first == key;
      if (swept) continue;  // the sweep's value wins
      ConfigSpec trial = c;
      trial.sets.push_back({key, value});
      auto err = validateConfig(trial);
      if (err && err->find("has no parameter") != std::string::npos) continue;
      if (err) throw UsageError("--set: " + *err);
      c.sets.push_back({key, value});
      used = true;
    }
    if (!used) throw UsageError("--set: no configuration has a parameter '" + key + "'");
  }
}

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char ch : s) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return out + "\"";
}

std::string number(double v) {
  if (!std::isfinite(v)) return "";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

/// Column name of a pass: "shadow map" -> "shadow_map_ms", "scan + warp" -> "scan_warp_ms".
std::string passColumn(const std::string& pass) {
  std::string c;
  for (char ch : pass) {
    if (std::isalnum(static_cast<unsigned char>(ch)))
      c += ch;
    else if (!c.empty() && c.back() != '_')
      c += '_';
  }
  while (!c.empty() && c.back() == '_') c.pop_back();
  return c + "_ms";
}

/// A count as a CSV cell: empty when not measured (NaN).
std::string count(double v) {
  return std::isfinite(v) ? std::to_string(std::uint64_t(v)) : std::string();
}

/// `--chart-y log` with a measured error of 0 (a log axis has no 0): "--chart-y log: TECHNIQUE
/// PARAMS measured error_pct 0, which a log axis cannot show (...)"; else nothing.
std::optional<std::string> logAxisProblem(const std::vector<ChartRow>& rows,
                                          const std::string& chartY) {
  if (chartY != "log") return std::nullopt;
  for (const ChartRow& r : rows) {
    if (r.errorPct > 0.0) continue;
    std::string label = r.technique;
    for (const auto& [k, v] : r.params) label += " " + k + "=" + v;
    return "--chart-y log: " + cutText(label, 120) +
           " measured error_pct 0, which a log axis cannot show (use --chart-y auto or linear)";
  }
  return std::nullopt;
}

/// Point labels: per technique, the values of the parameters that vary between its rows
/// (all its parameters when it has one row); the legend names those parameters.
void writeChart(const std::vector<ChartRow>& rows, ChartSpec spec, const std::string& png) {
  // Per technique: its row count and, per parameter, whether two rows differ (one pass, so
  // a CSV of many rows stays linear).
  struct KeyValues {
    std::string firstValue;
    bool differs = false;
  };
  std::vector<std::string> order;
  std::map<std::string, std::size_t> rowCount;
  std::map<std::string, std::map<std::string, KeyValues>> values;
  for (const ChartRow& r : rows) {
    if (rowCount[r.technique]++ == 0) order.push_back(r.technique);
    auto& keys = values[r.technique];
    for (const auto& [k, v] : r.params) {
      auto [it, added] = keys.try_emplace(k, KeyValues{v, false});
      if (!added && it->second.firstValue != v) it->second.differs = true;
    }
  }
  std::map<std::string, std::vector<std::string>> varying;
  for (const ChartRow& r : rows) {
    const bool alone = rowCount[r.technique] == 1;
    auto& list = varying[r.technique];
    for (const auto& [k, v] : r.params)
      if ((alone || values[r.technique][k].differs) &&
          std::find(list.begin(), list.end(), k) == list.end())
        list.push_back(k);
  }
  std::vector<ChartPoint> points;
  for (const ChartRow& r : rows) {
    std::string label;
    for (const std::string& k : varying[r.technique])
      for (const auto& [k2, v] : r.params)
        if (k2 == k) label += (label.empty() ? "" : "/") + v;
    points.push_back(
        {r.technique, label, spec.x == ChartX::Bytes ? r.bytes : r.totalMs, r.errorPct});
  }
  // The keys behind the labels: once in the subtitle when every technique has the same,
  // else in each technique's legend entry.
  auto keysOf = [&](const std::string& t) {
    std::string keys;
    for (const std::string& k : varying[t]) keys += (keys.empty() ? "" : "/") + k;
    return keys;
  };
  bool same = true;
  for (const std::string& t : order) same = same && keysOf(t) == keysOf(order.front());
  if (same && !keysOf(order.front()).empty())
    spec.subtitle += "; point labels: " + keysOf(order.front());
  for (const std::string& t : order)
    spec.seriesNotes.push_back(same || keysOf(t).empty() ? "" : "labels: " + keysOf(t));
  writeAtomically(
      png, [&](const std::string& path) { return writeSpeedAccuracyChart(points, spec, path); });
  std::printf("chart -> %s\n", png.c_str());
}

}  // namespace

const char* const kChartUsage =
    "       shadowlab-cli chart --csv FILE.csv --chart FILE.png [--chart-y auto|linear|log]\n"
    "                           [--x ms|bytes]\n";

int cmdChart(Args& a) {
  std::string csvPath, png, chartY = "auto";
  ChartX chartX = ChartX::TimeMs;
  for (std::size_t i = 1; i < a.rest.size(); ++i) {
    const std::string& o = a.rest[i];
    if (o == "--csv")
      csvPath = a.take(i, o);
    else if (o == "--chart")
      png = a.take(i, o);
    else if (o == "--chart-y")
      chartY = a.take(i, o);
    else if (o == "--x")
      chartX = parseChartXOption(a.take(i, o));
    else
      throw UsageError("unknown option '" + o +
                       "' (chart options: --csv, --chart, --chart-y, --x)");
  }
  if (csvPath.empty()) throw UsageError("--csv: missing (a CSV written by bench)");
  if (png.empty()) throw UsageError("--chart: missing (the PNG to write)");
  if (chartY != "auto" && chartY != "linear" && chartY != "log")
    throw UsageError("--chart-y: expected auto, linear or log, got '" + chartY + "'");
  checkOutputs({{"--chart", png}}, {{"--csv", csvPath}});
  ChartCsv csv = readChartCsv(csvPath, chartX);
  if (auto e = logAxisProblem(csv.rows, chartY)) throw UsageError(*e);  // before any drawing
  csv.spec.yScale = chartY;
  writeChart(csv.rows, csv.spec, png);
  return 0;
}

namespace {}  // namespace

int cmdBench(Args& a) {
  BenchConfig cfg = parseBench(a);
  checkOutputs({{"--csv", cfg.csv}, {"--chart", cfg.chart}}, {{"--scene", cfg.scene}});
  std::vector<ConfigSpec> configs;
  for (const std::string& t : cfg.techniques) {
    std::vector<ConfigSpec> more = expandTechniqueSweep(t);
    configs.insert(configs.end(), more.begin(), more.end());
  }
  applyCommonSets(configs, cfg.sets);
  {  // Unique labels (the same configuration may be listed twice).
    std::map<std::string, int> seen;
    for (ConfigSpec& c : configs) {
      c.label = c.techniqueId + (c.sets.empty() ? "" : " " + c.paramsText());
      if (int n = ++seen[c.label]; n > 1) c.label += " #" + std::to_string(n);
    }
  }
  std::shared_ptr<Scene> scene = loadScene(cfg.scene);
  checkOutputsAgainstScene({{"--csv", cfg.csv}, {"--chart", cfg.chart}}, *scene);

  // One camera per frame: along the path, or a fixed bookmark.
  std::string cameraText;
  const MeasureCameras cameras =
      measureCameras(*scene, cfg.path, cfg.camera, cfg.frames, cfg.pathHz, cameraText);
  if (cfg.pathHzGiven && !cameras.alongPath)
    std::fprintf(stderr,
                 "note: --path-hz: %s has no camera path: a fixed camera, no frames in between\n",
                 scene->name.c_str());
  // "path walk, 30 Hz": the spacing of the frames each configuration rendered.
  std::string spacingText = cameraText;
  if (cameras.alongPath) spacingText += ", " + number(cameras.pathHz) + " Hz";

  std::vector<std::vector<FrameSample>> samples(configs.size());
  std::string glDescription, timingMethod;
  int referenceEvaluations = 0;
  std::size_t framesRendered = 0;  // by each configuration (the first's), measured or not
  {
    gl::EglContext ctx;
    checkFrameSize(cfg.width, cfg.height);
    std::vector<std::unique_ptr<ConfigRunner>> runners;
    for (const ConfigSpec& c : configs)
      runners.push_back(std::make_unique<ConfigRunner>(c, scene, cfg.light));
    glDescription = runners.front()->renderer().glDescription();
    MeasureOptions opts;
    opts.width = cfg.width;
    opts.height = cfg.height;
    opts.publishing = true;  // the published numbers only (light.area, importance.halfmass.*)
    if (cfg.reference && !ShadowReference::available()) {
      std::fprintf(stderr, "note: %s (error columns empty)\n",
                   ShadowReference::unavailableReason());
      cfg.reference = false;
    }
    std::optional<ReferenceCache> reference;
    if (cfg.reference) reference.emplace(*scene);

    std::fprintf(stderr, "bench: %zu configurations x %d frames on %s (%s), %dx%d", runners.size(),
                 cfg.frames, scene->name.c_str(), spacingText.c_str(), cfg.width, cfg.height);
    if (cameras.alongPath)
      std::fprintf(stderr, ", %zu unmeasured frames in between for each", cameras.betweenCount());
    std::fprintf(stderr, "\n");
    ProgressBar progress("bench", runners.size() * std::size_t(cfg.frames));
    std::size_t inFrame = 0;
    // Warm-up at the first camera (shader variants compile on first use (llvmpipe JIT), maps
    // are allocated, DA-RTW's rotation settles; not measured), then interleaved frames.
    samples =
        runInterleaved(runners, cameras, opts, reference ? &*reference : nullptr, cfg.warmup,
                       [&](std::size_t i, int f, const FrameSample& s) {
                         for (const std::string& e : s.glErrors)
                           std::fprintf(stderr, "\nshadowlab-cli: GL error in %s, frame %d: %s\n",
                                        configs[i].label.c_str(), f, e.c_str());
                         if (!s.renderError.empty())
                           std::fprintf(stderr, "\nshadowlab-cli: %s, frame %d: %s\n",
                                        configs[i].label.c_str(), f, s.renderError.c_str());
                         if (!s.failed()) timingMethod = s.timingMethod;
                         const bool frameDone = ++inFrame == runners.size();
                         if (frameDone) inFrame = 0;
                         progress.step("frame " + std::to_string(f + 1) + "/" +
                                           std::to_string(cfg.frames) + "  " + configs[i].label,
                                       frameDone);
                       });
    progress.finish();
    referenceEvaluations = reference ? reference->evaluations() : 0;
    framesRendered = runners.front()->framesRendered();
  }

  // CSV: one row per configuration.
  std::vector<ConfigSummary> sums;
  std::vector<std::string> passNames;
  for (const auto& frames : samples) {
    sums.push_back(summarise(frames));
    for (const FrameSample& f : frames)
      for (const PassTiming& p : f.passes)
        if (std::find(passNames.begin(), passNames.end(), p.name) == passNames.end())
          passNames.push_back(p.name);
  }
  // The Pareto fronts against time (`pareto`) and against memory (`pareto_bytes`).
  auto frontAgainst = [&](auto cost) {
    std::vector<CostPoint> costs;
    // Configurations with a measured error and no failed frame (a configuration that fails
    // some frames is not comparable with one that renders them all).
    std::vector<std::size_t> index;
    for (std::size_t i = 0; i < sums.size(); ++i)
      if (std::isfinite(sums[i].errorPct) && sums[i].renderErrors == 0) {
        costs.push_back({cost(sums[i]), sums[i].errorPct});
        index.push_back(i);
      }
    std::vector<bool> on(sums.size(), false);
    for (std::size_t i : paretoFront(costs)) on[index[i]] = true;
    return on;
  };
  const std::vector<bool> frontMs = frontAgainst([](const ConfigSummary& s) { return s.totalMs; });
  const std::vector<bool> frontBytes = frontAgainst([](const ConfigSummary& s) { return s.bytes; });

  std::ostringstream csv;
  csv << "scene,camera,technique,params,label,frames,path_hz,width,height,timing_method,total_ms,"
         "total_ms_frames";
  for (const std::string& p : passNames) csv << "," << csvField(passColumn(p));
  csv << ",texels,bytes,error_pct,false_lit_pct,false_shadow_pct,covered_pixels,error_near_pct,"
         "error_far_pct,aliasing_mean,aliasing_p95,aliasing_max,flicker_pct,light_area_m2,halfmass_"
         "x,halfmass_y,rotation_deg,"
         "anisotropy,pareto,pareto_bytes,render_errors,gl_errors,failure,gl\n";
  for (std::size_t i = 0; i < configs.size(); ++i) {
    const ConfigSummary& s = sums[i];
    csv << csvField(scene->name) << "," << csvField(cameraText) << ","
        << csvField(configs[i].techniqueId) << "," << csvField(configs[i].paramsText()) << ","
        << csvField(configs[i].label) << "," << samples[i].size() << ","
        << (cameras.alongPath ? number(cameras.pathHz) : std::string()) << "," << cfg.width << ","
        << cfg.height << "," << csvField(s.timingMethod) << "," << number(s.totalMs) << ",";
    for (std::size_t f = 0; f < s.frameMs.size(); ++f)  // the spread behind the median
      csv << (f ? ";" : "") << number(s.frameMs[f]);
    for (const std::string& p : passNames)
      csv << "," << (s.passMs.count(p) ? number(s.passMs.at(p)) : std::string());
    csv << "," << count(s.texels) << "," << count(s.bytes) << "," << number(s.errorPct) << ","
        << number(s.falseLitPct) << "," << number(s.falseShadowPct) << "," << count(s.covered)
        << "," << number(s.errorNearPct) << "," << number(s.errorFarPct) << ","
        << number(s.aliasingMean) << "," << number(s.aliasingP95) << "," << number(s.aliasingMax)
        << "," << number(s.flickerPct) << "," << number(s.lightAreaM2) << "," << number(s.halfMassX)
        << "," << number(s.halfMassY) << "," << number(s.rotationDeg) << "," << number(s.anisotropy)
        << "," << (frontMs[i] ? 1 : 0) << "," << (frontBytes[i] ? 1 : 0) << "," << s.renderErrors
        << "," << s.glErrors << "," << csvField(s.failure) << "," << csvField(glDescription)
        << "\n";
  }
  std::string text = csv.str();
  text.pop_back();  // writeText adds the final newline
  writeText(cfg.csv, text);

  std::printf("%-34s %9s %9s %9s %9s %9s %9s %9s\n", "configuration", "total ms", "MiB", "error %",
              "m mean", "m p95", "flicker %", "pareto");
  for (std::size_t i = 0; i < configs.size(); ++i) {
    const ConfigSummary& s = sums[i];
    const char* front = frontMs[i] && frontBytes[i] ? "ms,bytes"
                        : frontMs[i]                ? "ms"
                        : frontBytes[i]             ? "bytes"
                                                    : "";
    if (s.failed()) {
      std::printf("%-34s failed: %s\n", configs[i].label.c_str(), s.failure.c_str());
      continue;
    }
    // Not measured (no covered pixel, one frame): n/a, never a number.
    auto cell = [](double v, const char* format) {
      if (!std::isfinite(v)) return std::string("n/a");
      char buf[32];
      std::snprintf(buf, sizeof buf, format, v);
      return std::string(buf);
    };
    std::printf("%-34s %9.2f %9.3f %9s %9s %9s %9s %9s\n", configs[i].label.c_str(), s.totalMs,
                s.bytes / (1024.0 * 1024.0), cell(s.errorPct, "%.3f").c_str(),
                cell(s.aliasingMean, "%.3f").c_str(), cell(s.aliasingP95, "%.3f").c_str(),
                cell(s.flickerPct, "%.4f").c_str(), front);
  }
  std::printf(
      "medians over %d frames (%s, %dx%d, timing %s, %d reference evaluations, %zu frames "
      "rendered by each configuration) -> %s\n",
      cfg.frames, spacingText.c_str(), cfg.width, cfg.height, timingMethod.c_str(),
      referenceEvaluations, framesRendered, cfg.csv.c_str());

  if (!cfg.chart.empty()) {
    std::vector<ChartRow> rows;
    for (std::size_t i = 0; i < configs.size(); ++i)
      // No covered pixel: nothing to plot; a failed frame: not comparable (as `chart` reads
      // the CSV).
      if (std::isfinite(sums[i].errorPct) && sums[i].renderErrors == 0)
        rows.push_back({configs[i].techniqueId, configs[i].sets, sums[i].totalMs, sums[i].bytes,
                        sums[i].errorPct});
    if (rows.empty()) {
      std::size_t withFailures = 0;
      for (const ConfigSummary& s : sums) withFailures += s.renderErrors ? 1 : 0;
      throw std::runtime_error(
          cfg.chart + ": not written: no configuration has a measured error (" +
          (withFailures ? std::to_string(withFailures) + " with failed frames, the others with "
                        : std::string()) +
          "no covered pixel in any frame); the CSV is written");
    }
    // Measured, so exit 1 (the CSV is written); `chart --csv` refuses it up front.
    if (auto e = logAxisProblem(rows, cfg.chartY))
      throw std::runtime_error(cfg.chart + ": not written: " + *e + "; the CSV is written");
    ChartSpec spec;
    spec.yScale = cfg.chartY;
    spec.x = cfg.chartX;
    spec.title = std::string(chartHeadline(cfg.chartX)) + ": " + scene->name + ", " + spacingText;
    spec.subtitle = std::to_string(cfg.width) + "x" + std::to_string(cfg.height) + ", " +
                    std::to_string(cfg.frames) + " frames (medians), timing " + timingMethod +
                    ", " + glDescription;
    writeChart(rows, spec, cfg.chart);
  }
  // Failed frames and GL errors fail the run, each configuration named.
  std::size_t bad = 0;
  for (std::size_t i = 0; i < configs.size(); ++i) {
    const ConfigSummary& s = sums[i];
    bad += s.renderErrors + s.glErrors;
    if (s.failed())
      std::fprintf(stderr, "shadowlab-cli: %s: failed every frame (%zu): %s\n",
                   configs[i].label.c_str(), s.renderErrors, s.failure.c_str());
    else if (s.renderErrors)
      std::fprintf(stderr,
                   "shadowlab-cli: %s: %zu of %zu frames failed (left out of the medians and "
                   "the Pareto fronts), first %s\n",
                   configs[i].label.c_str(), s.renderErrors, s.frameMs.size(), s.failure.c_str());
  }
  return bad ? 1 : 0;
}

}  // namespace sl::cli
