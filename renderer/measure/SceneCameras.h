// A scene's camera bookmarks and camera paths picked by name or index, as the CLI's --camera
// and --path name them and suites and claims do: what a measurement renders from.
#pragma once

#include <string>

#include "algo/Camera.h"
#include "scene/Scene.h"

namespace sl::measure {

/// A camera bookmark by name or index; empty: the first bookmark (or a framing camera).
Camera pickCamera(const Scene& scene, const std::string& which,
                  const std::string& opt = "--camera");
/// A camera path by name or index; empty: the first path. Throws UsageError naming the
/// scene's paths when there is none such.
const CameraPath& pickPath(const Scene& scene, const std::string& which);

}  // namespace sl::measure
