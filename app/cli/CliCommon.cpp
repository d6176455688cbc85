// Shared helpers of the shadowlab-cli commands; see CliCommon.h.
#include "CliCommon.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

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
    throw UsageError(opt + ": expected an integer, got '" + text + "'");
  }
}

double parseDouble(const std::string& opt, const std::string& text, double lo, double hi) {
  try {
    std::size_t used = 0;
    double v = std::stod(text, &used);
    if (used != text.size() || !std::isfinite(v)) throw std::invalid_argument(text);
    if (v < lo || v > hi) {
      char buf[160];
      std::snprintf(buf, sizeof buf, ": %s is out of range %g..%g", text.c_str(), lo, hi);
      throw UsageError(opt + buf);
    }
    return v;
  } catch (const UsageError&) {
    throw;
  } catch (const std::exception&) {
    throw UsageError(opt + ": expected a number, got '" + text + "'");
  }
}

std::pair<int, int> parseSize(const std::string& text) {
  auto x = text.find('x');
  if (x == std::string::npos) throw UsageError("--size: expected WxH, got '" + text + "'");
  return {parseInt("--size", text.substr(0, x), 1, 16384),
          parseInt("--size", text.substr(x + 1), 1, 16384)};
}

DirectionalLight parseLight(const std::string& opt, const std::string& v) {
  auto c = v.find(',');
  if (c == std::string::npos)
    throw UsageError(opt + ": expected AZIMUTH,ELEVATION in degrees, got '" + v + "'");
  DirectionalLight l;
  l.azimuthDeg = float(parseDouble(opt, v.substr(0, c), -1e6, 1e6));
  l.elevationDeg = float(parseDouble(opt, v.substr(c + 1), -1e6, 1e6));
  if (auto e = l.validate()) throw UsageError(opt + ": " + *e);
  return l;
}

std::shared_ptr<Scene> loadScene(const std::string& nameOrPath) {
  SceneLoadResult r = loadSceneByNameOrPath(nameOrPath);
  if (!r) throw UsageError(r.error);
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

void writeText(const std::string& path, const std::string& text) {
  if (fs::path(path).has_parent_path()) fs::create_directories(fs::path(path).parent_path());
  std::ofstream out(path);
  if (!out) throw UsageError(path + ": cannot write");
  out << text << "\n";
  if (!out) throw UsageError(path + ": cannot write");
}

void writePng(const std::string& path, const ImageRGBA8& img) {
  if (fs::path(path).has_parent_path()) fs::create_directories(fs::path(path).parent_path());
  if (auto e = writeImage(path, img)) throw UsageError(*e);
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
