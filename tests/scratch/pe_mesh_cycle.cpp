// Scratch comparison (not a test): potential-energy mesh stiffness k(phase) over one
// mesh cycle of a standard spur pair, one pair / two pairs in contact, k = the sum of the
// pair stiffnesses in contact (no load sharing, no relief: the rigid-contact reading
// most of the PE literature and ROSS use). Prints the single-pair stiffness at the pitch
// point, min / max / mean k over the cycle, for the thesis gear (several bore radii, both
// elasticity choices, both root angles) and for ROSS's 62/62 test gear.
// Build: cmake --build build --target pe_mesh_cycle_scratch && build/bin/pe_mesh_cycle_scratch
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gearhb/gears/geometry/gear_geometry.hpp"
#include "gearhb/gears/tooth/potential_energy.hpp"

using namespace gearhb;

namespace {

struct Cycle {
  double contact_ratio = 0, k_pitch = 0, k_min = 0, k_max = 0, k_mean = 0;
};

// Identical standard gears at the standard centre distance: the path of contact and the
// contact radii from gear_geometry (thesis ch. 7 geometry).
Cycle mesh_cycle(const PeGear& g, const PeOptions& o, int phases) {
  GearGeometry gg;
  gg.module = g.module;
  gg.teeth = g.teeth;
  gg.pressure_angle_deg = g.pressure_angle * 180 / M_PI;
  gg.addendum = g.addendum_coefficient * g.module;
  gg.dedendum = g.dedendum_coefficient * g.module;
  gg.face_width = g.face_width;
  const PathOfContact path = path_of_contact(gg, gg);
  const auto pair = [&](double s) {
    const ContactRadii r = contact_radii(gg, gg, s);
    return pe_pair_stiffness(g, g, r.r1, r.r2, true, o);
  };
  Cycle c;
  c.contact_ratio = path.contact_ratio;
  c.k_pitch = pair(path.T1C - path.T1A);
  c.k_min = 1e300;
  double sum = 0;
  for (int i = 0; i < phases; ++i) {
    double k = 0;   // midpoint rule over one base pitch; every pair on the path adds
    for (double s = (i + 0.5) * path.base_pitch / phases; s <= path.AE; s += path.base_pitch) k += pair(s);
    c.k_min = std::min(c.k_min, k);
    c.k_max = std::max(c.k_max, k);
    sum += k;
  }
  c.k_mean = sum / phases;
  return c;
}

void print(const char* name, const Cycle& c) {
  std::printf("%-58s eps %.6f  pair@pitch %7.2f  min %7.2f  max %7.2f  mean %7.2f MN/m\n", name, c.contact_ratio,
              c.k_pitch / 1e6, c.k_min / 1e6, c.k_max / 1e6, c.k_mean / 1e6);
}

// The four model variants (plane strain / stress, generated / beam root angle) of one gear.
void variants(const char* label, const PeGear& g, int phases) {
  for (PeElasticity e : {PeElasticity::plane_strain, PeElasticity::plane_stress})
    for (PeRootAngle ra : {PeRootAngle::generated_fillet, PeRootAngle::beam_root}) {
      PeOptions o;
      o.elasticity = e;
      o.root_angle = ra;
      const PeToothGeometry t = pe_tooth_geometry(g, ra);
      char name[160];
      std::snprintf(name, sizeof name, "%s h_f %.2f theta_f %.4f %s %s%s", label, t.h_f, t.theta_f,
                    e == PeElasticity::plane_strain ? "strain" : "stress",
                    ra == PeRootAngle::generated_fillet ? "gen" : "beam",
                    pe_fillet_in_range(t.h_f, t.theta_f) ? "" : " (out of fit)");
      print(name, mesh_cycle(g, o, phases));
    }
}

}  // namespace

int main() {
  const int phases = 4096;
  // Thesis gear (ch. 7): z 50, m 3 mm, 20 deg, ha* 1, hf* 1.25, b 20 mm, E 207 GPa, nu 0.3;
  // rho_f* 0.38 and the bore are not in the thesis: assumed and varied.
  PeGear thesis;
  thesis.youngs_modulus = 207e9;
  for (double bore : {0.0125, 0.025, 0.035, 0.045}) {
    thesis.bore_radius = bore;
    char label[64];
    std::snprintf(label, sizeof label, "thesis r_int %4.1f mm", bore * 1e3);
    variants(label, thesis, phases);
  }
  PeOptions nofillet;
  nofillet.fillet_foundation = false;
  print("thesis without fillet foundation (strain)", mesh_cycle(thesis, nofillet, phases));

  // ROSS test gear (petrobras/ross tests/test_gear.py): z 62, m 2 mm, b 20 mm, 20 deg,
  // E 206 GPa, nu 0.3, hub bore radius 17.5 mm; ROSS: ha* 1, clearance 0.25.
  PeGear ross;
  ross.teeth = 62;
  ross.module = 2e-3;
  ross.youngs_modulus = 206e9;
  ross.bore_radius = 0.0175;
  variants("ROSS 62/62 r_int 17.5 mm", ross, phases);
  return 0;
}
