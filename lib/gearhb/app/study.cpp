#include "gearhb/app/study.hpp"

#include <cstdio>
#include <iostream>
#include <memory>
#include <new>
#include <sstream>
#include <stdexcept>

#include "gearhb/app/output_folder.hpp"
#include "gearhb/core/gsl_errors.hpp"

namespace gearhb {

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

// The length of the well-formed UTF-8 sequence at s[i] (RFC 3629: no overlong form, no
// surrogate, at most U+10FFFF), or 0 where the byte starts none.
namespace {

// The length of the well-formed UTF-8 sequence at s[i] (RFC 3629: no overlong form, no
// surrogate, at most U+10FFFF), or 0 where the byte starts none.
std::size_t utf8_sequence(const std::string& s, std::size_t i) {
  const auto byte = [&](std::size_t k) { return k < s.size() ? static_cast<unsigned char>(s[k]) : 0u; };
  const unsigned c = byte(i);
  const auto cont = [&](std::size_t k, unsigned lo = 0x80, unsigned hi = 0xbf) { return byte(k) >= lo && byte(k) <= hi; };
  if (c < 0x80) return 1;
  if (c >= 0xc2 && c <= 0xdf) return cont(i + 1) ? 2 : 0;
  if (c >= 0xe0 && c <= 0xef) {
    const unsigned lo = c == 0xe0 ? 0xa0 : 0x80, hi = c == 0xed ? 0x9f : 0xbf;
    return cont(i + 1, lo, hi) && cont(i + 2) ? 3 : 0;
  }
  if (c >= 0xf0 && c <= 0xf4) {
    const unsigned lo = c == 0xf0 ? 0x90 : 0x80, hi = c == 0xf4 ? 0x8f : 0xbf;
    return cont(i + 1, lo, hi) && cont(i + 2) && cont(i + 3) ? 4 : 0;
  }
  return 0;
}

}  // namespace

std::string one_line(const std::string& message) {
  std::string out;
  for (std::size_t i = 0; i < message.size();) {
    const auto c = static_cast<unsigned char>(message[i]);
    const std::size_t n = utf8_sequence(message, i);
    if (n > 1 || (n == 1 && c >= 0x20 && c != 0x7f)) {
      out.append(message, i, n);
      i += n;
      continue;
    }
    if (c == '\n') {
      out += "\\n";
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", unsigned(c));
      out += buf;
    }
    ++i;
  }
  return out;
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

}  // namespace

int Study::run(int argc, char** argv, const std::function<void(Run&)>& steps) {
  const std::string default_out = "build/data/" + program_;
  Parsed p;
  std::unique_ptr<OutputFolder> out;
  try {
    p = parse(argc, argv, params_, labels_, default_out, positional_name_);
    positional_ = p.positional;
    if (p.help) {
      std::cout << help_text();
      return 0;
    }
    if (checks_) checks_(p.selection);
    out = std::make_unique<OutputFolder>(p.out, program_);
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
    Run run(program_, p.selection, out->staging().string(), p.quiet);
    run.write_text("params.json", params_.to_json().dump(2) + "\n");
    steps(run);
    run.write_text("key_numbers.json", run.key_numbers().json().dump(2) + "\n");
    run.write("timings.csv", run.timings_);
    out->publish();
  } catch (const std::exception& e) {
    out.reset();   // removes the staging folder: DIR is left as it was
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

void draw_with_script(Run& run, const std::string& script, const std::string& what) {
  // the script reads the key numbers too: written into the staging folder now (the frame
  // rewrites the same file once the steps are done)
  run.write_text("key_numbers.json", run.key_numbers().json().dump(2) + "\n");
  if (script.empty() || !run_program_quietly({"/usr/bin/python3", script, run.staging_path()}))
    run.say(what + " not drawn (needs /usr/bin/python3 with matplotlib; --set plot=0 skips it)");
}

}  // namespace gearhb
