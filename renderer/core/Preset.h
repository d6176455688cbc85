// JSON presets (and lessons): scene, technique, parameters, camera and light in one file.
// The same parameter declarations validate them as the UI and the command line.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "algo/Camera.h"
#include "algo/Light.h"

namespace sl {

struct Preset {
  std::string title;
  std::string explanation;  ///< what to look at (lessons)
  std::string scene;        ///< built-in name or path
  std::string technique;
  std::map<std::string, std::string> params;  ///< key -> value text (validated on apply)
  std::optional<Camera> camera;
  std::optional<Light> light;  ///< core/LightJson: {"type", ...}
};

/// Reads a preset; the error names the file and the problem.
std::optional<Preset> loadPreset(const std::filesystem::path& path, std::string* error);
std::string presetToJson(const Preset& preset);

}  // namespace sl
