// The output policy of every writer (algo/OutputFile.h): inputs and other outputs refused
// with symbolic links and ".." resolved, no FIFO or device where the program names the file,
// a FIFO the user named refused only while nothing reads it, writes through a temporary file
// renamed over the target (a link's target replaced, the link kept), nothing left on failure.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

#include "algo/OutputFile.h"

namespace fs = std::filesystem;

namespace {

fs::path outDir(const char* name) {
  fs::path dir = fs::path(SHADOWLAB_TEST_OUT) / "output-file" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void writeText(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

std::string readText(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

/// `text` written to the target through writeOutputAtomically; its error or "".
std::string writeThrough(const sl::OutputTarget& target, const std::string& text) {
  auto e = sl::writeOutputAtomically(
      target, [&](const std::string& tmp) { return sl::writeFileBytes(tmp, text); });
  return e.value_or("");
}

bool leftovers(const fs::path& dir) {
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().find(".tmp") != std::string::npos) return true;
  return false;
}

}  // namespace

TEST(OutputFile, SameFileResolvesLinksDotsAndHardLinks) {
  const fs::path d = outDir("same");
  writeText(d / "in.json", "{}");
  fs::create_symlink(d / "in.json", d / "link.json");
  ASSERT_EQ(::link((d / "in.json").c_str(), (d / "hard.json").c_str()), 0);
  EXPECT_TRUE(sl::sameFile((d / "in.json").string(), (d / "link.json").string()));
  EXPECT_TRUE(sl::sameFile((d / "in.json").string(), (d / "hard.json").string()));
  EXPECT_TRUE(sl::sameFile((d / "in.json").string(), (d / "sub" / ".." / "in.json").string()));
  EXPECT_FALSE(sl::sameFile((d / "in.json").string(), (d / "other.json").string()));
}

TEST(OutputFile, InputsAndOtherOutputsAreRefusedNamed) {
  const fs::path d = outDir("inputs");
  writeText(d / "session.json", "{}");
  fs::create_symlink(d / "session.json", d / "viewport.png");
  const std::vector<sl::InputTarget> inputs = {{"the session", (d / "session.json").string()}};
  // An output that is a link to an input: resolved, refused.
  auto e = sl::checkOutputTargets({{"viewport.png", (d / "viewport.png").string(), false}}, inputs);
  ASSERT_TRUE(e);
  EXPECT_NE(e->find("is the same file as the session (the input would be overwritten)"),
            std::string::npos)
      << *e;
  e = sl::checkOutputTargets(
      {{"--csv", (d / "a.csv").string()}, {"--chart", (d / "." / "a.csv").string()}});
  ASSERT_TRUE(e);
  EXPECT_NE(e->find("is the same file as --csv (one would overwrite the other)"),
            std::string::npos);
  e = sl::checkOutputTargets({{"--out", d.string()}});
  ASSERT_TRUE(e);
  EXPECT_EQ(*e, "--out: '" + d.string() + "' is a folder");
  EXPECT_FALSE(sl::checkOutputTargets({{"--csv", (d / "new" / "b.csv").string()}}, inputs));
  EXPECT_TRUE(fs::is_directory(d / "new")) << "missing folders are created";
  EXPECT_EQ(readText(d / "session.json"), "{}");
}

TEST(OutputFile, FifosAndDevicesOnlyWhereTheUserNamedThem) {
  const fs::path d = outDir("special");
  const fs::path fifo = d / "published.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // A file the program names in its folder: a FIFO or device is refused, at once.
  auto e = sl::checkOutputTargets({{"published.json", fifo.string(), false}});
  ASSERT_TRUE(e);
  EXPECT_NE(e->find("is a FIFO, not a regular file: refused"), std::string::npos) << *e;
  e = sl::checkOutputTargets({{"null", "/dev/null", false}});
  ASSERT_TRUE(e);
  EXPECT_NE(e->find("is a character device, not a regular file"), std::string::npos) << *e;
  EXPECT_NE(writeThrough({"published.json", fifo.string(), false}, "x").find("is a FIFO"),
            std::string::npos);
  EXPECT_TRUE(fs::is_fifo(fifo)) << "the FIFO is neither written nor replaced";
  // A file the user named: a device is written in place, a FIFO refused while nothing reads.
  EXPECT_FALSE(sl::checkOutputTargets({{"--metrics", "/dev/null"}}));
  EXPECT_EQ(writeThrough({"--metrics", "/dev/null"}, "x"), "");
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  e = sl::checkOutputTargets({{"--metrics", fifo.string()}});
  ASSERT_TRUE(e);
  EXPECT_NE(e->find("is a FIFO that nothing reads"), std::string::npos) << *e;
}

TEST(OutputFile, WritesReplaceTheLinkTargetWholeAndLeaveNothingOnFailure) {
  const fs::path d = outDir("write");
  fs::create_directories(d / "elsewhere");
  writeText(d / "elsewhere" / "target.json", "old");
  fs::create_symlink(d / "elsewhere" / "target.json", d / "out.json");
  EXPECT_EQ(writeThrough({"--json", (d / "out.json").string()}, "new"), "");
  EXPECT_TRUE(fs::is_symlink(d / "out.json")) << "the link stays a link";
  EXPECT_EQ(readText(d / "elsewhere" / "target.json"), "new");
  EXPECT_FALSE(leftovers(d) || leftovers(d / "elsewhere"));
  // A writer that fails: the old file whole, no temporary file, the error names the target.
  writeText(d / "keep.json", "keep");
  const std::string target = (d / "keep.json").string();
  auto e = sl::writeOutputAtomically({"--json", target}, [](const std::string& tmp) {
    sl::writeFileBytes(tmp, "half");
    return std::optional<std::string>(tmp + ": cannot encode");
  });
  ASSERT_TRUE(e);
  EXPECT_EQ(*e, target + ": cannot encode");
  EXPECT_EQ(readText(d / "keep.json"), "keep");
  EXPECT_FALSE(leftovers(d));
}
