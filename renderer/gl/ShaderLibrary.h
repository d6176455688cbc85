// GLSL programs built from files in shaders/, with `#include "dir/file.glsl"` support
// (paths relative to the shader root; each file included once per program) and aliases
// (`#include "@lookup"` resolves to a file chosen by the technique). A compile or link
// error names the file and line; a failed rebuild keeps the last good program in use.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl/Gl.h"

namespace sl::gl {

struct ProgramDesc {
  std::string name;                                    ///< for messages, e.g. "uniform/depth"
  std::vector<std::pair<GLenum, std::string>> stages;  ///< stage -> file (relative)
  std::map<std::string, std::string> aliases;          ///< "@lookup" -> "uniform/lookup.glsl"
  std::vector<std::string> defines;                    ///< "NAME" or "NAME VALUE"
};

class ShaderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ShaderLibrary {
 public:
  explicit ShaderLibrary(std::filesystem::path root);
  const std::filesystem::path& root() const { return root_; }
  /// Default root: SHADOWLAB_SHADER_DIR env var, else the compiled-in source path.
  static std::filesystem::path defaultRoot();
  /// Preprocessed source of one stage (for tests and error messages).
  std::string preprocess(const std::string& file, const ProgramDesc& desc,
                         std::vector<std::string>& fileTable) const;
  /// Compiles and links; throws ShaderError("file:line: message") on failure.
  GLuint build(const ProgramDesc& desc) const;

 private:
  std::filesystem::path root_;
};

/// A program that can be rebuilt in place (hot reload) and sets uniforms by name.
class Program {
 public:
  Program() = default;
  Program(const ShaderLibrary& lib, ProgramDesc desc);  ///< throws ShaderError
  GLuint id() const { return h_.id(); }
  explicit operator bool() const { return bool(h_); }
  /// Rebuilds from the files; on failure keeps the previous program and returns the error.
  std::optional<std::string> rebuild(const ShaderLibrary& lib);
  void use() const { glUseProgram(h_.id()); }

  GLint location(const char* name) const;
  void set(const char* name, int v) const;
  void set(const char* name, unsigned v) const;
  void set(const char* name, float v) const;
  void set(const char* name, const glm::vec2& v) const;
  void set(const char* name, const glm::vec3& v) const;
  void set(const char* name, const glm::vec4& v) const;
  void set(const char* name, const glm::ivec2& v) const;
  void set(const char* name, const glm::mat4& v) const;
  void set(const char* name, const glm::mat2& v) const;
  void set(const char* name, const glm::mat3& v) const;

 private:
  Handle<ProgramDeleter> h_;
  ProgramDesc desc_;
  mutable std::map<std::string, GLint, std::less<>> locations_;
};

}  // namespace sl::gl
