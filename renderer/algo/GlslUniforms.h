// The names of the `uniform` variables a GLSL source declares, read from its preprocessed
// text (plain string processing, no GL): gl::Program refuses to set a name its sources do
// not declare, so a misspelled uniform is an error instead of a silent no-op.
#pragma once

#include <set>
#include <string>
#include <string_view>

namespace sl {

/// Every name declared with the `uniform` storage qualifier (with or without a layout
/// qualifier, arrays by their base name, several declarators per statement), comments
/// ignored. Uniform blocks contribute their member names. Preprocessor conditionals are
/// not evaluated: a declaration inside #if 0 still counts (the check stays lenient).
std::set<std::string> declaredUniforms(std::string_view source);

/// The base name of a uniform location name: "u_weights[3]" -> "u_weights".
std::string_view uniformBaseName(std::string_view name);

}  // namespace sl
