// Reading untrusted input files within limits: only regular files (no devices, FIFOs or
// sockets: nothing can block or stream forever), at most a given size, and JSON nesting
// checked by a byte scan before any recursive parser sees the text. Shared by the glTF
// loader and the JSON and CSV readers of the CLI.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace sl {

/// Why an input file was not read. what() is one line without the file's name (the caller
/// adds it): "file not found", "is a FIFO, not a regular file: refused (...)", ...
struct InputFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Text from an input (a name, a title, a message) that reaches a title, a label or a message
/// is cut to this many bytes.
inline constexpr std::size_t kMaxMessageBytes = 300;

/// `text` cut to `maxBytes` ("... (N bytes)" after the cut; never inside a UTF-8 sequence).
std::string cutText(std::string text, std::size_t maxBytes = kMaxMessageBytes);

/// "N MiB" (whole mebibytes, rounded down) or "N bytes" below one MiB.
std::string byteLimitText(std::uint64_t bytes);

/// The whole of a regular file of at most `maxBytes` bytes. The file is opened non-blocking
/// (a FIFO cannot hang the open) and checked with fstat on the open descriptor, so nothing is
/// read from anything but a regular file. Over the limit: "is N bytes, over the limit of
/// X MiB per file (limitName)". Throws InputFileError.
std::vector<unsigned char> readRegularFile(const std::filesystem::path& path,
                                           std::uint64_t maxBytes, std::string_view limitName);

/// The byte offset of the first '[' or '{' that opens a level deeper than `maxDepth`, or
/// std::string_view::npos. One pass, no recursion; brackets inside strings (escapes
/// included) do not count, nor, with `comments`, brackets and quotes inside // and /* */
/// comments (for parsers that skip them: a quote in a comment must not hide the brackets
/// after it). Malformed JSON is left for the parser to describe.
std::size_t jsonDepthExcess(std::string_view text, int maxDepth, bool comments = false);

/// The byte offset of the '[' or '{' that opens the (maxContainers + 1)-th array or object, or
/// std::string_view::npos: parsers build a node per value (tinygltf's model, hundreds of bytes
/// per node), so the count bounds their memory before they start. Same scan as above.
std::size_t jsonContainerExcess(std::string_view text, std::size_t maxContainers,
                                bool comments = false);

}  // namespace sl
