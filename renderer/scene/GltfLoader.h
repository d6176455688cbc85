// glTF 2.0 (.gltf and .glb) loading through tinygltf, flattened into a Scene.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "Scene.h"

namespace sl {

struct SceneLoadResult {
  std::shared_ptr<Scene> scene;  ///< null on failure
  std::string error;             ///< one line naming the file and what is wrong
  explicit operator bool() const { return scene != nullptr; }
};

/// Loads a .gltf or .glb file. Never throws; on failure `error` names the file and
/// the problem (missing, malformed, truncated, no triangles, NaN/inf positions,
/// unsupported required extension "X", ...).
SceneLoadResult loadGltf(const std::filesystem::path& path);

/// Directory of the built-in scenes (scene/DataDir.h: SHADOWLAB_SCENE_DIR env var, else
/// share/shadowlab/scenes beside the program, else the compiled-in source path).
std::filesystem::path builtinSceneDir();
/// Names of the built-in scenes (file stems of scenes/*.gltf|glb), sorted.
std::vector<std::string> builtinSceneNames();
/// A built-in name ("plane-box") or a file path -> loaded scene.
SceneLoadResult loadSceneByNameOrPath(const std::string& nameOrPath);

}  // namespace sl
