#pragma once
// The mesh stiffnesses of a planetary set computed from its teeth (planetary-set file key
// mesh.stiffness "tooth_model"; programs/gearhb_planetary/README.md "Mesh stiffness from the
// teeth"), in place of the rectangular waves of planetary_mesh.hpp:
//
//   sun-planet   an external spur pair: gearhb_gear's pair model (tools/gear_file.hpp
//                gear_file_loaded_pair: beam | potential_energy | fe, the file's
//                model.method) on the gear pair that mesh.sun_planet_pair describes in the
//                gear-pair file's vocabulary, the sun gear 1 (z_s), the planet gear 2 (z_p),
//                module, pressure angle and addendum those of the set; loaded by the mesh's
//                nominal static force F (nominal_mesh_force). k(theta_j) = F / STE_j at the
//                pair's model.phases phases, exactly gearhb_gear's k_N_per_m of ste_1.csv
//                for that file with torques [F / (force per unit torque)].
//   ring-planet  an internal pair (the library has no internal tooth form for its FE,
//                geometry/tooth_form.hpp), by mesh.ring_planet_stiffness:
//     potential_energy (default)  the potential-energy method: the ring's tooth as an
//                internal involute cantilever (tooth/potential_energy.hpp
//                pe_internal_tooth_compliance: bending, shear, axial, no foundation under it),
//                the planet's tooth as gearhb_gear's (with Sainsot's fillet foundation at the
//                planet's rim_radius), linear Hertz; the pairs along the internal path of
//                contact (internal_path) in parallel at each of the pair's phases (Liang, Zuo
//                & Pandey, Mech. Mach. Theory 76 (2014) 20-38, the method; the ring of the
//                planet's material and face width);
//     iso6336    ISO 6336-1:2006 method B (rating/iso6336.hpp) with the internal gear's
//                virtual tooth count infinite: single stiffness c' b and mean c_gamma_alpha b
//                = c' b (0.75 eps + 0.25), i.e. the rectangular wave whose single-pair level
//                is c' b, double-pair level 1.75 c' b, over the internal pair's contact ratio
//                eps (internal_contact_ratio); the planet's face width, steel.
//   The planet drives the ring (the sun the input): A, where the contact enters, is at the
//   planet's root.
//
// The sets' model has standard centre distances (z_r = z_s + 2 z_p, planetary_file.hpp), so
// the pair's profile shifts must be 0 and it takes no centre distance of its own.
#include <string>

#include <nlohmann/json.hpp>

#include "gearhb/gears/rating/iso6336.hpp"
#include "gearhb/gears/sets/planetary.hpp"
#include "gearhb/gears/sets/planetary_mesh.hpp"

namespace gearhb {

// The nominal static force of every mesh [N] (its share of the input torque T [N m] on
// member `input`, N planets sharing equally): each planet carries F on both meshes (its
// moment balance, equal base radii), so the sun takes N F r_bs, the ring N F r_br and the
// carrier N F (r_bs + r_br):
//     F = T / (N r_b,input),   r_b,carrier = r_bs + r_br.
double nominal_mesh_force(const PlanetaryTeeth& t, double pressure_angle, int planets, Body input, double torque);

// The transverse contact ratio of the ring-planet (internal) pair at the standard centre
// distance a = (z_r - z_p) m / 2 (ISO 21771): tip radii r_ap = r_p + h_a* m (planet),
// r_ar = r_r - h_a* m (ring, inside its pitch circle),
//     eps = [sqrt(r_ap^2 - r_bp^2) - sqrt(r_ar^2 - r_br^2) + a sin(alpha)] / (pi m cos(alpha)).
// NaN where the ring's tip circle lies inside its base circle.
double internal_contact_ratio(const PlanetaryTeeth& t, double pressure_angle);

// The internal pair's path of contact on its line of action, as distances from the planet's
// tangent point T1 [m]: A (the ring's tip circle, the planet's root side) at
// T1A = sqrt(r_ar^2 - r_br^2) - a sin(alpha), E (the planet's tip circle) at
// T1E = sqrt(r_ap^2 - r_bp^2); a point P at T1P touches the planet at sqrt(r_bp^2 + T1P^2)
// and the ring at sqrt(r_br^2 + (T1P + a sin(alpha))^2) (the ring's tangent point lies
// a sin(alpha) behind T1). pb the base pitch.
struct InternalPath {
  double T1A = 0.0, T1E = 0.0, a_sin = 0.0, rbp = 0.0, rbr = 0.0, pb = 0.0;
};
InternalPath internal_path(const PlanetaryTeeth& t, double pressure_angle);

enum class RingPlanetModel { potential_energy, iso6336 };

// The ring-sun mesh phase gamma_rs [mesh cycles, in [0, 1)] of a planet from the teeth
// (unshifted, standard centre distances), the sun turning counter-clockwise relative to the
// carrier (planetary_mesh.hpp mesh_phases), each mesh's wave starting (theta = 0) when a new
// pair enters its path at A. The planet turns clockwise by phi; the sun pushes the flanks of
// its teeth that face backwards, it pushes the ring with the flanks that face forwards (the
// two meshes use opposite flanks: the tooth thickness enters). An involute flank meets a line
// of action at rb_p times the angle between its origin on the base circle and the line's
// tangent point; with the tangent points of the sun-planet and ring-planet lines at alpha and
// pi - alpha from the direction to the sun's centre, a pair enters the sun mesh at the
// planet's tip (T2A_s = sqrt(r_ap^2 - r_bp^2) from its tangent point, the distance falling as
// phi grows) and the ring mesh at T1A_r (internal_path; the distance growing), so
//     gamma_rs = z_p / (2 pi) [pi - 2 alpha - 2 theta_b + (T2A_s + T1A_r) / r_bp]   (mod 1),
//     theta_b = pi / (2 z_p) + inv(alpha)   (the planet's half tooth angle at its base circle).
// (Parker & Lin 2004 eq. (10) states the same dependence on the tooth thickness; this is our
// derivation, checked by the construction of reference/scripts/planetary_ring_sun_phase.py.)
double ring_sun_phase_from_teeth(const PlanetaryTeeth& t, double pressure_angle);

// The ring-planet mesh's back-flank mirror phase psi [rad, in [0, 2 pi)] (planetary_mesh.hpp
// ring_back_mirror): gearhb_gear's back_flank_phase (mesh_dynamics.hpp) with the planet as
// gear 1 of the internal pair: the derivation there uses only gear 1's tooth and the symmetry
// of the two lines of action about the line of centres, which the internal pair shares, so
//     psi = 2 pi (s_bp + 2 alpha r_bp - 2 T1A_r) / p_b   (mod 2 pi),
// s_bp = r_bp (pi / z_p + 2 inv(alpha)) the planet's base tooth thickness, T1A_r internal_path's.
// (The sun-planet mesh's is back_flank_phase of its pair, the sun gear 1.)
double ring_back_mirror_phase(const PlanetaryTeeth& t, double pressure_angle);

// What the tooth model gives for a set.
struct PlanetaryToothStiffness {
  nlohmann::json sun_planet_pair;   // the sun-planet pair as a gear-pair file (torques [T1])
  double sun_planet_torque = 0.0;   // T1 on the sun of one mesh [N m]
  double tooth_force = 0.0;          // F [N]
  double sun_contact_ratio = 0.0;   // of the sun-planet pair's geometry
  SampledMesh sun;                  // k(theta) of the pair model [N/m]
  RingPlanetModel ring_model = RingPlanetModel::potential_energy;
  SampledMesh ring_pe;              // potential_energy: k(theta) of the ring-planet pair [N/m]
  double ring_contact_ratio = 0.0;  // of the ring-planet pair's geometry
  double sun_back_mirror = 0.0, ring_back_mirror = 0.0;   // psi of each mesh kind's back flank [rad]
  Iso6336Stiffness ring_iso;        // iso6336: ISO 6336-1 of the ring-planet pair
  RectangularMesh ring;             // iso6336: its rectangular wave
  // k(theta) of the ring-planet mesh at phase theta [N/m], either model.
  double ring_stiffness(int j, int J) const;
};

// The set's tooth stiffnesses. pair: the file's mesh.sun_planet_pair (its keys are checked as
// a gear-pair file's, an error naming `file` and mesh.sun_planet_pair.<key>); name: the set's.
// Throws UsageError.
PlanetaryToothStiffness planetary_tooth_stiffness(const nlohmann::json& pair, const std::string& file,
                                                  const std::string& name, const PlanetaryTeeth& t,
                                                  double pressure_angle, int planets, Body input, double torque,
                                                  RingPlanetModel ring_model);

}  // namespace gearhb
