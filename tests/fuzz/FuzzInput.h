// Shared by the libFuzzer targets: the readers under test take file paths, so each input is
// written to a file in this process's own temporary folder; and every refusal must be a
// message a user can act on (one line, naming the file, bounded), or the target aborts.
#pragma once

#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace sl::fuzz {

/// This process's folder for inputs (tmpfs when there is one), removed at exit.
inline const std::filesystem::path& inputDir() {
  static const std::filesystem::path dir = [] {
    std::error_code ec;
    std::filesystem::path base = std::filesystem::is_directory("/dev/shm", ec)
                                     ? std::filesystem::path("/dev/shm")
                                     : std::filesystem::temp_directory_path();
    std::filesystem::path d = base / ("shadowlab-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    std::atexit([] {
      std::error_code e;
      std::filesystem::remove_all(inputDir(), e);
    });
    return d;
  }();
  return dir;
}

/// Writes the input to inputDir()/name and returns the path.
inline std::filesystem::path writeInput(const std::uint8_t* data, std::size_t size,
                                        const std::string& name) {
  const std::filesystem::path path = inputDir() / name;
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), std::streamsize(size));
  return path;
}

/// A refusal as the user sees it: one line, starting with `prefix` (the file's name), at
/// most `maxBytes` long. Anything else is a finding: print it and abort.
inline void checkMessage(std::string_view message, std::string_view prefix,
                         std::size_t maxBytes = 1024) {
  const char* wrong = nullptr;
  if (message.find('\n') != std::string_view::npos)
    wrong = "more than one line";
  else if (message.substr(0, prefix.size()) != prefix)
    wrong = "does not start with the file's name";
  else if (message.size() > maxBytes)
    wrong = "too long";
  if (!wrong) return;
  std::fprintf(stderr, "shadowlab fuzz: bad message (%s, %zu bytes): %.*s\n", wrong, message.size(),
               int(std::min<std::size_t>(message.size(), 2000)), message.data());
  std::abort();
}

}  // namespace sl::fuzz
