#pragma once
// A static transmission error given as a file (your own gear, measured or from
// another program): CSV, one mesh cycle,
//
//     phase,ste_um
//     0,12.31
//     0.015625,12.35
//     ...
//
// phase in [0, 1) (fraction of the mesh cycle), uniform (phase_j = j / rows,
// to 1e-6), first row at 0; ste_um the loaded STE in micrometres. Blank lines
// and lines starting with '#' are skipped. Every violation throws
// SteFileError with one line naming the file and the line number.
#include <stdexcept>
#include <string>
#include <vector>

namespace gearhb {

struct SteFileError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

struct SteFile {
  std::vector<double> phase;   // [-]
  std::vector<double> ste;     // [m]
};

// min_rows: the least number of samples (2H+1 for H harmonics);
// require_positive: every STE > 0 (needed when the mesh stiffness is F / STE).
SteFile read_ste_file(const std::string& path, int min_rows, bool require_positive);

}  // namespace gearhb
