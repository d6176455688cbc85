// `shadowlab-cli stability --suite FILE.json`: a suite of purpose-built failure cases
// (scenes/suites/), each a scene, camera, light and motion run for several techniques, with
// expectations on the numbers; exit 1 naming every expectation that fails, and every case
// that ran no configuration. The whole file is checked before anything runs: an unknown
// technique (unless marked "optional"), parameter, metric or label, or a value out of range,
// exits 2 naming the file and the JSON path. Format: docs/user-guide/suites.md.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "StabilityRun.h"
#include "core/JsonInput.h"
#include "core/LightJson.h"
#include "gl/EglContext.h"
#include "scene/GltfLoader.h"

using nlohmann::json;

namespace sl::cli {
namespace {

/// How a metric that measured nothing reads: "not measured (why)", never a value.
constexpr const char* kNotMeasured = "not measured (";

std::string valueText(const json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_boolean()) return v.get<bool>() ? "on" : "off";
  if (v.is_number_integer()) return std::to_string(v.get<long long>());
  if (v.is_number()) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.10g", v.get<double>());
    return buf;
  }
  return v.dump();
}

glm::vec3 vec3Of(const JsonReader& r, const json& v, const std::string& path) {
  if (!v.is_array() || v.size() != 3) r.expected(v, path, "[x, y, z] in metres");
  return {float(r.number(v[0], jsonPath(path, 0))), float(r.number(v[1], jsonPath(path, 1))),
          float(r.number(v[2], jsonPath(path, 2)))};
}

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

/// joined(items), cut after the item that passes `maxChars` with ", ... (N in all: `list`)":
/// error lines stay bounded (one line of at most 300 bytes) however many there are.
std::string joinedBounded(const std::vector<std::string>& items, std::size_t maxChars,
                          const std::string& where = ": shadowlab-cli list") {
  std::string out;
  for (const std::string& s : items) {
    if (out.size() > maxChars)
      return out + ", ... (" + std::to_string(items.size()) + " in all" + where + ")";
    out += (out.empty() ? "" : ", ") + s;
  }
  return out;
}

/// A case's labels for a message: each quoted to 40 bytes, the list cut after ~100 (a label
/// is any string a suite gives: the fuzzer found an 8 KB one echoed whole).
std::string boundedLabels(const std::set<std::string>& labels) {
  std::vector<std::string> quoted;
  for (const std::string& l : labels) quoted.push_back(quoteText(l, 40));
  return joinedBounded(quoted, 100, "");
}

struct SuiteTechnique {
  ConfigSpec spec;
  bool optional = false;    ///< "optional": true: skipped (not an error) when not registered
  std::string skipped;      ///< why it does not run ("" when it does)
  bool deselected = false;  ///< not selected by --techniques
};

/// {technique, metric, op, value} or {better, worse, metric[, op]}.
struct Expectation {
  bool pair = false;
  std::string technique, better, worse, metric, op, why, xfail;
  std::vector<std::string> except;
  double value = 0.0;
};

struct SuiteCase {
  std::string name, what, sceneName;
  std::string cameraName;  ///< a bookmark ("" with cameraObject or for the first one)
  std::optional<Camera> cameraObject;
  std::optional<Light> light;
  std::string motion = "static";  ///< static | orbit | path
  double orbitDegPerFrame = 0.2;
  std::string path;
  double pathHz = kDefaultPathHz;  ///< "path_hz": along the path, a frame every 1/HZ s
  int frames = 30, warmup = 0;
  int width = 320, height = 180;
  std::string sizeWhere = "size";  ///< where the size came from: "size", "cases[i].size", "--size"
  std::vector<SuiteTechnique> techniques;
  std::vector<Expectation> expect;
};

const std::set<std::string> kOps = {"==", "!=", "<", "<=", ">", ">="};

bool compare(double a, const std::string& op, double b) {
  if (op == "==") return a == b;
  if (op == "!=") return a != b;
  if (op == "<") return a < b;
  if (op == "<=") return a <= b;
  if (op == ">") return a > b;
  return a >= b;
}

// The real limit on a size is the GL implementation's (checked once a context exists).
constexpr int kMaxSize = 1 << 16, kMaxFrames = 1000000;

/// Whether a case's "scene" names something the loader finds (loadSceneByNameOrPath: a
/// built-in name, or a path); an error naming what was looked for, or nothing.
std::optional<std::string> findScene(const std::string& name) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const bool looksLikePath =
      name.find('/') != std::string::npos || name.find('\\') != std::string::npos ||
      fs::path(name).extension() == ".gltf" || fs::path(name).extension() == ".glb";
  if (!looksLikePath)
    for (const char* ext : {".gltf", ".glb"})
      if (fs::is_regular_file(builtinSceneDir() / (name + ext), ec)) return std::nullopt;
  if (fs::exists(name, ec)) return std::nullopt;
  if (looksLikePath) return "no file '" + quoteText(name, 120) + "'";
  return "unknown scene '" + quoteText(name, 60) +
         "' (built-in scenes: " + joined(builtinSceneNames()) + "; or a path to a .gltf/.glb file)";
}

std::pair<int, int> sizeOf(const JsonReader& r, const json& s, const std::string& path) {
  if (!s.is_array() || s.size() != 2) r.expected(s, path, "[width, height]");
  return {r.integer(s[0], jsonPath(path, 0), 1, kMaxSize),
          r.integer(s[1], jsonPath(path, 1), 1, kMaxSize)};
}

Camera cameraOf(const JsonReader& r, const json& c, const std::string& path) {
  r.onlyKeys(c, path, {"position", "target", "up", "fov_deg", "near_m", "far_m"});
  Camera cam;
  const json* pos = JsonReader::member(c, "position");
  const json* target = JsonReader::member(c, "target");
  if (!pos || !target) r.fail(path, "a camera object needs \"position\" and \"target\"");
  cam.position = vec3Of(r, *pos, jsonPath(path, "position"));
  cam.target = vec3Of(r, *target, jsonPath(path, "target"));
  if (const json* up = JsonReader::member(c, "up")) cam.up = vec3Of(r, *up, jsonPath(path, "up"));
  cam.fovYDeg = float(r.number(c, path, "fov_deg", cam.fovYDeg));
  cam.nearM = float(r.number(c, path, "near_m", cam.nearM));
  cam.farM = float(r.number(c, path, "far_m", cam.farM));
  if (auto e = cameraFieldError(cam, {"up", "near_m", "far_m"}))
    r.fail(jsonPath(path, e->first), e->second);
  if (auto e = cam.validate()) r.fail(path, Camera::withoutPrefix(*e));
  return cam;
}

Light lightOf(const JsonReader& r, const json& l, const std::string& path) {
  return readLightJson(r, l, path, JsonKeyStyle::SnakeCase, true);
}

/// One entry of a case's "techniques": "ID" or {"id", "set", "label", "optional"}. An
/// unknown id is an error unless "optional": true; every key of "set" must be a parameter
/// of the technique (or a shared one) and every value in its range.
SuiteTechnique techniqueOf(const JsonReader& r, const json& t, const std::string& path,
                           const std::vector<std::string>& onlyTechniques) {
  SuiteTechnique st;
  std::string idPath = path;
  if (t.is_string()) {
    st.spec.techniqueId = t.get<std::string>();
  } else if (t.is_object()) {
    r.onlyKeys(t, path, {"id", "set", "label", "optional"});
    const json* id = JsonReader::member(t, "id");
    if (!id) r.fail(path, "missing \"id\" (a technique is \"ID\" or {\"id\", \"set\", \"label\"})");
    idPath = jsonPath(path, "id");
    st.spec.techniqueId = r.string(*id, idPath);
    st.spec.label = r.string(t, path, "label", "");
    st.optional = r.boolean(t, path, "optional", false);
  } else {
    r.expected(t, path, "\"ID\" or {\"id\": ID, \"set\": {KEY: VALUE}, \"label\": L}");
  }
  if (st.spec.label.empty()) st.spec.label = st.spec.techniqueId;
  const TechniqueInfo* info = Renderer::findTechnique(st.spec.techniqueId);
  if (!info) {
    if (st.optional) {
      st.skipped = "technique " + st.spec.techniqueId + " not available (optional)";
      return st;
    }
    // The known ids, bounded: the whole line stays within what a hostile input may make the
    // tool print (tests/fixtures/hostile: 300 bytes).
    std::vector<std::string> known;
    for (const TechniqueInfo& ti : Renderer::techniques()) known.push_back(ti.id);
    r.fail(idPath, "unknown technique '" + quoteText(st.spec.techniqueId, 60) + "' (known: " +
                       joinedBounded(known, 60) + "; \"optional\": true in its entry skips it)");
  }
  const json* set = JsonReader::member(t, "set");
  if (set) {
    const std::string setPath = jsonPath(path, "set");
    r.requireObject(*set, setPath);
    ParamSet own(info->params), shared(rendererParamDecls());
    for (const auto& [k, v] : set->items()) {
      const std::string keyPath = jsonPath(setPath, k);
      ParamSet* params = own.has(k) ? &own : shared.has(k) ? &shared : nullptr;
      if (!params) {
        // One bounded line: the technique's own keys (cut, with their count), the shared
        // ones counted (there are more of them with every view feature).
        std::vector<std::string> ownKeys;
        for (const ParamDecl& d : own.decls()) ownKeys.push_back(d.key);
        r.fail(keyPath,
               "technique '" + st.spec.techniqueId + "' has no parameter '" + quoteText(k, 60) +
                   "' (its own: " + (ownKeys.empty() ? "none" : joinedBounded(ownKeys, 80)) +
                   "; and " + std::to_string(shared.decls().size()) +
                   " shared view.* and shading.* ones: shadowlab-cli list)");
      }
      if (!v.is_number() && !v.is_boolean() && !v.is_string())
        r.expected(v, keyPath, "a number, true/false or a name");
      const std::string text = valueText(v);
      if (auto e = params->setFromString(k, text))
        r.fail(keyPath,
               quoteText(*e) + (e->find(text) == std::string::npos ? " (got " + quoteJson(v) + ")"
                                                                   : std::string()));
      st.spec.sets.push_back({k, text});
    }
    // Values in range that the technique cannot render together (fvsm.grid = 3).
    if (auto e = checkTechniqueParams(*info, own))
      r.fail(setPath, "technique '" + st.spec.techniqueId + "': " + quoteText(*e));
  }
  if (!onlyTechniques.empty() && std::find(onlyTechniques.begin(), onlyTechniques.end(),
                                           st.spec.techniqueId) == onlyTechniques.end()) {
    st.skipped = "technique " + st.spec.techniqueId + " not selected (--techniques)";
    st.deselected = true;
  }
  return st;
}

Expectation expectationOf(const JsonReader& r, const json& e, const std::string& path,
                          const std::set<std::string>& labels) {
  r.onlyKeys(e, path,
             {"technique", "better", "worse", "metric", "op", "value", "why", "except", "xfail"});
  Expectation x;
  auto labelAt = [&](std::string_view key, bool star) {
    const std::string p = jsonPath(path, key);
    std::string l = r.string(e[std::string(key)], p);
    if (!(star && l == "*") && !labels.count(l))
      r.fail(p, "names '" + quoteText(l, 60) +
                    "', which the case does not run (labels: " + boundedLabels(labels) + ")");
    return l;
  };
  const json* metric = JsonReader::member(e, "metric");
  if (!metric)
    r.fail(path,
           "missing \"metric\" (an expectation is {technique, metric, op, value} or "
           "{better, worse, metric})");
  x.metric = r.string(*metric, jsonPath(path, "metric"));
  if (!StabilitySummary().metrics().count(x.metric)) {
    std::vector<std::string> list;
    for (const auto& [k, v] : StabilitySummary().metrics()) list.push_back(k);
    r.fail(jsonPath(path, "metric"),
           "unknown metric '" + quoteText(x.metric, 60) + "' (metrics: " + joined(list) + ")");
  }
  x.pair = e.contains("better") || e.contains("worse");
  if (x.pair) {
    if (!(e.contains("better") && e.contains("worse")))
      r.fail(path, "\"better\" needs \"worse\" (and back)");
    for (const char* k : {"technique", "value", "except"})
      if (e.contains(k))
        r.fail(jsonPath(path, k),
               "does not go with \"better\"/\"worse\" (an expectation is "
               "{technique, metric, op, value} or {better, worse, metric})");
    x.better = labelAt("better", false);
    x.worse = labelAt("worse", false);
    if (x.better == x.worse)
      r.fail(jsonPath(path, "worse"), "names '" + quoteText(x.worse, 60) +
                                          "' as \"better\" does: it would compare a technique "
                                          "with itself, which checks nothing");
    x.op = "<";
  } else {
    for (const char* k : {"technique", "op", "value"})
      if (!e.contains(k))
        r.fail(path, std::string("missing \"") + k +
                         "\" (an expectation is {technique, metric, op, value} or "
                         "{better, worse, metric})");
    x.technique = labelAt("technique", true);
    x.value = r.number(e["value"], jsonPath(path, "value"));
  }
  if (const json* op = JsonReader::member(e, "op")) {
    x.op = r.string(*op, jsonPath(path, "op"));
    if (!kOps.count(x.op)) r.expected(*op, jsonPath(path, "op"), "one of == != < <= > >=");
  }
  if (const json* ex = JsonReader::member(e, "except")) {
    const std::string p = jsonPath(path, "except");
    if (x.technique != "*") r.fail(p, "goes with \"technique\": \"*\"");
    r.requireArray(*ex, p);
    for (std::size_t i = 0; i < ex->size(); ++i) {
      std::string l = r.string((*ex)[i], jsonPath(p, i));
      if (!labels.count(l))
        r.fail(jsonPath(p, i), "names '" + quoteText(l, 60) + "', which the case does not run");
      x.except.push_back(l);
    }
    if (x.except.size() >= labels.size() &&
        std::all_of(labels.begin(), labels.end(), [&](const std::string& l) {
          return std::find(x.except.begin(), x.except.end(), l) != x.except.end();
        }))
      r.fail(p, "leaves \"*\" no technique to check (the case runs: " + boundedLabels(labels) +
                    "): the expectation would check nothing");
  }
  x.why = r.string(e, path, "why", "");
  x.xfail = r.string(e, path, "xfail", "");
  return x;
}

std::vector<SuiteCase> parseSuite(const JsonReader& r, const json& root, double framesScale,
                                  const std::optional<std::pair<int, int>>& sizeOverride,
                                  const std::vector<std::string>& onlyTechniques) {
  r.onlyKeys(root, "", {"name", "description", "size", "cases"});
  const json* casesJson = JsonReader::member(root, "cases");
  if (!casesJson) r.fail("", "missing \"cases\" (an array of cases)");
  r.requireArray(*casesJson, "cases");
  (void)r.string(root, "", "name", "");
  (void)r.string(root, "", "description", "");
  std::pair<int, int> defSize{320, 180};
  if (const json* s = JsonReader::member(root, "size")) defSize = sizeOf(r, *s, "size");
  std::vector<SuiteCase> cases;
  std::set<std::string> names;
  for (std::size_t ci = 0; ci < casesJson->size(); ++ci) {
    const json& c = (*casesJson)[ci];
    const std::string where = jsonPath("cases", ci);
    r.onlyKeys(c, where,
               {"name", "what", "scene", "camera", "light", "motion", "orbit_deg_per_frame", "path",
                "path_hz", "frames", "warmup_frames", "size", "techniques", "expect"});
    SuiteCase sc;
    sc.name = r.string(c, where, "name", "");
    if (sc.name.empty()) r.fail(where, "missing \"name\"");
    if (!names.insert(sc.name).second)
      r.fail(jsonPath(where, "name"), "duplicate case name '" + quoteText(sc.name, 60) + "'");
    sc.what = r.string(c, where, "what", "");
    sc.sceneName = r.string(c, where, "scene", "");
    if (sc.sceneName.empty()) r.fail(where, "missing \"scene\"");
    if (auto e = findScene(sc.sceneName)) r.fail(jsonPath(where, "scene"), *e);
    if (const json* cam = JsonReader::member(c, "camera")) {
      if (cam->is_string())
        sc.cameraName = cam->get<std::string>();
      else if (cam->is_object())
        sc.cameraObject = cameraOf(r, *cam, jsonPath(where, "camera"));
      else
        r.expected(*cam, jsonPath(where, "camera"), "a bookmark name or a camera object");
    }
    if (const json* l = JsonReader::member(c, "light"))
      sc.light = lightOf(r, *l, jsonPath(where, "light"));
    sc.motion = r.string(c, where, "motion", "static");
    if (sc.motion != "static" && sc.motion != "orbit" && sc.motion != "path")
      r.expected(c["motion"], jsonPath(where, "motion"), "static, orbit or path");
    sc.orbitDegPerFrame = r.number(c, where, "orbit_deg_per_frame", 0.2);
    if (!(std::abs(sc.orbitDegPerFrame) <= kMaxOrbitDegPerFrame))
      r.fail(jsonPath(where, "orbit_deg_per_frame"),
             fmt(sc.orbitDegPerFrame) + " is out of range -" + fmt(kMaxOrbitDegPerFrame) + ".." +
                 fmt(kMaxOrbitDegPerFrame) + " degrees a frame (kMaxOrbitDegPerFrame)");
    sc.path = r.string(c, where, "path", "");
    if (JsonReader::member(c, "path_hz")) {
      const std::string hzPath = jsonPath(where, "path_hz");
      if (sc.motion != "path")
        r.fail(hzPath, "goes with \"motion\": \"path\" (a " + sc.motion +
                           " camera renders no frames in between)");
      sc.pathHz = r.number(c["path_hz"], hzPath);
      if (!(sc.pathHz >= 0.0 && sc.pathHz <= kMaxPathHz))
        r.fail(hzPath, fmt(sc.pathHz) + " is out of range 0.." + fmt(kMaxPathHz) +
                           " frames a second of path time (kMaxPathHz)");
    }
    sc.warmup = r.integer(c, where, "warmup_frames", 0, 0, kMaxFrames);
    const int frames = r.integer(c, where, "frames", 30, 1, kMaxFrames);
    // Scaled, still bounded: every frame's camera and record is built (10^6 x 100 frames
    // died in std::bad_alloc).
    const double scaled = std::round(double(frames) * framesScale);
    if (scaled > double(kMaxFrames))
      r.fail(jsonPath(where, "frames"), std::to_string(frames) + " frames x --frames-scale " +
                                            fmt(framesScale) + " = " + fmt(scaled) +
                                            " frames, over the limit of " +
                                            std::to_string(kMaxFrames) + " (kMaxFrames)");
    sc.frames = std::max(sc.warmup + 2, int(scaled));
    std::tie(sc.width, sc.height) = defSize;
    if (const json* s = JsonReader::member(c, "size")) {
      sc.sizeWhere = jsonPath(where, "size");
      std::tie(sc.width, sc.height) = sizeOf(r, *s, sc.sizeWhere);
    }
    if (sizeOverride) {
      std::tie(sc.width, sc.height) = *sizeOverride;
      sc.sizeWhere = "--size";
    }
    const json* techniques = JsonReader::member(c, "techniques");
    if (!techniques || !techniques->is_array() || techniques->empty())
      r.fail(jsonPath(where, "techniques"), "expected a non-empty array of techniques");
    std::set<std::string> labels;
    for (std::size_t ti = 0; ti < techniques->size(); ++ti) {
      const std::string tp = jsonPath(jsonPath(where, "techniques"), ti);
      SuiteTechnique st = techniqueOf(r, (*techniques)[ti], tp, onlyTechniques);
      if (!labels.insert(st.spec.label).second)
        r.fail(tp,
               "two techniques labelled '" + quoteText(st.spec.label, 60) + "' (add \"label\")");
      sc.techniques.push_back(std::move(st));
    }
    if (const json* expect = JsonReader::member(c, "expect")) {
      const std::string ep = jsonPath(where, "expect");
      r.requireArray(*expect, ep);
      if (expect->empty())
        r.fail(ep,
               "an empty list checks nothing (leave \"expect\" out for a case that only "
               "reports its table)");
      for (std::size_t ei = 0; ei < expect->size(); ++ei)
        sc.expect.push_back(expectationOf(r, (*expect)[ei], jsonPath(ep, ei), labels));
    }
    cases.push_back(std::move(sc));
  }
  return cases;
}

Camera caseCamera(const SuiteCase& sc, const Scene& scene) {
  if (sc.cameraObject) return *sc.cameraObject;
  return pickCamera(scene, sc.cameraName, "camera");
}

struct ExpectationResult {
  std::string text;    ///< "uniform mask_change_frames == 0"
  std::string status;  ///< "pass", "FAIL", "skipped"
  std::string detail;  ///< "got 0", "skipped: technique X not available"
  std::string why;
};

struct Tally {
  int passed = 0, failed = 0, skipped = 0, xfailed = 0, xpassed = 0;
  std::vector<std::string> failures;
  std::ostringstream report;  ///< the tables and expectation lines, printed at the end
};

void count(Tally& tally, const SuiteCase& sc, const ExpectationResult& r,
           const std::string& xfail) {
  if (r.status == "xfail") {
    ++tally.xfailed;
    tally.report << "   known failure: " << r.text << " (" << r.detail << ") - " << xfail << "\n";
  } else if (r.status == "XPASS") {
    ++tally.xpassed;
    tally.report << "   XPASS (holds now; drop its \"xfail\"): " << r.text << " (" << r.detail
                 << ")\n";
  } else if (r.status == "pass") {
    ++tally.passed;
    tally.report << "   pass: " << r.text << " (" << r.detail << ")\n";
  } else if (r.status == "skipped") {
    ++tally.skipped;
    tally.report << "   skipped: " << r.text << ": " << r.detail << "\n";
  } else {
    ++tally.failed;
    tally.report << "   FAIL: " << r.text << " (" << r.detail << ")"
                 << (r.why.empty() ? "" : " - " + r.why) << "\n";
    tally.failures.push_back("case '" + sc.name + "': " + r.text + " (" + r.detail + ")");
  }
}

/// Runs one case: its table and expectations go to `tally`; returns the case's JSON.
json runCase(const SuiteCase& sc, ProgressBar& progress, Tally& tally) {
  std::shared_ptr<Scene> scene = loadScene(sc.sceneName);
  Camera cam = caseCamera(sc, *scene);
  std::vector<Camera> cameras;
  std::vector<std::vector<Camera>> between;  // along a path: the in-between frames
  if (sc.motion == "path") {
    MeasureCameras along = pathCameras(pickPath(*scene, sc.path), sc.frames, sc.pathHz,
                                       "case '" + quoteText(sc.name, 60) + "': path_hz");
    cameras = std::move(along.measured);
    between = std::move(along.between);
  } else {
    if (sc.motion == "orbit") cam = orbitCentred(cam, *scene);
    for (int f = 0; f < sc.frames; ++f) {
      cameras.push_back(cam);
      if (sc.motion == "orbit") cam.orbit(float(sc.orbitDegPerFrame), 0.0f);
    }
  }

  std::vector<std::unique_ptr<ConfigRunner>> runners;
  std::vector<const SuiteTechnique*> ran;
  for (const SuiteTechnique& t : sc.techniques) {
    if (!t.skipped.empty()) continue;
    runners.push_back(std::make_unique<ConfigRunner>(t.spec, scene, sc.light));
    ran.push_back(&t);
  }
  std::map<std::string, StabilitySummary> byLabel;
  if (!runners.empty()) {
    ReferenceCache reference(*scene);
    MeasureOptions opts;
    opts.width = sc.width;
    opts.height = sc.height;
    opts.publishing = true;
    auto frames = runFrames(runners, cameras, opts, &reference, progress, between);
    for (std::size_t i = 0; i < runners.size(); ++i)
      byLabel[ran[i]->spec.label] = summariseStability(frames[i], sc.warmup);
  }
  runners.clear();

  // The table of this case.
  std::ostringstream& report = tally.report;
  report << "\n== " << sc.name << ": " << sc.what << "\n   " << scene->name << ", " << sc.motion
         << (sc.motion == "orbit" ? " " + fmt(sc.orbitDegPerFrame) + " deg/frame" : "")
         << (sc.motion == "path" ? " " + fmt(sc.pathHz) + " Hz" : "") << ", " << sc.frames
         << " frames (warm-up " << sc.warmup << "), " << sc.width << "x" << sc.height << "\n";
  char line[256];
  std::snprintf(line, sizeof line, "   %-30s %8s %8s %9s %9s %8s %9s %8s %8s\n", "technique",
                "error %", "m p95", "flicker %", "flick max", "mask chg", "max chg %", "rot chg",
                "ms");
  report << line;
  json caseJson;
  caseJson["name"] = sc.name;
  caseJson["what"] = sc.what;
  caseJson["scene"] = scene->name;
  caseJson["motion"] = sc.motion;
  if (sc.motion == "path") caseJson["path_hz"] = sc.pathHz;
  caseJson["frames"] = sc.frames;
  caseJson["warmup_frames"] = sc.warmup;
  caseJson["size"] = {sc.width, sc.height};
  caseJson["configurations_run"] = ran.size();
  json techJson = json::object();
  for (const SuiteTechnique& t : sc.techniques) {
    if (!t.skipped.empty()) {
      report << "   " << t.spec.label << ": skipped: " << t.skipped << "\n";
      techJson[t.spec.label] = {{"skipped", t.skipped}};
      continue;
    }
    const StabilitySummary& s = byLabel.at(t.spec.label);
    if (s.failed())
      report << "   " << t.spec.label << ": " << s.renderErrors << " of " << sc.frames
             << " frames failed, first " << s.failure << "\n";
    // A metric that measured nothing reads n/a, never a number.
    const std::map<std::string, double> m = s.metrics();
    auto cell = [&](const char* metric, const char* format) {
      const double v = m.at(metric);
      if (!std::isfinite(v)) return std::string("n/a");
      char buf[32];
      std::snprintf(buf, sizeof buf, format, v);
      return std::string(buf);
    };
    std::snprintf(
        line, sizeof line, "   %-30s %8s %8s %9s %9s %8s %9s %8s %8s\n", t.spec.label.c_str(),
        cell("error_pct", "%.3f").c_str(), cell("aliasing_p95", "%.3f").c_str(),
        cell("flicker_pct", "%.4f").c_str(), cell("flicker_pct_max", "%.4f").c_str(),
        cell("mask_change_frames", "%.0f").c_str(), cell("max_mask_changed_pct", "%.4f").c_str(),
        cell("rotation_changes", "%.0f").c_str(), cell("total_ms", "%.1f").c_str());
    report << line;
    json tj = summaryJson(s);
    tj["technique"] = t.spec.techniqueId;
    json params = json::object();
    for (const auto& [k, v] : t.spec.sets) params[k] = v;
    tj["params"] = params;
    techJson[t.spec.label] = tj;
  }
  caseJson["techniques"] = techJson;

  // A case that ran nothing checked nothing: that is a failure, not a pass.
  if (ran.empty()) {
    ExpectationResult r;
    r.text = "the case runs at least one configuration";
    r.status = "FAIL";
    r.detail = "ran none: every technique was skipped";
    count(tally, sc, r, "");
    caseJson["status"] = "FAIL";
    caseJson["detail"] = r.detail;
  }

  // A configuration whose frames failed measured nothing there: the case fails, whatever
  // its expectations say.
  json failuresJson = json::array();
  for (const SuiteTechnique* t : ran) {
    const StabilitySummary& s = byLabel.at(t->spec.label);
    if (!s.failed()) continue;
    ExpectationResult r;
    r.text = t->spec.label + " renders every frame";
    r.status = "FAIL";
    r.detail = std::to_string(s.renderErrors) + " of " + std::to_string(sc.frames) +
               " frames failed, first " + s.failure;
    count(tally, sc, r, "");
    failuresJson.push_back({{"technique", t->spec.label}, {"detail", r.detail}});
  }
  if (!failuresJson.empty()) caseJson["failed_configurations"] = failuresJson;

  // Expectations.
  json expJson = json::array();
  // Why `label`'s `metric` is not checked: not run, or an error metric not measured.
  // Why `label`'s `metric` cannot pass: frames of it failed (only the failure counts are
  // still checked as usual).
  auto failReason = [&](const std::string& label, const std::string& metric) -> std::string {
    auto it = byLabel.find(label);
    if (it == byLabel.end() || !it->second.failed() || StabilitySummary::isFailureCount(metric))
      return "";
    return label + ": " + std::to_string(it->second.renderErrors) + " of " +
           std::to_string(sc.frames) + " frames failed, first " + it->second.failure;
  };
  auto skipReason = [&](const std::string& label, const std::string& metric) -> std::string {
    for (const SuiteTechnique& t : sc.techniques)
      if (t.spec.label == label && !t.skipped.empty()) return t.skipped;
    if (!std::isfinite(byLabel.at(label).metrics().at(metric)))
      return kNotMeasured + StabilitySummary::notMeasuredReason(metric) + ")";
    return "";
  };
  int checkedExpectations = 0, notMeasured = 0;  // checked; skipped as not measured
  std::vector<std::string> notMeasuredWhy;       // their reasons, each once
  for (const Expectation& e : sc.expect) {
    ExpectationResult r;
    r.why = e.why;
    if (e.pair) {
      r.text = e.better + " " + e.metric + " " + e.op + " " + e.worse + " " + e.metric;
      std::string sk = skipReason(e.better, e.metric);
      if (sk.empty()) sk = skipReason(e.worse, e.metric);
      std::string failed = failReason(e.better, e.metric);
      if (failed.empty()) failed = failReason(e.worse, e.metric);
      if (!failed.empty()) {
        r.status = "FAIL";
        r.detail = failed;
      } else if (!sk.empty()) {
        r.status = "skipped";
        r.detail = sk;
      } else {
        double vb = byLabel.at(e.better).metrics().at(e.metric);
        double vw = byLabel.at(e.worse).metrics().at(e.metric);
        r.status = compare(vb, e.op, vw) ? "pass" : "FAIL";
        r.detail = "got " + fmt(vb) + " against " + fmt(vw);
      }
      expJson.push_back({{"better", e.better},
                         {"worse", e.worse},
                         {"metric", e.metric},
                         {"op", e.op},
                         {"status", r.status},
                         {"detail", r.detail}});
    } else {
      r.text = e.technique + " " + e.metric + " " + e.op + " " + fmt(e.value);
      std::vector<std::string> labels;
      if (e.technique == "*") {
        for (const SuiteTechnique& t : sc.techniques)
          if (std::find(e.except.begin(), e.except.end(), t.spec.label) == e.except.end())
            labels.push_back(t.spec.label);
        if (!e.except.empty()) r.text = "* except " + json(e.except).dump() + r.text.substr(1);
      } else {
        labels.push_back(e.technique);
      }
      std::string got, failedLabels, skippedText, skippedLabels;
      int checked = 0;
      std::string failedDetail;  // configurations whose frames failed: not measured
      for (const std::string& l : labels) {
        if (std::string why = failReason(l, e.metric); !why.empty()) {
          ++checked;
          failedLabels += (failedLabels.empty() ? "" : ", ") + l;
          failedDetail += (failedDetail.empty() ? "" : "; ") + why;
          continue;
        }
        if (std::string sk = skipReason(l, e.metric); !sk.empty()) {
          if (skippedText.find(sk) == std::string::npos)
            skippedText += (skippedText.empty() ? "" : "; ") + sk;
          skippedLabels += (skippedLabels.empty() ? "" : ", ") + l + " (" + sk + ")";
          continue;
        }
        ++checked;
        double v = byLabel.at(l).metrics().at(e.metric);
        got += (got.empty() ? "" : ", ") + (e.technique == "*" ? l + " " : std::string()) + fmt(v);
        if (!compare(v, e.op, e.value)) failedLabels += (failedLabels.empty() ? "" : ", ") + l;
      }
      if (checked == 0) {
        r.status = "skipped";
        r.detail = skippedText;
      } else {
        r.status = failedLabels.empty() ? "pass" : "FAIL";
        r.detail =
            (got.empty() ? "" : "got " + got) + (failedDetail.empty() || got.empty() ? "" : "; ") +
            failedDetail +
            (failedLabels.empty() || e.technique != "*" ? "" : " (failing: " + failedLabels + ")") +
            (skippedLabels.empty() ? "" : "; not checked: " + skippedLabels);
      }
      expJson.push_back({{"technique", e.technique},
                         {"metric", e.metric},
                         {"op", e.op},
                         {"value", e.value},
                         {"status", r.status},
                         {"detail", r.detail}});
    }
    if (!r.why.empty()) expJson.back()["why"] = r.why;
    // A known failure ("xfail": why) does not fail the run; when it holds, say so.
    if (!e.xfail.empty() && r.status != "skipped") {
      r.status = r.status == "FAIL" ? "xfail" : "XPASS";
      expJson.back()["status"] = r.status;
      expJson.back()["xfail"] = e.xfail;
    }
    if (r.status == "skipped") {
      // "not measured (why)": counted, each reason once.
      if (const auto at = r.detail.find(kNotMeasured); at != std::string::npos) {
        ++notMeasured;
        const std::size_t from = at + std::string_view(kNotMeasured).size();
        const std::string why = r.detail.substr(from, r.detail.find(')', from) - from);
        if (std::find(notMeasuredWhy.begin(), notMeasuredWhy.end(), why) == notMeasuredWhy.end())
          notMeasuredWhy.push_back(why);
      }
    } else {
      ++checkedExpectations;
    }
    count(tally, sc, r, e.xfail);
  }
  // Expectations that all went unchecked because no frame covered a pixel: the case measured
  // nothing it claims, which is a failure (a broken camera or scene), not a pass.
  if (!sc.expect.empty() && checkedExpectations == 0 && notMeasured > 0 && !ran.empty()) {
    ExpectationResult r;
    r.text = "the case checks at least one of its expectations";
    r.status = "FAIL";
    std::string why;
    for (const std::string& w : notMeasuredWhy) why += (why.empty() ? "" : "; ") + w;
    r.detail = "checked none: " + std::to_string(notMeasured) + " of " +
               std::to_string(sc.expect.size()) + " not measured (" + why + ")";
    count(tally, sc, r, "");
    expJson.push_back({{"status", r.status}, {"detail", r.detail}, {"text", r.text}});
  }
  caseJson["expectations"] = expJson;
  return caseJson;
}

}  // namespace

std::size_t checkSuiteFile(const std::string& file) {
  const JsonReader reader(file);
  try {
    return parseSuite(reader, reader.parseFile(), 1.0, std::nullopt, {}).size();
  } catch (const JsonInputError& e) {
    throw UsageError(e.what());
  }
}

int runSuite(const std::string& file, double framesScale,
             const std::optional<std::pair<int, int>>& sizeOverride,
             const std::vector<std::string>& onlyCases,
             const std::vector<std::string>& onlyTechniques, const std::string& jsonPath) {
  // Everything in the file is checked before any case runs: a bad file exits 2 with one line
  // naming the file, the JSON path and what was expected.
  const JsonReader reader(file);
  json root;
  std::vector<SuiteCase> cases;
  try {
    root = reader.parseFile();
    cases = parseSuite(reader, root, framesScale, sizeOverride, onlyTechniques);
  } catch (const JsonInputError& e) {
    throw UsageError(e.what());
  }
  for (const std::string& only : onlyCases) {
    bool found = false;
    for (const SuiteCase& c : cases) found = found || c.name == only;
    if (!found) throw UsageError("--case: the suite has no case '" + only + "'");
  }
  auto selected = [&](const SuiteCase& c) {
    if (!onlyCases.empty() &&
        std::find(onlyCases.begin(), onlyCases.end(), c.name) == onlyCases.end())
      return false;
    // --techniques leaves out the cases that run none of the techniques it names.
    for (const SuiteTechnique& t : c.techniques)
      if (!t.deselected) return true;
    return false;
  };
  std::size_t totalSteps = 0, selectedCases = 0;
  for (const SuiteCase& c : cases) {
    if (!selected(c)) continue;
    ++selectedCases;
    for (const SuiteTechnique& t : c.techniques)
      totalSteps += t.skipped.empty() ? std::size_t(c.frames) : 0;
  }
  if (selectedCases == 0)
    throw UsageError(file + ": no case runs any of the techniques given to --techniques");

  json out;
  out["suite"] = root.value("name", file);
  out["file"] = file;
  out["frames_scale"] = framesScale;
  out["complete"] = false;
  json casesJson = json::array();
  Tally tally;
  // The results so far, written after every case (and before the first, which also checks
  // that the path is writable before any work): a case that throws loses nothing before it.
  auto save = [&]() {
    if (jsonPath.empty()) return;
    out["cases"] = casesJson;
    out["passed"] = tally.passed;
    out["failed"] = tally.failed;
    out["skipped"] = tally.skipped;
    out["known_failures"] = tally.xfailed;
    out["unexpected_passes"] = tally.xpassed;
    writeText(jsonPath,
              out.dump(2, ' ', false,
                       json::error_handler_t::replace));  // atomic: temp file + rename (CliCommon)
  };
  save();

  gl::EglContext ctx;
  // Every selected case's frame size against this GL implementation, before any case runs.
  for (const SuiteCase& c : cases) {
    if (!selected(c)) continue;
    auto e = Renderer::checkFrameSize(c.width, c.height);
    if (!e) e = frameMemoryError(c.width, c.height);
    if (e)
      throw UsageError(c.sizeWhere == "--size" ? "--size: " + *e
                                               : file + ": " + c.sizeWhere + ": " + *e);
  }
  ProgressBar progress("suite", totalSteps);
  std::string running, runningName;
  try {
    for (std::size_t ci = 0; ci < cases.size(); ++ci) {
      const SuiteCase& sc = cases[ci];
      if (!selected(sc)) continue;
      runningName = sc.name;
      running = sl::jsonPath("cases", ci) + " (case '" + sc.name + "')";
      casesJson.push_back(runCase(sc, progress, tally));
      save();
    }
  } catch (const std::exception& e) {
    progress.finish();
    std::cout << tally.report.str() << std::flush;
    out["error"] = {{"case", runningName}, {"message", e.what()}};
    try {
      save();
    } catch (const std::exception&) {
      // The case's own error is the one to report.
    }
    const std::string what = file + ": " + running + ": " + e.what();
    if (dynamic_cast<const UsageError*>(&e)) throw UsageError(what);
    throw std::runtime_error(what);
  }
  progress.finish();
  out["complete"] = true;
  std::cout << tally.report.str();
  std::printf(
      "\n%d expectations passed, %d failed, %d skipped, %d known failures, %d unexpected "
      "passes\n",
      tally.passed, tally.failed, tally.skipped, tally.xfailed, tally.xpassed);
  if (!jsonPath.empty()) {
    save();
    std::printf("-> %s\n", jsonPath.c_str());
  }
  for (const std::string& f : tally.failures)
    std::fprintf(stderr, "shadowlab-cli: FAILED %s\n", f.c_str());
  return tally.failed ? 1 : 0;
}

}  // namespace sl::cli
