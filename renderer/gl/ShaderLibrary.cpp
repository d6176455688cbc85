#include "ShaderLibrary.h"

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <regex>
#include <set>
#include <sstream>

#include <glm/gtc/type_ptr.hpp>

#include "algo/GlslUniforms.h"
#include "algo/InputFile.h"
#include "scene/DataDir.h"

#ifndef SHADOWLAB_SHADER_DIR
#define SHADOWLAB_SHADER_DIR "shaders"
#endif

namespace sl::gl {

namespace {

/// A shader file: a regular file of at most kMaxShaderFileBytes (the shader folder may come
/// from SHADOWLAB_SHADER_DIR: no FIFO, device or endless file is read).
std::string readFile(const std::filesystem::path& path) {
  try {
    const std::vector<unsigned char> bytes =
        readRegularFile(path, kMaxShaderFileBytes, "kMaxShaderFileBytes");
    return std::string(bytes.begin(), bytes.end());
  } catch (const InputFileError& e) {
    throw ShaderError(cutText(path.string(), kMaxQuotedPathBytes) + ": " + e.what());
  }
}

/// The file named by an `#include "FILE"` line (spaces around allowed), or nothing for any
/// other line. No regular expression: a line of any length is one linear scan.
std::optional<std::string> includedName(const std::string& line) {
  std::size_t i = line.find_first_not_of(" \t");
  if (i == std::string::npos || line[i] != '#') return std::nullopt;
  i = line.find_first_not_of(" \t", i + 1);
  if (i == std::string::npos || line.compare(i, 7, "include") != 0) return std::nullopt;
  i = line.find_first_not_of(" \t", i + 7);
  if (i == std::string::npos || line[i] != '"') return std::nullopt;
  const std::size_t close = line.find('"', i + 1);
  if (close == std::string::npos || line.find_first_not_of(" \t\r", close + 1) != std::string::npos)
    return std::nullopt;
  return line.substr(i + 1, close - i - 1);
}

/// The file an `#include` in a shader's text names, inside the shader folder `root`:
/// ShaderError unless it is a relative path of at most kMaxShaderIncludeBytes that stays
/// inside `root` once symbolic links and ".." are resolved.
std::string checkedInclude(const std::filesystem::path& root, const std::string& including,
                           const std::string& name) {
  const std::string where = "shaders/" + cutText(including, kMaxQuotedPathBytes) + ": #include \"" +
                            cutText(name, kMaxQuotedPathBytes) + "\"";
  if (name.empty() || name.size() > kMaxShaderIncludeBytes)
    throw ShaderError(where + ": a file name of 1.." + std::to_string(kMaxShaderIncludeBytes) +
                      " bytes expected (kMaxShaderIncludeBytes)");
  const std::filesystem::path rel(name);
  std::error_code ec;
  const std::filesystem::path base = std::filesystem::weakly_canonical(root, ec);
  const std::filesystem::path full = std::filesystem::weakly_canonical(root / rel, ec);
  const auto [endBase, endFull] = std::mismatch(base.begin(), base.end(), full.begin(), full.end());
  if (rel.is_absolute() || ec || endBase != base.end() || endFull == full.end())
    throw ShaderError(where + ": outside the shader folder " +
                      cutText(root.string(), kMaxQuotedPathBytes) +
                      " (includes are relative to it and stay inside)");
  return name;
}

std::string stageName(GLenum stage) {
  switch (stage) {
    case GL_VERTEX_SHADER:
      return "vertex";
    case GL_FRAGMENT_SHADER:
      return "fragment";
    case GL_COMPUTE_SHADER:
      return "compute";
    case GL_TESS_CONTROL_SHADER:
      return "tessellation control";
    case GL_TESS_EVALUATION_SHADER:
      return "tessellation evaluation";
    case GL_GEOMETRY_SHADER:
      return "geometry";
    default:
      return "shader";
  }
}

// Mesa reports "S:L(C): error: ..." where S is the source-string number we set with
// #line; NVIDIA reports "S(L) : error ...". Rewrite both to "file:L: ...".
std::string mapLog(const std::string& log, const std::vector<std::string>& files) {
  static const std::regex mesa(R"(^(\d+):(\d+)\((\d+)\):\s*(.*)$)");
  static const std::regex nv(R"(^(\d+)\((\d+)\)\s*:\s*(.*)$)");
  std::istringstream in(log);
  std::string line, out;
  while (std::getline(in, line)) {
    line = cutText(line, kMaxMessageBytes);  // a log quoting a huge token: bounded, and the
                                             // regular expressions below recurse per byte
    std::smatch m;
    if (std::regex_match(line, m, mesa) || std::regex_match(line, m, nv)) {
      size_t idx = std::stoul(m[1]);
      std::string file = idx < files.size() ? files[idx] : "?";
      std::string rest = m.size() == 5 ? m[4].str() : m[3].str();
      out += "shaders/" + file + ":" + m[2].str() + ": " + rest + "\n";
    } else if (!line.empty()) {
      out += line + "\n";
    }
  }
  while (!out.empty() && out.back() == '\n') out.pop_back();
  return out;
}

void expand(const std::filesystem::path& root, const std::string& file, const ProgramDesc& desc,
            std::vector<std::string>& files, std::set<std::string>& included, std::string& out,
            int depth) {
  if (depth > kMaxShaderIncludeDepth)
    throw ShaderError("shaders/" + cutText(file, kMaxQuotedPathBytes) +
                      ": #include nesting deeper than " + std::to_string(kMaxShaderIncludeDepth) +
                      " (kMaxShaderIncludeDepth)");
  std::string resolved = file;
  if (!resolved.empty() && resolved[0] == '@') {
    auto it = desc.aliases.find(resolved);
    if (it == desc.aliases.end())
      throw ShaderError("program '" + desc.name + "': no file given for include alias " + file);
    resolved = it->second;
  }
  if (included.count(resolved)) return;
  included.insert(resolved);
  std::string text = readFile(root / resolved);
  int index = int(files.size());
  files.push_back(resolved);
  out += "#line 1 " + std::to_string(index) + "\n";
  std::istringstream in(text);
  std::string line;
  int lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    if (std::optional<std::string> name = includedName(line)) {
      // An alias ("@lookup") is the program's choice (C++); a file named in the text must
      // stay inside the shader folder.
      if ((*name)[0] != '@') *name = checkedInclude(root, resolved, *name);
      expand(root, *name, desc, files, included, out, depth + 1);
      out += "#line " + std::to_string(lineNo + 1) + " " + std::to_string(index) + "\n";
    } else if (line.rfind("#version", 0) == 0) {
      out += "\n";  // the library writes the version line
    } else {
      out += line + "\n";
    }
  }
}

}  // namespace

ShaderLibrary::ShaderLibrary(std::filesystem::path root) : root_(std::move(root)) {}

std::filesystem::path ShaderLibrary::defaultRoot() {
  return dataDir("shaders", std::getenv("SHADOWLAB_SHADER_DIR"), SHADOWLAB_SHADER_DIR);
}

std::string ShaderLibrary::preprocess(const std::string& file, const ProgramDesc& desc,
                                      std::vector<std::string>& files) const {
  std::string out = "#version 450 core\n";
  for (const std::string& d : desc.defines) out += "#define " + d + "\n";
  std::set<std::string> included;
  expand(root_, file, desc, files, included, out, 0);
  return out;
}

GLuint ShaderLibrary::build(const ProgramDesc& desc, std::set<std::string>* uniforms) const {
  std::vector<GLuint> shaders;
  auto cleanup = [&] {
    for (GLuint s : shaders) glDeleteShader(s);
  };
  for (const auto& [stage, file] : desc.stages) {
    std::vector<std::string> files;
    std::string src;
    try {
      src = preprocess(file, desc, files);
    } catch (...) {
      cleanup();
      throw;
    }
    if (uniforms) uniforms->merge(declaredUniforms(src));
    GLuint sh = glCreateShader(stage);
    shaders.push_back(sh);
    const char* p = src.c_str();
    glShaderSource(sh, 1, &p, nullptr);
    glCompileShader(sh);
    GLint ok = 0;
    glGetShaderiv(sh, GL_COMPILE_STATUS, &ok);
    if (!ok) {
      GLint len = 0;
      glGetShaderiv(sh, GL_INFO_LOG_LENGTH, &len);
      std::string log(size_t(std::max(len, 1)), '\0');
      glGetShaderInfoLog(sh, len, nullptr, log.data());
      cleanup();
      throw ShaderError("program '" + desc.name + "', " + stageName(stage) +
                        " shader failed to compile:\n" + mapLog(log.c_str(), files));
    }
  }
  GLuint prog = glCreateProgram();
  for (GLuint s : shaders) glAttachShader(prog, s);
  glLinkProgram(prog);
  cleanup();
  GLint ok = 0;
  glGetProgramiv(prog, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetProgramiv(prog, GL_INFO_LOG_LENGTH, &len);
    std::string log(size_t(std::max(len, 1)), '\0');
    glGetProgramInfoLog(prog, len, nullptr, log.data());
    glDeleteProgram(prog);
    throw ShaderError("program '" + desc.name + "' failed to link: " + std::string(log.c_str()));
  }
  return prog;
}

Program::Program(const ShaderLibrary& lib, ProgramDesc desc) : desc_(std::move(desc)) {
  std::set<std::string> names;
  h_ = Handle<ProgramDeleter>(lib.build(desc_, &names));
  uniforms_ = {names.begin(), names.end()};
}

std::optional<std::string> Program::rebuild(const ShaderLibrary& lib) {
  try {
    std::set<std::string> names;
    h_ = Handle<ProgramDeleter>(lib.build(desc_, &names));
    uniforms_ = {names.begin(), names.end()};
    locations_.clear();
    return std::nullopt;
  } catch (const ShaderError& e) {
    return std::string(e.what());
  }
}

bool Program::declares(std::string_view name) const {
  return uniforms_.count(uniformBaseName(name)) > 0;
}

GLint Program::location(const char* name) const {
  auto it = locations_.find(name);
  if (it != locations_.end()) return it->second;
  if (!declares(name)) {
    std::string known;
    for (const std::string& u : uniforms_) known += (known.empty() ? "" : ", ") + u;
    throw UnknownUniformError("program '" + desc_.name + "' declares no uniform '" +
                              std::string(name) + "' (declared: " + known + ")");
  }
  GLint loc = glGetUniformLocation(h_.id(), name);
  locations_.emplace(name, loc);
  return loc;
}

void Program::set(const char* n, int v) const {
  glProgramUniform1i(id(), location(n), v);
}
void Program::set(const char* n, unsigned v) const {
  glProgramUniform1ui(id(), location(n), v);
}
void Program::set(const char* n, float v) const {
  glProgramUniform1f(id(), location(n), v);
}
void Program::set(const char* n, const glm::vec2& v) const {
  glProgramUniform2fv(id(), location(n), 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::vec3& v) const {
  glProgramUniform3fv(id(), location(n), 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::vec4& v) const {
  glProgramUniform4fv(id(), location(n), 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::ivec2& v) const {
  glProgramUniform2iv(id(), location(n), 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::mat4& v) const {
  glProgramUniformMatrix4fv(id(), location(n), 1, GL_FALSE, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::mat2& v) const {
  glProgramUniformMatrix2fv(id(), location(n), 1, GL_FALSE, glm::value_ptr(v));
}

void Program::set(const char* n, const glm::mat3& v) const {
  glProgramUniformMatrix3fv(id(), location(n), 1, GL_FALSE, glm::value_ptr(v));
}

}  // namespace sl::gl
