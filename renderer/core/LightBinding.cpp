// bindLight: sl::Light -> the uniforms of shaders/common/light.glsl.
#include "core/LightBinding.h"

#include <cmath>

namespace sl {

void bindLight(const gl::Program& program, const Light& light) {
  program.set("u_lightType", int(light.type));
  program.set("u_lightTowards", light.directionalTowards());
  program.set("u_lightPosition", light.positionM);
  program.set("u_lightAxis", light.spotAxis());
  program.set("u_lightCosOuter", std::cos(glm::radians(light.outerConeDeg)));
  program.set("u_lightCosInner", std::cos(glm::radians(light.innerConeDeg)));
  program.set("u_lightRange", light.rangeM);
}

}  // namespace sl
