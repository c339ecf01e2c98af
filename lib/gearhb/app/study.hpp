#pragma once
// The frame every chapter program runs in (README "Running a chapter").
//
//   chNN_name [--case all|quick|own|LABEL] [--out DIR] [--set key=value]... [--quiet] [--help]
//
//   --case all    every case of the chapter: the data of every figure (default)
//   --case quick  the regression subset CTest runs: the same steps on fewer or cheaper cases
//   --case own    one case with your own parameters (the "own case" group of --help)
//   --case LABEL  one case of the chapter's case table
//
// A chapter program is a class whose steps are short functions; its main() builds a
// Study, registers its parameter structs and its case labels, and hands its steps to
// Study::run. The study
//   1. parses the command line and validates every parameter (ranges, then the
//      chapter's cross-parameter checks) before anything is written: bad input is
//      one line on stderr and exit status 2;
//   2. runs the steps with a Run, which writes every file into this run's own staging
//      folder next to DIR (app/output_folder.hpp: unique per run, locked while the run
//      lives, removed by a later run if this one was killed);
//   3. on success publishes the staging folder as DIR in one step and prints the wall
//      time; on failure (exit 1, one line saying where and why) removes the staging
//      folder, so DIR is left as it was. Error lines are valid UTF-8 (bytes that are
//      not are shown escaped).
// Every run writes params.json (the parameters used), key_numbers.json and
// timings.csv (wall-clock seconds per step: the only file that differs between runs).
#include <chrono>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include "gearhb/app/cli.hpp"
#include "gearhb/app/output.hpp"
#include "gearhb/hb/continuation.hpp"

namespace gearhb {

// What a run computes.
struct Selection {
  enum class Kind { all, quick, own, one } kind = Kind::all;
  std::string label;   // the case, for Kind::one
};

// Handed to a chapter's steps: what to compute and where its files go.
class Run {
 public:
  Run(std::string program, Selection selection, std::string staging, bool quiet);

  const Selection& selection() const { return sel_; }
  bool quick() const { return sel_.kind == Selection::Kind::quick; }
  bool own() const { return sel_.kind == Selection::Kind::own; }
  // The chapter-wide steps (linear references, checks, studies) run for all and quick.
  bool whole_chapter() const { return sel_.kind == Selection::Kind::all || quick(); }
  // Whether the case `label` of the case table is computed in this run
  // (all: every case; quick: those the chapter marked quick; LABEL: that one).
  bool wants(const std::string& label, bool in_quick_subset) const;

  // Files (names relative to the output folder; written atomically into staging).
  void write(const std::string& file, const Table& table) const;
  void write_text(const std::string& file, const std::string& text) const;
  KeyNumbers& key_numbers() { return key_; }
  // The staging folder (for a tool that writes into it itself, e.g. a plot script).
  const std::string& staging_path() const { return staging_; }

  // Narration on stdout ("<program>: <line>") and a progress line on stderr
  // (at most one a second, none with --quiet).
  void say(const std::string& line) const;
  void progress(const std::string& what, long point, double omega, double step);
  // A continuation progress callback that reports through progress() as `what`.
  std::function<void(const ContinuationProgress&)> progress_of(const std::string& what);

  // Time one step: runs f(), records its wall-clock seconds in timings.csv.
  template <class F>
  auto timed(const std::string& what, F&& f) {
    const auto t0 = std::chrono::steady_clock::now();
    struct Record {
      Run* run; std::string what; std::chrono::steady_clock::time_point t0;
      ~Record() { run->timings_.add_row({what, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()}); }
    } record{this, what, t0};
    return f();
  }

 private:
  friend class Study;
  std::string program_;
  Selection sel_;
  std::string staging_;
  bool quiet_;
  KeyNumbers key_;
  Table timings_{{"step", "seconds"}};
  std::chrono::steady_clock::time_point last_progress_{};
};

class Study {
 public:
  // program: the executable's name; banner: the equation and what the program makes
  // (printed by --help). The default output folder is build/data/<program>.
  Study(std::string program, std::string banner);

  ParameterSet& parameters() { return params_; }
  // The chapter's case labels, and which of them form the quick subset.
  void cases(const std::vector<std::string>& labels, const std::vector<std::string>& quick);
  // The program takes one positional argument (e.g. a model file), named `what`
  // in --help; available from positional() once the command line is parsed.
  void positional(const std::string& what) { positional_name_ = what; }
  const std::string& positional() const { return positional_; }
  // Cross-parameter checks (throw UsageError through ParameterSet::require); run
  // after --set and the range checks, before anything is written.
  void check(std::function<void(const Selection&)> checks) { checks_ = std::move(checks); }

  // Parse, validate, run `steps`, publish. Returns the exit status (0, 1 or 2).
  int run(int argc, char** argv, const std::function<void(Run&)>& steps);

 private:
  std::string program_, banner_;
  ParameterSet params_;
  std::vector<std::string> labels_;
  std::set<std::string> quick_;
  std::function<void(const Selection&)> checks_;
  std::string positional_name_, positional_;
  std::string help_text() const;
};

// A program that reads one input file (gearhb_frc's model, gearhb_gear's gear pair):
// registers the file as the positional argument `what`, lets --set PATH=VALUE address
// the file (ParameterSet::keep_unregistered), adds the `plot` switch (1 draw the
// figures, 0 data only) and runs `read` among the study's checks, so a bad file
// exits 2 before anything is written.
void file_program(Study& study, const std::string& what, bool* plot, std::function<void()> read);

// A message as one line of valid UTF-8, whatever the user's input held: a control
// character (a newline in a value) and a byte that is not UTF-8 (RFC 3629: overlong
// forms, surrogates and code points beyond U+10FFFF are not) are shown escaped as
// \n and \xNN. Every error line of the frame passes through it.
std::string one_line(const std::string& message);

// Draw the figures of a run: /usr/bin/python3 SCRIPT STAGING (the script writes its
// PNGs into the staging folder), after writing the key numbers so far into it (scripts read
// them: the ranges with no stable period-1 orbit; gearhb_planetary's figures lacked them).
// Says `what` was not drawn when the script is empty or fails; never fails the run.
void draw_with_script(Run& run, const std::string& script, const std::string& what);

}  // namespace gearhb
