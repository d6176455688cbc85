// The omni family's declarations (OmniDeclarations.h).
#include "OmniDeclarations.h"

#include <algorithm>

#include "core/Publish.h"
#include "core/ShadowPass.h"

namespace sl {

namespace {
const glm::dvec3 kAxes[3] = {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}};
}  // namespace

ParamDecl omniAxisParamDecl(std::string key, std::string label, std::string group,
                            std::string help) {
  return choiceParam(std::move(key), std::move(label), std::move(group), {"y", "x", "z"})
      .withHelp(std::move(help));
}

glm::dvec3 omniAxisOf(const ParamSet& params, const std::string& key) {
  return kAxes[std::clamp(params.getInt(key), 0, 2)];
}

PublicationDecl omniMapsPublicationDecl(std::string key, std::string what, std::string cost,
                                        int mapsPerFrame) {
  return {std::move(key), PublicationKind::ImageSet, std::move(what), std::move(cost),
          [mapsPerFrame](const ParamSet& ps) {
            const int r = ps.getInt("resolution");
            return publishedImageBytes(r, r) * std::uint64_t(mapsPerFrame);
          }};
}

std::function<std::optional<std::string>(const ParamSet&)> omniMapsCheck(int layers,
                                                                         std::string what) {
  return [layers, what = std::move(what)](const ParamSet& ps) {
    return DepthMapArray::sizeError(int(ps.getInt("resolution")), layers, what, "resolution");
  };
}

}  // namespace sl
