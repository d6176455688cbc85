// Writing outputs without losing anything: the one policy of every writer (the command line's
// files, the GUI's --grab, image exports and sessions, reproduce's report). Before the work:
// no output is an input of the run or another output (symbolic links, ".." and hard links
// resolved), none is a folder, and its folder takes a new file. Writing: into a temporary file
// beside the output's resolved path, then renamed over it, so a failure leaves the old file
// whole and nothing half-written. A FIFO or device is written only where the user named that
// exact file (`--metrics /dev/null`); a file the program names itself in an output folder
// must be a regular file or none.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sl {

/// An output and what names it in messages ("--csv", "--grab (viewport.png)").
struct OutputTarget {
  std::string name;
  std::string path;
  /// The user named this exact file: an existing device or FIFO (with a reader) is written in
  /// place. False for a file the program names in an output folder: only a regular file (or
  /// none) is replaced there.
  bool userNamed = true;
};

/// An input of the run that no output may replace ("--scene", "the session").
struct InputTarget {
  std::string name;
  std::string path;
};

/// The same file for two paths, whether or not they exist yet: symbolic links and ".."
/// resolved, hard links compared by identity.
bool sameFile(const std::string& a, const std::string& b);

/// Creates `folder` when missing and checks that it takes a new file (a probe file is created
/// and removed): "cannot create the folder 'F' (why)", "cannot write in the folder 'F' (why)",
/// or nothing.
std::optional<std::string> probeOutputFolder(const std::filesystem::path& folder);

/// True for a FIFO that no process reads now: opening it for writing would block forever.
bool fifoWithoutReader(const std::string& path);

/// Checks outputs before the work: the first problem as one line naming the output
/// ("--chart: 'a.png' is the same file as --csv (one would overwrite the other)", "... is the
/// same file as --scene (the input would be overwritten)", "... is a folder", "... is a FIFO,
/// not a regular file: refused ...", a folder that cannot be made or written), or nothing.
/// Creates missing folders.
std::optional<std::string> checkOutputTargets(const std::vector<OutputTarget>& outputs,
                                              const std::vector<InputTarget>& inputs = {});

/// Writes `bytes` to `path` (created or truncated), every write, flush and close checked:
/// "P: cannot write (No space left on device)" or nothing.
std::optional<std::string> writeFileBytes(const std::string& path, std::string_view bytes);

/// Writes `target` atomically: `write` fills a temporary file (created here, empty, same
/// extension) in the folder of the target's resolved path, which is then renamed over it. An
/// existing device or FIFO is written in place only when `target.userNamed` (a FIFO only
/// while something reads it), else refused. `write` returns an error or nothing. The error
/// names the target ("P: cannot write (...)"); no temporary file is left behind.
std::optional<std::string> writeOutputAtomically(
    const OutputTarget& target,
    const std::function<std::optional<std::string>(const std::string&)>& write);

}  // namespace sl
