// `shadowlab-cli reproduce`: see Reproduce.h.
#include "Reproduce.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <string_view>

#include <nlohmann/json.hpp>

#include "Commands.h"
#include "Montage.h"
#include "algo/InputFile.h"
#include "core/JsonInput.h"
#include "core/Preset.h"
#include "gl/EglContext.h"
#include "scene/GltfLoader.h"

namespace sl::cli {

const char* const kReproduceUsage =
    "       shadowlab-cli reproduce --out DIR [--seed 000..004]... [--claim ID]... [--quick]\n"
    "                               [--claims FILE.json|FOLDER]\n"
    "         (every claim of scenes/claims/*.json measured and judged: DIR/REPORT.md with\n"
    "          figures, DIR/report.json; --quick: the claims' small sizes, a few minutes)\n";

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string num(double v) {
  if (!std::isfinite(v)) return "n/a";
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

/// "0.93 [0.88, 0.99]": a value and its 95 % interval (the value alone when exact).
std::string intervalText(const claims::Interval& iv) {
  if (iv.low == iv.high && iv.low == iv.value) return num(iv.value);
  return num(iv.value) + " [" + num(iv.low) + ", " + num(iv.high) + "]";
}

// --- Reading a claims file: every error names the file and the JSON path.

struct Reader {
  std::string file;
  /// "FILE: PATH: what" (PATH dotted: claims[3].expect.op), as every JSON input says it.
  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    try {
      JsonReader(file).fail(path, what);
    } catch (const JsonInputError& e) {
      throw UsageError(cutText(e.what(), 600));
    }
  }
  void keys(const json& o, const std::string& path,
            std::initializer_list<const char*> known) const {
    if (!o.is_object()) fail(path, "expected an object");
    for (const auto& [k, v] : o.items()) {
      bool ok = false;
      std::string list;
      for (const char* n : known) {
        ok = ok || k == n;
        list += (list.empty() ? "" : ", ") + std::string(n);
      }
      if (!ok) fail(jsonPath(path, k), "unknown key (known: " + list + ")");
    }
  }
  std::string str(const json& o, const std::string& path, const char* key, bool required,
                  const std::string& fallback = "") const {
    if (!o.contains(key)) {
      if (required) fail(jsonPath(path, key), "missing");
      return fallback;
    }
    if (!o.at(key).is_string()) fail(jsonPath(path, key), "expected a string");
    return o.at(key).get<std::string>();
  }
  double number(const json& o, const std::string& path, const char* key) const {
    if (!o.contains(key)) fail(jsonPath(path, key), "missing");
    const json& v = o.at(key);
    if (!v.is_number() || !std::isfinite(v.get<double>()))
      fail(jsonPath(path, key), "expected a finite number");
    return v.get<double>();
  }
  std::vector<std::string> strings(const json& o, const std::string& path, const char* key) const {
    std::vector<std::string> out;
    if (!o.contains(key)) return out;
    if (!o.at(key).is_array()) fail(jsonPath(path, key), "expected an array of strings");
    for (std::size_t i = 0; i < o.at(key).size(); ++i) {
      if (!o.at(key)[i].is_string()) fail(jsonPath(jsonPath(path, key), i), "expected a string");
      out.push_back(o.at(key)[i].get<std::string>());
    }
    return out;
  }
};

Predicate readPredicate(const Reader& r, const json& o, const std::string& path) {
  r.keys(o, path, {"op", "value", "tolerance", "factor"});
  Predicate p;
  p.op = r.str(o, path, "op", true);
  if (p.op != "<=" && p.op != ">=" && p.op != "<" && p.op != ">" && p.op != "within" &&
      p.op != "within-factor")
    r.fail(jsonPath(path, "op"),
           "expected <=, >=, <, >, within or within-factor, got '" + p.op + "'");
  p.value = r.number(o, path, "value");
  if (p.op == "within-factor") {
    p.tolerance = r.number(o, path, "factor");
    if (p.tolerance <= 1.0) r.fail(jsonPath(path, "factor"), "must be above 1 (within kx: k > 1)");
    if (p.value <= 0.0) r.fail(jsonPath(path, "value"), "within-factor needs a positive value");
  } else if (o.contains("factor")) {
    r.fail(jsonPath(path, "factor"), "only 'within-factor' takes a factor");
  }
  if (p.op == "within") {
    p.tolerance = r.number(o, path, "tolerance");
    if (p.tolerance < 0.0) r.fail(jsonPath(path, "tolerance"), "must not be negative");
    if (p.tolerance >= claims::kMaxWithinTolerance)
      r.fail(jsonPath(path, "tolerance"), "must be below " + num(claims::kMaxWithinTolerance) +
                                              " (claims::kMaxWithinTolerance: within " +
                                              num(100.0 * claims::kMaxWithinTolerance) +
                                              " % of a value admits 0 and its double)");
    if (p.value == 0.0) r.fail(jsonPath(path, "value"), "within needs a non-zero value (relative)");
  } else if (o.contains("tolerance")) {
    r.fail(jsonPath(path, "tolerance"), "only 'within' takes a tolerance");
  }
  return p;
}

RunSize readSize(const Reader& r, const json& o, const std::string& path, RunSize s) {
  r.keys(o, path, {"size", "frames", "warmup"});
  if (o.contains("size")) {
    try {
      std::tie(s.width, s.height) = parseSize(r.str(o, path, "size", true));
    } catch (const UsageError& e) {
      r.fail(jsonPath(path, "size"), e.what());
    }
  }
  if (o.contains("frames")) {
    const double f = r.number(o, path, "frames");
    if (f < 1 || f > 1000 || f != std::floor(f))
      r.fail(jsonPath(path, "frames"), "expected 1..1000");
    s.frames = int(f);
  }
  if (o.contains("warmup")) {
    const double w = r.number(o, path, "warmup");
    if (w < 0 || w > 100 || w != std::floor(w)) r.fail(jsonPath(path, "warmup"), "expected 0..100");
    s.warmup = int(w);
  }
  return s;
}

/// A configuration: {"preset"?: "papers/X.json", "technique"?, "params"?: {k: "v"}}: the
/// preset's technique and parameters, then these on top. `presetScene` receives the preset's
/// scene.
ConfigSpec readConfig(const Reader& r, const json& o, const std::string& path,
                      std::string* presetScene) {
  r.keys(o, path, {"preset", "technique", "params"});
  ConfigSpec c;
  std::map<std::string, std::string> params;
  if (o.contains("preset")) {
    const std::string rel = r.str(o, path, "preset", true);
    std::string error;
    const fs::path file = builtinSceneDir() / rel;
    const std::optional<Preset> p = loadPreset(file, &error);
    if (!p) r.fail(jsonPath(path, "preset"), error);
    c.techniqueId = p->technique;
    for (const auto& [k, v] : p->params) c.sets.push_back({k, v});
    if (presetScene && presetScene->empty()) *presetScene = p->scene;
  }
  if (o.contains("technique")) c.techniqueId = r.str(o, path, "technique", true);
  if (c.techniqueId.empty())
    r.fail(jsonPath(path, "technique"), "missing (or a preset that names one)");
  if (o.contains("params")) {
    const json& ps = o.at("params");
    if (!ps.is_object())
      r.fail(jsonPath(path, "params"), "expected an object of \"key\": \"value\"");
    for (const auto& item : ps.items()) {
      // (Not a structured binding: clang's C++20 cannot capture one in the lambda below.)
      const std::string k = item.key();
      const json& v = item.value();
      if (!v.is_string()) r.fail(jsonPath(jsonPath(path, "params"), k), "expected a string value");
      auto it =
          std::find_if(c.sets.begin(), c.sets.end(), [&](const auto& kv) { return kv.first == k; });
      if (it != c.sets.end())
        it->second = v.get<std::string>();
      else
        c.sets.push_back({k, v.get<std::string>()});
    }
  }
  if (auto e = validateConfig(c)) r.fail(path, *e);
  c.label = c.techniqueId + (c.sets.empty() ? "" : " " + c.paramsText());
  return c;
}

bool metricKnown(const std::string& m) {
  static const std::set<std::string> known = {
      "error_pct",     "error_near_pct", "error_far_pct", "false_lit_pct", "false_shadow_pct",
      "aliasing_mean", "aliasing_p95",   "aliasing_max",  "flicker_pct",   "total_ms",
      "shadow_ms",     "bytes",          "texels"};
  return known.count(m) || m.rfind("pass:", 0) == 0 || m.rfind("pass_share:", 0) == 0;
}

/// Two configurations that render alike: the same technique and every parameter (its own
/// and the shared ones, defaults included) at the same value.
bool sameConfiguration(const ConfigSpec& a, const ConfigSpec& b) {
  if (a.techniqueId != b.techniqueId) return false;
  const TechniqueInfo* info = findTechniqueInfo(a.techniqueId);
  if (!info) return false;
  auto values = [&](const ConfigSpec& c) {
    ParamSet own(info->params), shared(rendererParamDecls());
    for (const auto& [k, v] : c.sets) (own.has(k) ? own : shared).setFromString(k, v);
    std::map<std::string, std::string> out;
    for (const ParamSet* set : {&own, &shared})
      for (const ParamDecl& d : set->decls()) out[d.key] = set->format(d.key);
    return out;
  };
  return values(a) == values(b);
}

/// A value that compares consecutive frames (flicker, changes) needs two of them in both runs.
void requireTwoFrames(const Reader& r, const Measurement& m, const std::string& path,
                      const std::string& what) {
  for (const auto& [name, size] : {std::pair{"full", m.full}, std::pair{"quick", m.quick}})
    if (size.frames < 2)
      r.fail(jsonPath(path, name), what + " compares consecutive frames: the " + name +
                                       " run has " + std::to_string(size.frames) +
                                       " frame, at least 2 are needed");
}

/// The value of a comparison that shows no effect: 1 for a ratio, 0 for a difference; none
/// for a value alone.
std::optional<double> noEffectValue(const Measurement& m) {
  if (m.kind == "cpu") return m.storageB.empty() ? std::nullopt : std::optional<double>(1.0);
  if (m.kind == "publication" || m.combine == "a") return std::nullopt;
  return m.combine == "ratio" ? 1.0 : 0.0;
}

/// "partly" is an effect in the paper's direction, smaller than the paper's: a one-sided
/// predicate in expect's direction, looser than expect, and on the paper's side of "no effect"
/// (a ratio of 1.06 is not partly "less error").
void checkPartly(const Reader& r, const Claim& claim, const std::string& path) {
  const Predicate& e = claim.expect;
  const Predicate& p = *claim.partly;
  if (e.direction() == 0 || p.direction() != e.direction())
    r.fail(path, "partly needs a one-sided expect and the same direction (" + e.text() + ")");
  if (p.side(e.value) != 0 || p.value == e.value)
    r.fail(path, "partly (" + p.text() + ") must be looser than expect (" + e.text() + ")");
  if (const auto none = noEffectValue(claim.measurement); none && p.holds(*none))
    r.fail(path, "partly (" + p.text() + ") admits no effect (" + num(*none) +
                     "): partly is an effect in the paper's direction, smaller than the paper's");
}

Measurement readMeasurement(const Reader& r, const json& o, const std::string& path,
                            const RunSize& fullDefault, const RunSize& quickDefault) {
  r.keys(o, path,
         {"kind", "scene", "camera", "path", "light", "a", "b", "metric", "combine", "number",
          "statistic", "storage", "storage_b", "value", "figure", "full", "quick"});
  Measurement m;
  m.kind = r.str(o, path, "kind", true);
  bool known = false;
  for (const char* k : kMeasurementKinds) known = known || m.kind == k;
  if (!known)
    r.fail(jsonPath(path, "kind"),
           "unknown '" + m.kind + "' (error-compare, time-ratio, memory-ratio, publication, cpu)");
  m.full = fullDefault;
  m.quick = quickDefault;
  if (o.contains("full")) m.full = readSize(r, o.at("full"), jsonPath(path, "full"), fullDefault);
  if (o.contains("quick"))
    m.quick = readSize(r, o.at("quick"), jsonPath(path, "quick"), quickDefault);
  if (m.kind == "cpu") {
    m.storageA = r.strings(o, path, "storage");
    m.storageB = r.strings(o, path, "storage_b");
    if (m.storageA.empty())
      r.fail(jsonPath(path, "storage"), "missing (the storage command's arguments)");
    m.value = r.str(o, path, "value", true);
    if (m.value != "s" && m.value != "mx" && m.value != "mz" && m.value != "parts" &&
        m.value != "part_s_spread" && m.value != "imbalance" && m.value.rfind("split:", 0) != 0)
      r.fail(jsonPath(path, "value"),
             "expected s, mx, mz, imbalance, parts, part_s_spread or split:I");
    if (m.storageA == m.storageB)
      r.fail(jsonPath(path, "storage_b"),
             "the same arguments as storage: a comparison with itself measures nothing");
    for (const auto* args : {&m.storageA, &m.storageB}) {
      if (args->empty()) continue;
      try {
        const StorageQuery q = storageQuery(*args);
        if (m.value.rfind("split:", 0) == 0) {
          const int i = parseInt("split", m.value.substr(6), 0, 64);
          if (std::size_t(i) >= q.splits.size())
            r.fail(
                jsonPath(path, "value"),
                "split index beyond the " + std::to_string(q.splits.size()) + " split distances");
        }
      } catch (const UsageError& e) {
        r.fail(jsonPath(path, args == &m.storageA ? "storage" : "storage_b"), e.what());
      }
    }
    if (o.contains("figure")) {
      if (!o.at("figure").is_boolean()) r.fail(jsonPath(path, "figure"), "expected true or false");
      m.figure = o.at("figure").get<bool>();
    }
    return m;
  }
  std::string presetScene;
  if (!o.contains("a")) r.fail(jsonPath(path, "a"), "missing (the configuration measured)");
  m.configs.push_back(readConfig(r, o.at("a"), jsonPath(path, "a"), &presetScene));
  if (o.contains("b")) m.configs.push_back(readConfig(r, o.at("b"), jsonPath(path, "b"), nullptr));
  m.scene = r.str(o, path, "scene", false, presetScene);
  if (m.scene.empty()) r.fail(jsonPath(path, "scene"), "missing (or a preset in a that names one)");
  m.camera = r.str(o, path, "camera", false);
  m.path = r.str(o, path, "path", false);
  if (!m.camera.empty() && !m.path.empty())
    r.fail(jsonPath(path, "camera"), "give camera or path, not both");
  m.lightText = r.str(o, path, "light", false);
  if (!m.lightText.empty()) {
    try {
      m.light = parseLight("light", m.lightText);
    } catch (const UsageError& e) {
      r.fail(jsonPath(path, "light"), e.what());
    }
  }
  if (m.kind == "publication") {
    // A still camera: `render --frames N` from it re-runs the same frames (render has no path
    // of frames).
    if (m.camera.empty())
      r.fail(jsonPath(path, "camera"), "missing (a publication is measured from a still camera)");
    m.number = r.str(o, path, "number", true);
    m.statistic = r.str(o, path, "statistic", true);
    if (m.statistic != "median" && m.statistic != "min" && m.statistic != "max" &&
        m.statistic != "final" && m.statistic != "changes")
      r.fail(jsonPath(path, "statistic"), "expected median, min, max, final or changes");
    if (m.configs.size() != 1)
      r.fail(jsonPath(path, "b"), "a publication measures one configuration");
    if (m.statistic == "changes") requireTwoFrames(r, m, path, "changes");
    const TechniqueInfo* info = findTechniqueInfo(m.configs[0].techniqueId);
    bool published = false;
    for (const PublicationDecl& d : info->publications) {
      const std::string& k = d.key;
      const auto star = k.find('*');
      published = published || k == m.number ||
                  (star != std::string::npos && m.number.size() > k.size() - 1 &&
                   m.number.compare(0, star, k, 0, star) == 0 &&
                   m.number.compare(m.number.size() - (k.size() - star - 1), std::string::npos, k,
                                    star + 1) == 0);
    }
    if (!published)
      r.fail(jsonPath(path, "number"),
             "'" + m.number + "' is not a number " + info->id + " publishes");
    return m;
  }
  const char* defaultMetric = m.kind == "time-ratio"     ? "total_ms"
                              : m.kind == "memory-ratio" ? "bytes"
                                                         : "error_pct";
  m.metric = r.str(o, path, "metric", false, defaultMetric);
  if (!metricKnown(m.metric))
    r.fail(jsonPath(path, "metric"),
           "unknown '" + m.metric +
               "' (error_pct, error_near_pct, error_far_pct, false_lit_pct, false_shadow_pct, "
               "aliasing_mean, aliasing_p95, "
               "aliasing_max, flicker_pct, total_ms, shadow_ms, bytes, texels, pass:NAME, "
               "pass_share:NAME; NAME may be PREFIX* or NAME+NAME)");
  if (m.configs.size() == 2 && sameConfiguration(m.configs[0], m.configs[1]))
    r.fail(jsonPath(path, "b"), "the same configuration as a (" + m.configs[0].label +
                                    "): a comparison with itself measures nothing");
  if (m.metric == "flicker_pct") requireTwoFrames(r, m, path, "flicker_pct");
  m.combine = r.str(o, path, "combine", false, m.configs.size() == 2 ? "ratio" : "a");
  if (m.combine != "ratio" && m.combine != "difference" && m.combine != "a")
    r.fail(jsonPath(path, "combine"), "expected ratio, difference or a");
  if (m.combine != "a" && m.configs.size() != 2)
    r.fail(jsonPath(path, "b"), "missing (combine " + m.combine + " needs two configurations)");
  // Enough frames for an interval that can exclude the paper's side (--quick: indicative).
  const int fewest = m.kind == "error-compare" ? kMinErrorFrames
                     : m.kind == "time-ratio"  ? kMinTimingRepetitions
                                               : 1;
  if (m.full.frames < fewest)
    r.fail(jsonPath(path, "full"), "frames: " + std::to_string(m.full.frames) + ", a " + m.kind +
                                       " needs at least " + std::to_string(fewest) +
                                       " (paired frame by frame)");
  return m;
}

// --- Measuring.

double metricOf(const ConfigSummary& s, const std::string& metric) {
  if (metric == "error_pct") return s.errorPct;
  if (metric == "error_near_pct") return s.errorNearPct;
  if (metric == "error_far_pct") return s.errorFarPct;
  if (metric == "false_lit_pct") return s.falseLitPct;
  if (metric == "false_shadow_pct") return s.falseShadowPct;
  if (metric == "aliasing_mean") return s.aliasingMean;
  if (metric == "aliasing_p95") return s.aliasingP95;
  if (metric == "aliasing_max") return s.aliasingMax;
  if (metric == "flicker_pct") return s.flickerPct;
  if (metric == "total_ms") return s.totalMs;
  if (metric == "shadow_ms") {  // the frame less the camera's G-buffer and the composite
    double ms = s.totalMs;
    for (const char* pass : {"gbuffer", "composite"})
      if (auto it = s.passMs.find(pass); it != s.passMs.end()) ms -= it->second;
    return ms;
  }
  if (metric == "bytes") return s.bytes;
  if (metric == "texels") return s.texels;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const char* prefix : {"pass:", "pass_share:"}) {
    const std::string p = prefix;
    if (metric.rfind(p, 0) != 0) continue;
    // NAME, PREFIX* for every pass whose name starts with PREFIX ("asm edges*"), or several
    // joined by '+' ("moments+rotation estimate"): their sum; each must have been timed.
    double ms = 0.0;
    std::stringstream names(metric.substr(p.size()));
    for (std::string name; std::getline(names, name, '+');) {
      const bool many = !name.empty() && name.back() == '*';
      if (many) name.pop_back();
      bool found = false;
      for (const auto& [pass, passMs] : s.passMs)
        if (many ? pass.rfind(name, 0) == 0 : pass == name) ms += passMs, found = true;
      if (!found) return nan;
    }
    return p == "pass:" ? ms : ms / s.totalMs;
  }
  return nan;
}

bool needsReference(const Measurement& m) {
  return m.kind == "error-compare" ||
         (m.metric != "total_ms" && m.metric != "shadow_ms" && m.metric != "bytes" &&
          m.metric != "texels" && m.metric.rfind("pass", 0) != 0 && m.kind != "publication");
}

std::string figureName(const std::string& id, const std::string& suffix) {
  return "figures/" + id + suffix + ".png";
}

MeasuredValue measureRendered(const std::string& id, const Measurement& m, bool quick,
                              const fs::path& outDir, const std::string& suffix) {
  MeasuredValue out;
  const RunSize size = quick ? m.quick : m.full;
  std::shared_ptr<Scene> scene = loadScene(m.scene);
  std::string cameraText;
  // Along a path, bench's spacing: a frame every 1/kDefaultPathHz s between the measured ones
  // (--quick: none).
  const MeasureCameras cameras = measureCameras(*scene, m.path, m.camera, size.frames,
                                                quick ? kQuickPathHz : kDefaultPathHz, cameraText);
  checkFrameSize(size.width, size.height);
  std::vector<std::unique_ptr<ConfigRunner>> runners;
  for (const ConfigSpec& c : m.configs)
    runners.push_back(std::make_unique<ConfigRunner>(c, scene, m.light));
  MeasureOptions opts;
  opts.width = size.width;
  opts.height = size.height;
  opts.publishing = true;
  const bool reference = needsReference(m) && ShadowReference::available();
  if (needsReference(m) && !reference) {
    out.why = ShadowReference::unavailableReason();
    return out;
  }
  opts.keepImages = reference;
  std::optional<ReferenceCache> cache;
  if (reference) cache.emplace(*scene);
  const auto samples =
      runInterleaved(runners, cameras, opts, cache ? &*cache : nullptr, size.warmup, nullptr);
  std::vector<ConfigSummary> sums;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    sums.push_back(summarise(samples[i]));
    if (sums.back().renderErrors > 0) {
      out.why = m.configs[i].label + ": " + sums.back().failure;
      return out;
    }
    if (sums.back().glErrors > 0) {
      out.why = m.configs[i].label + ": GL errors in its frames";
      return out;
    }
  }
  const std::string where = scene->name + ", " + cameraText +
                            (cameras.alongPath ? ", " + num(cameras.pathHz) + " Hz" : "") + ", " +
                            std::to_string(size.width) + "x" + std::to_string(size.height) + ", " +
                            std::to_string(size.frames) + " frames";
  if (m.kind == "publication") {
    std::vector<double> v;
    for (const FrameSample& f : samples[0]) {
      auto it = f.numbers.find(m.number);
      if (it != f.numbers.end() && std::isfinite(it->second)) v.push_back(it->second);
    }
    if (v.size() != samples[0].size()) {
      out.why = m.number + " was published in " + std::to_string(v.size()) + " of " +
                std::to_string(samples[0].size()) + " frames";
      return out;
    }
    double value = 0.0;
    if (m.statistic == "median") value = median(v);
    if (m.statistic == "min") value = *std::min_element(v.begin(), v.end());
    if (m.statistic == "max") value = *std::max_element(v.begin(), v.end());
    if (m.statistic == "final") value = v.back();
    if (m.statistic == "changes")
      for (std::size_t i = 1; i < v.size(); ++i) value += std::abs(v[i] - v[i - 1]) > 1e-9 ? 1 : 0;
    std::string series;
    for (std::size_t i = 0; i < v.size() && i < 12; ++i) series += (i ? ", " : "") + num(v[i]);
    if (v.size() > 12) series += ", ...";
    out.measured = true;
    out.value = value;
    out.interval = {value, value, value, 0};
    out.text = m.configs[0].label + ": " + m.number + " per frame " + series + "; " + m.statistic +
               " = " + num(value) + " (" + where + ")";
    return out;
  }
  // Each frame's value of every configuration, paired: a frame without a value in one of
  // them (no covered pixel, no such pass) is left out of all.
  std::vector<std::vector<double>> perFrame(samples.size());
  for (std::size_t f = 0; f < samples[0].size(); ++f) {
    std::vector<double> row;
    for (const auto& s : samples) row.push_back(metricOf(summarise({s[f]}), m.metric));
    if (std::all_of(row.begin(), row.end(), [](double v) { return std::isfinite(v); }))
      for (std::size_t i = 0; i < row.size(); ++i) perFrame[i].push_back(row[i]);
  }
  if (perFrame[0].empty()) {
    out.why = m.metric + " not measured (" +
              (m.metric.rfind("pass", 0) == 0 ? "no such pass"
               : m.metric == "flicker_pct"    ? "no pixel covered in two consecutive frames"
                                              : "no covered pixel") +
              ") in any of the " + std::to_string(samples[0].size()) + " frames";
    return out;
  }
  const claims::Combine combine = m.combine == "ratio"        ? claims::Combine::Ratio
                                  : m.combine == "difference" ? claims::Combine::Difference
                                                              : claims::Combine::A;
  const claims::Interval iv = claims::pairedBootstrap(
      perFrame[0], perFrame.size() > 1 ? perFrame[1] : std::vector<double>{}, combine);
  if (!std::isfinite(iv.value)) {
    out.why = m.metric + " of " + m.configs.back().label + " is 0 in every frame: no ratio";
    return out;
  }
  std::vector<double> values;  // each configuration's mean over the paired frames
  for (const auto& v : perFrame)
    values.push_back(std::accumulate(v.begin(), v.end(), 0.0) / double(v.size()));
  out.measured = true;
  out.value = iv.value;
  out.interval = iv;
  out.text = m.metric + ": " + m.configs[0].label + " " + num(values[0]);
  if (values.size() > 1) out.text += ", " + m.configs[1].label + " " + num(values[1]);
  if (m.combine != "a" || values.size() == 1)
    out.text += "; " +
                std::string(m.combine == "ratio"        ? "a / b = "
                            : m.combine == "difference" ? "a - b = "
                                                        : "a = ") +
                intervalText(iv);
  out.text += " (" + where + (reference ? ", against the exact reference" : "") + "; means over " +
              std::to_string(iv.pairs) + " paired frames, 95 % bootstrap interval)";
  // The last frame's images, side by side with their errors (the compare montage).
  if (reference && !montageUnavailable()) {
    std::vector<ui::FigureCell> cells;
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const FrameSample& last = samples[i].back();
      if (last.color.width == 0) continue;
      cells.push_back(
          {m.configs[i].label,
           m.metric + " " + num(values[i]) + ", " + num(sums[i].bytes / (1024.0 * 1024.0)) + " MiB",
           last.color, last.errorImage});
    }
    if (!cells.empty()) {
      const std::string rel = figureName(id, suffix);
      writeMontage(cells, id + ": " + where + " (magenta: wrongly lit, cyan: wrongly shadowed)", 0,
                   std::nullopt, (outDir / rel).string());
      out.figures.push_back(rel);
    }
  }
  return out;
}

MeasuredValue measureCpu(const std::string& id, const Measurement& m, const fs::path& outDir,
                         const std::string& suffix) {
  MeasuredValue out;
  auto valueOf = [&](const std::vector<std::string>& args, std::string& text) {
    const StorageQuery q = storageQuery(args);
    const partition::StorageResult& r = q.result;
    double v = 0.0;
    if (m.value == "s") v = r.s;
    if (m.value == "mx") v = r.mx;
    if (m.value == "mz") v = r.mz;
    if (m.value == "parts") v = double(r.parts.size());
    if (m.value == "imbalance") v = std::max(r.mx, r.mz) / std::min(r.mx, r.mz);
    if (m.value == "part_s_spread") {
      double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
      for (const auto& p : r.parts) lo = std::min(lo, p.storage.s), hi = std::max(hi, p.storage.s);
      v = hi / lo;
    }
    if (m.value.rfind("split:", 0) == 0) v = q.splits[std::size_t(std::stoi(m.value.substr(6)))];
    std::string joined;
    for (const std::string& a : args) joined += (joined.empty() ? "" : " ") + a;
    text = "storage " + joined + ": " + m.value + " = " + num(v) + " (S " + num(r.s) + ", " +
           std::to_string(r.parts.size()) + " map" + (r.parts.size() == 1 ? "" : "s") + ")";
    return v;
  };
  std::string ta, tb;
  const double a = valueOf(m.storageA, ta);
  out.value = a;
  out.text = ta;
  if (!m.storageB.empty()) {
    const double b = valueOf(m.storageB, tb);
    out.value = a / b;
    out.text += "; " + tb + "; a / b = " + num(out.value);
  }
  out.measured = std::isfinite(out.value);
  out.interval = {out.value, out.value, out.value, 0};
  if (!out.measured) out.why = "the value is not finite: " + out.text;
  if (m.figure && montageUnavailable() == std::nullopt) {
    Args args;
    args.rest.push_back("storage");
    args.rest.insert(args.rest.end(), m.storageA.begin(), m.storageA.end());
    const std::string prefix = "figures/" + id + suffix;
    args.rest.push_back("--out");
    args.rest.push_back((outDir / prefix).string());
    args.rest.push_back("--grid");
    args.rest.push_back("41");
    std::fflush(stdout);
    if (cmdStorage(args) == 0) {
      out.figures.push_back(prefix + "-eta.png");
      out.figures.push_back(prefix + "-hemisphere.png");
    }
  }
  return out;
}

MeasuredValue measure(const std::string& id, const Measurement& m, bool quick,
                      const fs::path& outDir, const std::string& suffix) {
  try {
    if (m.kind == "cpu") return measureCpu(id, m, outDir, suffix);
    return measureRendered(id, m, quick, outDir, suffix);
  } catch (const std::exception& e) {
    MeasuredValue out;
    out.why = cutText(e.what());
    return out;
  }
}

/// `s` as one word of a POSIX shell: as is when every character is one no shell treats
/// specially (letters, digits and _@%+=:,./-), else in single quotes (a quote inside as '\'').
std::string shellQuote(const std::string& s) {
  const bool plain = !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) ||
           std::string_view("_@%+=:,./-").find(c) != std::string_view::npos;
  });
  if (plain) return s;
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::vector<std::string> commandsFor(const std::string& id, const Measurement& m, bool quick) {
  std::vector<std::string> out;
  if (m.kind == "cpu") {
    for (const auto* args : {&m.storageA, &m.storageB}) {
      if (args->empty()) continue;
      std::string c = "shadowlab-cli storage";
      for (const std::string& a : *args) c += " " + shellQuote(a);
      out.push_back(c);
    }
    return out;
  }
  const RunSize size = quick ? m.quick : m.full;
  std::string where = " --scene " + shellQuote(m.scene);
  if (!m.camera.empty()) where += " --camera " + shellQuote(m.camera);
  if (!m.path.empty()) where += " --path " + shellQuote(m.path);
  if (!m.lightText.empty()) where += " --light " + shellQuote(m.lightText);
  const std::string sz = " --size " + std::to_string(size.width) + "x" +
                         std::to_string(size.height) + " --frames " + std::to_string(size.frames);
  // bench reads KEY=V1,V2 as a sweep: a value with ',' or ':' cannot be written there.
  bool sweepable = true;
  for (const ConfigSpec& c : m.configs)
    for (const auto& [k, v] : c.sets)
      sweepable = sweepable && v.find_first_of(",:") == std::string::npos;
  if (m.kind != "publication" && sweepable) {
    std::string c = "shadowlab-cli bench" + where + sz + " --warmup " + std::to_string(size.warmup);
    if (quick && m.camera.empty()) c += " --path-hz " + num(kQuickPathHz);  // as measured
    for (const ConfigSpec& cfg : m.configs) {
      std::string t = cfg.techniqueId;
      for (const auto& [k, v] : cfg.sets) t += ":" + k + "=" + v;
      c += " --technique " + shellQuote(t);
    }
    if (!needsReference(m)) c += " --no-reference";
    c += " --csv " + id + ".csv";
    out.push_back(c);
  } else {
    for (const ConfigSpec& cfg : m.configs) {
      std::string c =
          "shadowlab-cli render" + where + " --technique " + shellQuote(cfg.techniqueId);
      for (const auto& [k, v] : cfg.sets) c += " --set " + shellQuote(k + "=" + v);
      c += " --size " + std::to_string(size.width) + "x" + std::to_string(size.height) +
           " --frames " + std::to_string(size.frames) + " --out " + id + ".png --metrics " + id +
           ".json";
      out.push_back(c);
    }
  }
  return out;
}

std::string cell(std::string s) {
  for (char& c : s)
    if (c == '|' || c == '\n') c = ' ';
  return s;
}

}  // namespace

std::vector<Claim> loadClaims(const fs::path& file) {
  Reader r{file.string()};
  json doc;
  try {
    doc = JsonReader(file.string()).parseFile();  // regular file, size and depth limits
  } catch (const std::exception& e) {
    throw UsageError(cutText(e.what(), 600));
  }
  r.keys(doc, "", {"seed", "source", "sizes", "claims"});
  const std::string seed = r.str(doc, "", "seed", true);
  if (seed.size() != 3 || !std::all_of(seed.begin(), seed.end(), ::isdigit))
    r.fail("seed", "expected three digits, e.g. \"000\"");
  const std::string source = r.str(doc, "", "source", true);
  RunSize full, quick{160, 90, 2, 1};
  if (doc.contains("sizes")) {
    const json& s = doc.at("sizes");
    r.keys(s, "sizes", {"full", "quick"});
    if (s.contains("full")) full = readSize(r, s.at("full"), "sizes.full", full);
    if (s.contains("quick")) quick = readSize(r, s.at("quick"), "sizes.quick", quick);
  }
  if (!doc.contains("claims") || !doc.at("claims").is_array() || doc.at("claims").empty())
    r.fail("claims", "expected a non-empty array of claims");
  std::vector<Claim> out;
  for (std::size_t i = 0; i < doc.at("claims").size(); ++i) {
    const json& c = doc.at("claims")[i];
    const std::string path = jsonPath("claims", i);
    r.keys(c, path,
           {"id", "kind", "quote", "translation", "statement", "paper_number", "note", "measure",
            "expect", "partly", "mechanism"});
    Claim claim;
    claim.file = file.string();
    claim.seed = seed;
    claim.source = source;
    claim.id = r.str(c, path, "id", true);
    if (claim.id.empty() || claim.id.size() > 64 ||
        claim.id.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789-") != std::string::npos)
      r.fail(jsonPath(path, "id"), "expected 1..64 of a-z, 0-9 and '-'");
    for (std::size_t k = 0; k < out.size(); ++k)
      if (out[k].id == claim.id)
        r.fail(jsonPath(path, "id"), "'" + claim.id + "' is also the id of " +
                                         jsonPath("claims", k) +
                                         " (ids name the report's sections and figures)");
    claim.kind = r.str(c, path, "kind", true);
    if (std::none_of(std::begin(kClaimKinds), std::end(kClaimKinds),
                     [&](const char* k) { return claim.kind == k; }))
      r.fail(jsonPath(path, "kind"),
             "expected seed (the seed says it), tool (ShadowLab's own) or check (holds by "
             "construction or arithmetic), got '" +
                 claim.kind + "'");
    const bool seedClaim = claim.kind == "seed";
    claim.quote = r.str(c, path, "quote", seedClaim);
    claim.translation = r.str(c, path, "translation", false);
    claim.statement = r.str(c, path, "statement", !seedClaim);
    if (!claim.translation.empty() && claim.quote.empty())
      r.fail(jsonPath(path, "translation"), "a translation of no quote");
    claim.paperNumber = r.str(c, path, "paper_number", true);
    claim.note = r.str(c, path, "note", false);
    if (!c.contains("measure")) r.fail(jsonPath(path, "measure"), "missing");
    claim.measurement = readMeasurement(r, c.at("measure"), jsonPath(path, "measure"), full, quick);
    if (!c.contains("expect")) r.fail(jsonPath(path, "expect"), "missing");
    claim.expect = readPredicate(r, c.at("expect"), jsonPath(path, "expect"));
    if (c.contains("partly")) {
      claim.partly = readPredicate(r, c.at("partly"), jsonPath(path, "partly"));
      checkPartly(r, claim, jsonPath(path, "partly"));
    }
    if (c.contains("mechanism")) {
      const json& mj = c.at("mechanism");
      r.keys(mj, jsonPath(path, "mechanism"), {"text", "measure"});
      claim.mechanismText = r.str(mj, jsonPath(path, "mechanism"), "text", true);
      if (!mj.contains("measure"))
        r.fail(jsonPath(jsonPath(path, "mechanism"), "measure"), "missing");
      claim.mechanism = readMeasurement(
          r, mj.at("measure"), jsonPath(jsonPath(path, "mechanism"), "measure"), full, quick);
    }
    out.push_back(std::move(claim));
  }
  return out;
}

std::vector<Claim> loadClaimFolder(const fs::path& folder) {
  std::vector<fs::path> files;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(folder, ec))
    if (e.path().extension() == ".json") files.push_back(e.path());
  if (ec) throw UsageError(folder.string() + ": cannot be read (" + ec.message() + ")");
  std::sort(files.begin(), files.end());
  std::vector<Claim> all;
  std::map<std::string, std::string> seen;
  for (const fs::path& f : files)
    for (Claim& c : loadClaims(f)) {
      if (auto it = seen.find(c.id); it != seen.end())
        throw UsageError(f.string() + ": claim id '" + c.id + "' is also in " + it->second);
      seen[c.id] = f.string();
      all.push_back(std::move(c));
    }
  return all;
}

std::string verdictFor(const Claim& claim, const MeasuredValue& value) {
  if (!value.measured) return claims::verdictName(claims::Verdict::NotTestable);
  return claims::verdictName(claims::judge(claim.expect, claim.partly, value.interval));
}

std::vector<std::string> rerunCommands(const Claim& claim, bool quick) {
  std::vector<std::string> out = commandsFor(claim.id, claim.measurement, quick);
  out.push_back("shadowlab-cli reproduce --claim " + claim.id + (quick ? " --quick" : "") +
                " --out reproduce-" + claim.id);
  return out;
}

ClaimOutcome runClaim(const Claim& claim, bool quick, const fs::path& outDir) {
  const auto start = std::chrono::steady_clock::now();
  ClaimOutcome o;
  o.main = measure(claim.id, claim.measurement, quick, outDir, "");
  o.verdict = verdictFor(claim, o.main);
  const RunSize& size = quick ? claim.measurement.quick : claim.measurement.full;
  o.indicative = o.main.interval.pairs > 0 &&
                 size.frames < (claim.measurement.kind == "error-compare" ? kMinErrorFrames
                                                                          : kMinTimingRepetitions);
  if (claim.mechanism && o.verdict != "reproduced" &&
      o.verdict != claims::verdictName(claims::Verdict::NotTestable))
    o.mechanism = measure(claim.id, *claim.mechanism, quick, outDir, "-mechanism");
  o.commands = rerunCommands(claim, quick);
  o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return o;
}

namespace {

/// The verdicts in the order the report counts them.
std::vector<std::string> verdictNames() {
  std::vector<std::string> out;
  for (claims::Verdict v :
       {claims::Verdict::Reproduced, claims::Verdict::Partly, claims::Verdict::NotReproduced,
        claims::Verdict::Inconclusive, claims::Verdict::NotTestable})
    out.push_back(claims::verdictName(v));
  return out;
}

std::string verdictText(const ClaimOutcome& o) {
  return o.verdict + (o.indicative ? " (quick run: indicative)" : "");
}

/// One table row per claim of `kind`.
void claimTable(std::ostringstream& md, const std::vector<Claim>& claims,
                const std::vector<ClaimOutcome>& outcomes, const std::string& kind) {
  md << "| claim | seed | " << (kind == "seed" ? "paper's number" : "expected")
     << " | measured [95 % interval] | threshold | verdict |\n";
  md << "|---|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < claims.size(); ++i) {
    const Claim& c = claims[i];
    if (c.kind != kind) continue;
    const ClaimOutcome& o = outcomes[i];
    md << "| [" << c.id << "](#" << c.id << ") | " << c.seed << " | " << cell(c.paperNumber)
       << " | " << (o.main.measured ? intervalText(o.main.interval) : "—") << " | "
       << c.expect.text() << " | " << verdictText(o) << " |\n";
  }
}

}  // namespace

std::string reportMarkdown(const std::vector<Claim>& claims,
                           const std::vector<ClaimOutcome>& outcomes, bool quick,
                           const std::string& glDescription, double seconds) {
  std::ostringstream md;
  md << "# The papers' claims, reproduced\n\n";
  if (quick)
    md << "**A quick run** (`--quick`): small frames and few frames per claim, and along a "
          "camera path no frame rendered between the measured ones (`--path-hz 0`); every "
          "verdict from a comparison is indicative only.\n\n";
  md << "Generated by `shadowlab-cli reproduce" << (quick ? " --quick" : "")
     << "` from the claims in `scenes/claims/` (" << claims.size() << " claims, "
     << formatDuration(seconds) << " on " << glDescription << "). A claim is of one of three "
     << "kinds: **seed** (a source document says it, quoted verbatim), **tool** (ShadowLab's "
        "own reading) or **check** (an implementation check that holds by construction or "
        "arithmetic); the headline counts seed claims only. A comparison is measured frame by "
        "frame, paired, and given with its 95 % bootstrap interval ("
     << claims::kBootstrapResamples
     << " resamples of the frames, fixed seed): reproduced when "
        "the interval lies on the paper's side of the threshold, not reproduced when it lies on "
        "the other, inconclusive when it straddles it; partly only for an effect in the paper's "
        "direction smaller than the paper's. Timings are ratios within one interleaved run on "
        "this machine, not the papers' GPUs (on a software rasteriser each pass is timed with "
        "glFinish and a wall clock)";
  if (std::ifstream load("/proc/loadavg"); load) {
    double one = 0.0;
    if (load >> one)
      md << "; the machine's load average was " << num(one)
         << " when the run ended (other processes share its cores, and the timing ratios vary "
            "with it)";
  }
  md << ".\n\n";
  const std::vector<std::string> names = verdictNames();
  md << "## Seed claims per seed\n\n| seed |";
  for (const std::string& n : names) md << " " << n << " |";
  md << "\n|---|";
  for (std::size_t k = 0; k < names.size(); ++k) md << "---|";
  md << "\n";
  std::map<std::string, std::map<std::string, int>> perSeed;
  std::map<std::string, int> total;
  for (std::size_t i = 0; i < claims.size(); ++i)
    if (claims[i].kind == "seed")
      ++perSeed[claims[i].seed][outcomes[i].verdict], ++total[outcomes[i].verdict];
  for (auto& [seed, count] : perSeed) {
    md << "| " << seed << " |";
    for (const std::string& n : names) md << " " << count[n] << " |";
    md << "\n";
  }
  md << "| all |";
  for (const std::string& n : names) md << " " << total[n] << " |";
  md << "\n";
  const std::pair<const char*, const char*> tables[] = {
      {"seed", "## Seed claims: what the source documents say\n\n"},
      {"tool", "## Tool claims: ShadowLab's own readings (not the seeds')\n\n"},
      {"check", "## Implementation checks (hold by construction or arithmetic)\n\n"}};
  for (const auto& table : tables) {
    const auto& kind = table.first;  // a named copy: clang 14 cannot capture a binding
    if (std::none_of(claims.begin(), claims.end(), [&](const Claim& c) { return c.kind == kind; }))
      continue;
    md << "\n" << table.second;
    claimTable(md, claims, outcomes, kind);
  }
  std::string lastSeed;
  for (std::size_t i = 0; i < claims.size(); ++i) {
    const Claim& c = claims[i];
    const ClaimOutcome& o = outcomes[i];
    if (c.seed != lastSeed) {
      md << "\n## " << c.seed << ": " << c.source << "\n";
      lastSeed = c.seed;
    }
    md << "\n### " << c.id << "\n\n";
    md << "**Kind:** " << c.kind << "\n\n";
    if (!c.quote.empty()) md << "**Paper:** \"" << c.quote << "\"\n\n";
    if (!c.translation.empty()) md << "**Translation:** " << c.translation << "\n\n";
    if (!c.statement.empty())
      md << (c.kind == "tool" ? "**ShadowLab's claim:** " : "**Check:** ") << c.statement << "\n\n";
    md << "**Paper's number:** " << c.paperNumber << "\n\n";
    if (!c.note.empty()) md << "**Reading:** " << c.note << "\n\n";
    md << "**Measurement (" << c.measurement.kind << "):** "
       << (o.main.measured ? o.main.text : "not testable here: " + o.main.why) << "\n\n";
    md << "**Threshold:** reproduced when the value";
    if (o.main.interval.pairs > 0) md << "'s interval lies inside";
    md << " " << c.expect.text();
    if (c.partly) md << "; partly when it lies outside that and inside " << c.partly->text();
    md << "\n\n";
    md << "**Verdict:** " << verdictText(o) << "\n\n";
    if (o.verdict == "not reproduced" || o.verdict == "partly") {
      md << "**Mechanism:** ";
      if (o.mechanism)
        md << c.mechanismText << " Measured: "
           << (o.mechanism->measured ? o.mechanism->text
                                     : "not testable here: " + o.mechanism->why);
      else
        md << "not found";
      md << "\n\n";
    }
    md << "**Command:**\n\n```sh\n";
    for (const std::string& cmd : o.commands) md << cmd << "\n";
    md << "```\n";
    std::vector<std::string> figures = o.main.figures;
    if (o.mechanism)
      figures.insert(figures.end(), o.mechanism->figures.begin(), o.mechanism->figures.end());
    for (const std::string& f : figures) md << "\n![" << c.id << "](" << f << ")\n";
  }
  md << "\n## Threats to validity\n\n"
        "- **A software rasteriser.** Every frame is rendered by Mesa's llvmpipe on the CPU "
        "cores: passes that are cheap on a GPU (rasterisation, tessellation, mip chains) cost "
        "differently here, and other processes share the cores, so a timing ratio is this "
        "machine's, not the papers'. `scripts/gpu-check.sh` runs the timing claims on a GPU; "
        "there the ratios, not the error comparisons, are expected to change.\n"
        "- **Stand-in scenes.** The papers' scenes (Crytek Sponza, a power plant, the "
        "lecture's examples) are not here; the claims run on small built-in scenes made to "
        "show each effect, so an effect may be larger or smaller than on the papers' "
        "content.\n"
        "- **The tool's readings.** A claim without a number is measured through a reading "
        "(the **Reading** line); another reading may give another verdict.\n"
        "- **Few frames.** The intervals cover the frame-to-frame spread of one path on one "
        "machine; they say nothing of other paths, scenes or drivers"
     << (quick ? ", and this quick run measured fewer frames than a verdict needs" : "") << ".\n";
  return md.str();
}

/// The report's files against the claims read (algo/OutputFile.h), before any claim runs: the
/// claims folder is not --out (report.json would be read as claims the next time) and no
/// file the report writes is a claims file.
void checkReproduceOutputs(const std::string& out, const fs::path& source,
                           const std::vector<Claim>& claims) {
  std::error_code ec;
  if (fs::is_directory(source, ec) && sameFile(source.string(), out))
    throw UsageError("--out: '" + out + "' is the claims folder (" + source.string() +
                     "): report.json would be read as claims; give another folder");
  std::vector<InputTarget> inputs;
  std::set<std::string> files;
  for (const Claim& c : claims) files.insert(c.file);
  for (const std::string& f : files) inputs.push_back({"--claims (" + f + ")", f});
  const fs::path dir(out);
  std::vector<OutputFile> outputs;
  for (const char* name : {"REPORT.md", "report.json"})
    outputs.push_back({"--out (" + std::string(name) + ")", (dir / name).string(), false});
  for (const Claim& c : claims)
    for (const char* suffix :
         {"", "-mechanism", "-eta", "-hemisphere", "-mechanism-eta", "-mechanism-hemisphere"})
      outputs.push_back(
          {"--out (" + c.id + suffix + ".png)", (dir / figureName(c.id, suffix)).string(), false});
  checkOutputs(outputs, inputs);
}

int cmdReproduce(Args& a) {
  std::string out, claimsPath;
  bool quick = false;
  std::set<std::string> seeds, ids;
  for (std::size_t i = 1; i < a.rest.size(); ++i) {
    const std::string& o = a.rest[i];
    if (o == "--out")
      out = a.take(i, o);
    else if (o == "--quick")
      quick = true;
    else if (o == "--seed") {
      const std::string s = a.take(i, o);
      if (s != "000" && s != "001" && s != "002" && s != "003" && s != "004")
        throw UsageError("--seed: expected 000, 001, 002, 003 or 004, got '" + s + "'");
      seeds.insert(s);
    } else if (o == "--claim")
      ids.insert(a.take(i, o));
    else if (o == "--claims")
      claimsPath = a.take(i, o);
    else
      throw UsageError("unknown option '" + o +
                       "' (reproduce options: --out, --seed, --claim, "
                       "--quick, --claims)");
  }
  if (out.empty()) throw UsageError("--out: missing (the folder for REPORT.md and its figures)");
  const fs::path source = claimsPath.empty() ? builtinSceneDir() / "claims" : fs::path(claimsPath);
  std::vector<Claim> all = fs::is_directory(source) ? loadClaimFolder(source) : loadClaims(source);
  std::vector<Claim> claims;
  for (Claim& c : all)
    if ((seeds.empty() || seeds.count(c.seed)) && (ids.empty() || ids.count(c.id)))
      claims.push_back(std::move(c));
  for (const std::string& id : ids)
    if (std::none_of(claims.begin(), claims.end(), [&](const Claim& c) { return c.id == id; }))
      throw UsageError("--claim: no claim '" + id + "' (in " + source.string() +
                       (seeds.empty() ? "" : " for the seeds given") + ")");
  if (claims.empty()) throw UsageError("--seed: no claim for the seeds given");
  checkReproduceOutputs(out, source, claims);

  const auto start = std::chrono::steady_clock::now();
  std::vector<ClaimOutcome> outcomes;
  std::string glDescription;
  {
    gl::EglContext ctx;
    {
      Renderer probe;
      glDescription = probe.glDescription();
    }
    ProgressBar progress(quick ? "reproduce --quick" : "reproduce", claims.size());
    for (const Claim& c : claims) {
      outcomes.push_back(runClaim(c, quick, out));
      progress.step(c.id + ": " + outcomes.back().verdict, true);
    }
    progress.finish();
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string reportMd = (fs::path(out) / "REPORT.md").string();
  writeText(OutputFile{reportMd, reportMd, false},
            reportMarkdown(claims, outcomes, quick, glDescription, seconds));
  json j = json::array();
  for (std::size_t i = 0; i < claims.size(); ++i) {
    const Claim& c = claims[i];
    const ClaimOutcome& o = outcomes[i];
    json e;
    e["id"] = c.id;
    e["seed"] = c.seed;
    e["kind"] = c.kind;
    e["measurement_kind"] = c.measurement.kind;
    if (!c.quote.empty()) e["quote"] = c.quote;
    if (!c.translation.empty()) e["translation"] = c.translation;
    if (!c.statement.empty()) e["statement"] = c.statement;
    e["paper_number"] = c.paperNumber;
    e["verdict"] = o.verdict;
    e["indicative"] = o.indicative;
    e["measured"] = o.main.measured;
    if (o.main.measured) {
      e["value"] = o.main.value;
      e["interval"] = {o.main.interval.low, o.main.interval.high};
      e["pairs"] = o.main.interval.pairs;
    }
    e["measurement"] = o.main.measured ? o.main.text : o.main.why;
    e["threshold"] = c.expect.text();
    e["commands"] = o.commands;
    e["figures"] = o.main.figures;
    e["seconds"] = o.seconds;
    j.push_back(e);
  }
  const std::string reportJson = (fs::path(out) / "report.json").string();
  writeText(OutputFile{reportJson, reportJson, false},
            j.dump(2, ' ', false, json::error_handler_t::replace));
  std::map<std::string, int> count;
  for (std::size_t i = 0; i < claims.size(); ++i)
    if (claims[i].kind == "seed") ++count[outcomes[i].verdict];
  const char* notTestable = claims::verdictName(claims::Verdict::NotTestable);
  std::printf(
      "%zu claims; seed claims: %d reproduced, %d partly, %d not reproduced, %d inconclusive, "
      "%d not testable here (%s) -> %s\n",
      claims.size(), count["reproduced"], count["partly"], count["not reproduced"],
      count["inconclusive"], count[notTestable], formatDuration(seconds).c_str(), reportMd.c_str());
  // A claim (of any kind) that could not be measured is a failed run, not a verdict (exit 1).
  return std::any_of(outcomes.begin(), outcomes.end(),
                     [&](const ClaimOutcome& o) { return o.verdict == notTestable; })
             ? 1
             : 0;
}

}  // namespace sl::cli
