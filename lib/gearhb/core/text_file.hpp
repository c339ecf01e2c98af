#pragma once
// Reading a user's input file with bounds, so that no input can exhaust memory: the
// path must name a regular file (not a folder, a device such as /dev/zero, or a
// pipe) of at most `max_bytes`, and no line may be longer than `max_line` characters.
// Lines are returned without their terminator, a CRLF line ending accepted as LF.
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace gearhb {

// What is wrong with the file, in words (the caller adds the key that named it).
struct TextFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

constexpr std::size_t max_input_file_bytes = std::size_t(16) << 20;   // 16 MiB
constexpr std::size_t max_input_line = 4096;                           // characters

// The whole file. Throws TextFileError ("cannot be opened", "is a folder, not a file",
// "is not a regular file", "is larger than 16 MiB", "cannot be read (<reason>)", "holds a
// NUL byte": text files have none).
std::string read_text_file(const std::string& path, std::size_t max_bytes = max_input_file_bytes);

// TextFileError naming the first line of `text` longer than `max_line` characters.
void check_line_lengths(const std::string& text, std::size_t max_line = max_input_line);

// The file's lines (LF or CRLF), each at most `max_line` characters (TextFileError
// naming the line number otherwise).
std::vector<std::string> read_text_lines(const std::string& path, std::size_t max_bytes = max_input_file_bytes,
                                         std::size_t max_line = max_input_line);

}  // namespace gearhb
