#include "algo/InputFile.h"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace sl {
namespace {

/// Closes a POSIX file descriptor on scope exit.
struct FdCloser {
  int fd;
  ~FdCloser() {
    if (fd >= 0) ::close(fd);
  }
};

const char* fileKind(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

}  // namespace

std::string cutText(std::string text, std::size_t maxBytes) {
  if (text.size() <= maxBytes) return text;
  const std::size_t total = text.size();
  std::size_t n = maxBytes;
  while (n > 0 && (static_cast<unsigned char>(text[n]) & 0xC0) == 0x80) --n;
  text.resize(n);
  return text + "... (" + std::to_string(total) + " bytes)";
}

std::string byteLimitText(std::uint64_t bytes) {
  if (bytes >= (std::uint64_t(1) << 20)) return std::to_string(bytes >> 20) + " MiB";
  return std::to_string(bytes) + " bytes";
}

std::vector<unsigned char> readRegularFile(const std::filesystem::path& path,
                                           std::uint64_t maxBytes, std::string_view limitName) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) {
    const int e = errno;
    if (e == ENOENT || e == ENOTDIR) throw InputFileError("file not found");
    throw InputFileError(std::string("cannot be opened for reading: ") + std::strerror(e));
  }
  FdCloser closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0)
    throw InputFileError(std::string("cannot be inspected: ") + std::strerror(errno));
  if (!S_ISREG(st.st_mode))
    throw InputFileError(std::string("is ") + fileKind(st.st_mode) +
                         ", not a regular file: refused (only regular files are read)");
  const std::uint64_t size = std::uint64_t(st.st_size);
  if (size > maxBytes)
    throw InputFileError("is " + std::to_string(size) + " bytes, over the limit of " +
                         byteLimitText(maxBytes) + " per file (" + std::string(limitName) + ")");
  std::vector<unsigned char> bytes(static_cast<std::size_t>(size));
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::read(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw InputFileError(std::string("read error: ") + std::strerror(errno));
    if (n == 0) break;  // shrank while being read
    done += std::size_t(n);
  }
  bytes.resize(done);
  return bytes;
}

namespace {

/// One pass over JSON text: opened() for every '[' or '{' outside strings (and, with
/// `comments`, outside // and /* */ comments), closed() for every ']' or '}'. Stops at the
/// first opening for which opened() returns true and returns its offset; npos otherwise.
template <typename Opened, typename Closed>
std::size_t scanJsonBrackets(std::string_view text, bool comments, Opened opened, Closed closed) {
  bool inString = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (c == '\\')
        ++i;  // the escaped character cannot end the string
      else if (c == '"')
        inString = false;
      continue;
    }
    if (comments && c == '/' && i + 1 < text.size() && text[i + 1] == '/') {
      const std::size_t end = text.find('\n', i + 2);
      if (end == std::string_view::npos) break;
      i = end;
    } else if (comments && c == '/' && i + 1 < text.size() && text[i + 1] == '*') {
      const std::size_t end = text.find("*/", i + 2);
      if (end == std::string_view::npos) break;
      i = end + 1;
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (opened()) return i;
    } else if (c == ']' || c == '}') {
      closed();
    }
  }
  return std::string_view::npos;
}

}  // namespace

std::size_t jsonDepthExcess(std::string_view text, int maxDepth, bool comments) {
  int depth = 0;
  return scanJsonBrackets(
      text, comments, [&] { return ++depth > maxDepth; },
      [&] {
        if (depth > 0) --depth;
      });
}

std::size_t jsonContainerExcess(std::string_view text, std::size_t maxContainers, bool comments) {
  std::size_t count = 0;
  return scanJsonBrackets(
      text, comments, [&] { return ++count > maxContainers; }, [] {});
}

}  // namespace sl
