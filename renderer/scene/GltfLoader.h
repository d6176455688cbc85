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

/// Directory of the built-in scenes given the value of the SHADOWLAB_SCENE_DIR env var (null
/// or empty: unset): scene/DataDir.h's order, that value, else share/shadowlab/scenes beside
/// the program, else the compiled-in source path.
std::filesystem::path builtinSceneDir(const char* environmentValue);
/// builtinSceneDir(getenv("SHADOWLAB_SCENE_DIR")).
std::filesystem::path builtinSceneDir();
/// Names of the built-in scenes (file stems of `dir`/*.gltf|glb), sorted.
std::vector<std::string> builtinSceneNames(const std::filesystem::path& dir = builtinSceneDir());
/// A built-in name ("plane-box", looked up in `sceneDir`) or a file path -> loaded scene.
SceneLoadResult loadSceneByNameOrPath(const std::string& nameOrPath,
                                      const std::filesystem::path& sceneDir = builtinSceneDir());

}  // namespace sl
