// Where the programs find their data (scene/DataDir.h): the environment, else an installed
// tree beside the program (wherever it was moved), else the source tree of the build.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "scene/DataDir.h"

namespace fs = std::filesystem;

namespace {

struct TempTree {
  fs::path root;
  TempTree() {
    root =
        fs::temp_directory_path() /
        ("shadowlab-datadir-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
         "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root);
    fs::create_directories(root);
  }
  ~TempTree() {
    std::error_code ec;
    fs::remove_all(root, ec);
  }
};

}  // namespace

TEST(DataDir, TheEnvironmentWinsOverEverything) {
  TempTree t;
  fs::create_directories(t.root / "prefix/share/shadowlab/shaders");
  EXPECT_EQ(sl::resolveDataDir("shaders", "/dev/shaders", t.root / "prefix/bin", "share/shadowlab",
                               "/src/shaders"),
            fs::path("/dev/shaders"));
}

TEST(DataDir, AnInstalledTreeIsFoundBesideTheProgramWhereverItWasMoved) {
  TempTree t;
  for (const char* where : {"first", "moved/elsewhere"}) {
    const fs::path prefix = t.root / where;
    fs::create_directories(prefix / "bin");
    fs::create_directories(prefix / "share/shadowlab/scenes");
    EXPECT_EQ(sl::resolveDataDir("scenes", "", prefix / "bin", "share/shadowlab", "/src/scenes"),
              (prefix / "share/shadowlab/scenes").lexically_normal())
        << where;
  }
}

TEST(DataDir, ABuildTreeFallsBackToTheSourceTree) {
  TempTree t;
  fs::create_directories(t.root / "build/app");
  // No share/shadowlab beside the program: the compiled-in source path.
  EXPECT_EQ(
      sl::resolveDataDir("shaders", "", t.root / "build/app", "share/shadowlab", "/src/shaders"),
      fs::path("/src/shaders"));
  // A file where the folder would be is not a data folder.
  fs::create_directories(t.root / "build/share/shadowlab");
  std::ofstream(t.root / "build/share/shadowlab/shaders") << "not a folder";
  EXPECT_EQ(
      sl::resolveDataDir("shaders", "", t.root / "build/app", "share/shadowlab", "/src/shaders"),
      fs::path("/src/shaders"));
  // An unknown program folder (no /proc): the source tree too.
  EXPECT_EQ(sl::resolveDataDir("shaders", "", fs::path(), "share/shadowlab", "/src/shaders"),
            fs::path("/src/shaders"));
}

TEST(DataDir, TheRunningProgramsFolderIsKnown) {
  const fs::path dir = sl::executableDir();
  ASSERT_FALSE(dir.empty());
  EXPECT_TRUE(fs::is_directory(dir)) << dir;
}
