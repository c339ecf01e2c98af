#include "gearhb/app/output.hpp"

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>
#include <cmath>

extern char** environ;

namespace gearhb {

bool run_program_quietly(const std::vector<std::string>& argv) {
  if (argv.empty()) return false;
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t io;
  posix_spawn_file_actions_init(&io);
  posix_spawn_file_actions_addopen(&io, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&io, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, args[0], &io, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&io);
  if (spawned != 0) return false;
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return false;
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

void write_file_atomic(const std::string& path, const std::string& content) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  if (target.has_parent_path()) fs::create_directories(target.parent_path());
  const fs::path tmp = target.string() + ".tmp." + std::to_string(::getpid());
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (!f) throw std::runtime_error("cannot open " + tmp.string() + " for writing");
    f << content;
    f.flush();
    if (!f) {
      f.close();
      fs::remove(tmp);
      throw std::runtime_error("write failed: " + tmp.string());
    }
  }
  // On disk before the rename, so a crash never leaves a renamed empty file.
  const int fd = ::open(tmp.c_str(), O_RDONLY);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
  std::error_code ec;
  fs::rename(tmp, target, ec);
  if (ec) {
    fs::remove(tmp);
    throw std::runtime_error("cannot rename " + tmp.string() + " to " + path + ": " + ec.message());
  }
}

Table::Table(std::vector<std::string> columns) : columns_(std::move(columns)) {}

void Table::append(const Table& more) {
  if (more.columns_ != columns_) throw std::logic_error("Table::append: other columns");
  for (const auto& r : more.rows_) rows_.push_back(r);
}

void Table::add_row(std::vector<Cell> row) {
  if (row.size() != columns_.size())
    throw std::logic_error("Table::add_row: row has " + std::to_string(row.size()) +
                           " cells, table has " + std::to_string(columns_.size()) + " columns");
  // A non-finite number is an error of the run that computed it, never data.
  for (std::size_t c = 0; c < row.size(); ++c)
    if (const double* d = std::get_if<double>(&row[c]); d && !std::isfinite(*d))
      throw std::runtime_error("non-finite value (" + std::to_string(*d) + ") in column '" + columns_[c] +
                               "', row " + std::to_string(rows_.size() + 1));
  rows_.push_back(std::move(row));
}

std::string Table::to_csv() const {
  std::string out;
  for (std::size_t c = 0; c < columns_.size(); ++c) out += (c ? "," : "") + columns_[c];
  out += "\n";
  char buf[64];
  for (const auto& row : rows_) {
    for (std::size_t c = 0; c < row.size(); ++c) {
      if (c) out += ",";
      if (const double* d = std::get_if<double>(&row[c])) {
        std::snprintf(buf, sizeof buf, "%.10g", *d);
        out += buf;
      } else if (const long* l = std::get_if<long>(&row[c])) {
        out += std::to_string(*l);
      } else {
        out += std::get<std::string>(row[c]);
      }
    }
    out += "\n";
  }
  return out;
}

Table::Cell cell(bool computed, double v) { return computed ? Table::Cell(v) : Table::Cell(std::string()); }

void KeyNumbers::add(const std::string& name, double value, const std::string& unit) {
  if (!std::isfinite(value))
    throw std::runtime_error("key number '" + name + "' is not finite (" + std::to_string(value) + ")");
  j_[name] = {{"value", value}, {"unit", unit}};
}

}  // namespace gearhb
