#pragma once
// Writing a program's results (README "Output files"): CSV tables with a header
// row, key_numbers.json, and the echo of the parameters. Every file is written
// atomically (temporary file in the same folder, fsync, then rename), so a crash
// never leaves a half-written file behind. A non-finite number (inf, NaN) in a
// table or a key number is an error naming the column or key: it is never written.
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

namespace gearhb {

// Write `content` to `path` through a temporary file and a rename.
// Creates the parent folders. Throws std::runtime_error on I/O failure.
void write_file_atomic(const std::string& path, const std::string& content);

// Run a helper program (e.g. a figure script) with its arguments passed as they are:
// no shell, so no character of a path can become a command. Its stdout and stderr go
// to /dev/null. Returns true when it ran and exited with status 0.
bool run_program_quietly(const std::vector<std::string>& argv);

// A CSV table: named columns, rows of numbers or short strings.
class Table {
 public:
  using Cell = std::variant<double, long, std::string>;
  explicit Table(std::vector<std::string> columns);
  void add_row(std::vector<Cell> row);   // must match the column count; finite numbers only
  void append(const Table& more);         // its rows; its columns must be these
  std::size_t rows() const { return rows_.size(); }
  std::string to_csv() const;            // %.10g numbers, header first
  void write(const std::string& path) const { write_file_atomic(path, to_csv()); }

 private:
  std::vector<std::string> columns_;
  std::vector<std::vector<Cell>> rows_;
};

// A number, or an empty cell when it was not computed or does not exist (e.g. the
// band of a contact state that never occurs); read back as NaN by figures/style.py.
Table::Cell cell(bool computed, double v);

// The numbers that reference/<chapter>.json checks: {"name": {"value", "unit"}}.
class KeyNumbers {
 public:
  void add(const std::string& name, double value, const std::string& unit);
  const nlohmann::json& json() const { return j_; }
  void write(const std::string& path) const { write_file_atomic(path, j_.dump(2) + "\n"); }

 private:
  nlohmann::json j_ = nlohmann::json::object();
};

}  // namespace gearhb
