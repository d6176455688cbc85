// The shared input-file limits (algo/InputFile.h) used by the glTF loader, the preset and
// suite readers and `chart`: only regular files, a size cap, JSON depth by a byte scan.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include <sys/stat.h>

#include "algo/InputFile.h"

namespace fs = std::filesystem;

namespace {

fs::path outDir() {
  fs::path dir = fs::path(SHADOWLAB_TEST_OUT) / "input-file";
  fs::create_directories(dir);
  return dir;
}

void writeFile(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

/// The message of the InputFileError that reading `p` throws ("" if none).
std::string readError(const fs::path& p, std::uint64_t maxBytes) {
  try {
    sl::readRegularFile(p, maxBytes, "kTestLimit");
  } catch (const sl::InputFileError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(InputFile, ReadsARegularFileWithinTheLimit) {
  const fs::path p = outDir() / "small.txt";
  writeFile(p, "hello");
  const std::vector<unsigned char> bytes = sl::readRegularFile(p, 5, "kTestLimit");
  EXPECT_EQ(std::string(bytes.begin(), bytes.end()), "hello");
}

TEST(InputFile, RefusesAFileOverTheLimitNamingIt) {
  const fs::path p = outDir() / "big.txt";
  writeFile(p, std::string(3u << 20, 'x'));
  EXPECT_EQ(readError(p, 2u << 20),
            "is 3145728 bytes, over the limit of 2 MiB per file (kTestLimit)");
  EXPECT_EQ(readError(p, 100),
            "is 3145728 bytes, over the limit of 100 bytes per file (kTestLimit)");
}

TEST(InputFile, RefusesDevicesFifosAndDirectories) {
  if (fs::exists("/dev/zero")) {
    EXPECT_EQ(readError("/dev/zero", 1 << 20),
              "is a character device, not a regular file: refused (only regular files are read)");
  }
  const fs::path fifo = outDir() / "pipe";
  fs::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // Opened non-blocking: no writer, and still no hang.
  EXPECT_EQ(readError(fifo, 1 << 20),
            "is a FIFO, not a regular file: refused (only regular files are read)");
  EXPECT_EQ(readError(outDir(), 1 << 20),
            "is a directory, not a regular file: refused (only regular files are read)");
  EXPECT_EQ(readError(outDir() / "missing.json", 1 << 20), "file not found");
}

TEST(InputFile, JsonDepthCountsBracketsOutsideStrings) {
  EXPECT_EQ(sl::jsonDepthExcess("[[1]]", 2), std::string_view::npos);
  EXPECT_EQ(sl::jsonDepthExcess("[[[1]]]", 2), 2u);
  EXPECT_EQ(sl::jsonDepthExcess(R"({"a":{"b":[]}})", 2), 10u);
  // Brackets in strings, escaped quotes included, do not count.
  EXPECT_EQ(sl::jsonDepthExcess(R"(["[[[[", "\"[[[["])", 1), std::string_view::npos);
  // Siblings do not add up.
  EXPECT_EQ(sl::jsonDepthExcess("[[],[],[[]]]", 3), std::string_view::npos);
  // A million levels: found without recursion.
  const std::string deep(1000000, '[');
  EXPECT_EQ(sl::jsonDepthExcess(deep, 256), 256u);
}

TEST(InputFile, JsonDepthSkipsCommentsOnlyWhenAsked) {
  // A quote in a comment must not hide the brackets after it.
  const std::string hidden = "/* \" */ [[[1]]]";
  EXPECT_EQ(sl::jsonDepthExcess(hidden, 2, true), 10u);
  EXPECT_EQ(sl::jsonDepthExcess("// \"\n[[[1]]]", 2, true), 7u);
  EXPECT_EQ(sl::jsonDepthExcess("// [[[[\n[1]", 2, true), std::string_view::npos);
  EXPECT_EQ(sl::jsonDepthExcess("/* [[[[ */ [1]", 2, true), std::string_view::npos);
  // Without comments (glTF), "//" is just bytes.
  EXPECT_EQ(sl::jsonDepthExcess("// [[[", 2), 5u);
}
