// Shared helpers of the shadowlab-cli commands; see CliCommon.h.
#include "CliCommon.h"
#include "algo/InputFile.h"
#include "algo/OutputFile.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>

#include "core/JsonInput.h"
#include "core/Renderer.h"
#include "measure/Measure.h"
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
  // strtod, not stod: a number too small for a normal double (1e-320) is a number (its
  // denormal value, then checked against the range), not "expected a number".
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = text.empty() || std::isspace(static_cast<unsigned char>(text[0]))
                       ? 0.0
                       : std::strtod(begin, &end);
  if (end != begin + text.size() || text.empty())
    throw UsageError(opt + ": expected a number, got '" + quoteText(text) + "'");
  if (errno == ERANGE && std::abs(v) > 1.0)
    throw UsageError(opt + ": " + quoteText(text, 60) +
                     " is out of range (beyond +-1.8e308, the largest a double holds)");
  if (!std::isfinite(v)) throw UsageError(opt + ": " + quoteText(text) + " is not a finite number");
  if (v < lo || v > hi) {
    char range[96];
    std::snprintf(range, sizeof range, " is out of range %g..%g", lo, hi);
    throw UsageError(opt + ": " + quoteText(text) + range);
  }
  return v;
}

double parsePathHz(const std::string& opt, const std::string& text) {
  return parseDouble(opt, text, 0.0, kMaxPathHz);
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
  // Any float here; Light::validate then names the bounds (kMaxLightPositionM, the cones).
  auto num = [&](std::size_t i, const char* field) {
    const double maxFloat = std::numeric_limits<float>::max();
    return float(parseDouble(opt + " (" + kind + " " + field + ")", f[i], -maxFloat, maxFloat));
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

std::optional<std::string> writeFile(const std::string& path, const std::string& bytes) {
  return writeFileBytes(path, bytes);
}

void checkOutputs(const std::vector<OutputFile>& outputs, const std::vector<InputTarget>& inputs) {
  if (auto e = checkOutputTargets(outputs, inputs)) throw UsageError(*e);
}

void checkOutputsAgainstScene(const std::vector<OutputFile>& outputs, const Scene& scene) {
  for (const OutputFile& o : outputs)
    for (const std::string& in : scene.inputFiles)
      if (!o.path.empty() && sameFile(in, o.path))
        throw UsageError(o.name + ": '" + o.path + "' is the same file as '" + in +
                         "', which the scene " + scene.name +
                         " loaded (the input would be overwritten)");
}

void checkOutputFolder(const std::string& option, const std::string& folder) {
  if (auto e = probeOutputFolder(folder)) throw UsageError(option + ": " + *e);
}

void writeAtomically(const OutputFile& target,
                     const std::function<std::optional<std::string>(const std::string&)>& write) {
  if (auto e = writeOutputAtomically(target, write)) throw std::runtime_error(*e);
}

void writeText(const OutputFile& target, const std::string& text) {
  writeAtomically(target, [&](const std::string& p) { return writeFile(p, text + "\n"); });
}

void writePng(const OutputFile& target, const ImageRGBA8& img) {
  writeAtomically(target, [&](const std::string& p) { return writeImage(p, img); });
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
