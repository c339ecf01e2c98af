#include "gearhb/core/text_file.hpp"

#include <sys/stat.h>

#include <fstream>
#include <iterator>

namespace gearhb {

std::string read_text_file(const std::string& path, std::size_t max_bytes) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) throw TextFileError("cannot be opened (no such file?)");
  if (S_ISDIR(st.st_mode)) throw TextFileError("is a folder, not a file");
  if (!S_ISREG(st.st_mode)) throw TextFileError("is not a regular file (a device or a pipe?)");
  if (std::size_t(st.st_size) > max_bytes)
    throw TextFileError("is larger than " + std::to_string(max_bytes >> 20) + " MiB");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw TextFileError("cannot be opened");
  std::string text;
  text.reserve(std::size_t(st.st_size));
  // read at most max_bytes + 1 even if the file grew after stat()
  std::istreambuf_iterator<char> it(in), end;
  for (; it != end && text.size() <= max_bytes; ++it) text.push_back(*it);
  if (text.size() > max_bytes) throw TextFileError("is larger than " + std::to_string(max_bytes >> 20) + " MiB");
  return text;
}

std::vector<std::string> read_text_lines(const std::string& path, std::size_t max_bytes, std::size_t max_line) {
  const std::string text = read_text_file(path, max_bytes);
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t stop = text.find('\n', start);
    if (stop == std::string::npos) stop = text.size();
    std::size_t len = stop - start;
    if (len > 0 && text[start + len - 1] == '\r') --len;
    if (len > max_line)
      throw TextFileError("line " + std::to_string(lines.size() + 1) + " is longer than " +
                          std::to_string(max_line) + " characters");
    lines.push_back(text.substr(start, len));
    start = stop + 1;
  }
  return lines;
}

}  // namespace gearhb
