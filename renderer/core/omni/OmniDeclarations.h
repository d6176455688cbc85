// The omni family's declarations (`cube`, `dual-paraboloid`, `spherical`), made once: the
// axis parameter of a map's frame, the publication of its maps, the size check of its depth
// map array. No GL.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "core/Technique.h"

namespace sl {

/// An omni map's axis parameter (Enum y, x, z), the pole or split axis of its frame.
ParamDecl omniAxisParamDecl(std::string key, std::string label, std::string group,
                            std::string help);
/// The world axis (unit) `params` holds for omniAxisParamDecl's `key`.
glm::dvec3 omniAxisOf(const ParamSet& params, const std::string& key);
/// The publication of an omni technique's maps, `mapsPerFrame` images of `resolution`^2 at most
/// (`key` a pattern, "face.*.map"): `cost` is its formula for the UI.
PublicationDecl omniMapsPublicationDecl(std::string key, std::string what, std::string cost,
                                        int mapsPerFrame);
/// TechniqueInfo::checkParams of `layers` maps of `resolution`^2 in one depth map array
/// (`what` names them: "cube: up to 6 faces").
std::function<std::optional<std::string>(const ParamSet&)> omniMapsCheck(int layers,
                                                                         std::string what);

}  // namespace sl
