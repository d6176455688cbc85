// glTF input hardening (Hardening.h): limits, refusals, the restricted file system tinygltf
// reads external files through, the lenient image decoder.
#include "scene/gltf/Hardening.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <limits>
#include <optional>
#include <string_view>

#include "algo/InputFile.h"

namespace sl::gltf {
namespace {

namespace fs = std::filesystem;

/// Extensions a file may list in `extensionsRequired`. The first three are implemented
/// (punctual lights: the first directional one, else the first spot or point, lights the scene;
/// texture transforms are baked into the base colour uvs; quantized attributes are read like any
/// normalized accessor). The last two only change shading that ShadowLab does its own way, so
/// ignoring them cannot change geometry, alpha cut-outs or shadows. Everything else (Draco,
/// meshopt, BasisU, WebP, ...) would leave geometry or textures unreadable: such files are refused.
constexpr std::array<std::string_view, 5> kAcceptedRequiredExtensions = {
    "KHR_lights_punctual", "KHR_texture_transform", "KHR_mesh_quantization",
    "KHR_materials_emissive_strength", "KHR_materials_unlit"};

/// The whole of a regular file of at most kMaxFileBytes (sl::readRegularFile: devices, FIFOs
/// and sockets are refused before anything is read). `what` prefixes every message ("" for
/// the scene file, whose name loadGltf() adds).
std::vector<unsigned char> readRegularFile(const fs::path& path, const std::string& what) {
  try {
    return sl::readRegularFile(path, kMaxFileBytes, "kMaxFileBytes");
  } catch (const InputFileError& e) {
    fail(what + e.what());
  }
}

/// The offset and length of the first "uri" string value in JSON `text` that is longer than
/// kMaxUriBytes and not a data: URI, or {npos, 0}. One pass over the tokens' strings (escapes
/// skipped, so a quote inside a string is not a token); lengths are the raw JSON bytes.
std::pair<std::size_t, std::size_t> overlongUri(std::string_view text) {
  constexpr std::size_t npos = std::string_view::npos;
  // The string starting at the quote `at`: its content's end (the closing quote) or npos.
  auto stringEnd = [&](std::size_t at) {
    for (std::size_t k = at + 1; k < text.size(); ++k) {
      if (text[k] == '\\')
        ++k;
      else if (text[k] == '"')
        return k;
    }
    return npos;
  };
  auto skipBlanks = [&](std::size_t k) {
    while (k < text.size() &&
           (text[k] == ' ' || text[k] == '\t' || text[k] == '\n' || text[k] == '\r'))
      ++k;
    return k;
  };
  for (std::size_t k = 0; k < text.size(); ++k) {
    if (text[k] != '"') continue;
    const std::size_t end = stringEnd(k);
    if (end == npos) break;
    const bool uriKey = text.substr(k + 1, end - k - 1) == "uri";
    k = end;
    if (!uriKey) continue;
    std::size_t v = skipBlanks(end + 1);
    if (v >= text.size() || text[v] != ':') continue;
    v = skipBlanks(v + 1);
    if (v >= text.size() || text[v] != '"') continue;
    const std::size_t valueEnd = stringEnd(v);
    if (valueEnd == npos) break;
    const std::size_t length = valueEnd - v - 1;
    if (length > kMaxUriBytes && text.substr(v + 1, 5) != "data:") return {v + 1, length};
    k = valueEnd;
  }
  return {npos, 0};
}

/// Refuses JSON nested deeper than kMaxJsonDepth (before any recursive parser sees it) or
/// holding more than kMaxJsonContainers arrays and objects (before any parser allocates).
void checkJsonDepth(const unsigned char* bytes, std::size_t size, const std::string& what) {
  const std::string_view text(reinterpret_cast<const char*>(bytes), size);
  std::size_t at = jsonDepthExcess(text, kMaxJsonDepth);
  if (at != std::string_view::npos)
    fail(what + " is nested deeper than " + std::to_string(kMaxJsonDepth) + " levels (at byte " +
         std::to_string(at) + "): refused (kMaxJsonDepth)");
  at = jsonContainerExcess(text, kMaxJsonContainers);
  if (at != std::string_view::npos)
    fail(what + " holds more than " + std::to_string(kMaxJsonContainers) +
         " arrays and objects (at byte " + std::to_string(at) + "): refused (kMaxJsonContainers)");
  if (const auto [uriAt, length] = overlongUri(text); uriAt != std::string_view::npos)
    fail(what + " has a URI of " + std::to_string(length) + " bytes (" +
         quoteInput(std::string(text.substr(uriAt, kMaxQuotedBytes + 1))) + " at byte " +
         std::to_string(uriAt) + "), longer than any file path: refused (kMaxUriBytes " +
         std::to_string(kMaxUriBytes) + ")");
}

/// Why an external (non-data:) URI is refused, or "" if it is a relative path that stays
/// inside the scene's directory. `uri` is already percent-decoded (by tinygltf).
std::string uriProblem(const std::string& uri) {
  static const std::string allowed =
      "only relative paths inside the scene's directory and data: URIs are read";
  if (uri.empty()) return "is empty";
  // A scheme: a letter, then letters, digits, '+', '-' or '.', then ':' (a Windows drive
  // letter such as "C:" is caught here too).
  std::size_t colon = uri.find(':');
  if (colon != std::string::npos && colon > 0 && std::isalpha(static_cast<unsigned char>(uri[0]))) {
    bool scheme = true;
    for (std::size_t k = 1; k < colon; ++k) {
      unsigned char c = static_cast<unsigned char>(uri[k]);
      if (!std::isalnum(c) && c != '+' && c != '-' && c != '.') scheme = false;
    }
    if (scheme) {
      std::string name = uri.substr(0, colon);
      for (char& c : name) c = char(std::tolower(static_cast<unsigned char>(c)));
      if (name == "data")
        return "is a data: URI that could not be decoded (only base64 data: URIs are read)";
      return "is refused: a " + name.substr(0, 20) + ": URI (" + allowed + ")";
    }
  }
  if (uri[0] == '/' || uri[0] == '\\') return "is refused: an absolute path (" + allowed + ")";
  std::size_t start = 0;
  while (start <= uri.size()) {
    std::size_t end = uri.find_first_of("/\\", start);
    if (end == std::string::npos) end = uri.size();
    if (uri.compare(start, end - start, "..") == 0)
      return "is refused: '..' leaves the scene's directory (" + allowed + ")";
    start = end + 1;
  }
  if (uri.find('\0') != std::string::npos) return "is refused: it contains a NUL byte";
  return "";
}

/// tinygltf's file system, restricted: external files are looked up only in the scene's
/// directory (never the working directory), only relative URIs that stay inside it are
/// accepted, and they are read with readRegularFile(). The first refusal is kept in `error`
/// because tinygltf reports a missing image only as a warning.
struct ExternalFiles {
  std::string prefix;  ///< the scene's directory, ending with '/'
  std::string error;
  std::vector<std::string> read_;  ///< the files read, in order

  void refuse(const std::string& message) {
    if (error.empty()) error = message;
  }

  /// The URI of a path tinygltf built as JoinPath(dir, uri); nullopt for other directories.
  std::optional<std::string> uriOf(const std::string& path) const {
    if (path.compare(0, prefix.size(), prefix) != 0) return std::nullopt;
    return path.substr(prefix.size());
  }

  static bool exists(const std::string& path, void* user) {
    auto& self = *static_cast<ExternalFiles*>(user);
    std::optional<std::string> uri = self.uriOf(path);
    if (!uri) return false;
    if (std::string problem = uriProblem(*uri); !problem.empty()) {
      self.refuse("external file URI " + quoteInput(*uri) + " " + problem);
      return false;
    }
    std::error_code ec;
    return fs::exists(fs::path(path), ec);
  }

  static std::string expand(const std::string& path, void*) { return path; }  // no wordexp

  static bool read(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                   void* user) {
    auto& self = *static_cast<ExternalFiles*>(user);
    std::string uri = self.uriOf(path).value_or(path);
    try {
      // Inside the scene's folder after symbolic links too: a link to a system file is
      // not the scene's.
      std::error_code ec;
      const fs::path folder = fs::weakly_canonical(fs::absolute(self.prefix), ec);
      const fs::path target = fs::weakly_canonical(fs::absolute(path), ec);
      const auto [end, at] =
          std::mismatch(folder.begin(), folder.end(), target.begin(), target.end());
      if (!ec && end != folder.end() && !end->empty())
        fail("external file " + quoteInput(uri) +
             " leads outside the scene's folder (a symbolic link): refused");
      *out = readRegularFile(path, "external file " + quoteInput(uri) + " ");
      self.read_.push_back(path);
      return true;
    } catch (const LoadFailure& f) {
      self.refuse(f.message);
      if (err) *err += f.message;
    } catch (const std::bad_alloc&) {
      self.refuse("external file " + quoteInput(uri) + ": out of memory");
    }
    return false;
  }

  static bool write(std::string* err, const std::string&, const std::vector<unsigned char>&,
                    void*) {
    if (err) *err += "writing is not supported";
    return false;
  }
};

std::uint32_t readBigEndian(const unsigned char* p, int bytes) {
  std::uint32_t v = 0;
  for (int k = 0; k < bytes; ++k) v = (v << 8) | p[k];
  return v;
}

/// Width and height from a PNG or JPEG header, without decoding; nullopt if neither.
std::optional<std::pair<std::uint32_t, std::uint32_t>> imageSize(const unsigned char* b,
                                                                 std::size_t n) {
  static const unsigned char png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (n >= 24 && std::memcmp(b, png, 8) == 0 && std::memcmp(b + 12, "IHDR", 4) == 0)
    return std::make_pair(readBigEndian(b + 16, 4), readBigEndian(b + 20, 4));
  if (n < 4 || b[0] != 0xFF || b[1] != 0xD8) return std::nullopt;
  std::size_t at = 2;  // JPEG: walk the marker segments to the first start-of-frame
  while (at + 4 <= n) {
    if (b[at] != 0xFF) return std::nullopt;
    const unsigned char marker = b[at + 1];
    if (marker == 0xFF) {  // fill byte
      ++at;
      continue;
    }
    if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD9)) {  // no length
      at += 2;
      continue;
    }
    const std::size_t length = readBigEndian(b + at + 2, 2);
    const bool startOfFrame =
        marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
    if (startOfFrame) {
      if (at + 9 > n) return std::nullopt;
      return std::make_pair(readBigEndian(b + at + 7, 2), readBigEndian(b + at + 5, 2));
    }
    if (length < 2) return std::nullopt;
    at += 2 + length;
  }
  return std::nullopt;
}

/// tinygltf's image decoder, except that an undecodable image is a warning, not a failure.
/// Only PNG and JPEG (glTF's image formats) are decoded, and only up to kMaxImageSide and
/// kMaxImagePixels, and kMaxTotalImagePixels for all of a file's images (`user`: the pixels
/// decoded so far, a std::uint64_t): the header is read first, so a small file cannot make the
/// decoder allocate gigabytes.
bool decodeImageLeniently(tinygltf::Image* image, const int imageIndex, std::string* err,
                          std::string* warn, int reqWidth, int reqHeight,
                          const unsigned char* bytes, int size, void* user) {
  (void)err;
  const std::string label = "image " + std::to_string(imageIndex) + " not decoded: ";
  auto dims = imageSize(bytes, size > 0 ? std::size_t(size) : 0);
  if (!dims) {
    if (warn) *warn += label + "neither PNG nor JPEG\n";
    return true;
  }
  auto [w, h] = *dims;
  if (w == 0 || h == 0 || w > std::uint32_t(kMaxImageSide) || h > std::uint32_t(kMaxImageSide) ||
      std::uint64_t(w) * h > kMaxImagePixels) {
    if (warn)
      *warn += label + std::to_string(w) + "x" + std::to_string(h) +
               " pixels is beyond the limit of " + std::to_string(kMaxImageSide) +
               " per side (kMaxImageSide) and " + std::to_string(kMaxImagePixels) +
               " pixels (kMaxImagePixels)\n";
    return true;
  }
  auto* totalPixels = static_cast<std::uint64_t*>(user);
  if (totalPixels) {
    if (*totalPixels + std::uint64_t(w) * h > kMaxTotalImagePixels) {
      if (warn)
        *warn += label + std::to_string(w) + "x" + std::to_string(h) +
                 " pixels would take the file's images beyond " +
                 std::to_string(kMaxTotalImagePixels) + " pixels in all (kMaxTotalImagePixels)\n";
      return true;
    }
    *totalPixels += std::uint64_t(w) * h;  // counted when tried: a failed decode allocated too
  }
  std::string why;
  if (tinygltf::LoadImageData(image, imageIndex, &why, warn, reqWidth, reqHeight, bytes, size,
                              nullptr))
    return true;
  if (warn) *warn += label + why + "\n";
  return true;
}

std::uint32_t readU32(const std::vector<unsigned char>& bytes, std::size_t at) {
  std::uint32_t v;
  std::memcpy(&v, bytes.data() + at, 4);
  return v;
}

/// The GLB container checks tinygltf reports less clearly.
void checkGlbHeader(const std::vector<unsigned char>& bytes) {
  const std::size_t size = bytes.size();
  if (size < 12)
    fail("truncated .glb: " + std::to_string(size) + " bytes, the header alone needs 12");
  std::uint32_t version = readU32(bytes, 4), length = readU32(bytes, 8);
  if (version != 2) fail("unsupported glTF binary version " + std::to_string(version));
  if (length > size)
    fail("truncated .glb: the header declares " + std::to_string(length) +
         " bytes but the file has " + std::to_string(size));
  if (length < size)
    fail("malformed .glb: the header declares " + std::to_string(length) +
         " bytes but the file has " + std::to_string(size) + " (" + std::to_string(size - length) +
         " bytes after the declared end)");
  if (length < 20) fail("truncated .glb: no JSON chunk");
  std::uint32_t jsonLength = readU32(bytes, 12), jsonType = readU32(bytes, 16);
  if (jsonType != 0x4E4F534Au) fail("malformed .glb: the first chunk is not JSON");
  if (std::uint64_t(jsonLength) + 20u > length)
    fail("truncated .glb: the JSON chunk (" + std::to_string(jsonLength) +
         " bytes) runs past the end of the file");
}

std::string describeParseError(const std::string& tinygltfError) {
  std::string msg = cutText(oneLine(tinygltfError), 2 * kMaxQuotedBytes);
  if (msg.empty()) return "could not be parsed as glTF";
  if (std::size_t p = msg.find("[json.exception."); p != std::string::npos) {
    std::size_t close = msg.find("] ", p);
    if (close != std::string::npos) msg.erase(p, close + 2 - p);
    return "malformed JSON: " + msg;
  }
  if (msg.find("JSON") != std::string::npos || msg.find("json") != std::string::npos)
    return "malformed JSON: " + msg;
  return "invalid glTF: " + msg;
}

void refuseUnsupportedRequiredExtensions(const tinygltf::Model& model) {
  std::vector<std::string> unsupported;
  for (const std::string& ext : model.extensionsRequired)
    if (std::find(kAcceptedRequiredExtensions.begin(), kAcceptedRequiredExtensions.end(), ext) ==
        kAcceptedRequiredExtensions.end())
      unsupported.push_back(inQuotes(ext));
  if (unsupported.empty()) return;
  std::string list;
  for (const std::string& e : unsupported) list += (list.empty() ? "" : ", ") + e;
  fail(std::string("requires unsupported extension") + (unsupported.size() > 1 ? "s " : " ") +
       list);
}

}  // namespace

ParsedGltf parseWithinLimits(const fs::path& path) {
  std::error_code ec;
  fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) fail("file not found");
  if (fs::is_directory(status)) fail("is a directory, not a glTF file");
  std::vector<unsigned char> bytes = readRegularFile(path, "");
  if (bytes.empty()) fail("empty file");
  if (bytes.size() > std::numeric_limits<unsigned int>::max()) fail("file larger than 4 GiB");

  const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  if (!binary && lowerExtension(path) == ".glb") {
    if (bytes.size() < 4) fail("truncated .glb: " + std::to_string(bytes.size()) + " bytes");
    fail("not a glTF binary (the file does not start with 'glTF')");
  }
  if (binary) {
    checkGlbHeader(bytes);
    checkJsonDepth(bytes.data() + 20, readU32(bytes, 12), "the JSON chunk");
  } else {
    checkJsonDepth(bytes.data(), bytes.size(), "the JSON");
  }

  tinygltf::TinyGLTF parser;
  std::uint64_t decodedPixels = 0;
  parser.SetImageLoader(&decodeImageLeniently, &decodedPixels);
  std::string baseDir = path.parent_path().string();
  if (baseDir.empty()) baseDir = ".";
  ExternalFiles files;
  files.prefix = baseDir.back() == '/' ? baseDir : baseDir + "/";
  parser.SetFsCallbacks({&ExternalFiles::exists, &ExternalFiles::expand, &ExternalFiles::read,
                         &ExternalFiles::write, &files});
  tinygltf::Model model;
  std::string err, warnText;
  bool ok = binary ? parser.LoadBinaryFromMemory(&model, &err, &warnText, bytes.data(),
                                                 static_cast<unsigned int>(bytes.size()), baseDir)
                   : parser.LoadASCIIFromString(&model, &err, &warnText,
                                                reinterpret_cast<const char*>(bytes.data()),
                                                static_cast<unsigned int>(bytes.size()), baseDir);
  // The required extensions are parsed early, so they explain a failure best.
  refuseUnsupportedRequiredExtensions(model);
  if (!files.error.empty()) fail(files.error);
  if (!ok) fail(describeParseError(err));
  return {std::move(model), std::move(files.read_), std::move(warnText)};
}

/// "2.5 s".
std::string secondsText(float s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g s", double(s));
  return buf;
}

std::string inQuotes(const std::string& s) {
  return "'" + s + "'";
}

/// In quotes, cut to kMaxQuotedBytes, control characters shown as '?'.
std::string quoteInput(const std::string& s) {
  std::string out = s.substr(0, kMaxQuotedBytes);
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  return "'" + out + (s.size() > kMaxQuotedBytes ? "...'" : "'");
}

/// Newlines and runs of blanks collapsed so an error stays on one line.
std::string oneLine(const std::string& text) {
  std::string out;
  bool pendingBreak = false;
  for (char c : text) {
    if (c == '\n' || c == '\r') {
      pendingBreak = !out.empty();
      continue;
    }
    if (pendingBreak) {
      while (!out.empty() && (out.back() == ' ' || out.back() == '.')) out.pop_back();
      out += "; ";
      pendingBreak = false;
    }
    out += c;
  }
  while (!out.empty() && (out.back() == ' ' || out.back() == ';')) out.pop_back();
  return out;
}

void addLines(std::vector<std::string>& to, const std::string& text) {
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    if (!line.empty()) to.push_back(cutText(std::move(line)));
    start = end + 1;
  }
}

std::string lowerExtension(const fs::path& p) {
  std::string ext = p.extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace sl::gltf
