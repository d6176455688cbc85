// The output policy of every writer; see OutputFile.h.
#include "algo/OutputFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>

namespace sl {

namespace fs = std::filesystem;

namespace {

/// The folder a file goes into ("." for a bare name).
fs::path folderOf(const fs::path& path) {
  fs::path parent = path.parent_path();
  return parent.empty() ? fs::path(".") : parent;
}

/// The path symbolic links lead to (absolute; the parts that do not exist yet kept as given).
fs::path resolvedPath(const std::string& path) {
  std::error_code ec;
  fs::path abs = fs::absolute(path, ec);
  if (ec) return path;
  fs::path resolved = fs::weakly_canonical(abs, ec);
  return ec ? abs : resolved;
}

const char* specialKind(fs::file_type type) {
  switch (type) {
    case fs::file_type::fifo:
      return "a FIFO";
    case fs::file_type::character:
      return "a character device";
    case fs::file_type::block:
      return "a block device";
    case fs::file_type::socket:
      return "a socket";
    default:
      return "not a regular file";
  }
}

/// Where an output is written: the file a symbolic link leads to, else the path as given.
fs::path writtenPath(const std::string& path) {
  std::error_code ec;
  return fs::is_symlink(fs::symlink_status(path, ec)) ? resolvedPath(path) : fs::path(path);
}

std::string quoted(const std::string& path) {
  return "'" + path + "'";
}

/// What is wrong with an existing non-regular output, or nothing (written in place).
std::optional<std::string> nonRegularProblem(const OutputTarget& o, fs::file_type type) {
  if (!o.userNamed)
    return std::string(specialKind(type)) +
           ", not a regular file: refused (an output is a regular file, written to a "
           "temporary file and renamed)";
  if (type == fs::file_type::fifo && fifoWithoutReader(o.path))
    return std::string(
        "a FIFO that nothing reads (writing would wait forever): start its reader first");
  return std::nullopt;
}

}  // namespace

bool sameFile(const std::string& a, const std::string& b) {
  std::error_code ec;
  if (fs::equivalent(a, b, ec)) return true;
  return resolvedPath(a) == resolvedPath(b);
}

std::optional<std::string> probeOutputFolder(const fs::path& folder) {
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) {
    fs::create_directories(folder, ec);
    if (ec || !fs::is_directory(folder, ec))
      return "cannot create the folder '" + folder.string() + "' (" +
             (ec ? ec.message() : std::string("not a folder")) + ")";
  }
  const std::string probe = (folder / (".shadowlab-probe-" + std::to_string(getpid()))).string();
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) {
    const int err = errno;
    return "cannot write in the folder '" + folder.string() + "' (" + std::strerror(err) + ")";
  }
  ::close(fd);
  ::unlink(probe.c_str());
  return std::nullopt;
}

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

std::optional<std::string> checkOutputTargets(const std::vector<OutputTarget>& outputs,
                                              const std::vector<InputTarget>& inputs) {
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const OutputTarget& o = outputs[i];
    if (o.path.empty()) continue;
    const std::string head = o.name + ": " + quoted(o.path);
    for (std::size_t k = 0; k < i; ++k)
      if (!outputs[k].path.empty() && sameFile(outputs[k].path, o.path))
        return head + " is the same file as " + outputs[k].name +
               " (one would overwrite the other)";
    for (const InputTarget& in : inputs)
      if (!in.path.empty() && sameFile(in.path, o.path))
        return head + " is the same file as " + in.name + " (the input would be overwritten)";
    std::error_code ec;
    const fs::file_status st = fs::status(o.path, ec);
    if (fs::is_directory(st)) return head + " is a folder";
    if (fs::exists(st) && !fs::is_regular_file(st)) {
      if (auto why = nonRegularProblem(o, st.type())) return head + " is " + *why;
      if (::access(o.path.c_str(), W_OK) != 0)
        return head + " is not writable (" + std::strerror(errno) + ")";
      continue;  // a device or FIFO the user named: written in place
    }
    if (auto e = probeOutputFolder(folderOf(writtenPath(o.path)))) return o.name + ": " + *e;
  }
  return std::nullopt;
}

std::optional<std::string> writeFileBytes(const std::string& path, std::string_view bytes) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return path + ": cannot write (" + std::strerror(errno) + ")";
  bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
  int err = ok ? 0 : errno;
  if (std::fflush(f) != 0 && ok) ok = false, err = errno;
  if (std::fclose(f) != 0 && ok) ok = false, err = errno;
  if (!ok) return path + ": cannot write (" + std::strerror(err) + ")";
  return std::nullopt;
}

std::optional<std::string> writeOutputAtomically(
    const OutputTarget& target,
    const std::function<std::optional<std::string>(const std::string&)>& write) {
  const std::string& path = target.path;
  auto failure = [&](std::string why, const std::string& tmp) {
    // The writer's message names the temporary file: name the real one.
    for (std::size_t at; !tmp.empty() && (at = why.find(tmp)) != std::string::npos;)
      why.replace(at, tmp.size(), path);
    if (why.rfind(path, 0) != 0) why = path + ": " + why;
    return std::optional<std::string>(std::move(why));
  };
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (fs::is_directory(st)) return failure("is a folder: not written", "");
  if (fs::exists(st) && !fs::is_regular_file(st)) {  // /dev/null, /dev/stdout, a pipe
    if (auto why = nonRegularProblem(target, st.type())) return failure("is " + *why, "");
    if (auto e = write(path)) return failure(*e, "");
    return std::nullopt;
  }
  // Symbolic links resolved first: the file they lead to is replaced, not the link.
  const fs::path resolved = writtenPath(path);
  const fs::path folder = folderOf(resolved);
  fs::create_directories(folder, ec);
  if (ec)
    return failure("cannot create the folder '" + folder.string() + "' (" + ec.message() + ")", "");
  static std::atomic<int> counter{0};
  const fs::path name = resolved.filename();
  const std::string tmp =
      (folder / ("." + name.stem().string() + ".tmp" + std::to_string(getpid()) + "-" +
                 std::to_string(++counter) + name.extension().string()))
          .string();
  // Created here, new and empty (never a link or FIFO planted under that name).
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
  if (fd < 0)
    return failure(
        "cannot write in the folder '" + folder.string() + "' (" + std::strerror(errno) + ")", "");
  ::close(fd);
  if (auto e = write(tmp)) {
    fs::remove(tmp, ec);
    return failure(*e, tmp);
  }
  fs::rename(tmp, resolved, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    return failure("cannot write (" + ec.message() + ")", tmp);
  }
  return std::nullopt;
}

}  // namespace sl
