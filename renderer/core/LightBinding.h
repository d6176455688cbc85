// Binds the frame's light (sl::Light) to the uniforms of shaders/common/light.glsl: the one
// place C++ sets them, used by the resolve, composite and RTW importance passes.
#pragma once

#include "algo/Light.h"
#include "gl/ShaderLibrary.h"

namespace sl {

/// Sets u_lightType, u_lightTowards, u_lightPosition, u_lightAxis, u_lightCosOuter,
/// u_lightCosInner and u_lightRange on `program` (glProgramUniform: it need not be in use).
void bindLight(const gl::Program& program, const Light& light);

}  // namespace sl
