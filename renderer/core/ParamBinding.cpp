// Binding declared parameters to programs (see ParamBinding.h).
#include "core/ParamBinding.h"

namespace sl {

int bindParams(const gl::Program& program, const ParamSet& params) {
  int bound = 0;
  for (const ParamDecl& d : params.decls()) {
    if (d.uniform.empty() || !program.declares(d.uniform)) continue;
    const double v = params.get(d.key);
    if (d.type == ParamType::Float)
      program.set(d.uniform.c_str(), float(v));
    else
      program.set(d.uniform.c_str(), int(v));
    ++bound;
  }
  return bound;
}

std::optional<std::string> checkParamUniforms(std::span<const ParamDecl> decls,
                                              std::span<const gl::Program* const> programs) {
  std::string errors;
  for (const ParamDecl& d : decls) {
    if (d.uniform.empty()) continue;
    bool found = false;
    for (const gl::Program* p : programs) found = found || (p && *p && p->declares(d.uniform));
    if (found) continue;
    std::string names;
    for (const gl::Program* p : programs)
      if (p) names += (names.empty() ? "" : ", ") + p->name();
    errors += std::string(errors.empty() ? "" : "; ") + "parameter '" + d.key + "' sets uniform '" +
              d.uniform + "', which none of its programs declares (" + names + ")";
  }
  if (errors.empty()) return std::nullopt;
  return errors;
}

}  // namespace sl
