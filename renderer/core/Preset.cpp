#include "core/Preset.h"

#include <algorithm>
#include <tuple>

#include <nlohmann/json.hpp>

#include "algo/Params.h"
#include "algo/TextTemplate.h"
#include "core/JsonInput.h"
#include "core/LightJson.h"
#include "core/Renderer.h"

namespace sl {

namespace {

using nlohmann::json;

glm::vec3 vec3From(const JsonReader& r, const json& j, const std::string& path) {
  if (!j.is_array() || j.size() != 3) r.expected(j, path, "[x, y, z] in metres");
  return {float(r.number(j[0], jsonPath(path, 0))), float(r.number(j[1], jsonPath(path, 1))),
          float(r.number(j[2], jsonPath(path, 2)))};
}

std::string paramText(const json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_boolean()) return v.get<bool>() ? "on" : "off";
  return v.dump();
}

const TechniqueInfo* findTechniqueOrFail(const JsonReader& r, const std::string& id,
                                         const std::string& path) {
  if (const TechniqueInfo* info = Renderer::findTechnique(id)) return info;
  std::string known;
  for (const TechniqueInfo& t : Renderer::techniques()) known += (known.empty() ? "" : ", ") + t.id;
  r.fail(path, "unknown technique '" + quoteText(id, 60) + "' (known: " + known + ")");
}

/// Reads {"key": value, ...} at `path` into text values. With `sets` (nullptr entries
/// skipped), every key must be declared by one of them and its value in range.
std::map<std::string, std::string> readParams(const JsonReader& r, const json& params,
                                              const std::string& path, const std::string& technique,
                                              std::initializer_list<ParamSet*> sets) {
  r.requireObject(params, path);
  std::map<std::string, std::string> out;
  for (const auto& [k, v] : params.items()) {
    const std::string at = jsonPath(path, k);
    if (!v.is_number() && !v.is_boolean() && !v.is_string())
      r.expected(v, at, "a number, true/false or a name");
    const std::string text = paramText(v);
    if (!technique.empty()) {
      ParamSet* set = nullptr;
      for (ParamSet* s : sets)
        if (!set && s && s->has(k)) set = s;
      if (!set)
        r.fail(at, "technique '" + technique + "' has no parameter '" + quoteText(k, 60) + "'");
      if (auto e = set->setFromString(k, text))
        r.fail(at,
               quoteText(*e) + (e->find(text) == std::string::npos ? " (got " + quoteJson(v) + ")"
                                                                   : std::string()));
    }
    out[k] = text;
  }
  return out;
}

bool isBase64(const std::string& s) {
  std::size_t pad = 0;
  for (char c : s) {
    const bool digit = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
                       c == '+' || c == '/';
    if (c == '=')
      ++pad;
    else if (!digit || pad > 0)
      return false;
  }
  return pad <= 2 && s.size() % 4 == 0;
}

PresetCompare parseCompare(const JsonReader& r, const json& c, const std::string& at) {
  r.onlyKeys(c, at, {"technique", "params"});
  PresetCompare out;
  out.technique = r.string(c, at, "technique", "");
  const json* params = JsonReader::member(c, "params");
  if (out.technique.empty()) {
    if (params && !params->empty())
      r.fail(jsonPath(at, "params"),
             "parameters for the split view need \"" + jsonPath(at, "technique") + "\"");
    return out;
  }
  const TechniqueInfo* info = findTechniqueOrFail(r, out.technique, jsonPath(at, "technique"));
  // Only the compare technique's own parameters: the shared ones are the main side's.
  ParamSet own(info->params);
  if (params) out.params = readParams(r, *params, jsonPath(at, "params"), out.technique, {&own});
  return out;
}

PresetLayout parseLayout(const JsonReader& r, const json& l) {
  r.onlyKeys(l, "layout", {"docks", "state", "large", "strip"});
  PresetLayout out;
  if (const json* docks = JsonReader::member(l, "docks")) {
    r.requireArray(*docks, "layout.docks");
    if (docks->size() > kMaxPresetLayoutDocks)
      r.fail("layout.docks", "more than " + std::to_string(kMaxPresetLayoutDocks) +
                                 " docks: refused (kMaxPresetLayoutDocks)");
    for (std::size_t i = 0; i < docks->size(); ++i) {
      const std::string name = r.string((*docks)[i], jsonPath("layout.docks", i));
      if (name.empty() || name.size() > 60)
        r.fail(jsonPath("layout.docks", i),
               "expected a dock name of 1..60 bytes, got " + quoteJson((*docks)[i]));
      out.docks.push_back(name);
    }
  }
  out.state = r.string(l, "layout", "state", "");
  if (out.state.size() > kMaxPresetLayoutStateBytes)
    r.fail("layout.state", "is " + std::to_string(out.state.size()) + " bytes, over the limit of " +
                               std::to_string(kMaxPresetLayoutStateBytes) +
                               " (kMaxPresetLayoutStateBytes)");
  if (!isBase64(out.state))
    r.fail("layout.state", "expected the window state as base64, got " + quoteText(out.state, 60));
  out.large = r.string(l, "layout", "large", "");
  if (!out.large.empty() &&
      std::find(out.docks.begin(), out.docks.end(), out.large) == out.docks.end())
    r.fail("layout.large",
           "names '" + quoteText(out.large, 60) + "', which \"docks\" does not list");
  if (const json* strip = JsonReader::member(l, "strip")) {
    r.requireArray(*strip, "layout.strip");
    if (strip->empty() || strip->size() > kMaxPresetStripKeys)
      r.fail("layout.strip", "expected 1 to " + std::to_string(kMaxPresetStripKeys) +
                                 " parameter keys, got " + std::to_string(strip->size()));
    for (std::size_t i = 0; i < strip->size(); ++i) {
      const std::string key = r.string((*strip)[i], jsonPath("layout.strip", i));
      if (std::find(out.strip.begin(), out.strip.end(), key) != out.strip.end())
        r.fail(jsonPath("layout.strip", i), "'" + quoteText(key, 60) + "' is listed twice");
      out.strip.push_back(key);
    }
  }
  return out;
}

/// Every key of the layout's strip is a parameter of each case's technique (a lesson without
/// cases: its own) or a shared view parameter; the error names the case and the key. A
/// preset without a technique applies to the current one: its keys are checked when shown.
void checkStrip(const JsonReader& r, const Preset& p) {
  std::vector<const Preset*> shown;
  if (p.cases.empty()) shown.push_back(&p);
  for (const Preset& c : p.cases) shown.push_back(&c);
  const ParamSet shared(rendererParamDecls());
  for (std::size_t i = 0; i < p.layout->strip.size(); ++i) {
    const std::string& key = p.layout->strip[i];
    for (std::size_t k = 0; k < shown.size(); ++k) {
      const Preset& c = *shown[k];
      if (c.technique.empty() || shared.has(key)) continue;
      const TechniqueInfo* info = Renderer::findTechnique(c.technique);  // checked when read
      if (info && ParamSet(info->params).has(key)) continue;
      r.fail(jsonPath("layout.strip", i),
             (p.cases.empty()
                  ? std::string()
                  : "case " + std::to_string(k + 1) + " ('" + quoteText(c.title, 60) + "'): ") +
                 "technique '" + c.technique + "' has no parameter '" + quoteText(key, 60) + "'");
    }
  }
}

/// The fields a preset and each of its cases share, at `at` ("" for the preset itself,
/// "cases[i]"): present ones replace what `p` holds.
void parseBody(const JsonReader& r, const json& j, const std::string& at, Preset& p) {
  p.title = r.string(j, at, "title", p.title);
  p.explanation = r.string(j, at, "explanation", p.explanation);
  for (const auto& [key, text, limit, limitName] :
       {std::tuple{"title", &p.title, kMaxPresetTitleBytes, "kMaxPresetTitleBytes"},
        std::tuple{"explanation", &p.explanation, kMaxPresetExplanationBytes,
                   "kMaxPresetExplanationBytes"}})
    if (text->size() > limit)
      r.fail(jsonPath(at, key), "a text of " + std::to_string(text->size()) +
                                    " bytes, over the limit of " + std::to_string(limit) + " (" +
                                    limitName + ")");
  const std::string scene = r.string(j, at, "scene", p.scene);
  if (scene != p.scene) p.camera.reset(), p.light.reset();  // another scene: its own
  p.scene = scene;
  const bool ownTechnique = JsonReader::member(j, "technique") != nullptr;
  const std::string before = p.technique;
  p.technique = r.string(j, at, "technique", p.technique);
  const TechniqueInfo* info = p.technique.empty()
                                  ? nullptr
                                  : findTechniqueOrFail(r, p.technique, jsonPath(at, "technique"));
  const json* params = JsonReader::member(j, "params");
  if (!at.empty() && ownTechnique && !params && !p.params.empty())
    r.fail(at,
           "a case that names its own \"technique\" gives its own \"params\" (the "
           "preset's are for '" +
               quoteText(before, 60) + "')");
  if (params) {
    // With a technique, every key is its parameter (or a shared one) and every value in
    // range; without one the keys apply to the current technique and are checked there.
    std::optional<ParamSet> own, shared;
    if (info) own.emplace(info->params), shared.emplace(rendererParamDecls());
    p.params = readParams(r, *params, jsonPath(at, "params"), p.technique,
                          {own ? &*own : nullptr, shared ? &*shared : nullptr});
  }
  if (const json* c = JsonReader::member(j, "camera")) {
    const std::string cam_at = jsonPath(at, "camera");
    r.onlyKeys(*c, cam_at, {"position", "target", "up", "fovYDeg", "nearM", "farM"});
    const json* pos = JsonReader::member(*c, "position");
    const json* target = JsonReader::member(*c, "target");
    if (!pos || !target) r.fail(cam_at, "a camera needs \"position\" and \"target\"");
    Camera cam;
    cam.position = vec3From(r, *pos, jsonPath(cam_at, "position"));
    cam.target = vec3From(r, *target, jsonPath(cam_at, "target"));
    if (const json* up = JsonReader::member(*c, "up"))
      cam.up = vec3From(r, *up, jsonPath(cam_at, "up"));
    cam.fovYDeg = float(r.number(*c, cam_at, "fovYDeg", cam.fovYDeg));
    cam.nearM = float(r.number(*c, cam_at, "nearM", cam.nearM));
    cam.farM = float(r.number(*c, cam_at, "farM", cam.farM));
    if (auto e = cameraFieldError(cam, {"up", "nearM", "farM"}))
      r.fail(jsonPath(cam_at, e->first), e->second);
    if (auto err = cam.validate()) r.fail(cam_at, Camera::withoutPrefix(*err));
    p.camera = cam;
  }
  if (const json* l = JsonReader::member(j, "light")) {
    p.light = readLightJson(r, *l, jsonPath(at, "light"), JsonKeyStyle::CamelCase, false);
  }
  if (const json* c = JsonReader::member(j, "compare"))
    p.compare = parseCompare(r, *c, jsonPath(at, "compare"));
  // The explanation's live numbers ("{error_pct}", "{compare.error_pct}"): well formed, and a
  // right-half number only where there is a right half.
  std::string error;
  const auto text = TextTemplate::parse(p.explanation, &error);
  if (!text) r.fail(jsonPath(at, "explanation"), error);
  for (const TextPlaceholder& ph : text->placeholders())
    if (ph.compare && (!p.compare || p.compare->technique.empty()))
      r.fail(
          jsonPath(at, "explanation"),
          "{" + ph.spelling + "} quotes the split view's right half, but there is no \"compare\"");
}

Preset parsePreset(const JsonReader& r, const json& j) {
  r.onlyKeys(j, "",
             {"title", "explanation", "scene", "technique", "params", "camera", "light", "compare",
              "layout", "cases"});
  Preset p;
  parseBody(r, j, "", p);
  if (const json* l = JsonReader::member(j, "layout")) p.layout = parseLayout(r, *l);
  if (const json* cases = JsonReader::member(j, "cases")) {
    r.requireArray(*cases, "cases");
    if (cases->size() < 2 || cases->size() > kMaxPresetCases)
      r.fail("cases", "expected 2 to " + std::to_string(kMaxPresetCases) + " cases, got " +
                          std::to_string(cases->size()));
    for (std::size_t i = 0; i < cases->size(); ++i) {
      const std::string at = jsonPath("cases", i);
      const json& c = (*cases)[i];
      r.requireObject(c, at);
      r.onlyKeys(
          c, at,
          {"title", "explanation", "scene", "technique", "params", "camera", "light", "compare"});
      for (const char* key : {"title", "explanation"})
        if (!JsonReader::member(c, key)) r.fail(at, std::string("a case needs \"") + key + "\"");
      Preset one = p;  // the preset's fields, the case's on top
      one.cases.clear();
      one.layout.reset();
      parseBody(r, c, at, one);
      p.cases.push_back(std::move(one));
    }
  }
  if (p.layout && !p.layout->strip.empty()) checkStrip(r, p);
  return p;
}

}  // namespace

std::optional<Preset> loadPreset(const std::filesystem::path& path, std::string* error) {
  const JsonReader reader(path.string());
  try {
    return parsePreset(reader, reader.parseFile());
  } catch (const JsonInputError& e) {
    if (error) *error = e.what();
    return std::nullopt;
  }
}

namespace {
nlohmann::json toJson(const Preset& p) {
  nlohmann::json j;
  j["title"] = p.title;
  j["explanation"] = p.explanation;
  j["scene"] = p.scene;
  j["technique"] = p.technique;
  j["params"] = p.params;
  if (p.camera) {
    const Camera& c = *p.camera;
    j["camera"] = {{"position", {c.position.x, c.position.y, c.position.z}},
                   {"target", {c.target.x, c.target.y, c.target.z}},
                   {"up", {c.up.x, c.up.y, c.up.z}},
                   {"fovYDeg", c.fovYDeg},
                   {"nearM", c.nearM},
                   {"farM", c.farM}};
  }
  if (p.light) j["light"] = lightToJson(*p.light, JsonKeyStyle::CamelCase);
  if (p.compare)
    j["compare"] = {{"technique", p.compare->technique}, {"params", p.compare->params}};
  if (p.layout) {
    j["layout"] = {{"docks", p.layout->docks}, {"state", p.layout->state}};
    if (!p.layout->large.empty()) j["layout"]["large"] = p.layout->large;
    if (!p.layout->strip.empty()) j["layout"]["strip"] = p.layout->strip;
  }
  // Each case whole: read back on top of the preset, it gives the same case.
  for (const Preset& c : p.cases) j["cases"].push_back(toJson(c));
  return j;
}
}  // namespace

std::string presetToJson(const Preset& p) {
  return toJson(p).dump(2);
}

}  // namespace sl
