// readLightJson / lightToJson: the one reader and writer of the light object of presets
// and suites (LightJson.h).
#include "core/LightJson.h"

namespace sl {

namespace {

using nlohmann::json;

struct Keys {
  const char *azimuth, *elevation, *outer, *inner, *range;
};
Keys keysFor(JsonKeyStyle style) {
  if (style == JsonKeyStyle::CamelCase)
    return {"azimuthDeg", "elevationDeg", "outerConeDeg", "innerConeDeg", "rangeM"};
  return {"azimuth_deg", "elevation_deg", "outer_cone_deg", "inner_cone_deg", "range_m"};
}

glm::vec3 vec3At(const JsonReader& r, const json& v, const std::string& path) {
  if (!v.is_array() || v.size() != 3) r.expected(v, path, "[x, y, z]");
  return {float(r.number(v[0], jsonPath(path, 0))), float(r.number(v[1], jsonPath(path, 1))),
          float(r.number(v[2], jsonPath(path, 2)))};
}

}  // namespace

Light readLightJson(const JsonReader& r, const json& l, const std::string& path, JsonKeyStyle style,
                    bool requireAngles) {
  const Keys k = keysFor(style);
  r.requireObject(l, path);
  Light light;
  std::string typeName = "directional";
  if (const json* t = JsonReader::member(l, "type")) {
    typeName = r.string(*t, jsonPath(path, "type"));
    auto type = lightTypeFromName(typeName);
    if (!type)
      r.fail(jsonPath(path, "type"),
             "expected \"directional\", \"spot\" or \"point\", got " + quoteJson(*t));
    light.type = *type;
  }
  switch (light.type) {
    case LightType::Directional:
      r.onlyKeys(l, path, {"type", k.azimuth, k.elevation});
      if (requireAngles && (!l.contains(k.azimuth) || !l.contains(k.elevation)))
        r.expected(l, path, std::string("{\"") + k.azimuth + "\": A, \"" + k.elevation + "\": E}");
      light.azimuthDeg = float(r.number(l, path, k.azimuth, light.azimuthDeg));
      light.elevationDeg = float(r.number(l, path, k.elevation, light.elevationDeg));
      break;
    case LightType::Spot:
    case LightType::Point: {
      const bool spot = light.type == LightType::Spot;
      if (spot)
        r.onlyKeys(l, path, {"type", "position", "direction", k.outer, k.inner, k.range});
      else
        r.onlyKeys(l, path, {"type", "position", k.range});
      const json* pos = JsonReader::member(l, "position");
      if (!pos) r.fail(path, "a " + typeName + " light needs \"position\": [x, y, z]");
      light.positionM = vec3At(r, *pos, jsonPath(path, "position"));
      if (spot) {
        const json* dir = JsonReader::member(l, "direction");
        if (!dir) r.fail(path, "a spot light needs \"direction\": [x, y, z]");
        light.direction = vec3At(r, *dir, jsonPath(path, "direction"));
        light.outerConeDeg = float(r.number(l, path, k.outer, light.outerConeDeg));
        light.innerConeDeg = float(r.number(l, path, k.inner, light.innerConeDeg));
      }
      light.rangeM = float(r.number(l, path, k.range, light.rangeM));
      break;
    }
  }
  if (auto e = light.validate()) r.fail(path, *e);
  return light;
}

json lightToJson(const Light& light, JsonKeyStyle style) {
  const Keys k = keysFor(style);
  if (light.type == LightType::Directional)
    return {{k.azimuth, light.azimuthDeg}, {k.elevation, light.elevationDeg}};
  json j = {{"type", std::string(lightTypeName(light.type))},
            {"position", {light.positionM.x, light.positionM.y, light.positionM.z}},
            {k.range, light.rangeM}};
  if (light.type == LightType::Spot) {
    j["direction"] = {light.direction.x, light.direction.y, light.direction.z};
    j[k.outer] = light.outerConeDeg;
    j[k.inner] = light.innerConeDeg;
  }
  return j;
}

}  // namespace sl
