#include "gearhb/gears/pair/ste.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "gearhb/core/fourier.hpp"
#include "gearhb/core/gsl_errors.hpp"
#include "gearhb/gears/tooth/hertz.hpp"

namespace gearhb {

int SteModel::elements() const {
  if (tooth_elements > 0) return tooth_elements;
  const double eps = path_of_contact(gear, gear).contact_ratio;
  // floor(P * eps): 6 * 1.755 -> 10 (thesis Fig. 46), 8 * 1.755 -> 14 (Fig. 62).
  return int(std::floor(positions_per_base_pitch * eps + 1e-9));
}

double SteModel::force(double torque) const {
  return tooth_force == ToothForce::over_pitch_radius ? torque / gear.pitch_radius()
                                                      : torque / gear.base_radius();
}

ToothBeam tooth_beam(const SteModel& m) {
  return tooth_beam(m.gear, m.youngs_modulus, m.elements(), m.thickness_at,
                    m.constant_thickness ? m.constant_thickness_value : 0.0);
}

ToothBeam tooth_beam(const GearGeometry& g, double E, int ne, ThicknessAt at, double constant_thickness) {
  if (ne < 2) throw std::invalid_argument("tooth_beam: need at least 2 elements");
  const double rf = g.root_radius(), rb = g.base_radius(), h = g.tooth_height(), L = h / ne;   // ra - rf
  const double b = g.face_width;
  if (!(h > 0.0)) throw std::invalid_argument("tooth_beam: tooth height ha + hf must be > 0");
  ToothBeam t;
  for (int i = 0; i <= ne; ++i) t.x.push_back(i * L);
  for (int e = 0; e < ne; ++e) {
    double s = constant_thickness;
    if (!(constant_thickness > 0.0)) {
      const double r0 = rf + t.x[e], r1 = rf + t.x[e + 1];
      const double r = at == ThicknessAt::element_root_node ? r0
                       : at == ThicknessAt::element_tip_node ? r1
                                                             : 0.5 * (r0 + r1);
      s = tooth_thickness(g, std::max(r, rb));
    }
    if (!(s > 0.0)) throw std::invalid_argument("tooth_beam: tooth thickness <= 0 (pointed tooth)");
    t.s.push_back(s);
    t.EI.push_back(E * b * s * s * s / 12.0);   // J = b s^3 / 12 (§7.4)
  }
  return t;
}

SinglePairSolve solve_single_pair(const ToothBeam& tooth, int k1, int k2, double F) {
  SinglePairSolve r;
  const int b1 = r.model.add_beam(tooth.x, tooth.EI);
  const int b2 = r.model.add_beam(tooth.x, tooth.EI);
  r.model.clamp(r.model.node(b1, 0));
  r.model.clamp(r.model.node(b2, 0));
  // The thesis applies the tooth force with negative sign on both nodes (§7.4).
  r.model.add_force(r.model.node(b1, k1), -F);
  r.model.add_force(r.model.node(b2, k2), -F);
  r.solution = r.model.solve();
  r.ste_elastic = -(r.solution.Q[BeamModel::w_dof(r.model.node(b1, k1))] +
                    r.solution.Q[BeamModel::w_dof(r.model.node(b2, k2))]);
  return r;
}

namespace {

// The 4-beam model with both driving roots moved by -X.
TwoPairSolve build_and_solve(const ToothBeam& tooth, int kA1, int kA2, int kB1, int kB2, double X) {
  TwoPairSolve r;
  BeamModel& m = r.model;
  const int b[4] = {m.add_beam(tooth.x, tooth.EI), m.add_beam(tooth.x, tooth.EI),
                    m.add_beam(tooth.x, tooth.EI), m.add_beam(tooth.x, tooth.EI)};
  m.guide(m.node(b[0], 0), -X);
  m.clamp(m.node(b[1], 0));
  m.guide(m.node(b[2], 0), -X);
  m.clamp(m.node(b[3], 0));
  // Fused contact nodes: the driven tooth's frame is turned by 180 deg, so its
  // translation is the opposite of the driving tooth's, its rotation equal (§7.2).
  m.fuse(m.node(b[0], kA1), m.node(b[1], kA2), -1.0, true);
  m.fuse(m.node(b[2], kB1), m.node(b[3], kB2), -1.0, true);
  r.solution = m.solve();
  r.X = X;
  // Force each guided root must receive to move by -X: the pair load.
  r.force_A = -r.solution.reactions[BeamModel::w_dof(m.node(b[0], 0))];
  r.force_B = -r.solution.reactions[BeamModel::w_dof(m.node(b[2], 0))];
  r.stiffness_A = r.force_A / X;
  r.stiffness_B = r.force_B / X;
  return r;
}

// Fused pair as one clamped-guided beam (driving root -> contact -> driven root)
// for the closed-form check.
double fused_pair_stiffness_closed_form(const ToothBeam& t, int k1, int k2) {
  std::vector<double> x, EI;
  for (int i = 0; i <= k1; ++i) x.push_back(t.x[i]);
  for (int e = 0; e < k1; ++e) EI.push_back(t.EI[e]);
  const double xc = t.x[k1];
  for (int j = k2 - 1; j >= 0; --j) {   // driven tooth from node k2 down to its root
    x.push_back(xc + (t.x[k2] - t.x[j]));
    EI.push_back(t.EI[j]);
  }
  return stepped_clamped_guided_stiffness(x, EI);
}

// Force of pair A such that both pairs close the same approach:
// g(F_A) = X_A(F_A) - X_B(F - F_A), increasing in F_A, g(0) < 0 < g(F) since both
// approaches grow with the force (GSL Brent on [0, F], 1e-13 relative).
double consistent_split(double kA, double kB, double F, double length, int nh) {
  char force[32];
  std::snprintf(force, sizeof force, "%g", F);
  auto residual = [&](double FA) {
    const double FB = F - FA;
    return FA / kA + nh * palmgren_line_contact_approach(FA, length) -
           (FB / kB + nh * palmgren_line_contact_approach(FB, length));
  };
  return brent_root(residual, 0.0, F, 1e-13, std::string("consistent two-pair force split (F = ") + force + " N)", 200);
}

}  // namespace

TwoPairSolve solve_two_pairs(const ToothBeam& tooth, int kA1, int kA2, int kB1, int kB2, double F) {
  // Linear in X: solve once for a trial X, then scale to carry F (§7.2).
  const double X_trial = 1e-6;
  TwoPairSolve r = build_and_solve(tooth, kA1, kA2, kB1, kB2, X_trial);
  const double scale = F / (r.force_A + r.force_B);
  r.X = X_trial * scale;
  r.force_A *= scale;
  r.force_B *= scale;
  r.solution.Q *= scale;
  r.solution.reactions *= scale;
  return r;
}

std::vector<MeshPosition> mesh_positions(const SteModel& m) {
  const int P = m.positions_per_base_pitch;
  if (P < 2 || P > max_positions_per_base_pitch)
    throw std::invalid_argument("mesh_positions: positions per base pitch P = " + std::to_string(P) +
                                " outside [2, " + std::to_string(max_positions_per_base_pitch) + "]");
  const int ne = m.elements();
  if (ne < P) throw std::invalid_argument("mesh_positions: tooth elements (" + std::to_string(ne) +
                                          ") must be >= positions per base pitch (" + std::to_string(P) + ")");
  if (ne >= 2 * P)
    throw std::invalid_argument("mesh_positions: tooth elements >= 2 P would put three pairs in contact");
  std::vector<MeshPosition> cycle;
  for (int j = 0; j < P; ++j) {
    MeshPosition p;
    p.phase = double(j) / P;
    p.kA1 = j + 1;
    p.kA2 = ne + 1 - p.kA1;
    if (p.kA1 + P <= ne) {
      p.pairs = 2;
      p.kB1 = p.kA1 + P;
      p.kB2 = ne + 1 - p.kB1;
    }
    cycle.push_back(p);
  }
  return cycle;
}

namespace {

void solve_two_pair_position(const SteModel& m, const ToothBeam& tooth, double F, MeshPosition& p) {
  const double b = m.gear.face_width;
  const int nh = int(m.hertz);
  auto hz = [&](double f) { return palmgren_line_contact_approach(f, b); };
  const TwoPairSolve s = solve_two_pairs(tooth, p.kA1, p.kA2, p.kB1, p.kB2, F);
  p.elastic = p.elastic_linear = s.X;
  p.force_A = s.force_A;
  p.force_B = s.force_B;
  const double kA = fused_pair_stiffness_closed_form(tooth, p.kA1, p.kA2);
  const double kB = fused_pair_stiffness_closed_form(tooth, p.kB1, p.kB2);
  p.elastic_closed_form = F / (kA + kB);
  switch (m.two_pair_hertz) {
    case TwoPairHertz::equal_split:
      p.hertz = nh * hz(0.5 * F);
      break;
    case TwoPairHertz::fe_split_mean:
      p.hertz = nh * 0.5 * (hz(s.force_A) + hz(s.force_B));
      break;
    case TwoPairHertz::consistent:
      if (nh > 0) {
        const double FA = consistent_split(s.stiffness_A, s.stiffness_B, F, b, nh);
        p.force_A = FA;
        p.force_B = F - FA;
        p.elastic = FA / s.stiffness_A;   // each pair's own elastic part
        p.hertz = nh * hz(FA);
      }
      break;
  }
}

void solve_single_pair_position(const SteModel& m, const ToothBeam& tooth, double F, MeshPosition& p) {
  const SinglePairSolve s = solve_single_pair(tooth, p.kA1, p.kA2, F);
  p.elastic = p.elastic_linear = s.ste_elastic;
  p.force_A = F;
  p.hertz = int(m.hertz) * palmgren_line_contact_approach(F, m.gear.face_width);
  p.elastic_closed_form = F * (stepped_cantilever_compliance(tooth.x, tooth.EI, tooth.x[p.kA1]) +
                               stepped_cantilever_compliance(tooth.x, tooth.EI, tooth.x[p.kA2]));
}

}  // namespace

std::vector<MeshPosition> ste_over_mesh_cycle(const SteModel& m, double torque) {
  std::vector<MeshPosition> cycle = mesh_positions(m);
  const ToothBeam tooth = tooth_beam(m);
  const double F = m.force(torque);
  for (MeshPosition& p : cycle) {
    if (p.pairs == 2) solve_two_pair_position(m, tooth, F, p);
    else solve_single_pair_position(m, tooth, F, p);
    p.ste = p.elastic + p.hertz;
  }
  return cycle;
}

double mean_mesh_stiffness(const std::vector<MeshPosition>& cycle, double F) {
  double sum = 0.0;
  for (const auto& p : cycle) sum += F / p.ste;
  return sum / double(cycle.size());
}

Eigen::VectorXd ste_fourier(const std::vector<MeshPosition>& cycle, int* H_out) {
  const int N = int(cycle.size());
  const int H = (N - 2) / 2;
  if (H < 1) throw std::invalid_argument("ste_fourier: need at least 4 samples");
  Aft aft(H, N);
  Eigen::VectorXd x(N);
  for (int j = 0; j < N; ++j) x[j] = cycle[j].ste;
  if (H_out) *H_out = H;
  return aft.to_frequency(x);
}

}  // namespace gearhb
