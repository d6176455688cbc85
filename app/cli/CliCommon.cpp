// Shared helpers of the shadowlab-cli commands; see CliCommon.h.
#include "CliCommon.h"
#include "algo/InputFile.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "core/JsonInput.h"
#include "core/Renderer.h"
#include "scene/GltfLoader.h"

namespace fs = std::filesystem;

namespace sl::cli {

int parseInt(const std::string& opt, const std::string& text, int lo, int hi) {
  try {
    std::size_t used = 0;
    int v = std::stoi(text, &used);
    if (used != text.size()) throw std::invalid_argument(text);
    if (v < lo || v > hi)
      throw UsageError(opt + ": " + text + " is out of range " + std::to_string(lo) + ".." +
                       std::to_string(hi));
    return v;
  } catch (const UsageError&) {
    throw;
  } catch (const std::exception&) {
    throw UsageError(opt + ": expected an integer, got '" + quoteText(text) + "'");
  }
}

double parseDouble(const std::string& opt, const std::string& text, double lo, double hi) {
  try {
    std::size_t used = 0;
    double v = std::stod(text, &used);
    if (used != text.size() || !std::isfinite(v)) throw std::invalid_argument(text);
    if (v < lo || v > hi) {
      char range[96];
      std::snprintf(range, sizeof range, " is out of range %g..%g", lo, hi);
      throw UsageError(opt + ": " + quoteText(text) + range);
    }
    return v;
  } catch (const UsageError&) {
    throw;
  } catch (const std::exception&) {
    throw UsageError(opt + ": expected a number, got '" + quoteText(text) + "'");
  }
}

std::pair<int, int> parseSize(const std::string& text) {
  auto x = text.find('x');
  if (x == std::string::npos)
    throw UsageError("--size: expected WxH, got '" + quoteText(text) + "'");
  // The real limit is the GL implementation's (checkFrameSize, once a context exists).
  return {parseInt("--size", text.substr(0, x), 1, 1 << 16),
          parseInt("--size", text.substr(x + 1), 1, 1 << 16)};
}

std::optional<std::string> frameMemoryError(int width, int height) {
  const std::uint64_t bytes = std::uint64_t(width) * std::uint64_t(height) * kBytesPerFramePixel;
  if (bytes <= kMaxFrameBytes) return std::nullopt;
  char gib[32];
  std::snprintf(gib, sizeof gib, "%.1f", double(bytes) / double(1u << 30));
  return std::to_string(width) + "x" + std::to_string(height) + " needs about " + gib + " GiB (~" +
         std::to_string(kBytesPerFramePixel) +
         " bytes a pixel: G-buffer, resolve targets, read-backs, reference): over the limit of " +
         sl::byteLimitText(kMaxFrameBytes) + " (kMaxFrameBytes)";
}

void checkFrameSize(int width, int height) {
  if (auto e = Renderer::checkFrameSize(width, height)) throw UsageError("--size: " + *e);
  if (auto e = frameMemoryError(width, height)) throw UsageError("--size: " + *e);
}

Light parseLight(const std::string& opt, const std::string& v) {
  std::string kind = "dir", rest = v;
  if (auto colon = v.find(':'); colon != std::string::npos) {
    kind = v.substr(0, colon);
    rest = v.substr(colon + 1);
  }
  std::vector<std::string> f;
  for (std::size_t start = 0;;) {
    const std::size_t comma = rest.find(',', start);
    f.push_back(rest.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  auto num = [&](std::size_t i, const char* field) {
    return float(parseDouble(opt + " (" + kind + " " + field + ")", f[i], -1e6, 1e6));
  };
  Light l;
  if (kind == "dir" || kind == "directional") {
    if (f.size() != 2)
      throw UsageError(opt + ": expected [dir:]AZIMUTH,ELEVATION in degrees, got '" + v + "'");
    l = Light::directional(num(0, "azimuth"), num(1, "elevation"));
  } else if (kind == "point") {
    if (f.size() != 3 && f.size() != 4)
      throw UsageError(opt + ": expected point:X,Y,Z[,RANGE] (metres), got '" + v + "'");
    l = Light::point({num(0, "x"), num(1, "y"), num(2, "z")},
                     f.size() > 3 ? num(3, "range") : 0.0f);
  } else if (kind == "spot") {
    if (f.size() < 7 || f.size() > 9)
      throw UsageError(opt + ": expected spot:X,Y,Z,DX,DY,DZ,OUTER_DEG[,INNER_DEG[,RANGE]], got '" +
                       v + "'");
    l = Light::spot({num(0, "x"), num(1, "y"), num(2, "z")},
                    {num(3, "direction x"), num(4, "direction y"), num(5, "direction z")},
                    num(6, "outer cone"), f.size() > 7 ? num(7, "inner cone") : 0.0f,
                    f.size() > 8 ? num(8, "range") : 0.0f);
  } else {
    throw UsageError(opt + ": unknown light kind '" + kind + "' (" + kLightSyntax + ")");
  }
  if (auto e = l.validate()) throw UsageError(opt + ": " + *e);
  return l;
}

std::shared_ptr<Scene> loadScene(const std::string& nameOrPath) {
  SceneLoadResult r = loadSceneByNameOrPath(nameOrPath);
  if (!r) throw UsageError(r.error);
  // The loader's notes (a texture that failed to load, a primitive skipped): once per load.
  const std::string file = r.scene->sourcePath.empty() ? nameOrPath : r.scene->sourcePath;
  for (const std::string& w : r.scene->warnings)
    std::fprintf(stderr, "warning: %s: %s\n", file.c_str(), w.c_str());
  return r.scene;
}

Camera pickCamera(const Scene& scene, const std::string& which, const std::string& opt) {
  if (which.empty()) return scene.cameras.empty() ? scene.defaultCamera() : scene.cameras[0].camera;
  for (const auto& b : scene.cameras)
    if (b.name == which) return b.camera;
  try {
    std::size_t used = 0;
    std::size_t idx = std::stoul(which, &used);
    if (used == which.size() && idx < scene.cameras.size()) return scene.cameras[idx].camera;
  } catch (...) {
  }
  std::string known;
  for (const auto& b : scene.cameras) known += (known.empty() ? "" : ", ") + b.name;
  throw UsageError(opt + ": scene '" + scene.name + "' has no camera '" + which +
                   "' (cameras: " + (known.empty() ? "none" : known) + ")");
}

const CameraPath& pickPath(const Scene& scene, const std::string& which) {
  if (which.empty() && !scene.paths.empty()) return scene.paths.front();
  for (const auto& p : scene.paths)
    if (p.name == which) return p;
  try {
    std::size_t used = 0;
    std::size_t idx = std::stoul(which, &used);
    if (used == which.size() && idx < scene.paths.size()) return scene.paths[idx];
  } catch (...) {
  }
  std::string known;
  for (const auto& p : scene.paths) known += (known.empty() ? "" : ", ") + p.name;
  throw UsageError("--path: scene '" + scene.name + "' has no camera path '" + which +
                   "' (paths: " + (known.empty() ? "none" : known) + ")");
}

namespace {

/// The folder a file goes into ("." for a bare name).
fs::path folderOf(const std::string& path) {
  fs::path parent = fs::path(path).parent_path();
  return parent.empty() ? fs::path(".") : parent;
}

/// The same file for two paths (whether or not they exist yet): symbolic links and ".."
/// resolved, hard links compared by identity.
bool sameFile(const std::string& a, const std::string& b) {
  std::error_code ec;
  if (fs::equivalent(a, b, ec)) return true;
  const fs::path ca = fs::weakly_canonical(fs::absolute(a), ec);
  const fs::path cb = fs::weakly_canonical(fs::absolute(b), ec);
  return ca == cb;
}

/// Creates `folder` when missing and checks that it takes a new file (a probe file is
/// created and removed); an error or nothing.
std::optional<std::string> probeFolder(const fs::path& folder) {
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) {
    fs::create_directories(folder, ec);
    if (ec || !fs::is_directory(folder, ec))
      return "cannot create the folder '" + folder.string() + "' (" +
             (ec ? ec.message() : std::string("not a folder")) + ")";
  }
  const std::string probe = (folder / (".shadowlab-probe-" + std::to_string(getpid()))).string();
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
  if (fd < 0) {
    const int err = errno;
    return "cannot write in the folder '" + folder.string() + "' (" + std::strerror(err) + ")";
  }
  ::close(fd);
  ::unlink(probe.c_str());
  return std::nullopt;
}

}  // namespace

std::optional<std::string> writeFile(const std::string& path, const std::string& text) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return path + ": cannot write (" + std::strerror(errno) + ")";
  bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  int err = ok ? 0 : errno;
  if (std::fflush(f) != 0 && ok) ok = false, err = errno;
  if (std::fclose(f) != 0 && ok) ok = false, err = errno;
  if (!ok) return path + ": cannot write (" + std::strerror(err) + ")";
  return std::nullopt;
}

/// True for a FIFO that no process reads now: opening it for writing would block forever.
bool fifoWithoutReader(const std::string& path) {
  std::error_code ec;
  if (fs::status(path, ec).type() != fs::file_type::fifo) return false;
  const int fd = ::open(path.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd >= 0) {
    ::close(fd);
    return false;
  }
  return errno == ENXIO;
}

void checkOutputs(const std::vector<OutputFile>& outputs, const std::vector<OutputFile>& inputs) {
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const OutputFile& o = outputs[i];
    if (o.path.empty()) continue;
    for (std::size_t k = 0; k < i; ++k)
      if (!outputs[k].path.empty() && sameFile(outputs[k].path, o.path))
        throw UsageError(o.option + ": '" + o.path + "' is the same file as " + outputs[k].option +
                         " (one would overwrite the other)");
    for (const OutputFile& in : inputs)
      if (!in.path.empty() && sameFile(in.path, o.path))
        throw UsageError(o.option + ": '" + o.path + "' is the same file as " + in.option +
                         " (the input would be overwritten)");
    std::error_code ec;
    const fs::file_status st = fs::status(o.path, ec);
    if (fs::is_directory(st)) throw UsageError(o.option + ": '" + o.path + "' is a folder");
    if (fs::exists(st) && !fs::is_regular_file(st)) {  // a device or pipe: written in place
      if (fifoWithoutReader(o.path))
        throw UsageError(o.option + ": '" + o.path +
                         "' is a FIFO that nothing reads (writing would wait forever): start "
                         "its reader first");
      if (::access(o.path.c_str(), W_OK) != 0)
        throw UsageError(o.option + ": '" + o.path + "' is not writable (" + std::strerror(errno) +
                         ")");
      continue;
    }
    if (auto e = probeFolder(folderOf(o.path))) throw UsageError(o.option + ": " + *e);
  }
}

void checkOutputsAgainstScene(const std::vector<OutputFile>& outputs, const Scene& scene) {
  for (const OutputFile& o : outputs)
    for (const std::string& in : scene.inputFiles)
      if (!o.path.empty() && sameFile(in, o.path))
        throw UsageError(o.option + ": '" + o.path + "' is the same file as '" + in +
                         "', which the scene " + scene.name +
                         " loaded (the input would be overwritten)");
}

void checkOutputFolder(const std::string& option, const std::string& folder) {
  if (auto e = probeFolder(folder)) throw UsageError(option + ": " + *e);
}

void writeAtomically(const std::string& path,
                     const std::function<std::optional<std::string>(const std::string&)>& write) {
  auto fail = [&](std::string why, const std::string& tmp) {
    // The writer's message names the temporary file: name the real one.
    for (std::size_t at; !tmp.empty() && (at = why.find(tmp)) != std::string::npos;)
      why.replace(at, tmp.size(), path);
    if (why.rfind(path, 0) != 0) why = path + ": " + why;
    throw std::runtime_error(why);
  };
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (fs::exists(st) && !fs::is_regular_file(st)) {  // /dev/null, /dev/stdout, a pipe
    if (fifoWithoutReader(path)) fail("a FIFO that nothing reads any more: not written", "");
    if (auto e = write(path)) fail(*e, "");
    return;
  }
  const fs::path folder = folderOf(path);
  fs::create_directories(folder, ec);
  if (ec) fail("cannot create the folder '" + folder.string() + "' (" + ec.message() + ")", "");
  static int counter = 0;
  const fs::path name = fs::path(path).filename();
  const std::string tmp =
      (folder / ("." + name.stem().string() + ".tmp" + std::to_string(getpid()) + "-" +
                 std::to_string(++counter) + name.extension().string()))
          .string();
  if (auto e = write(tmp)) {
    fs::remove(tmp, ec);
    fail(*e, tmp);
  }
  fs::rename(tmp, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    fail("cannot write (" + ec.message() + ")", tmp);
  }
}

void writeText(const std::string& path, const std::string& text) {
  writeAtomically(path, [&](const std::string& p) { return writeFile(p, text + "\n"); });
}

void writePng(const std::string& path, const ImageRGBA8& img) {
  writeAtomically(path, [&](const std::string& p) { return writeImage(p, img); });
}

std::string formatDuration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) seconds = 0;
  long s = std::lround(seconds);
  char buf[32];
  if (s >= 3600)
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  else
    std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
  return buf;
}

ProgressBar::ProgressBar(std::string what, std::size_t totalSteps)
    : what_(std::move(what)),
      total_(std::max<std::size_t>(totalSteps, 1)),
      tty_(isatty(STDERR_FILENO) == 1),
      start_(std::chrono::steady_clock::now()),
      lastPlain_(start_ - std::chrono::hours(1)) {}

void ProgressBar::step(const std::string& detail, bool frameDone) {
  done_ = std::min(done_ + 1, total_);
  if (tty_)
    draw(detail, false);
  else if (frameDone)
    draw(detail, done_ == total_);
}

void ProgressBar::draw(const std::string& detail, bool force) {
  using namespace std::chrono;
  const auto now = steady_clock::now();
  const double elapsed = duration<double>(now - start_).count();
  // Time left from the mean step time so far (steps are alike: interleaved configurations).
  const double left = done_ ? elapsed / double(done_) * double(total_ - done_) : 0.0;
  const double frac = double(done_) / double(total_);
  if (tty_) {
    constexpr int kWidth = 30;
    int filled = int(std::lround(frac * kWidth));
    std::string bar(std::size_t(filled), '#');
    bar.resize(kWidth, '-');
    std::fprintf(stderr, "\r%s [%s] %3d%% %zu/%zu  %s left  %s\x1b[K", what_.c_str(), bar.c_str(),
                 int(frac * 100.0), done_, total_, formatDuration(left).c_str(), detail.c_str());
    std::fflush(stderr);
    return;
  }
  if (!force && now - lastPlain_ < seconds(2)) return;
  lastPlain_ = now;
  std::fprintf(stderr, "%s: %3d%% (%zu/%zu) %s, %s elapsed, about %s left\n", what_.c_str(),
               int(frac * 100.0), done_, total_, detail.c_str(), formatDuration(elapsed).c_str(),
               formatDuration(left).c_str());
}

void ProgressBar::finish() {
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (tty_) std::fprintf(stderr, "\r\x1b[K");
  std::fprintf(stderr, "%s: done, %zu runs in %s\n", what_.c_str(), done_,
               formatDuration(elapsed).c_str());
}

}  // namespace sl::cli
