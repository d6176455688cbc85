#include "core/Preset.h"

#include <nlohmann/json.hpp>

#include "algo/Params.h"
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

Preset parsePreset(const JsonReader& r, const json& j) {
  r.onlyKeys(j, "", {"title", "explanation", "scene", "technique", "params", "camera", "light"});
  Preset p;
  p.title = r.string(j, "", "title", "");
  p.explanation = r.string(j, "", "explanation", "");
  p.scene = r.string(j, "", "scene", "");
  p.technique = r.string(j, "", "technique", "");
  const TechniqueInfo* info = nullptr;
  if (!p.technique.empty()) {
    info = Renderer::findTechnique(p.technique);
    if (!info) {
      std::string known;
      for (const TechniqueInfo& t : Renderer::techniques())
        known += (known.empty() ? "" : ", ") + t.id;
      r.fail("technique",
             "unknown technique '" + quoteText(p.technique, 60) + "' (known: " + known + ")");
    }
  }
  if (const json* params = JsonReader::member(j, "params")) {
    r.requireObject(*params, "params");
    // With a technique, every key is its parameter (or a shared one) and every value in
    // range; without one the keys apply to the current technique and are checked there.
    std::optional<ParamSet> own, shared;
    if (info) own.emplace(info->params), shared.emplace(rendererParamDecls());
    for (const auto& [k, v] : params->items()) {
      const std::string path = jsonPath("params", k);
      if (!v.is_number() && !v.is_boolean() && !v.is_string())
        r.expected(v, path, "a number, true/false or a name");
      const std::string text = paramText(v);
      if (info) {
        ParamSet* set = own->has(k) ? &*own : shared->has(k) ? &*shared : nullptr;
        if (!set)
          r.fail(path,
                 "technique '" + p.technique + "' has no parameter '" + quoteText(k, 60) + "'");
        if (auto e = set->setFromString(k, text))
          r.fail(path,
                 quoteText(*e) + (e->find(text) == std::string::npos ? " (got " + quoteJson(v) + ")"
                                                                     : std::string()));
      }
      p.params[k] = text;
    }
  }
  if (const json* c = JsonReader::member(j, "camera")) {
    r.onlyKeys(*c, "camera", {"position", "target", "up", "fovYDeg", "nearM", "farM"});
    const json* pos = JsonReader::member(*c, "position");
    const json* target = JsonReader::member(*c, "target");
    if (!pos || !target) r.fail("camera", "a camera needs \"position\" and \"target\"");
    Camera cam;
    cam.position = vec3From(r, *pos, "camera.position");
    cam.target = vec3From(r, *target, "camera.target");
    if (const json* up = JsonReader::member(*c, "up")) cam.up = vec3From(r, *up, "camera.up");
    cam.fovYDeg = float(r.number(*c, "camera", "fovYDeg", cam.fovYDeg));
    cam.nearM = float(r.number(*c, "camera", "nearM", cam.nearM));
    cam.farM = float(r.number(*c, "camera", "farM", cam.farM));
    if (auto err = cam.validate()) r.fail("camera", *err);
    p.camera = cam;
  }
  if (const json* l = JsonReader::member(j, "light")) {
    p.light = readLightJson(r, *l, "light", JsonKeyStyle::CamelCase, false);
  }
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

std::string presetToJson(const Preset& p) {
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
                   {"fovYDeg", c.fovYDeg},
                   {"nearM", c.nearM},
                   {"farM", c.farM}};
  }
  if (p.light) j["light"] = lightToJson(*p.light, JsonKeyStyle::CamelCase);
  return j.dump(2);
}

}  // namespace sl
