#include "gearhb/app/study.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <new>
#include <sstream>
#include <stdexcept>

#include "gearhb/core/gsl_errors.hpp"

namespace gearhb {

namespace fs = std::filesystem;

// --- Run ------------------------------------------------------------------------

Run::Run(std::string program, Selection selection, std::string staging, bool quiet)
    : program_(std::move(program)), sel_(std::move(selection)), staging_(std::move(staging)), quiet_(quiet) {}

bool Run::wants(const std::string& label, bool in_quick_subset) const {
  switch (sel_.kind) {
    case Selection::Kind::all: return true;
    case Selection::Kind::quick: return in_quick_subset;
    case Selection::Kind::own: return false;
    case Selection::Kind::one: return label == sel_.label;
  }
  return false;
}

void Run::write(const std::string& file, const Table& table) const {
  write_file_atomic(staging_ + "/" + file, table.to_csv());
}

void Run::write_text(const std::string& file, const std::string& text) const {
  write_file_atomic(staging_ + "/" + file, text);
}

void Run::say(const std::string& line) const { std::cout << program_ << ": " << line << std::endl; }

void Run::progress(const std::string& what, long point, double omega, double step) {
  if (quiet_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_progress_ < std::chrono::seconds(1)) return;
  last_progress_ = now;
  std::fprintf(stderr, "%s: %s: point %ld, omega = %.6g rad/s, step %.3g\n", program_.c_str(), what.c_str(),
               point, omega, step);
}

std::function<void(const ContinuationProgress&)> Run::progress_of(const std::string& what) {
  return [this, what](const ContinuationProgress& p) { progress(what, p.point, p.omega, p.ds); };
}

// --- Study ----------------------------------------------------------------------

Study::Study(std::string program, std::string banner)
    : program_(std::move(program)), banner_(std::move(banner)) {}

void Study::cases(const std::vector<std::string>& labels, const std::vector<std::string>& quick) {
  labels_ = labels;
  quick_ = std::set<std::string>(quick.begin(), quick.end());
}

std::string Study::help_text() const {
  std::ostringstream os;
  os << banner_ << "\n\n"
     << "Usage: " << program_ << (positional_name_.empty() ? "" : " " + positional_name_)
     << (labels_.empty() ? "" : " [--case all|quick|own|LABEL]") << " [--out DIR] [--set key=value]... [--quiet]\n"
     << "Options:\n";
  if (!labels_.empty()) {
    os << "  --case all     every case of the chapter: the data of every figure (default)\n"
       << "  --case quick   the regression subset run by CTest\n"
       << "  --case own     one case with your parameters (the 'own case' group below)\n"
       << "  --case LABEL   one case of the chapter's table:";
    for (const auto& l : labels_) os << " " << l;
    os << "\n";
  }
  os << "  --out DIR      output folder (default build/data/" << program_ << ")\n"
     << "  --set k=v      override one parameter (repeatable)\n"
     << "  --quiet        no progress lines on stderr\n"
     << "  --help         this text\n\n"
     << params_.help_text();
  return os.str();
}

namespace {

struct Parsed {
  Selection selection;
  std::string out, positional;
  bool help = false, quiet = false;
};

Parsed parse(int argc, char** argv, ParameterSet& params, const std::vector<std::string>& labels,
             const std::string& default_out, const std::string& positional_name) {
  Parsed p;
  p.out = default_out;
  std::string which = "all";
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    auto value = [&](const std::string& flag) -> std::string {
      if (arg.size() > flag.size() && arg.compare(0, flag.size() + 1, flag + "=") == 0)
        return arg.substr(flag.size() + 1);
      if (a + 1 >= argc) throw UsageError(flag + " expects a value");
      return argv[++a];
    };
    auto is = [&](const std::string& flag) { return arg == flag || arg.rfind(flag + "=", 0) == 0; };
    if (arg == "--help" || arg == "-h") p.help = true;
    else if (arg == "--quiet") p.quiet = true;
    else if (is("--out")) p.out = value("--out");
    else if (is("--set")) params.set(value("--set"));
    else if (is("--case")) which = value("--case");
    else if (!positional_name.empty() && p.positional.empty() && !arg.empty() && arg[0] != '-') p.positional = arg;
    else throw UsageError("unknown argument '" + arg + "' (see --help)");
  }
  if (!positional_name.empty() && p.positional.empty() && !p.help)
    throw UsageError("missing " + positional_name + " (see --help)");
  if (p.out.empty()) throw UsageError("--out needs a non-empty folder name");
  if (which == "all") p.selection.kind = Selection::Kind::all;
  else if (which == "quick") p.selection.kind = Selection::Kind::quick;
  else if (which == "own") p.selection.kind = Selection::Kind::own;
  else {
    bool known = false;
    for (const auto& l : labels) known = known || l == which;
    if (!known) throw UsageError("--case '" + which + "' is not all, quick, own or a case of this chapter (see --help)");
    p.selection = {Selection::Kind::one, which};
  }
  params.validate();
  if (p.selection.kind != Selection::Kind::own) {
    const auto own = params.overridden_own_case();
    if (!own.empty())
      throw UsageError("parameter '" + own.front() + "' sets the own case: add --case own");
  }
  return p;
}

// A message is one line: a control character of the user's input (a newline in a
// value) is shown escaped, never printed.
std::string one_line(const std::string& message) {
  std::string out;
  for (const unsigned char c : message) {
    if (c >= 0x20 && c != 0x7f) {
      out.push_back(char(c));
    } else if (c == '\n') {
      out += "\\n";
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", unsigned(c));
      out += buf;
    }
  }
  return out;
}

// The output folder as an absolute, normalised path without a trailing separator.
fs::path output_folder(const std::string& out) {
  fs::path abs = fs::absolute(out).lexically_normal();
  if (abs.filename().empty()) abs = abs.parent_path();
  if (abs.filename().empty() || abs == abs.root_path() || abs.filename() == "." || abs.filename() == "..")
    throw UsageError("--out '" + out + "' does not name a folder");
  return abs;
}

// The staging folder beside the output folder: ".<name>.staging".
fs::path staging_for(const fs::path& folder) {
  return folder.parent_path() / ("." + folder.filename().string() + ".staging");
}

// DIR is replaced as a whole by a run, so it must be empty or hold an earlier run's
// output (its key_numbers.json): a user's folder of other files is never swept away.
void check_replaceable(const fs::path& folder, const std::string& out) {
  std::error_code ec;
  const auto status = fs::symlink_status(folder, ec);
  if (ec || status.type() == fs::file_type::not_found) return;
  if (status.type() != fs::file_type::directory)
    throw UsageError("--out '" + out + "' is not a folder");
  if (!fs::is_empty(folder, ec) && !fs::exists(folder / "key_numbers.json"))
    throw UsageError("--out '" + out + "' holds files that are not a gearhb run's output (no key_numbers.json): "
                     "choose an empty or new folder");
}

// Test hook (tests/publish_kill.sh): GEARHB_PUBLISH_KILL_AT=staged|swapped kills the
// process with SIGKILL at that point of publish(), to show DIR is never half written.
void kill_point(const char* where) {
  const char* at = std::getenv("GEARHB_PUBLISH_KILL_AT");
  if (at != nullptr && std::strcmp(at, where) == 0) std::raise(SIGKILL);
}

void sync_folder(const fs::path& folder) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

// Publish the whole staging folder as DIR in one atomic step, so that DIR is always
// exactly one run's complete output: rename it onto a DIR that does not exist, or
// swap the two folders (Linux renameat2 RENAME_EXCHANGE) and remove the old output,
// now in the staging folder's place. Where the file system cannot swap, DIR is moved
// aside first (a kill between the two renames leaves no DIR, never a mixed one).
void publish(const fs::path& staging, const fs::path& folder) {
  sync_folder(staging);
  kill_point("staged");
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(folder, ec))) {
    fs::rename(staging, folder);
  } else if (::renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, folder.c_str(), RENAME_EXCHANGE) != 0) {
    if (errno != EINVAL && errno != ENOSYS)
      throw std::runtime_error("cannot publish " + folder.string() + ": " + std::strerror(errno));
    const fs::path aside = folder.parent_path() / ("." + folder.filename().string() + ".old");
    fs::remove_all(aside, ec);
    fs::rename(folder, aside);
    fs::rename(staging, folder);
    fs::rename(aside, staging);
  }
  sync_folder(folder.parent_path());
  kill_point("swapped");
  fs::remove_all(staging);   // the previous output
}

}  // namespace

int Study::run(int argc, char** argv, const std::function<void(Run&)>& steps) {
  const std::string default_out = "build/data/" + program_;
  Parsed p;
  fs::path folder, staging;
  try {
    p = parse(argc, argv, params_, labels_, default_out, positional_name_);
    positional_ = p.positional;
    if (p.help) {
      std::cout << help_text();
      return 0;
    }
    if (checks_) checks_(p.selection);
    folder = output_folder(p.out);
    check_replaceable(folder, p.out);
    staging = staging_for(folder);
    // The output folder must be writable: make the staging folder now (a killed run's is removed).
    std::error_code ec;
    fs::remove_all(staging, ec);
    fs::remove_all(folder.parent_path() / ("." + folder.filename().string() + ".old"), ec);
    fs::create_directories(staging, ec);
    if (ec) throw UsageError("--out '" + p.out + "': cannot write there (" + ec.message() + ")");
  } catch (const UsageError& e) {
    std::cerr << program_ << ": error: " << one_line(e.what()) << "\n";
    return 2;
  } catch (const std::exception& e) {   // a check that failed for another reason
    std::cerr << program_ << ": failed: " << one_line(e.what()) << "\n";
    return 1;
  }
  const auto t0 = std::chrono::steady_clock::now();
  GslErrorsReturned gsl_policy;
  try {
    Run run(program_, p.selection, staging.string(), p.quiet);
    run.write_text("params.json", params_.to_json().dump(2) + "\n");
    steps(run);
    run.key_numbers().write((staging / "key_numbers.json").string());
    run.write("timings.csv", run.timings_);
    publish(staging, folder);
  } catch (const std::exception& e) {
    std::error_code ec;
    fs::remove_all(staging, ec);
    const bool usage = dynamic_cast<const UsageError*>(&e) != nullptr;
    const bool memory = dynamic_cast<const std::bad_alloc*>(&e) != nullptr;
    std::cerr << program_ << (usage ? ": error: " : ": failed: ")
              << (memory ? "out of memory (reduce H, N or the number of points)" : one_line(e.what())) << "\n";
    return usage ? 2 : 1;
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("%s: done in %.1f s, data in %s\n", program_.c_str(), secs, p.out.c_str());
  return 0;
}

void file_program(Study& study, const std::string& what, bool* plot, std::function<void()> read) {
  ParameterSet& P = study.parameters();
  P.keep_unregistered();   // --set PATH=VALUE addresses the file
  P.group("program");
  P.add("plot", plot, "-", "1 draw the figures into DIR (needs python3-matplotlib), 0 data only");
  study.positional(what);
  study.check([read = std::move(read)](const Selection&) { read(); });
}

void draw_with_script(const Run& run, const std::string& script, const std::string& what) {
  if (script.empty() || !run_program_quietly({"/usr/bin/python3", script, run.staging_path()}))
    run.say(what + " not drawn (needs /usr/bin/python3 with matplotlib; --set plot=0 skips it)");
}

}  // namespace gearhb
