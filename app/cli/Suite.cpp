// `shadowlab-cli stability --suite FILE.json`: a suite of purpose-built failure cases
// (scenes/suites/), each a scene, camera, light and motion run for several techniques, with
// expectations on the numbers; exit 1 naming every expectation that fails. Techniques or
// parameters not registered are skipped, saying so. Format: README, "Speed against accuracy".
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "StabilityRun.h"
#include "gl/EglContext.h"

using nlohmann::json;

namespace sl::cli {
namespace {

/// A suite's problem (bad file): UsageError naming the file and where.
[[noreturn]] void suiteError(const std::string& file, const std::string& where,
                             const std::string& what) {
  throw UsageError(file + ": " + where + ": " + what);
}

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

glm::vec3 vec3Of(const json& v, const std::string& file, const std::string& where) {
  if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number())
    suiteError(file, where, "expected [x, y, z] in metres");
  return {v[0].get<float>(), v[1].get<float>(), v[2].get<float>()};
}

struct SuiteTechnique {
  ConfigSpec spec;
  std::string skipped;  ///< why it does not run ("" when it does)
};

struct SuiteCase {
  std::string name, what, sceneName;
  json camera, light, expect;
  std::string motion = "static";  ///< static | orbit | path
  double orbitDegPerFrame = 0.2;
  std::string path;
  int frames = 30, warmup = 0;
  int width = 320, height = 180;
  std::vector<SuiteTechnique> techniques;
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

std::vector<SuiteCase> parseSuite(const json& root, const std::string& file, double framesScale,
                                  const std::optional<std::pair<int, int>>& sizeOverride,
                                  const std::vector<std::string>& onlyTechniques) {
  if (!root.is_object() || !root.contains("cases") || !root["cases"].is_array())
    suiteError(file, "top level", "expected an object with a \"cases\" array");
  int defW = 320, defH = 180;
  if (root.contains("size")) {
    const json& s = root["size"];
    if (!s.is_array() || s.size() != 2 || !s[0].is_number_integer() || !s[1].is_number_integer())
      suiteError(file, "size", "expected [width, height]");
    defW = s[0].get<int>(), defH = s[1].get<int>();
  }
  const std::set<std::string> known = {
      "name", "what",   "scene",         "camera", "light",      "motion", "orbit_deg_per_frame",
      "path", "frames", "warmup_frames", "size",   "techniques", "expect"};
  std::vector<SuiteCase> cases;
  std::set<std::string> names;
  for (std::size_t ci = 0; ci < root["cases"].size(); ++ci) {
    const json& c = root["cases"][ci];
    std::string where = "cases[" + std::to_string(ci) + "]";
    if (!c.is_object()) suiteError(file, where, "expected an object");
    SuiteCase sc;
    sc.name = c.value("name", "");
    if (sc.name.empty()) suiteError(file, where, "missing \"name\"");
    where = "case '" + sc.name + "'";
    if (!names.insert(sc.name).second) suiteError(file, where, "duplicate name");
    for (const auto& [k, v] : c.items())
      if (!known.count(k)) suiteError(file, where, "unknown key \"" + k + "\"");
    sc.what = c.value("what", "");
    sc.sceneName = c.value("scene", "");
    if (sc.sceneName.empty()) suiteError(file, where, "missing \"scene\"");
    sc.camera = c.value("camera", json());
    sc.light = c.value("light", json());
    sc.motion = c.value("motion", "static");
    if (sc.motion != "static" && sc.motion != "orbit" && sc.motion != "path")
      suiteError(file, where, "\"motion\" must be static, orbit or path");
    sc.orbitDegPerFrame = c.value("orbit_deg_per_frame", 0.2);
    sc.path = c.value("path", "");
    sc.warmup = c.value("warmup_frames", 0);
    const int frames = c.value("frames", 30);
    if (frames < 1 || sc.warmup < 0) suiteError(file, where, "frames must be >= 1, warmup >= 0");
    sc.frames = std::max(sc.warmup + 2, int(std::lround(frames * framesScale)));
    sc.width = defW, sc.height = defH;
    if (c.contains("size")) {
      const json& s = c["size"];
      if (!s.is_array() || s.size() != 2) suiteError(file, where, "size: expected [w, h]");
      sc.width = s[0].get<int>(), sc.height = s[1].get<int>();
    }
    if (sizeOverride) std::tie(sc.width, sc.height) = *sizeOverride;
    if (!c.contains("techniques") || !c["techniques"].is_array() || c["techniques"].empty())
      suiteError(file, where, "missing \"techniques\" (a non-empty array)");
    std::set<std::string> labels;
    for (const json& t : c["techniques"]) {
      SuiteTechnique st;
      if (t.is_string()) {
        st.spec.techniqueId = t.get<std::string>();
      } else if (t.is_object() && t.contains("id")) {
        st.spec.techniqueId = t["id"].get<std::string>();
        if (t.contains("set")) {
          if (!t["set"].is_object())
            suiteError(file, where, "technique \"set\": expected an object");
          for (const auto& [k, v] : t["set"].items()) st.spec.sets.push_back({k, valueText(v)});
        }
        st.spec.label = t.value("label", "");
      } else {
        suiteError(file, where,
                   "a technique is \"ID\" or {\"id\": ..., \"set\": {...}, \"label\": ...}");
      }
      if (st.spec.label.empty()) st.spec.label = st.spec.techniqueId;
      if (!labels.insert(st.spec.label).second)
        suiteError(file, where, "two techniques labelled '" + st.spec.label + "' (add \"label\")");
      if (!Renderer::findTechnique(st.spec.techniqueId))
        st.skipped = "technique " + st.spec.techniqueId + " not available";
      else if (!onlyTechniques.empty() && std::find(onlyTechniques.begin(), onlyTechniques.end(),
                                                    st.spec.techniqueId) == onlyTechniques.end())
        st.skipped = "technique " + st.spec.techniqueId + " not selected (--techniques)";
      else if (auto e = validateConfig(st.spec))
        st.skipped = *e;
      sc.techniques.push_back(std::move(st));
    }
    sc.expect = c.value("expect", json::array());
    if (!sc.expect.is_array()) suiteError(file, where, "\"expect\": expected an array");
    for (const json& e : sc.expect) {
      auto checkLabelNow = [&](const std::string& l) {
        if (!labels.count(l))
          suiteError(file, where,
                     "expectation names '" + l + "', which the case does not run: " + e.dump());
      };
      if (!e.is_object() || !e.contains("metric") || !e["metric"].is_string())
        suiteError(file, where, "an expectation needs \"metric\": " + e.dump());
      const bool pair = e.contains("better") || e.contains("worse");
      if (pair && !(e.contains("better") && e.contains("worse")))
        suiteError(file, where, "\"better\" needs \"worse\" (and back): " + e.dump());
      if (!pair && !(e.contains("technique") && e.contains("op") && e.contains("value")))
        suiteError(file, where,
                   "an expectation is {technique, metric, op, value} or {better, worse, metric}: " +
                       e.dump());
      for (const auto& [k, v] : e.items())
        if (k != "technique" && k != "better" && k != "worse" && k != "metric" && k != "op" &&
            k != "value" && k != "why" && k != "except" && k != "xfail")
          suiteError(file, where, "unknown expectation key \"" + k + "\": " + e.dump());
      if (e.contains("except") && (!e["except"].is_array() || pair || e["technique"] != "*"))
        suiteError(file, where,
                   "\"except\" goes with \"technique\": \"*\" (a list of labels): " + e.dump());
      if (e.contains("except"))
        for (const json& l : e["except"]) checkLabelNow(l.get<std::string>());
      if (e.contains("op") && !kOps.count(e["op"].get<std::string>()))
        suiteError(file, where, "op must be one of == != < <= > >=: " + e.dump());
      if (!StabilitySummary().metrics().count(e["metric"].get<std::string>())) {
        std::string list;
        for (const auto& [k, v] : StabilitySummary().metrics())
          list += (list.empty() ? "" : ", ") + k;
        suiteError(
            file, where,
            "unknown metric '" + e["metric"].get<std::string>() + "' (metrics: " + list + ")");
      }
      auto checkLabel = [&](const std::string& l) {
        if (l != "*") checkLabelNow(l);
      };
      if (pair) {
        checkLabel(e["better"].get<std::string>());
        checkLabel(e["worse"].get<std::string>());
      } else {
        checkLabel(e["technique"].get<std::string>());
      }
    }
    cases.push_back(std::move(sc));
  }
  return cases;
}

Camera caseCamera(const SuiteCase& sc, const Scene& scene, const std::string& file) {
  const std::string where = "case '" + sc.name + "': camera";
  if (sc.camera.is_null()) return pickCamera(scene, "", where);
  if (sc.camera.is_string())
    return pickCamera(scene, sc.camera.get<std::string>(), file + ": " + where);
  if (!sc.camera.is_object()) suiteError(file, where, "expected a bookmark name or an object");
  Camera cam;
  cam.position = vec3Of(sc.camera.value("position", json()), file, where + ".position");
  cam.target = vec3Of(sc.camera.value("target", json()), file, where + ".target");
  if (sc.camera.contains("up")) cam.up = vec3Of(sc.camera["up"], file, where + ".up");
  cam.fovYDeg = sc.camera.value("fov_deg", cam.fovYDeg);
  cam.nearM = sc.camera.value("near_m", cam.nearM);
  cam.farM = sc.camera.value("far_m", cam.farM);
  if (auto e = cam.validate()) suiteError(file, where, *e);
  return cam;
}

std::optional<DirectionalLight> caseLight(const SuiteCase& sc, const std::string& file) {
  if (sc.light.is_null()) return std::nullopt;
  const std::string where = "case '" + sc.name + "': light";
  if (!sc.light.is_object() || !sc.light.contains("azimuth_deg") ||
      !sc.light.contains("elevation_deg"))
    suiteError(file, where, "expected {\"azimuth_deg\": A, \"elevation_deg\": E}");
  DirectionalLight l;
  l.azimuthDeg = sc.light["azimuth_deg"].get<float>();
  l.elevationDeg = sc.light["elevation_deg"].get<float>();
  if (auto e = l.validate()) suiteError(file, where, *e);
  return l;
}

struct ExpectationResult {
  std::string text;    ///< "uniform mask_change_frames == 0"
  std::string status;  ///< "pass", "FAIL", "skipped"
  std::string detail;  ///< "got 0", "skipped: technique X not available"
  std::string why;
};

}  // namespace

int runSuite(const std::string& file, double framesScale,
             const std::optional<std::pair<int, int>>& sizeOverride,
             const std::vector<std::string>& onlyCases,
             const std::vector<std::string>& onlyTechniques, const std::string& jsonPath) {
  std::ifstream in(file);
  if (!in) throw UsageError(file + ": cannot open the suite file");
  json root;
  try {
    root = json::parse(in, nullptr, true, /*ignore_comments=*/true);
  } catch (const json::exception& e) {
    throw UsageError(file + ": not valid JSON (" + std::string(e.what()) + ")");
  }
  std::vector<SuiteCase> cases;
  try {
    cases = parseSuite(root, file, framesScale, sizeOverride, onlyTechniques);
  } catch (const json::exception& e) {
    throw UsageError(file + ": " + e.what());
  }
  for (const std::string& only : onlyCases) {
    bool found = false;
    for (const SuiteCase& c : cases) found = found || c.name == only;
    if (!found) throw UsageError("--case: the suite has no case '" + only + "'");
  }
  std::size_t totalSteps = 0;
  auto selected = [&](const SuiteCase& c) {
    return onlyCases.empty() ||
           std::find(onlyCases.begin(), onlyCases.end(), c.name) != onlyCases.end();
  };
  for (const SuiteCase& c : cases) {
    if (!selected(c)) continue;
    for (const SuiteTechnique& t : c.techniques)
      totalSteps += t.skipped.empty() ? std::size_t(c.frames) : 0;
  }

  gl::EglContext ctx;
  ProgressBar progress("suite", totalSteps);
  json out;
  out["suite"] = root.value("name", file);
  out["file"] = file;
  out["frames_scale"] = framesScale;
  json casesJson = json::array();
  int passed = 0, failed = 0, skipped = 0, xfailed = 0, xpassed = 0;
  std::vector<std::string> failures;
  std::ostringstream report;

  for (const SuiteCase& sc : cases) {
    if (!selected(sc)) continue;
    std::shared_ptr<Scene> scene = loadScene(sc.sceneName);
    Camera cam = caseCamera(sc, *scene, file);
    std::optional<DirectionalLight> light = caseLight(sc, file);
    std::vector<Camera> cameras;
    if (sc.motion == "path") {
      const CameraPath& path = pickPath(*scene, sc.path);
      for (int f = 0; f < sc.frames; ++f)
        cameras.push_back(
            path.sample(sc.frames > 1 ? path.durationS() * float(f) / float(sc.frames - 1) : 0.0f));
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
      runners.push_back(std::make_unique<ConfigRunner>(t.spec, scene, light));
      ran.push_back(&t);
    }
    std::map<std::string, StabilitySummary> byLabel;
    if (!runners.empty()) {
      ReferenceCache reference(*scene);
      MeasureOptions opts;
      opts.width = sc.width;
      opts.height = sc.height;
      opts.publishing = true;
      auto frames = runFrames(runners, cameras, opts, &reference, progress);
      for (std::size_t i = 0; i < runners.size(); ++i)
        byLabel[ran[i]->spec.label] = summariseStability(frames[i], sc.warmup);
    }
    runners.clear();

    // The table of this case.
    report << "\n== " << sc.name << ": " << sc.what << "\n   " << scene->name << ", " << sc.motion
           << (sc.motion == "orbit" ? " " + fmt(sc.orbitDegPerFrame) + " deg/frame" : "") << ", "
           << sc.frames << " frames (warm-up " << sc.warmup << "), " << sc.width << "x" << sc.height
           << "\n";
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
    caseJson["frames"] = sc.frames;
    caseJson["warmup_frames"] = sc.warmup;
    caseJson["size"] = {sc.width, sc.height};
    json techJson = json::object();
    for (const SuiteTechnique& t : sc.techniques) {
      if (!t.skipped.empty()) {
        report << "   " << t.spec.label << ": skipped: " << t.skipped << "\n";
        techJson[t.spec.label] = {{"skipped", t.skipped}};
        continue;
      }
      const StabilitySummary& s = byLabel.at(t.spec.label);
      std::snprintf(line, sizeof line, "   %-30s %8.3f %8.3f %9.4f %9.4f %8d %9.4f %8d %8.1f\n",
                    t.spec.label.c_str(), s.errorPct, s.aliasingP95, s.flickerPct, s.flickerPctMax,
                    s.maskChangeFrames, s.maxMaskChangedPct, s.rotationChanges, s.totalMs);
      report << line;
      json tj = summaryJson(s);
      tj["technique"] = t.spec.techniqueId;
      json params = json::object();
      for (const auto& [k, v] : t.spec.sets) params[k] = v;
      tj["params"] = params;
      techJson[t.spec.label] = tj;
    }
    caseJson["techniques"] = techJson;

    // Expectations.
    json expJson = json::array();
    for (const json& e : sc.expect) {
      ExpectationResult r;
      r.why = e.value("why", "");
      const std::string metric = e["metric"].get<std::string>();
      auto skipReason = [&](const std::string& label) -> std::string {
        for (const SuiteTechnique& t : sc.techniques)
          if (t.spec.label == label && !t.skipped.empty()) return t.skipped;
        return "";
      };
      if (e.contains("better")) {
        const std::string b = e["better"].get<std::string>(), w = e["worse"].get<std::string>();
        const std::string op = e.value("op", std::string("<"));
        r.text = b + " " + metric + " " + op + " " + w + " " + metric;
        std::string sk = skipReason(b);
        if (sk.empty()) sk = skipReason(w);
        if (!sk.empty()) {
          r.status = "skipped";
          r.detail = sk;
        } else {
          double vb = byLabel.at(b).metrics().at(metric), vw = byLabel.at(w).metrics().at(metric);
          r.status = compare(vb, op, vw) ? "pass" : "FAIL";
          r.detail = "got " + fmt(vb) + " against " + fmt(vw);
        }
        expJson.push_back({{"better", b},
                           {"worse", w},
                           {"metric", metric},
                           {"op", op},
                           {"status", r.status},
                           {"detail", r.detail}});
      } else {
        const std::string label = e["technique"].get<std::string>();
        const std::string op = e["op"].get<std::string>();
        const double value = e["value"].get<double>();
        r.text = label + " " + metric + " " + op + " " + fmt(value);
        std::vector<std::string> labels;
        if (label == "*") {
          const json except = e.value("except", json::array());
          for (const SuiteTechnique& t : sc.techniques)
            if (std::find(except.begin(), except.end(), json(t.spec.label)) == except.end())
              labels.push_back(t.spec.label);
          if (!except.empty()) r.text = "* except " + except.dump() + r.text.substr(1);
        } else
          labels.push_back(label);
        std::string got, failedLabels, skippedText, skippedLabels;
        int checked = 0;
        for (const std::string& l : labels) {
          if (std::string sk = skipReason(l); !sk.empty()) {
            skippedText += (skippedText.empty() ? "" : "; ") + sk;
            skippedLabels += (skippedLabels.empty() ? "" : ", ") + l;
            continue;
          }
          ++checked;
          double v = byLabel.at(l).metrics().at(metric);
          got += (got.empty() ? "" : ", ") + (label == "*" ? l + " " : std::string()) + fmt(v);
          if (!compare(v, op, value)) failedLabels += (failedLabels.empty() ? "" : ", ") + l;
        }
        if (checked == 0) {
          r.status = "skipped";
          r.detail = skippedText;
        } else {
          r.status = failedLabels.empty() ? "pass" : "FAIL";
          r.detail =
              "got " + got +
              (failedLabels.empty() || label != "*" ? "" : " (failing: " + failedLabels + ")") +
              (skippedLabels.empty() ? "" : "; not run: " + skippedLabels);
        }
        expJson.push_back({{"technique", label},
                           {"metric", metric},
                           {"op", op},
                           {"value", value},
                           {"status", r.status},
                           {"detail", r.detail}});
      }
      if (!r.why.empty()) expJson.back()["why"] = r.why;
      // A known failure ("xfail": why) does not fail the run; when it holds, say so.
      const std::string xfail = e.value("xfail", "");
      if (!xfail.empty() && r.status != "skipped") {
        r.status = r.status == "FAIL" ? "xfail" : "XPASS";
        expJson.back()["status"] = r.status;
        expJson.back()["xfail"] = xfail;
      }
      if (r.status == "xfail") {
        ++xfailed;
        report << "   known failure: " << r.text << " (" << r.detail << ") - " << xfail << "\n";
      } else if (r.status == "XPASS") {
        ++xpassed;
        report << "   XPASS (holds now; drop its \"xfail\"): " << r.text << " (" << r.detail
               << ")\n";
      } else if (r.status == "pass") {
        ++passed;
        report << "   pass: " << r.text << " (" << r.detail << ")\n";
      } else if (r.status == "skipped") {
        ++skipped;
        report << "   skipped: " << r.text << ": " << r.detail << "\n";
      } else {
        ++failed;
        report << "   FAIL: " << r.text << " (" << r.detail << ")"
               << (r.why.empty() ? "" : " - " + r.why) << "\n";
        failures.push_back("case '" + sc.name + "': " + r.text + " (" + r.detail + ")");
      }
    }
    caseJson["expectations"] = expJson;
    casesJson.push_back(caseJson);
  }
  progress.finish();
  out["cases"] = casesJson;
  out["passed"] = passed;
  out["failed"] = failed;
  out["skipped"] = skipped;
  out["known_failures"] = xfailed;
  out["unexpected_passes"] = xpassed;
  std::cout << report.str();
  std::printf(
      "\n%d expectations passed, %d failed, %d skipped, %d known failures, %d unexpected "
      "passes\n",
      passed, failed, skipped, xfailed, xpassed);
  if (!jsonPath.empty()) {
    writeText(jsonPath, out.dump(2));
    std::printf("-> %s\n", jsonPath.c_str());
  }
  for (const std::string& f : failures)
    std::fprintf(stderr, "shadowlab-cli: FAILED %s\n", f.c_str());
  return failed ? 1 : 0;
}

}  // namespace sl::cli
