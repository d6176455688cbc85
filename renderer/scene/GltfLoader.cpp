// glTF 2.0 loading through tinygltf 2.7: parse (.gltf or .glb) within the limits against
// hostile files (gltf/Hardening), read accessors (gltf/Accessors), and flatten the node
// hierarchy into world-space triangle lists, materials, images, the light
// (KHR_lights_punctual), camera bookmarks and camera paths (gltf/Flattener).
// Spec: https://registry.khronos.org/glTF/specs/2.0/
#include "GltfLoader.h"

#include <algorithm>
#include <cstdlib>
#include <new>

#include "algo/InputFile.h"
#include "scene/DataDir.h"
#include "scene/gltf/Flattener.h"
#include "scene/gltf/Hardening.h"

namespace sl {
namespace {

namespace fs = std::filesystem;
using namespace gltf;

std::shared_ptr<Scene> loadOrFail(const fs::path& path) {
  ParsedGltf parsed = parseWithinLimits(path);
  auto scene = std::make_shared<Scene>();
  scene->name = path.stem().string();
  scene->sourcePath = path.string();
  scene->inputFiles.push_back(path.string());
  for (const std::string& f : parsed.externalFiles) scene->inputFiles.push_back(f);
  addLines(scene->warnings, parsed.warnings);
  Flattener(parsed.model, *scene).run();
  return scene;
}

bool hasGltfExtension(const fs::path& p) {
  std::string ext = lowerExtension(p);
  return ext == ".gltf" || ext == ".glb";
}

}  // namespace

SceneLoadResult loadGltf(const std::filesystem::path& path) {
  SceneLoadResult result;
  try {
    result.scene = loadOrFail(path);
  } catch (const LoadFailure& f) {
    result.error = path.string() + ": " + cutText(oneLine(f.message));
  } catch (const std::bad_alloc&) {
    result.error = path.string() + ": out of memory while loading";
  } catch (const std::exception& e) {
    result.error = path.string() + ": " + cutText(oneLine(e.what()));
  } catch (...) {
    result.error = path.string() + ": unknown error while loading";
  }
  if (!result.error.empty()) result.scene.reset();
  return result;
}

std::filesystem::path builtinSceneDir(const char* environmentValue) {
#ifdef SHADOWLAB_SCENE_DIR
  return dataDir("scenes", environmentValue, SHADOWLAB_SCENE_DIR);
#else
  return dataDir("scenes", environmentValue, "scenes");
#endif
}

std::filesystem::path builtinSceneDir() {
  return builtinSceneDir(std::getenv("SHADOWLAB_SCENE_DIR"));
}

std::vector<std::string> builtinSceneNames(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code fileEc;
    if (it->is_regular_file(fileEc) && hasGltfExtension(it->path()))
      names.push_back(it->path().stem().string());
  }
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

SceneLoadResult loadSceneByNameOrPath(const std::string& nameOrPath,
                                      const std::filesystem::path& sceneDir) {
  const fs::path asPath(nameOrPath);
  const bool looksLikePath = hasGltfExtension(asPath) ||
                             nameOrPath.find('/') != std::string::npos ||
                             nameOrPath.find('\\') != std::string::npos;
  if (looksLikePath) return loadGltf(asPath);

  if (!nameOrPath.empty()) {
    for (const char* ext : {".gltf", ".glb"}) {
      fs::path candidate = sceneDir / (nameOrPath + ext);
      std::error_code ec;
      if (fs::is_regular_file(candidate, ec)) {
        SceneLoadResult result = loadGltf(candidate);
        if (result) result.scene->name = nameOrPath;
        return result;
      }
    }
    std::error_code ec;
    if (fs::exists(asPath, ec)) return loadGltf(asPath);  // e.g. a file without extension
  }

  std::vector<std::string> names = builtinSceneNames(sceneDir);
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  SceneLoadResult result;
  result.error = "unknown scene '" + nameOrPath + "': not a built-in scene (" +
                 (list.empty() ? "none found in " + sceneDir.string() : list) +
                 ") nor a .gltf/.glb file";
  return result;
}

}  // namespace sl
