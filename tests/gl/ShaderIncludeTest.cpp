// A hostile shader folder (SHADOWLAB_SHADER_DIR names any folder): gl::ShaderLibrary keeps
// every #include inside the folder, bounded in length and depth, and reads only regular files
// of at most kMaxShaderFileBytes (tests/fixtures/hostile/shader-dir; a 100 KB #include line
// crashed the regular expression that read it, #include "/dev/zero" grew without bound).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <sys/stat.h>

#include "gl/ShaderLibrary.h"

namespace sl {
namespace {

namespace fs = std::filesystem;

const fs::path kFixture =
    fs::path(SHADOWLAB_TEST_DATA) / ".." / "fixtures" / "hostile" / "shader-dir";

/// preprocess()'s ShaderError for `file` under `root` ("" when it preprocesses).
std::string preprocessError(const fs::path& root, const std::string& file) {
  const gl::ShaderLibrary lib(root);
  std::vector<std::string> files;
  try {
    lib.preprocess(file, gl::ProgramDesc{"test", {}, {}, {}}, files);
  } catch (const gl::ShaderError& e) {
    return e.what();
  }
  return "";
}

fs::path scratch(const char* name) {
  const fs::path dir = fs::path(SHADOWLAB_TEST_OUT) / "gl" / "shader-include" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(ShaderInclude, IncludesInsideTheFolderArePreprocessed) {
  EXPECT_EQ(preprocessError(kFixture, "main.glsl"), "");
}

TEST(ShaderInclude, IncludesLeavingTheFolderAreRefused) {
  for (const char* file : {"outside.glsl", "dotdot.glsl", "dev-zero.glsl"}) {
    const std::string e = preprocessError(kFixture, file);
    EXPECT_NE(e.find(std::string("shaders/") + file + ": #include \""), std::string::npos) << e;
    EXPECT_NE(e.find("outside the shader folder"), std::string::npos) << file << ": " << e;
  }
  // A link inside the folder to a device outside it: resolved, refused (not read).
  const fs::path root = scratch("link");
  fs::create_symlink("/dev/zero", root / "zero.glsl");
  std::ofstream(root / "main.glsl") << "#include \"zero.glsl\"\n";
  EXPECT_NE(preprocessError(root, "main.glsl").find("outside the shader folder"),
            std::string::npos);
}

TEST(ShaderInclude, LongIncludeLinesDeepNestingAndLargeFilesAreRefused) {
  const fs::path root = scratch("bounds");
  // A 100 KB #include line: one linear scan, refused by its length.
  std::ofstream(root / "long.glsl") << "#include \"" << std::string(100000, 'a') << "\"\n";
  const std::string longLine = preprocessError(root, "long.glsl");
  EXPECT_NE(longLine.find("kMaxShaderIncludeBytes"), std::string::npos) << longLine;
  EXPECT_LT(longLine.size(), 400u) << "the message quotes the name cut";
  // A chain of includes one deeper than kMaxShaderIncludeDepth.
  for (int i = 0; i <= gl::kMaxShaderIncludeDepth + 1; ++i)
    std::ofstream(root / ("d" + std::to_string(i) + ".glsl"))
        << "#include \"d" << i + 1 << ".glsl\"\n";
  std::ofstream(root / ("d" + std::to_string(gl::kMaxShaderIncludeDepth + 2) + ".glsl")) << "\n";
  EXPECT_NE(preprocessError(root, "d0.glsl").find("kMaxShaderIncludeDepth"), std::string::npos);
  EXPECT_EQ(preprocessError(root, "d2.glsl"), "") << "a chain of the limit's depth is read";
  // A file over kMaxShaderFileBytes, and a FIFO: not read.
  std::ofstream(root / "big.glsl") << std::string(gl::kMaxShaderFileBytes + 1, ' ');
  EXPECT_NE(preprocessError(root, "big.glsl").find("kMaxShaderFileBytes"), std::string::npos);
  ASSERT_EQ(::mkfifo((root / "pipe.glsl").c_str(), 0600), 0);
  EXPECT_NE(preprocessError(root, "pipe.glsl").find("is a FIFO, not a regular file"),
            std::string::npos);
}

}  // namespace
}  // namespace sl
