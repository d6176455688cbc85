// Data folders: environment, installed layout beside the program, or the source tree.
#include "scene/DataDir.h"

#include <string>
#include <system_error>

#ifndef SHADOWLAB_DATA_SUBDIR
#define SHADOWLAB_DATA_SUBDIR "share/shadowlab"
#endif

namespace sl {

std::filesystem::path resolveDataDir(std::string_view sub, std::string_view envValue,
                                     const std::filesystem::path& exeDir,
                                     std::string_view dataSubdir,
                                     const std::filesystem::path& compiledIn) {
  namespace fs = std::filesystem;
  if (!envValue.empty()) return fs::path(std::string(envValue));
  if (!exeDir.empty()) {
    const fs::path installed =
        (exeDir / ".." / fs::path(std::string(dataSubdir)) / fs::path(std::string(sub)))
            .lexically_normal();
    std::error_code ec;
    if (fs::is_directory(installed, ec)) return installed;
  }
  return compiledIn;
}

std::filesystem::path executableDir() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec || exe.empty()) return {};
  return exe.parent_path();
}

std::filesystem::path dataDir(std::string_view sub, const char* envValue,
                              const std::filesystem::path& compiledIn) {
  return resolveDataDir(sub, envValue ? std::string_view(envValue) : std::string_view(),
                        executableDir(), SHADOWLAB_DATA_SUBDIR, compiledIn);
}

}  // namespace sl
