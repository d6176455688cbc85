// The light object of JSON presets and suites, read in one place: {"type": "directional" |
// "spot" | "point", ...}; without "type", the directional form both files always had.
// Presets name keys in camelCase (azimuthDeg), suites in snake_case (azimuth_deg).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "algo/Light.h"
#include "core/JsonInput.h"

namespace sl {

enum class JsonKeyStyle { CamelCase, SnakeCase };

/// Reads a light object at `path`. Keys (camelCase / snake_case):
///   type                          "directional" (default), "spot", "point"
///   azimuthDeg / azimuth_deg      directional; elevationDeg / elevation_deg
///   position                      spot, point: [x, y, z] metres (required)
///   direction                     spot: [x, y, z] the axis it shines along (required)
///   outerConeDeg / outer_cone_deg spot: half-angle, default 45
///   innerConeDeg / inner_cone_deg spot: default 0
///   rangeM / range_m              spot, point: metres, 0 (default) = infinite
/// `requireAngles`: a directional light must give both angles (suites); otherwise missing
/// ones keep Light's defaults (presets). Throws JsonInputError naming the bad field.
Light readLightJson(const JsonReader& r, const nlohmann::json& l, const std::string& path,
                    JsonKeyStyle style, bool requireAngles);

/// The light as JSON in the same form (directional: just the two angles, as before).
nlohmann::json lightToJson(const Light& light, JsonKeyStyle style);

}  // namespace sl
