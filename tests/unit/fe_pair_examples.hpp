#pragma once
// The three pairs of issue 33's table for the FE tooth-contact tests and benchmark, as in
// programs/gearhb_gear/examples/{thesis_pair,fzg_c,ross_pair}.json.
#include <array>
#include <vector>

#include "../tooth_form/example_gears.hpp"
#include "gearhb/gears/pair/fe_tooth_contact.hpp"

namespace fe_pair_examples {

struct PairCase {
  const char* name;
  gearhb::PairSteModel pair;
  gearhb::FePairOptions fe;
  std::array<double, 3> torques;   // the file's torques T1 [N m]
  double torque() const { return torques[2]; }
};

inline gearhb::GearGeometry with_width(gearhb::GearGeometry g, double b) {
  g.face_width = b;
  return g;
}

inline std::vector<PairCase> issue_pairs() {
  using namespace tooth_form_examples;
  std::vector<PairCase> out(3);
  out[0].name = "thesis 50/50 m 3";
  out[0].pair.gear1 = out[0].pair.gear2 = with_width(thesis(), 0.02);
  out[0].pair.youngs_modulus1 = out[0].pair.youngs_modulus2 = 207e9;
  out[0].torques = {100, 200, 300};
  out[1].name = "FZG C 16/24 m 4.5";
  out[1].pair.gear1 = with_width(fzg16(), 0.014);
  out[1].pair.gear2 = with_width(fzg24(), 0.014);
  out[1].pair.centre_distance = 0.0915;
  out[1].pair.youngs_modulus1 = out[1].pair.youngs_modulus2 = 206e9;
  out[1].torques = {94.1, 183.4, 302.0};
  out[2].name = "ROSS 62/62 m 2";
  out[2].pair.gear1 = out[2].pair.gear2 = with_width(spur(62, 2e-3, 0.0), 0.02);
  out[2].pair.youngs_modulus1 = out[2].pair.youngs_modulus2 = 206e9;
  out[2].fe.gear1.rim_radius = out[2].fe.gear2.rim_radius = 0.0175;
  out[2].torques = {50, 100, 200};
  return out;
}

}  // namespace fe_pair_examples
