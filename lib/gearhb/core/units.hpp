#pragma once
// Units: SI throughout, angles in radians, `omega` always an angular frequency [rad/s]
// (README "Glossary"). The one conversion the tables need, declared once.
#include <cmath>

namespace gearhb {

// An angular frequency omega [rad/s] in Hz: omega / (2 pi) (a mesh frequency f_mesh_hz).
inline double hz(double omega) { return omega / (2.0 * M_PI); }

}  // namespace gearhb
