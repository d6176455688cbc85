// Parameters reach shaders from their declaration: a ParamDecl names its uniform, and one
// function binds every declared parameter of a ParamSet to a program. No hand-written
// key -> uniform chains for such parameters.
#pragma once

#include <optional>
#include <span>
#include <string>

#include "algo/Params.h"
#include "gl/ShaderLibrary.h"

namespace sl {

/// Sets, for every parameter of `params` whose ParamDecl names a uniform that `program`
/// declares, that uniform to the current value (float for Float, int otherwise).
/// Returns how many were set.
int bindParams(const gl::Program& program, const ParamSet& params);

/// An error naming each declared uniform (ParamDecl::uniform) that none of `programs`
/// declares: a misspelling that would otherwise leave the parameter without effect.
std::optional<std::string> checkParamUniforms(std::span<const ParamDecl> decls,
                                              std::span<const gl::Program* const> programs);

}  // namespace sl
