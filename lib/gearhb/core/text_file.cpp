#include "gearhb/core/text_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace gearhb {

namespace {

// The file's bytes through read(2), at most max_bytes + 1 of them (a file may grow after
// stat(), and /proc files report size 0): a read error is a TextFileError naming it,
// never a stream exception.
std::string read_bytes(int fd, std::size_t max_bytes) {
  std::string text;
  char buf[1 << 16];
  while (text.size() <= max_bytes) {
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      throw TextFileError(std::string("cannot be read (") + std::strerror(errno) + ")");
    }
    text.append(buf, std::size_t(n));
  }
  return text;
}

}  // namespace

std::string read_text_file(const std::string& path, std::size_t max_bytes) {
  const std::string too_large = "is larger than " + std::to_string(max_bytes >> 20) + " MiB";
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) throw TextFileError("cannot be opened (no such file?)");
  if (S_ISDIR(st.st_mode)) throw TextFileError("is a folder, not a file");
  if (!S_ISREG(st.st_mode)) throw TextFileError("is not a regular file (a device or a pipe?)");
  if (std::size_t(st.st_size) > max_bytes) throw TextFileError(too_large);
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) throw TextFileError(std::string("cannot be opened (") + std::strerror(errno) + ")");
  std::string text;
  try {
    text = read_bytes(fd, max_bytes);
  } catch (...) {
    ::close(fd);
    throw;
  }
  ::close(fd);
  if (text.size() > max_bytes) throw TextFileError(too_large);
  // Text has no NUL: a parser would stop there and ignore the rest without a word.
  if (const auto nul = text.find('\0'); nul != std::string::npos)
    throw TextFileError("holds a NUL byte (byte " + std::to_string(nul + 1) + "): not a text file");
  return text;
}

void check_line_lengths(const std::string& text, std::size_t max_line) {
  std::size_t line = 1, start = 0;
  while (start <= text.size()) {
    std::size_t stop = text.find('\n', start);
    if (stop == std::string::npos) stop = text.size();
    std::size_t len = stop - start;
    if (len > 0 && text[start + len - 1] == '\r') --len;
    if (len > max_line)
      throw TextFileError("line " + std::to_string(line) + " is longer than " + std::to_string(max_line) +
                          " characters");
    start = stop + 1;
    ++line;
  }
}

std::vector<std::string> read_text_lines(const std::string& path, std::size_t max_bytes, std::size_t max_line) {
  const std::string text = read_text_file(path, max_bytes);
  check_line_lengths(text, max_line);
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t stop = text.find('\n', start);
    if (stop == std::string::npos) stop = text.size();
    std::size_t len = stop - start;
    if (len > 0 && text[start + len - 1] == '\r') --len;
    lines.push_back(text.substr(start, len));
    start = stop + 1;
  }
  return lines;
}

}  // namespace gearhb
