#include "core/JsonInput.h"

#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

#include "algo/InputFile.h"

namespace sl {

using nlohmann::json;

std::string quoteText(std::string_view text, std::size_t maxBytes) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (out.size() >= maxBytes) {
      // Do not leave half a UTF-8 sequence before the ellipsis.
      while (!out.empty() && (static_cast<unsigned char>(out.back()) & 0xC0) == 0x80)
        out.pop_back();
      if (!out.empty() && static_cast<unsigned char>(out.back()) >= 0xC0) out.pop_back();
      return out + "... (" + std::to_string(text.size()) + " bytes)";
    }
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c == '\n')
      out += "\\n";
    else if (c == '\r')
      out += "\\r";
    else if (c == '\t')
      out += "\\t";
    else if (c < 0x20 || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    } else
      out += static_cast<char>(c);
  }
  return out;
}

std::string quoteJson(const json& value, std::size_t maxBytes) {
  return quoteText(value.dump(-1, ' ', false, json::error_handler_t::replace), maxBytes);
}

std::string jsonPath(const std::string& parent, std::string_view key) {
  const std::string k = quoteText(key, 60);
  return parent.empty() ? k : parent + "." + k;
}

std::string jsonPath(const std::string& parent, std::size_t index) {
  return parent + "[" + std::to_string(index) + "]";
}

std::optional<std::pair<std::string, std::string>> cameraFieldError(const Camera& cam,
                                                                    const CameraFieldNames& keys) {
  auto number = [](float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", double(v));
    return std::string(buf);
  };
  if (std::isfinite(cam.up.x) && std::isfinite(cam.up.y) && std::isfinite(cam.up.z) &&
      !(glm::length(cam.up) > 1e-6f))
    return std::pair{keys.up, std::string("a zero vector: the camera has no up direction")};
  if (!(cam.nearM >= Camera::kMinNearM))
    return std::pair{keys.near, "must be at least " + number(Camera::kMinNearM) + " m, got " +
                                    number(cam.nearM)};
  if (std::isfinite(cam.farM) && !(cam.farM <= Camera::kMaxFarM))
    return std::pair{keys.far,
                     "must be at most " + number(Camera::kMaxFarM) + " m, got " + number(cam.farM)};
  if (std::isfinite(cam.nearM) && std::isfinite(cam.farM))
    if (auto e = Camera::depthPrecisionError(cam.nearM, cam.farM)) return std::pair{keys.near, *e};
  return std::nullopt;
}

namespace {

/// Follows the JSON path while a SAX parse runs, so that a number the parser cannot hold
/// (1e999) is named by where it is, not only by "not valid JSON"; and stops at a key an object
/// gives twice (the parser would keep the last value silently).
class PathTracker : public nlohmann::json_sax<json> {
 public:
  std::string failedToken;   ///< set by parse_error: the token the parser stopped at
  std::string duplicateKey;  ///< set by key(): a key its object already had (path() names it)
  /// The path of the value being read ("cases[0].frames"; "" at the top level).
  std::string path() const {
    std::string p;
    for (const Level& l : levels_) p = l.array ? jsonPath(p, l.index) : jsonPath(p, l.key);
    return p;
  }

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override { return open(false); }
  bool key(string_t& k) override {
    levels_.back().key = k;
    if (!levels_.back().keys.insert(k).second) {
      duplicateKey = k;
      return false;
    }
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(true); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t, const std::string& token,
                   const nlohmann::detail::exception&) override {
    failedToken = token;
    return false;
  }

 private:
  struct Level {
    bool array = false;
    std::size_t index = 0;       ///< arrays: the element being read
    std::string key;             ///< objects: the member being read
    std::set<std::string> keys;  ///< objects: the members read so far
  };
  std::vector<Level> levels_;

  bool value() {  // a value ended: an array moves on to its next element
    if (!levels_.empty() && levels_.back().array) ++levels_.back().index;
    return true;
  }
  bool open(bool array) {
    levels_.push_back({array, 0, {}});
    return true;
  }
  bool close() {
    levels_.pop_back();
    return value();
  }
};

}  // namespace

json JsonReader::parseFile() const {
  std::vector<unsigned char> bytes;
  try {
    bytes = readRegularFile(file_, kMaxJsonInputBytes, "kMaxJsonInputBytes");
  } catch (const InputFileError& e) {
    throw JsonInputError(file_ + ": " + e.what());
  }
  // nlohmann's parser recurses once per level: refuse deep nesting before it starts.
  const std::size_t deep = jsonDepthExcess(
      {reinterpret_cast<const char*>(bytes.data()), bytes.size()}, kMaxJsonInputDepth, true);
  if (deep != std::string_view::npos)
    throw JsonInputError(file_ + ": nested deeper than " + std::to_string(kMaxJsonInputDepth) +
                         " levels (at byte " + std::to_string(deep) +
                         "): refused (kMaxJsonInputDepth)");
  try {
    json doc = json::parse(bytes.begin(), bytes.end(), nullptr, /*allow_exceptions=*/true,
                           /*ignore_comments=*/true);
    // A key given twice in one object: the parser kept the last value; refused, named.
    PathTracker tracker;
    json::sax_parse(bytes.begin(), bytes.end(), &tracker, json::input_format_t::json,
                    /*strict=*/true, /*ignore_comments=*/true);
    if (!tracker.duplicateKey.empty())
      throw JsonInputError(file_ + ": " + tracker.path() +
                           ": the key is given twice in one object (JSON keys are unique; "
                           "which value would count is not defined)");
    return doc;
  } catch (const json::parse_error& e) {
    // "[json.exception.parse_error.101] parse error at line 3, column 5: syntax error ..."
    std::string what = e.what();
    if (auto p = what.find("] "); p != std::string::npos) what = what.substr(p + 2);
    throw JsonInputError(file_ + ": not valid JSON: " + quoteText(what));
  } catch (const json::out_of_range& e) {
    // 406: a number beyond what a double holds ("1e999"); named with its path.
    PathTracker tracker;
    json::sax_parse(bytes.begin(), bytes.end(), &tracker, json::input_format_t::json,
                    /*strict=*/true, /*ignore_comments=*/true);
    if (e.id == 406 && !tracker.failedToken.empty()) {
      const std::string where = tracker.path();
      throw JsonInputError(file_ + ": " + (where.empty() ? std::string("top level") : where) +
                           ": the number " + quoteText(tracker.failedToken, 60) +
                           " is out of range (beyond +-1.8e308, the largest a double holds)");
    }
    throw JsonInputError(file_ + ": not valid JSON");
  } catch (const json::exception&) {
    throw JsonInputError(file_ + ": not valid JSON");
  }
}

void JsonReader::fail(const std::string& path, const std::string& what) const {
  throw JsonInputError(file_ + ": " + (path.empty() ? std::string("top level") : path) + ": " +
                       what);
}

void JsonReader::expected(const json& v, const std::string& path,
                          const std::string& expected) const {
  fail(path, "expected " + expected + ", got " + quoteJson(v));
}

void JsonReader::requireObject(const json& v, const std::string& path) const {
  if (!v.is_object()) expected(v, path, "an object {...}");
}

void JsonReader::requireArray(const json& v, const std::string& path) const {
  if (!v.is_array()) expected(v, path, "an array [...]");
}

void JsonReader::onlyKeys(const json& obj, const std::string& path,
                          std::initializer_list<std::string_view> keys) const {
  requireObject(obj, path);
  for (const auto& [k, v] : obj.items()) {
    bool known = false;
    for (std::string_view key : keys) known = known || key == k;
    if (known) continue;
    std::string list;
    for (std::string_view key : keys) list += (list.empty() ? "" : ", ") + std::string(key);
    fail(jsonPath(path, k), "unknown key '" + quoteText(k, 60) + "' (known: " + list + ")");
  }
}

std::string JsonReader::string(const json& v, const std::string& path) const {
  if (!v.is_string()) expected(v, path, "a string");
  return v.get<std::string>();
}

double JsonReader::number(const json& v, const std::string& path) const {
  if (!v.is_number()) expected(v, path, "a number");
  const double d = v.get<double>();
  if (!std::isfinite(d)) expected(v, path, "a finite number");
  return d;
}

int JsonReader::integer(const json& v, const std::string& path, int lo, int hi) const {
  const std::string range = std::to_string(lo) + ".." + std::to_string(hi);
  if (!v.is_number()) expected(v, path, "an integer in " + range);
  const double d = v.get<double>();
  if (!std::isfinite(d) || d != std::floor(d) || d < lo || d > hi)
    expected(v, path, "an integer in " + range);
  return static_cast<int>(d);
}

bool JsonReader::boolean(const json& v, const std::string& path) const {
  if (!v.is_boolean()) expected(v, path, "true or false");
  return v.get<bool>();
}

const json* JsonReader::member(const json& obj, std::string_view key) {
  if (!obj.is_object()) return nullptr;
  auto it = obj.find(std::string(key));
  return it == obj.end() ? nullptr : &*it;
}

std::string JsonReader::string(const json& obj, const std::string& path, std::string_view key,
                               const std::string& fallback) const {
  const json* m = member(obj, key);
  return m ? string(*m, jsonPath(path, key)) : fallback;
}

double JsonReader::number(const json& obj, const std::string& path, std::string_view key,
                          double fallback) const {
  const json* m = member(obj, key);
  return m ? number(*m, jsonPath(path, key)) : fallback;
}

int JsonReader::integer(const json& obj, const std::string& path, std::string_view key,
                        int fallback, int lo, int hi) const {
  const json* m = member(obj, key);
  return m ? integer(*m, jsonPath(path, key), lo, hi) : fallback;
}

bool JsonReader::boolean(const json& obj, const std::string& path, std::string_view key,
                         bool fallback) const {
  const json* m = member(obj, key);
  return m ? boolean(*m, jsonPath(path, key)) : fallback;
}

}  // namespace sl
