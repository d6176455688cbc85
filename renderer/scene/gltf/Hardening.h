// glTF input hardening: the limits against hostile files, the failure a refusal throws, the
// file read and parsed under those limits, and how input is quoted in messages. Every limit
// is named in the message that refuses a file (tests/fixtures/hostile, GltfLoaderLimitsTest).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <tiny_gltf.h>

namespace sl::gltf {

/// An accessor larger than this is treated as corrupt rather than allocated.
constexpr std::size_t kMaxAccessorElements = std::size_t(1) << 28;

// Limits against hostile files. Each is named in the message that refuses a file.
/// The .gltf/.glb file and every external buffer or image file it names.
constexpr std::uint64_t kMaxFileBytes = std::uint64_t(1) << 30;
/// Nesting of JSON arrays and objects (the JSON parsers recurse; real files need < 20).
constexpr int kMaxJsonDepth = 256;
/// Arrays and objects in the JSON, counted before parsing: tinygltf's DOM and model take
/// ~0.7 KiB per container, so a 22 MB chain of 1,000,000 nodes took 1.2 GB and 100,000
/// cameras on 100,000 nodes (600,000) 800 MiB with the GL context. 2^18 keeps any accepted
/// file under 500 MiB (40,000 cameras, 240,000 containers: tests/fixtures/hostile); real
/// scenes have a few thousand nodes.
constexpr std::size_t kMaxJsonContainers = std::size_t(1) << 18;
/// A "uri" that is not a data: URI names a file relative to the scene: no path is longer than
/// PATH_MAX (4096 on Linux). Longer ones are refused in the JSON text, before tinygltf copies
/// them (a 40 MB URI took 500 MiB through its DOM, model, path and "File not found" message).
constexpr std::size_t kMaxUriBytes = 4096;
/// Node instances in the flattened hierarchy.
constexpr std::size_t kMaxNodeInstances = std::size_t(1) << 20;
/// Triangles in the flattened scene (all instances together).
constexpr std::size_t kMaxTriangles = std::size_t(1) << 25;
/// Memory a flattened triangle costs, all copies together (the flattened mesh, GPU buffers, the
/// reference's BVH): a 1 M-triangle mesh on 8 nodes took 3.9 GB, ~490 bytes a triangle.
constexpr std::uint64_t kBytesPerTriangle = 490;
/// Memory a flattened primitive costs besides its triangles, all copies together (its mesh
/// record and vectors, its GPU buffers and vertex array, the reference's geometry): one mesh
/// of 5,000 and of 10,000 one-triangle primitives, `render` at 64x36, peaked at 513,584 and
/// 820,240 KB: ~61 KiB a primitive (the same without the reference). 100,000 of them (a
/// 4.7 MB file) grew to 3.9 GB and died of std::bad_alloc; by this estimate, 5.8 GiB.
constexpr std::uint64_t kBytesPerPrimitive = std::uint64_t(61) << 10;
/// The memory the flattened scene may take by those estimates (~8.7 M triangles): refused
/// before anything is allocated (32 nodes of that mesh, under kMaxTriangles, would have taken
/// ~15 GB).
constexpr std::uint64_t kMaxSceneBytes = std::uint64_t(4) << 30;
/// Longest side and pixel count of a decoded image (larger ones are not decoded).
constexpr int kMaxImageSide = 16384;
constexpr std::uint64_t kMaxImagePixels = std::uint64_t(1) << 26;
/// Pixels of all the images of one file together (256 MiB as RGBA8): a PNG of 8192x8192 zeros
/// is 260 KB, so without it a few MB of images would decode to gigabytes.
constexpr std::uint64_t kMaxTotalImagePixels = std::uint64_t(1) << 26;
/// Input quoted in a message is cut to this many bytes.
constexpr std::size_t kMaxQuotedBytes = 120;
/// How far from the origin (largest |x|, |y| or |z| of the bounds, metres) the geometry may
/// reach. Positions, shadow maps and depths are floats in world space, and a float's spacing
/// grows with its magnitude: below 1e5 m (2^16..2^17) it is 2^-7 m, about 8 mm. Measured
/// with `default` moved 5e4 m away: uniform at 2048² 0.163 % error (0.164 % at the
/// origin), at 8192² 0.52 % (0.04 %): the raster's precision, not the reference's, which
/// offsets its rays by float spacings (metrics/ShadowReference). At 1e6 m the error grows
/// to 7 % (uniform) and 15 % (rtw-backward); at 1e7 m (1 m spacing) the image is blank.
/// Rendering camera-relative would lift this; until then such a scene is refused, saying to
/// recentre it.
constexpr double kMaxSceneExtentM = 1e5;

/// Internal failure; loadGltf() turns it into SceneLoadResult::error with the file name.
struct LoadFailure {
  std::string message;
};

[[noreturn]] inline void fail(std::string message) {
  throw LoadFailure{std::move(message)};
}

/// A file read and parsed by tinygltf under the limits above.
struct ParsedGltf {
  tinygltf::Model model;
  std::vector<std::string> externalFiles;  ///< the buffer and image files read, in order
  std::string warnings;                    ///< tinygltf's, one a line
};

/// Reads `path` (a .gltf or .glb) and parses it, refusing what the limits forbid: the file's
/// size, the GLB container, the JSON's nesting and containers, overlong or escaping URIs,
/// images beyond their pixel limits (left undecoded, with a warning), unsupported required
/// extensions. Throws LoadFailure.
ParsedGltf parseWithinLimits(const std::filesystem::path& path);

/// "2.5 s".
std::string secondsText(float s);
std::string inQuotes(const std::string& s);
/// In quotes, cut to kMaxQuotedBytes, control characters shown as '?'.
std::string quoteInput(const std::string& s);
/// Newlines and runs of blanks collapsed so an error stays on one line.
std::string oneLine(const std::string& text);
/// `text`'s lines, blanks trimmed and cut to a message's length, appended to `to`.
void addLines(std::vector<std::string>& to, const std::string& text);
/// The file's extension in lower case (".glb").
std::string lowerExtension(const std::filesystem::path& p);

}  // namespace sl::gltf
