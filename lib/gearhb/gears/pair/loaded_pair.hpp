#pragma once
// The loaded pair of one tooth model: what the STE tables, the Harris map and the
// dynamics of a spur pair take from a tooth model, built once per pair and asked per
// torque (gearhb_gear's model.method; README "A gear pair from its drawing"):
//
//   beam              chapter 7's beams (mesh_phases' own pair stiffness), with the
//                     file's Hertz and force conventions (ste_continuous.hpp)
//   potential_energy  the potential-energy pair stiffness (potential_energy.hpp) through
//                     mesh_phases' PairStiffnessFn seam, its linear Hertz inside
//   fe                tooth contact by finite elements on the generated tooth form
//                     (fe_tooth_contact.hpp): both gears meshed, assembled and factored
//                     once, the influence coefficients of every phase's contact points
//                     computed once; each torque is then a small contact problem per phase.
//
// The reliefs are separations of the contact problem in all three, so the Harris map's
// "without relief" curve needs no second model (ste(T, false)).
#include <memory>
#include <vector>

#include "gearhb/gears/pair/fe_tooth_contact.hpp"
#include "gearhb/gears/pair/ste_continuous.hpp"

namespace gearhb {

class LoadedPair {
 public:
  virtual ~LoadedPair() = default;
  // Tooth force [N] for gear 1's torque T1 [N m] (the model's convention).
  virtual double force(double torque) const = 0;
  // The STE over the mesh cycle's phases for T1, with the reliefs of the model or without.
  virtual std::vector<PairStePoint> ste(double torque, bool reliefs = true) const = 0;
  // One pair alone touching at s from A (no relief, no neighbour loaded): its STE [m].
  virtual double single_pair_ste(double s, double torque) const = 0;
  // The FE models behind method fe (mesh sizes, body torsion), nullptr for the others.
  virtual const FePairModel* fe_model() const { return nullptr; }
};

// beam (stiffness empty) or potential_energy (stiffness the PE pair stiffness). coupling
// > 0 [m/N]: the structural coupling of the loaded pairs (pe_body_coupling of both gears,
// potential_energy.hpp), the same off-diagonal compliance between every two pairs of a
// phase; the load is then shared by the coupled contact problem (coupled_load_sharing.hpp,
// C_ii = 1 / k_i, C_ij = coupling). Needs m.hertz none (std::invalid_argument otherwise).
std::unique_ptr<LoadedPair> phase_loaded_pair(const PairSteModel& m, int samples, const PairStiffnessFn& stiffness = {},
                                              double coupling = 0.0);
// fe: builds FePairModel(m, samples, options); m.tooth_force must be base_radius (the FE's
// force acts along the line of action: std::invalid_argument otherwise).
std::unique_ptr<LoadedPair> fe_loaded_pair(const PairSteModel& m, int samples, const FePairOptions& options = {});

}  // namespace gearhb
