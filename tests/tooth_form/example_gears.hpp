#pragma once
// The gears of issue 33 §1 for the tooth-form tests and the CSV writer: ha* = 1,
// hf* = 1.25, alpha = 20 deg (the basic rack's rho_f* is an option of tooth_form).
#include "gearhb/gears/geometry/gear_geometry.hpp"

namespace tooth_form_examples {

inline gearhb::GearGeometry spur(int z, double m, double x) {
  gearhb::GearGeometry g;
  g.teeth = z;
  g.module = m;
  g.profile_shift = x;
  g.addendum = 1.0 * m;
  g.dedendum = 1.25 * m;
  return g;
}
inline gearhb::GearGeometry thesis() { return spur(50, 3e-3, 0.0); }        // thesis §7.4
inline gearhb::GearGeometry fzg16() { return spur(16, 4.5e-3, 0.1817); }    // FZG type C pinion (DIN ISO 14635-1)
inline gearhb::GearGeometry fzg24() { return spur(24, 4.5e-3, 0.1715); }    // FZG type C wheel
inline gearhb::GearGeometry pinion10() { return spur(10, 3e-3, 0.0); }      // undercut (z_min = 17.1)

}  // namespace tooth_form_examples
