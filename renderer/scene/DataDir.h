// Where the programs find their data (shaders, built-in scenes and lessons): an environment
// variable for development, else beside the program in an installed or moved tree, else the
// source tree the build came from. No GL, no Qt.
#pragma once

#include <filesystem>
#include <string_view>

namespace sl {

/// The data folder `sub` ("shaders", "scenes"), in this order:
///  1. `envValue` when it is non-empty (SHADOWLAB_SHADER_DIR / SHADOWLAB_SCENE_DIR: shader
///     hot-reload from a source tree);
///  2. `exeDir`/../`dataSubdir`/`sub` when that is a folder (an installed tree: bin/ beside
///     share/shadowlab/, wherever the tree was moved);
///  3. `compiledIn` (a build tree: the source folder it was configured from).
/// Pure: reads nothing but the file system's answer to "is this a folder".
std::filesystem::path resolveDataDir(std::string_view sub, std::string_view envValue,
                                     const std::filesystem::path& exeDir,
                                     std::string_view dataSubdir,
                                     const std::filesystem::path& compiledIn);

/// The folder of the running program (/proc/self/exe), or empty when it cannot be read.
std::filesystem::path executableDir();

/// resolveDataDir for this program: `envValue` (the environment variable's value; null or
/// empty: unset), executableDir() and the install layout this build was configured with.
std::filesystem::path dataDir(std::string_view sub, const char* envValue,
                              const std::filesystem::path& compiledIn);

}  // namespace sl
