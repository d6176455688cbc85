// GLSL programs built from files in shaders/, with `#include "dir/file.glsl"` support
// (paths relative to the shader root, or absolute: tests keep their own techniques'
// shaders next to them; each file included once per program) and aliases
// (`#include "@lookup"` resolves to a file chosen by the technique). A compile or link
// error names the file and line; a failed rebuild keeps the last good program in use.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <set>
#include <string>
#include <string_view>
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

/// The shader folder is an input (SHADOWLAB_SHADER_DIR may name any folder): a shader file is
/// a regular file of at most kMaxShaderFileBytes; an `#include "FILE"` in a shader's text
/// names a relative path of at most kMaxShaderIncludeBytes inside the folder, nested at most
/// kMaxShaderIncludeDepth deep. Anything else is a ShaderError naming the file.
inline constexpr std::uint64_t kMaxShaderFileBytes = std::uint64_t(1) << 20;
inline constexpr std::size_t kMaxShaderIncludeBytes = 256;
inline constexpr int kMaxShaderIncludeDepth = 16;
/// A path quoted in a shader error is cut to this many bytes.
inline constexpr std::size_t kMaxQuotedPathBytes = 120;

class ShaderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ShaderLibrary {
 public:
  explicit ShaderLibrary(std::filesystem::path root);
  const std::filesystem::path& root() const { return root_; }
  /// Default root (scene/DataDir.h): SHADOWLAB_SHADER_DIR env var, else
  /// share/shadowlab/shaders beside the program, else the compiled-in source path.
  static std::filesystem::path defaultRoot();
  /// Preprocessed source of one stage (for tests and error messages).
  std::string preprocess(const std::string& file, const ProgramDesc& desc,
                         std::vector<std::string>& fileTable) const;
  /// Compiles and links; throws ShaderError("file:line: message") on failure. When
  /// `uniforms` is given, it receives every uniform name the preprocessed sources declare.
  GLuint build(const ProgramDesc& desc, std::set<std::string>* uniforms = nullptr) const;

 private:
  std::filesystem::path root_;
};

/// Set on a uniform name that none of a program's (preprocessed) sources declares: a
/// misspelling, or a parameter bound to the wrong program. A declared uniform that the
/// compiler optimised out is fine (the set is a no-op).
class UnknownUniformError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

/// A program that can be rebuilt in place (hot reload) and sets uniforms by name. Every
/// set() checks the name against the uniforms its sources declare (UnknownUniformError).
class Program {
 public:
  Program() = default;
  Program(const ShaderLibrary& lib, ProgramDesc desc);  ///< throws ShaderError
  GLuint id() const { return h_.id(); }
  explicit operator bool() const { return bool(h_); }
  /// Rebuilds from the files; on failure keeps the previous program and returns the error.
  std::optional<std::string> rebuild(const ShaderLibrary& lib);
  void use() const { glUseProgram(h_.id()); }

  /// The location of a declared uniform (-1 when optimised out); UnknownUniformError when
  /// no source declares it. "name[i]" addresses an array element.
  GLint location(const char* name) const;
  /// Whether the program's sources declare `name` (arrays by base name).
  bool declares(std::string_view name) const;
  const std::string& name() const { return desc_.name; }
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
  std::set<std::string, std::less<>> uniforms_;  ///< declared in the sources
};

}  // namespace sl::gl
