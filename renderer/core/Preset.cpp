#include "core/Preset.h"

#include <fstream>

#include <nlohmann/json.hpp>

namespace sl {

namespace {
glm::vec3 vec3From(const nlohmann::json& j) {
  if (!j.is_array() || j.size() != 3) throw std::runtime_error("expected [x, y, z]");
  return {j[0].get<float>(), j[1].get<float>(), j[2].get<float>()};
}
}  // namespace

std::optional<Preset> loadPreset(const std::filesystem::path& path, std::string* error) {
  std::ifstream in(path);
  if (!in) {
    if (error) *error = path.string() + ": cannot open preset file";
    return std::nullopt;
  }
  try {
    nlohmann::json j = nlohmann::json::parse(in);
    Preset p;
    p.title = j.value("title", "");
    p.explanation = j.value("explanation", "");
    p.scene = j.value("scene", "");
    p.technique = j.value("technique", "");
    if (j.contains("params")) {
      for (auto& [k, v] : j["params"].items())
        p.params[k] = v.is_string()    ? v.get<std::string>()
                      : v.is_boolean() ? (v.get<bool>() ? "on" : "off")
                                       : v.dump();
    }
    if (j.contains("camera")) {
      const auto& c = j["camera"];
      Camera cam;
      cam.position = vec3From(c.at("position"));
      cam.target = vec3From(c.at("target"));
      cam.fovYDeg = c.value("fovYDeg", cam.fovYDeg);
      cam.nearM = c.value("nearM", cam.nearM);
      cam.farM = c.value("farM", cam.farM);
      if (auto err = cam.validate()) throw std::runtime_error(*err);
      p.camera = cam;
    }
    if (j.contains("light")) {
      DirectionalLight l;
      l.azimuthDeg = j["light"].value("azimuthDeg", l.azimuthDeg);
      l.elevationDeg = j["light"].value("elevationDeg", l.elevationDeg);
      if (auto err = l.validate()) throw std::runtime_error(*err);
      p.light = l;
    }
    return p;
  } catch (const std::exception& e) {
    if (error) *error = path.string() + ": " + e.what();
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
  if (p.light)
    j["light"] = {{"azimuthDeg", p.light->azimuthDeg}, {"elevationDeg", p.light->elevationDeg}};
  return j.dump(2);
}

}  // namespace sl
