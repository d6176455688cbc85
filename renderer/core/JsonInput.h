// Reading JSON input files (suites, presets) with messages that name things: every problem
// is one line "FILE: PATH: what was expected, got VALUE", PATH a JSON path such as
// `cases[2].techniques[0].set.resolution`, VALUE at most ~200 bytes of the input. No raw
// library exception text ("[json.exception.type_error.302] ...") reaches the user.
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include <nlohmann/json.hpp>

#include "algo/Camera.h"

namespace sl {

/// Limits on a JSON input file (a preset or suite is a few KiB): larger or deeper files are
/// refused before parsing, with a message naming the limit.
inline constexpr std::uint64_t kMaxJsonInputBytes = std::uint64_t(16) << 20;
inline constexpr int kMaxJsonInputDepth = 64;

/// A bad JSON input file; what() is one line naming the file and the JSON path.
struct JsonInputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// One line of at most `maxBytes` bytes (then "..."), control characters escaped.
std::string quoteText(std::string_view text, std::size_t maxBytes = 200);
/// The value's compact JSON text, through quoteText.
std::string quoteJson(const nlohmann::json& value, std::size_t maxBytes = 200);
/// "parent.key" ("key" when parent is empty); the key quoted to 60 bytes.
std::string jsonPath(const std::string& parent, std::string_view key);
/// "parent[i]".
std::string jsonPath(const std::string& parent, std::size_t index);

/// The keys a camera object names its up vector, near and far planes with ("up", "near_m",
/// "far_m" in a suite; "up", "nearM", "farM" in a preset).
struct CameraFieldNames {
  std::string up, near, far;
};
/// A camera value a reader should refuse naming its field: {key, what} for a zero up vector,
/// a near plane below Camera::kMinNearM, a far plane beyond Camera::kMaxFarM.
std::optional<std::pair<std::string, std::string>> cameraFieldError(const Camera& cam,
                                                                    const CameraFieldNames& keys);

/// Typed access to one file's JSON, throwing JsonInputError("FILE: PATH: ...").
class JsonReader {
 public:
  explicit JsonReader(std::string file) : file_(std::move(file)) {}
  const std::string& file() const { return file_; }

  /// Reads and parses the file (comments allowed); "FILE: not valid JSON at byte N: ...".
  /// Only a regular file of at most kMaxJsonInputBytes, nested at most kMaxJsonInputDepth
  /// levels, is parsed ("FILE: is a FIFO, not a regular file: refused ...").
  nlohmann::json parseFile() const;

  [[noreturn]] void fail(const std::string& path, const std::string& what) const;
  /// fail(path, "expected " + expected + ", got " + quoteJson(v)).
  [[noreturn]] void expected(const nlohmann::json& v, const std::string& path,
                             const std::string& expected) const;

  void requireObject(const nlohmann::json& v, const std::string& path) const;
  void requireArray(const nlohmann::json& v, const std::string& path) const;
  /// Every key of the object is one of `keys`; otherwise "unknown key 'k' (known: ...)".
  void onlyKeys(const nlohmann::json& obj, const std::string& path,
                std::initializer_list<std::string_view> keys) const;

  std::string string(const nlohmann::json& v, const std::string& path) const;
  double number(const nlohmann::json& v, const std::string& path) const;  ///< finite
  int integer(const nlohmann::json& v, const std::string& path, int lo, int hi) const;
  bool boolean(const nlohmann::json& v, const std::string& path) const;

  /// The member `key` of the object `obj` (at `path`), or nullptr when absent.
  static const nlohmann::json* member(const nlohmann::json& obj, std::string_view key);
  /// Optional members with a default.
  std::string string(const nlohmann::json& obj, const std::string& path, std::string_view key,
                     const std::string& fallback) const;
  double number(const nlohmann::json& obj, const std::string& path, std::string_view key,
                double fallback) const;
  int integer(const nlohmann::json& obj, const std::string& path, std::string_view key,
              int fallback, int lo, int hi) const;
  bool boolean(const nlohmann::json& obj, const std::string& path, std::string_view key,
               bool fallback) const;

 private:
  std::string file_;
};

}  // namespace sl
