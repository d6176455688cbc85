// Numbers that are not finite in JSON outputs. JSON has no infinity or NaN, and both nlohmann
// and Qt write them as null, which reads as "not measured". A published number that is not
// finite is written as the string "inf", "-inf" or "nan" instead: `warp.n_prime` is "inf"
// when a perspective warp falls back to the orthographic map (n' infinite).
#pragma once

#include <cmath>

#include <nlohmann/json.hpp>

namespace sl {

/// "inf", "-inf" or "nan" for a value that is not finite; nullptr for a finite one.
inline const char* nonFiniteName(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return nullptr;
}

/// `v` as a JSON number, or as the string nonFiniteName(v) when it is not finite.
inline nlohmann::json jsonNumber(double v) {
  if (const char* name = nonFiniteName(v)) return name;
  return v;
}

}  // namespace sl
