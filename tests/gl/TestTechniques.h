// Techniques that live only in tests (RendererOptions::extraTechniques): they prove the
// lookup contract for several maps ("uniform-array2x2") and for a deferred resolve
// ("uniform-deferred"), and that misspelled uniforms and parameter keys fail
// ("typo-uniform", "typo-key").
#pragma once

#include <memory>
#include <vector>

#include "core/Renderer.h"

namespace sl::test {

/// uniform as a 2x2 texture array of sub-maps (resolution / 2 each), each with its own
/// matrix covering a quarter of the light frustum, selected by light uv.
TechniqueEntry array2x2Technique();
/// uniform resolved in the technique's own compute pass (ResolveMode::Deferred).
TechniqueEntry deferredUniformTechnique();
/// uniform plus a parameter whose ParamDecl names the uniform "u_biasSlpoe".
TechniqueEntry typoUniformTechnique();
/// uniform whose renderShadows reads the parameter "resolutoin".
TechniqueEntry typoKeyTechnique();

/// uniform whose lookup reads every texel as the far plane: everything lit ("test-all-lit"),
/// wrong on purpose (a claim measured on it is not reproduced).
TechniqueEntry allLitTechnique();

/// uniform that logs every frame it renders shadows for ("test-count"): which instance (one
/// per renderer) and the camera's position, in the order they ran (countedFrames()).
TechniqueEntry countingTechnique();
struct CountedFrame {
  const void* instance;
  glm::vec3 cameraPosition;
};
std::vector<CountedFrame>& countedFrames();

/// A renderer offering the four test techniques, with a built-in scene and its first camera.
std::unique_ptr<Renderer> makeTestRenderer(const std::string& scene, const std::string& technique);

}  // namespace sl::test
