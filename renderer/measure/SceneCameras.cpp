// Camera bookmarks and paths by name or index; see SceneCameras.h.
#include "measure/SceneCameras.h"

#include "measure/UsageError.h"

namespace sl::measure {

Camera pickCamera(const Scene& scene, const std::string& which, const std::string& opt) {
  if (which.empty()) return scene.cameras.empty() ? scene.defaultCamera() : scene.cameras[0].camera;
  for (const auto& b : scene.cameras)
    if (b.name == which) return b.camera;
  try {
    std::size_t used = 0;
    std::size_t idx = std::stoul(which, &used);
    if (used == which.size() && idx < scene.cameras.size()) return scene.cameras[idx].camera;
  } catch (...) {
  }
  std::string known;
  for (const auto& b : scene.cameras) known += (known.empty() ? "" : ", ") + b.name;
  throw UsageError(opt + ": scene '" + scene.name + "' has no camera '" + which +
                   "' (cameras: " + (known.empty() ? "none" : known) + ")");
}

const CameraPath& pickPath(const Scene& scene, const std::string& which) {
  if (which.empty() && !scene.paths.empty()) return scene.paths.front();
  for (const auto& p : scene.paths)
    if (p.name == which) return p;
  try {
    std::size_t used = 0;
    std::size_t idx = std::stoul(which, &used);
    if (used == which.size() && idx < scene.paths.size()) return scene.paths[idx];
  } catch (...) {
  }
  std::string known;
  for (const auto& p : scene.paths) known += (known.empty() ? "" : ", ") + p.name;
  throw UsageError("--path: scene '" + scene.name + "' has no camera path '" + which +
                   "' (paths: " + (known.empty() ? "none" : known) + ")");
}

}  // namespace sl::measure
