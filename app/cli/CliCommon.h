// What every shadowlab-cli command shares: argument parsing helpers, the "bad input" error
// (one line on stderr, exit 2), scene/camera/light lookup, output files (checked before the
// work, written atomically) and a terminal progress bar.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "algo/Camera.h"
#include "measure/SceneCameras.h"
#include "measure/UsageError.h"
#include "algo/OutputFile.h"
#include "metrics/Image.h"
#include "scene/Scene.h"

namespace sl::cli {

/// The commands are the measuring library's front end: its names (ConfigSpec, ConfigRunner,
/// runInterleaved, ...) read here as the commands' own.
using namespace sl::measure;

/// Bad input: one line on stderr naming the option or file and the problem, exit 2.
using sl::measure::UsageError;

struct Args {
  std::vector<std::string> rest;
  /// The value after option `opt` at rest[i] (advances i). A value that starts with `--`
  /// is the next option, not a value (`--scene --size 64x36`): an error naming `opt`.
  std::string take(std::size_t& i, const std::string& opt) {
    if (i + 1 >= rest.size()) throw UsageError(opt + ": missing value");
    if (rest[i + 1].rfind("--", 0) == 0)
      throw UsageError(opt + ": missing value (got the option '" + rest[i + 1] + "')");
    return rest[++i];
  }
};

int parseInt(const std::string& opt, const std::string& text, int lo, int hi);
double parseDouble(const std::string& opt, const std::string& text, double lo, double hi);
std::pair<int, int> parseSize(const std::string& text);  ///< "WxH" for --size
/// A --path-hz value (`opt` names it): a number in 0..kMaxPathHz (measure/Measure.h), else
/// UsageError.
double parsePathHz(const std::string& opt, const std::string& text);
/// Refuses a frame larger than this OpenGL implementation renders (Renderer::checkFrameSize):
/// UsageError naming --size and the limit. Needs a current GL context.
void checkFrameSize(int width, int height);
/// Memory a frame pixel costs a measuring command, all copies together (G-buffer and resolve
/// targets, their read-backs, the reference's mask): render --size 8192x8193 took 7.7 GB,
/// ~115 bytes a pixel.
inline constexpr std::uint64_t kBytesPerFramePixel = 115;
/// The frame memory a command may take by that estimate (~37 M pixels, 8192x4608).
inline constexpr std::uint64_t kMaxFrameBytes = std::uint64_t(4) << 30;
/// "WxH needs about X GiB ...: over the limit" when width x height exceeds kMaxFrameBytes by
/// the estimate, else nothing (checkFrameSize and suites check it after the GL limits, before
/// any frame).
std::optional<std::string> frameMemoryError(int width, int height);
/// A --light value, validated: "dir:AZ,EL" or "AZ,EL" (directional, degrees),
/// "point:X,Y,Z[,RANGE]", "spot:X,Y,Z,DX,DY,DZ,OUTER_DEG[,INNER_DEG[,RANGE]]" (metres,
/// degrees; range 0 = infinite). UsageError naming the bad field.
Light parseLight(const std::string& opt, const std::string& text);
/// The --light syntax, for usage texts.
inline constexpr const char* kLightSyntax =
    "dir:AZ,EL | point:X,Y,Z[,RANGE] | spot:X,Y,Z,DX,DY,DZ,OUTER[,INNER[,RANGE]]";

/// Loads a scene (UsageError on failure) and prints each of the loader's warnings on
/// stderr as "warning: FILE: ..." (once per call: load a scene once per command).
std::shared_ptr<Scene> loadScene(const std::string& nameOrPath);
/// An output file of a command and the option that names it ("--csv"); `userNamed` false for
/// a file the command names itself in an output folder (algo/OutputFile.h: only a regular
/// file or none is replaced there). The policy is algo/OutputFile.h's, shared with the GUI.
using OutputFile = sl::OutputTarget;
/// Output paths, checked before the work starts so that no result is lost at the end:
/// UsageError (exit 2) naming the option(s) when two outputs (or an output and one of
/// `inputs`) are the same file, an output is a folder, a FIFO or device where only a regular
/// file may be, or its folder cannot be created or takes no new file (a probe file is created
/// and removed). Creates missing folders.
void checkOutputs(const std::vector<OutputFile>& outputs,
                  const std::vector<sl::InputTarget>& inputs = {});
/// After the scene loaded: UsageError naming the option when an output is one of the files
/// the scene read (its file, buffers and images: Scene::inputFiles).
void checkOutputsAgainstScene(const std::vector<OutputFile>& outputs, const Scene& scene);
/// A folder that will receive outputs (compare --out-dir): created, and probed as above.
void checkOutputFolder(const std::string& option, const std::string& folder);

/// Writes `target` atomically (sl::writeOutputAtomically: a temporary file in the same folder,
/// renamed into place; a device or FIFO the user named written in place). `write` returns an
/// error or nothing. Any failure throws std::runtime_error (exit 1) naming the path; no
/// partial file is left behind. A plain path is a file the user named.
void writeAtomically(const OutputFile& target,
                     const std::function<std::optional<std::string>(const std::string&)>& write);
/// Writes `bytes` to `path` (created or truncated), every write, flush and close checked; an
/// error naming `path` ("p: cannot write (No space left on device)") or nothing.
std::optional<std::string> writeFile(const std::string& path, const std::string& bytes);
/// Text (plus a newline) and PNG through writeAtomically (parent folders are created).
void writeText(const OutputFile& target, const std::string& text);
void writePng(const OutputFile& target, const ImageRGBA8& img);
/// The same for a file the user named (`--csv PATH`).
inline void writeAtomically(
    const std::string& path,
    const std::function<std::optional<std::string>(const std::string&)>& write) {
  writeAtomically(OutputFile{path, path}, write);
}
inline void writeText(const std::string& path, const std::string& text) {
  writeText(OutputFile{path, path}, text);
}
inline void writePng(const std::string& path, const ImageRGBA8& img) {
  writePng(OutputFile{path, path}, img);
}

/// Seconds as "m:ss" (or "h:mm:ss").
std::string formatDuration(double seconds);

/// A progress bar on stderr with the time left. On a terminal one line redrawn in place;
/// otherwise (logs, CI) a plain line whenever a frame completes, at most every 2 s.
class ProgressBar {
 public:
  ProgressBar(std::string what, std::size_t totalSteps);
  /// One step done; `frameDone` marks the last step of a frame (for plain-line mode).
  void step(const std::string& detail, bool frameDone);
  void finish();  ///< final line (elapsed time)

 private:
  void draw(const std::string& detail, bool force);
  std::string what_;
  std::size_t total_ = 0, done_ = 0;
  bool tty_ = false;
  std::chrono::steady_clock::time_point start_, lastPlain_;
};

}  // namespace sl::cli
