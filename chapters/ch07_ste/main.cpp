// ch07_ste — thesis chapter 7: static transmission error (STE) of a spur-gear
// pair from a beam finite-element model of the teeth plus Hertzian contact.
//
// Thesis sections: §7.1-7.2 (beam model, assembly, Boolean fusion of contact
// nodes), §7.3 and §7.5 (Palmgren-Hertz approach), §7.4 (constant 6 mm
// thickness, checks against exact beam formulas), §7.5 (involute thickness,
// STE over the mesh cycle), §7.6 (refinement: P positions per base pitch),
// §7.7 (tooth-axis angles), §8.1 (mean mesh stiffness), §9 (max STE 13.77 um).
//
// Equations (see lib/include/gearhb/{gear_geometry,tooth_fe,hertz,ste,iso6336}.hpp):
//   beam element   K^(e) = EI/L^3 [12 6L -12 6L; 6L 4L^2 -6L 2L^2; ...],  J = b s^3/12
//   system         K Q = F + R, constraints by Q = T u + Q0 (T = the Boolean matrix)
//   thickness      s(r) = r s0/r0 + 2 r (inv a0 - inv a),  inv a = tan a - a,  a = acos(rb/r)
//   Hertz          delta[mm] = 3.84e-5 F[N]^0.9 / L[mm]^0.8
//   STE            one pair: w1 + w2 + delta;  two pairs: X with k_A X + k_B X = F, + delta
//   stiffness      k = mean over the cycle of F / STE     (thesis §8.1 misprints (T/r) V)
//   ISO 6336-1     c_gamma_alpha = c' (0.75 eps_alpha + 0.25),  c' = c'_th C_M C_R C_B
//
// Figures (build/figures/, drawn by figures/ch07_ste.py from build/data/ch07_ste/):
//   Fig. 48-49  deflection, one pair (nodes 6-18, 7-17), 6 mm, 300 Nm   deflection_const_single_*.csv
//   Fig. 50-51  exact cantilever elastic line, force at node 7 / node 6  elastic_line_exact_*.csv
//   Fig. 52-55  deflection, two fused pairs, 6 mm, 300 Nm               deflection_const_two_*.csv
//   Fig. 56     bending moment along the fused beam (2-22)             moment_const_two_pair.csv
//   Fig. 57     tooth profile s(r) and the stepped beam thickness       tooth_profile.csv, beam_thickness_P*.csv
//   Fig. 58-59  deformed teeth, involute thickness, 300 Nm             deflection_var_*.csv
//   Fig. 60     STE over the mesh cycle, T = 100/200/300 Nm (P = 6)    ste_first_model_T*.csv
//   Fig. 61     its Fourier coefficients                               ste_first_model_fourier_T*.csv
//   Fig. 62     the 14-node model: contact nodes per position (P = 8)  mesh_scheme_P8.csv
//   Fig. 63-64  STE and Fourier coefficients with P = 8                ste_T*.csv, ste_fourier_T*.csv
//   extra       convergence in P; readings of the open modelling choices  convergence.csv, readings.csv
// Not reproduced: the curves of Parker, Vijayakar & Imajo in Fig. 60 (data not available).
//
// Commands:
//   build/bin/ch07_ste --out build/data/ch07_ste
//   /usr/bin/python3 figures/make_all.py --only ch07_ste   (runs the above, then draws)
//   build/bin/ch07_ste --help                              (every parameter, default, unit)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "gearhb/app/cli.hpp"
#include "gearhb/gears/gear_geometry.hpp"
#include "gearhb/gears/hertz.hpp"
#include "gearhb/gears/iso6336.hpp"
#include "gearhb/app/output.hpp"
#include "gearhb/gears/ste.hpp"
#include "gearhb/gears/tooth_fe.hpp"

using namespace gearhb;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double um = 1e6, mm = 1e3;   // SI -> micrometres, millimetres

// ---------------------------------------------------------------------------
// Parameters, one struct per concern; defaults are the thesis values (§7.4).
// ---------------------------------------------------------------------------
struct GearParams {            // both gears identical (thesis §7.4 table)
  double module = 3e-3;        // [m]
  int teeth = 50;
  double pressure_angle = 20;  // [deg]
  double addendum = 3e-3;      // [m]
  double dedendum = 3.75e-3;   // [m]
  double face_width = 0.02;    // [m]
};
struct MaterialParams {
  double youngs_modulus = 207e9;   // [Pa]
  double poisson_ratio = 0.3;      // listed by the thesis; unused by Euler-Bernoulli beams
};
struct LoadParams {
  double torque_1 = 100, torque_2 = 200, torque_3 = 300;   // [N m], Fig. 60
};
struct ConstantThicknessParams {
  double thickness = 6e-3;     // [m], §7.4
};
struct MeshParams {
  int first_positions_per_base_pitch = 6;   // thesis first model: 11 nodes per tooth (Fig. 46)
  int positions_per_base_pitch = 8;         // refined model: 14 contact nodes (Fig. 62), written to ste_T*.csv
  int convergence_max_positions = 64;       // convergence study: P = 8, 16, ... up to this
};
struct ReadingParams {         // the modelling choices the text leaves open (see README)
  int thickness_at = 0;        // 0 element root-side node, 1 element midpoint, 2 element tip-side node
  int hertz_count = 2;         // 0 none, 1 once per contact, 2 once per tooth (thesis reading)
  int two_pair_hertz = 0;      // 0 F/2 per contact, 1 mean at the FE forces, 2 consistent split
  int tooth_force = 0;         // 0 F = T / r (thesis), 1 F = T / rb
};

struct Params {
  GearParams gear;
  MaterialParams material;
  LoadParams load;
  ConstantThicknessParams constant;
  MeshParams mesh;
  ReadingParams reading;
};

void bind(ParameterSet& ps, Params& p) {
  ps.add("module", &p.gear.module, "m", "module m", Range::positive());
  ps.add("teeth", &p.gear.teeth, "-", "number of teeth z (both gears)", Range::at_least(10));
  ps.add("pressure_angle", &p.gear.pressure_angle, "deg", "pressure angle alpha",
         Range::between(10, 35));
  ps.add("addendum", &p.gear.addendum, "m", "addendum ha", Range::positive());
  ps.add("dedendum", &p.gear.dedendum, "m", "dedendum hf", Range::positive());
  ps.add("face_width", &p.gear.face_width, "m", "face width b (beam width, Hertz contact length)",
         Range::positive());
  ps.add("youngs_modulus", &p.material.youngs_modulus, "Pa", "Young's modulus E", Range::positive());
  ps.add("poisson_ratio", &p.material.poisson_ratio, "-",
         "Poisson's ratio (thesis table; not used by Euler-Bernoulli beams)", Range::between(0, 0.5));
  ps.add("torque_1", &p.load.torque_1, "N m", "first torque of Fig. 60", Range::positive());
  ps.add("torque_2", &p.load.torque_2, "N m", "second torque of Fig. 60", Range::positive());
  ps.add("torque_3", &p.load.torque_3, "N m",
         "third torque of Fig. 60; also the torque of the constant-thickness checks, the max STE and "
         "the mean stiffness", Range::positive());
  ps.add("constant_thickness", &p.constant.thickness, "m", "tooth thickness of the §7.4 model",
         Range::positive());
  ps.add("first_positions_per_base_pitch", &p.mesh.first_positions_per_base_pitch, "-",
         "positions per base pitch of the first model (Figs. 46-61)", Range::at_least(4));
  ps.add("positions_per_base_pitch", &p.mesh.positions_per_base_pitch, "-",
         "positions per base pitch of the refined model written to ste_T*.csv (Figs. 62-64)",
         Range::at_least(4));
  ps.add("convergence_max_positions", &p.mesh.convergence_max_positions, "-",
         "largest P of the convergence study (P doubles from positions_per_base_pitch)",
         Range::at_least(4));
  ps.add("thickness_at", &p.reading.thickness_at, "-",
         "radius of an element's thickness: 0 root-side node, 1 midpoint, 2 tip-side node",
         Range::between(0, 2));
  ps.add("hertz_count", &p.reading.hertz_count, "-",
         "Palmgren approach added 0 never, 1 once per contact, 2 once per tooth", Range::between(0, 2));
  ps.add("two_pair_hertz", &p.reading.two_pair_hertz, "-",
         "two pairs: Hertz at 0 F/2, 1 mean over the FE pair forces, 2 consistent nonlinear split",
         Range::between(0, 2));
  ps.add("tooth_force", &p.reading.tooth_force, "-", "tooth force 0 T/r (thesis), 1 T/rb",
         Range::between(0, 1));
}

GearGeometry gear_of(const Params& p) {
  GearGeometry g;
  g.module = p.gear.module;
  g.teeth = p.gear.teeth;
  g.pressure_angle_deg = p.gear.pressure_angle;
  g.addendum = p.gear.addendum;
  g.dedendum = p.gear.dedendum;
  g.face_width = p.gear.face_width;
  return g;
}

SteModel model_of(const Params& p, int P, bool constant) {
  SteModel m;
  m.gear = gear_of(p);
  m.youngs_modulus = p.material.youngs_modulus;
  m.constant_thickness = constant;
  m.constant_thickness_value = p.constant.thickness;
  m.positions_per_base_pitch = P;
  m.thickness_at = ThicknessAt(p.reading.thickness_at);
  m.hertz = HertzCount(p.reading.hertz_count);
  m.two_pair_hertz = TwoPairHertz(p.reading.two_pair_hertz);
  m.tooth_force = ToothForce(p.reading.tooth_force);
  return m;
}

// Physical cross-checks, all before anything is written (SPEC §2).
void check(const Params& p) {
  const GearGeometry g = gear_of(p);
  ParameterSet::require(g.root_radius() > 0, "dedendum: root radius must be > 0");
  ParameterSet::require(g.root_radius() > g.base_radius(),
                        "dedendum: the root circle must lie outside the base circle (the involute "
                        "thickness s(r) is defined only for r >= rb)");
  ParameterSet::require(tooth_thickness(g, g.tip_radius()) > 0,
                        "addendum: the tooth is pointed (thickness <= 0 at the tip)");
  const double eps = path_of_contact(g, g).contact_ratio;
  ParameterSet::require(eps > 1.0 && eps < 2.0,
                        "addendum/pressure_angle: the model needs a contact ratio between 1 and 2");
  for (int P : {p.mesh.first_positions_per_base_pitch, p.mesh.positions_per_base_pitch}) {
    const int ne = int(std::floor(P * eps + 1e-9));
    ParameterSet::require(ne > P && ne < 2 * P,
                          "positions per base pitch " + std::to_string(P) +
                              ": floor(P * contact ratio) must lie between P and 2P");
  }
  ParameterSet::require(p.mesh.convergence_max_positions >= p.mesh.positions_per_base_pitch,
                        "convergence_max_positions must be >= positions_per_base_pitch");
  ParameterSet::require(p.mesh.convergence_max_positions <= 256,
                        "convergence_max_positions must be <= 256 (dense solver)");
  ParameterSet::require(p.load.torque_1 < p.load.torque_2 && p.load.torque_2 < p.load.torque_3,
                        "torque_1 < torque_2 < torque_3 required");
}

// ---------------------------------------------------------------------------
// Writers.
// ---------------------------------------------------------------------------
std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

// Nodal deflections of every beam of a model (thesis global node numbers, 1-based).
Table deflection_table(const BeamModel& m, const BeamModel::Solution& s) {
  Table t({"beam", "node", "x_mm", "w_um", "theta_rad"});
  for (int b = 0; b < m.beams(); ++b)
    for (int i = 0; i < m.beam_nodes(b); ++i) {
      const int n = m.node(b, i);
      t.add_row({long(b + 1), long(n + 1), m.beam_x(b)[i] * mm, s.Q[BeamModel::w_dof(n)] * um,
                 s.Q[BeamModel::theta_dof(n)]});
    }
  return t;
}

// Same, with the element thickness at each node for drawing the deformed tooth.
Table deformed_tooth_table(const BeamModel& m, const BeamModel::Solution& s, const ToothBeam& tooth) {
  Table t({"beam", "node", "x_mm", "w_um", "thickness_mm"});
  for (int b = 0; b < m.beams(); ++b)
    for (int i = 0; i < m.beam_nodes(b); ++i) {
      const int n = m.node(b, i);
      const double th = tooth.s[std::min<std::size_t>(i, tooth.s.size() - 1)];
      t.add_row({long(b + 1), long(n + 1), m.beam_x(b)[i] * mm, s.Q[BeamModel::w_dof(n)] * um, th * mm});
    }
  return t;
}

std::string pair_label(const BeamModel& m, int beam_a, int ka, int beam_b, int kb) {
  return std::to_string(m.node(beam_a, ka) + 1) + "-" + std::to_string(m.node(beam_b, kb) + 1);
}

Table cycle_table(const std::vector<MeshPosition>& c, double F) {
  Table t({"phase", "ste_um", "pairs_in_contact", "elastic_um", "hertz_um", "elastic_closed_form_um",
           "force_A_N", "force_B_N", "stiffness_N_per_m", "kA1", "kA2", "kB1", "kB2"});
  for (const auto& p : c)
    t.add_row({p.phase, p.ste * um, long(p.pairs), p.elastic * um, p.hertz * um,
               p.elastic_closed_form * um, p.force_A, p.force_B, F / p.ste, long(p.kA1), long(p.kA2),
               long(p.kB1), long(p.kB2)});
  return t;
}

Table fourier_table(const std::vector<MeshPosition>& c) {
  int H = 0;
  const Eigen::VectorXd a = ste_fourier(c, &H);
  Table t({"harmonic", "a_um", "b_um", "amplitude_um"});
  t.add_row({0L, a[0] * um, 0.0, std::fabs(a[0]) * um});
  for (int k = 1; k <= H; ++k)
    t.add_row({long(k), a[2 * k - 1] * um, a[2 * k] * um, std::hypot(a[2 * k - 1], a[2 * k]) * um});
  return t;
}

double max_ste(const std::vector<MeshPosition>& c) {
  double v = 0;
  for (const auto& p : c) v = std::max(v, p.ste);
  return v;
}

double max_rel_fe_vs_closed_form(const std::vector<MeshPosition>& c) {
  double e = 0;
  for (const auto& p : c) e = std::max(e, std::fabs(p.elastic_linear - p.elastic_closed_form) / p.elastic_closed_form);
  return e;
}

// Internal bending moment along the fused beam of pair A (driving root -> contact
// -> driven root), from the element end forces [V1 M1 V2 M2] = K^(e) q^(e):
// internal moment -M1 at an element's first node, +M2 at its second. The
// driven tooth's frame is turned by 180 deg (x and y reversed), which reverses
// the sign of its curvature, so its moments change sign in the driving frame.
Table fused_moment_table(const TwoPairSolve& s, int k1, int k2) {
  Table t({"s_mm", "moment_N_m", "tooth"});
  const BeamModel& m = s.model;
  const std::vector<double>& x = m.beam_x(0);
  for (int e = 0; e < k1; ++e) {
    const Eigen::Vector4d f = m.element_end_forces(s.solution, 0, e);
    t.add_row({x[e] * mm, -f[1], std::string("driving")});
    t.add_row({x[e + 1] * mm, f[3], std::string("driving")});
  }
  const double xc = x[k1];
  for (int e = k2 - 1; e >= 0; --e) {   // driven tooth, from the contact towards its root
    const Eigen::Vector4d f = m.element_end_forces(s.solution, 1, e);
    t.add_row({(xc + x[k2] - x[e + 1]) * mm, -f[3], std::string("driven")});
    t.add_row({(xc + x[k2] - x[e]) * mm, f[1], std::string("driven")});
  }
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  Params p;
  ParameterSet ps;
  bind(ps, p);
  const std::string usage =
      "ch07_ste: static transmission error of a spur-gear pair from a beam FE tooth model plus "
      "Hertzian contact (thesis ch. 7, Figs. 48-64).\nUsage: ch07_ste [--out DIR] [--set key=value]...";
  return run_chapter("ch07_ste", usage, argc, argv, ps, "build/data/ch07_ste", [&](const CommandLine& cl) {
    // ---- 1. Validate everything before writing anything. -------------------
    check(p);
    const std::string out = cl.out_dir + "/";
    KeyNumbers key;
    const GearGeometry gear = gear_of(p);
    const double torques[3] = {p.load.torque_1, p.load.torque_2, p.load.torque_3};
    const double T_main = p.load.torque_3;

    // ---- 2. Gear geometry: path of contact, contact ratio, §7.7 angles. ----
    const PathOfContact path = path_of_contact(gear, gear);
    {
      Table t({"quantity", "value", "unit"});
      auto row = [&](const std::string& n, double v, const std::string& u) { t.add_row({n, v, u}); };
      row("pitch_radius", gear.pitch_radius(), "m");
      row("base_radius", gear.base_radius(), "m");
      row("tip_radius", gear.tip_radius(), "m");
      row("root_radius", gear.root_radius(), "m");
      row("base_pitch", gear.base_pitch(), "m");
      row("T1C", path.T1C, "m");
      row("AC", path.AC, "m");
      row("CE", path.CE, "m");
      row("AE", path.AE, "m");
      row("contact_ratio", path.contact_ratio, "-");
      const ContactRadii rA = contact_radii(gear, gear, 0.0), rE = contact_radii(gear, gear, path.AE);
      row("driver_radius_at_A", rA.r1, "m");
      row("driver_radius_at_E", rE.r1, "m");
      t.write(out + "geometry.csv");
    }
    key.add("contact_ratio", path.contact_ratio, "-");
    key.add("AC_mm", path.AC * mm, "mm");
    key.add("CE_mm", path.CE * mm, "mm");
    {
      Table t({"variant", "rb_m", "AC_m", "CE_m", "T2C_m", "T2E_m", "beta_deg", "epsilon_deg",
               "cos_alpha_minus_beta", "cos_alpha_plus_epsilon", "force_variation_percent"});
      struct V { const char* name; T2CFormula f; bool round; };
      const V variants[] = {{"thesis_printed_values", T2CFormula::thesis_rb_sin, true},
                            {"thesis_formula_unrounded", T2CFormula::thesis_rb_sin, false},
                            {"corrected_rb_tan", T2CFormula::rb_tan, false}};
      for (const V& v : variants) {
        const ToothAxisAngles a = tooth_axis_angles(gear, path, v.f, v.round);
        t.add_row({std::string(v.name), a.rb, a.AC, a.CE, a.T2C, a.T2E, a.beta * 180 / kPi,
                   a.epsilon * 180 / kPi, a.cos_alpha_minus_beta, a.cos_alpha_plus_epsilon,
                   a.force_variation * 100});
        if (std::string(v.name) == "thesis_printed_values") {
          key.add("beta_deg", a.beta * 180 / kPi, "deg");
          key.add("epsilon_deg", a.epsilon * 180 / kPi, "deg");
          key.add("force_variation_percent", a.force_variation * 100, "%");
        }
        if (std::string(v.name) == "corrected_rb_tan") {
          key.add("corrected_T2C_mm", a.T2C * mm, "mm");
        }
      }
      t.write(out + "tooth_axis_angles.csv");
    }

    // ---- 3. Constant 6 mm thickness, one pair (Figs. 48-51). ---------------
    // First model (P = 6, 10 elements, nodes 1-11 / 12-22 / 23-33 / 34-44).
    const int P1 = p.mesh.first_positions_per_base_pitch;
    const SteModel const_model = model_of(p, P1, true);
    const ToothBeam const_tooth = tooth_beam(const_model);
    const double F_main = const_model.force(T_main);
    const double EI_const = const_tooth.EI[0];
    {
      double worst_exact_err = 0;
      int case_no = 0;
      for (int k = 1; k <= const_model.elements(); ++k) {
        const int k2 = const_model.elements() + 1 - k;
        if (k + P1 <= const_model.elements() || k > P1) continue;   // single-pair positions only
        const SinglePairSolve s = solve_single_pair(const_tooth, k, k2, F_main);
        const std::string label = pair_label(s.model, 0, k, 1, k2);
        deflection_table(s.model, s.solution).write(out + "deflection_const_single_" + label + ".csv");
        // Exact cantilever: STE = F (a1^3 + a2^3) / (3 EI).
        const double a1 = const_tooth.x[k], a2 = const_tooth.x[k2];
        const double exact = F_main * (a1 * a1 * a1 + a2 * a2 * a2) / (3 * EI_const);
        worst_exact_err = std::max(worst_exact_err, std::fabs(s.ste_elastic - exact) / exact);
        if (case_no++ == 0) {
          key.add("ste_single_pair_const_um", s.ste_elastic * um, "um");
        }
      }
      key.add("ste_single_pair_const_fe_vs_exact_rel", worst_exact_err, "-");
      // Figs. 50-51: the exact elastic line for the force at the two single-pair
      // nodes of the driving tooth (nodes 7 and 6 in the thesis numbering).
      for (int k = P1 - 0; k >= P1 - 1; --k) {
        if (k < 1) continue;
        Table t({"x_mm", "y_exact_um", "node_of_force"});
        const double a = const_tooth.x[k], Ltot = const_tooth.x.back();
        for (int i = 0; i <= 200; ++i) {
          const double x = Ltot * i / 200.0;
          t.add_row({x * mm, -cantilever_point_load_deflection(F_main, a, x, EI_const) * um, long(k + 1)});
        }
        t.write(out + "elastic_line_exact_node" + std::to_string(k + 1) + ".csv");
      }
    }

    // ---- 4. Constant thickness, two fused pairs (Figs. 52-56). -------------
    {
      const int ne = const_model.elements();
      Table reactions({"pair_nodes", "X_um", "dof", "reaction", "unit"});
      double worst_x_err = 0;
      bool first = true;
      for (int k = 1; k + P1 <= ne; ++k) {
        const int kA2 = ne + 1 - k, kB1 = k + P1, kB2 = ne + 1 - kB1;
        const TwoPairSolve s = solve_two_pairs(const_tooth, k, kA2, kB1, kB2, F_main);
        const std::string label = pair_label(s.model, 0, k, 1, kA2) + "_" + pair_label(s.model, 2, kB1, 3, kB2);
        deflection_table(s.model, s.solution).write(out + "deflection_const_two_" + label + ".csv");
        // Each fused pair is a clamped-guided beam of ne + 1 elements carrying F/2:
        // X = (F/2) L^3 / (12 EI), root moment (F/2) L / 2.
        const double L = const_tooth.x[1] * (ne + 1);
        const double X_exact = 0.5 * F_main * L * L * L / (12 * EI_const);
        worst_x_err = std::max(worst_x_err, std::fabs(s.X - X_exact) / X_exact);
        // The six constrained DOFs of the thesis' {R_V}: rotation of the guided
        // roots (nodes 1, 23), translation and rotation of the clamped roots (12, 34).
        const BeamModel& m = s.model;
        const int dofs[6] = {BeamModel::theta_dof(m.node(0, 0)), BeamModel::w_dof(m.node(1, 0)),
                             BeamModel::theta_dof(m.node(1, 0)), BeamModel::theta_dof(m.node(2, 0)),
                             BeamModel::w_dof(m.node(3, 0)), BeamModel::theta_dof(m.node(3, 0))};
        for (int d : dofs)
          reactions.add_row({label, s.X * um, std::string(d % 2 ? "theta_node_" : "w_node_") + std::to_string(d / 2 + 1),
                             s.solution.reactions[d], std::string(d % 2 ? "N m" : "N")});
        if (first) {
          first = false;
          key.add("ste_two_pairs_const_um", s.X * um, "um");
          key.add("reaction_moment_guided_root_N_m", s.solution.reactions[dofs[0]], "N m");
          key.add("reaction_force_clamped_root_N", s.solution.reactions[dofs[1]], "N");
          key.add("reaction_moment_clamped_root_N_m", s.solution.reactions[dofs[2]], "N m");
          fused_moment_table(s, k, kA2).write(out + "moment_const_two_pair.csv");
        }
      }
      key.add("ste_two_pairs_const_fe_vs_exact_rel", worst_x_err, "-");
      reactions.write(out + "reactions_const_two_pairs.csv");
    }

    // ---- 5. Involute thickness: tooth profile (Fig. 57). -------------------
    const int P2 = p.mesh.positions_per_base_pitch;
    const SteModel first_model = model_of(p, P1, false);
    const SteModel refined_model = model_of(p, P2, false);
    {
      Table t({"r_mm", "height_mm", "thickness_mm"});
      const double rf = gear.root_radius(), ra = gear.tip_radius();
      for (int i = 0; i <= 200; ++i) {
        const double r = rf + (ra - rf) * i / 200.0;
        t.add_row({r * mm, (r - rf) * mm, tooth_thickness(gear, r) * mm});
      }
      t.write(out + "tooth_profile.csv");
      for (const SteModel* m : {&first_model, &refined_model}) {
        const ToothBeam tb = tooth_beam(*m);
        Table b({"element", "x_start_mm", "x_end_mm", "thickness_mm", "EI_N_m2"});
        for (std::size_t e = 0; e < tb.EI.size(); ++e)
          b.add_row({long(e + 1), tb.x[e] * mm, tb.x[e + 1] * mm, tb.s[e] * mm, tb.EI[e]});
        b.write(out + "beam_thickness_P" + std::to_string(m->positions_per_base_pitch) + ".csv");
      }
    }

    // ---- 6. Deformed teeth, involute thickness, T_main (Figs. 58-59). ------
    {
      const ToothBeam tb = tooth_beam(first_model);
      const int ne = first_model.elements();
      const double F = first_model.force(T_main);
      const int ks = P1 - 1;   // first single-pair position (thesis 6-18)
      const SinglePairSolve s1 = solve_single_pair(tb, ks, ne + 1 - ks, F);
      deformed_tooth_table(s1.model, s1.solution, tb).write(out + "deflection_var_single.csv");
      const TwoPairSolve s2 = solve_two_pairs(tb, 1, ne, 1 + P1, ne - P1, F);
      deformed_tooth_table(s2.model, s2.solution, tb).write(out + "deflection_var_two.csv");
    }

    // ---- 7. STE over the mesh cycle (Figs. 60-61 first model, 63-64 refined).
    std::vector<MeshPosition> refined_main;
    double refined_max_check = 0;
    for (double T : torques) {
      const std::string tag = "T" + fmt("%g", T);
      const auto c1 = ste_over_mesh_cycle(first_model, T);
      cycle_table(c1, first_model.force(T)).write(out + "ste_first_model_" + tag + ".csv");
      fourier_table(c1).write(out + "ste_first_model_fourier_" + tag + ".csv");
      const auto c2 = ste_over_mesh_cycle(refined_model, T);
      // ste_T*.csv: the contract columns first (phase, ste_um, pairs_in_contact).
      cycle_table(c2, refined_model.force(T)).write(out + "ste_" + tag + ".csv");
      fourier_table(c2).write(out + "ste_fourier_" + tag + ".csv");
      refined_max_check = std::max({refined_max_check, max_rel_fe_vs_closed_form(c1), max_rel_fe_vs_closed_form(c2)});
      if (T == T_main) {
        refined_main = c2;
        key.add("ste_max_first_model_T3_um", max_ste(c1) * um, "um");
        key.add("mean_stiffness_first_model_T3_MN_per_m", mean_mesh_stiffness(c1, first_model.force(T)) / 1e6, "MN/m");
      }
    }
    key.add("ste_fe_vs_closed_form_max_rel", refined_max_check, "-");
    const double F3 = refined_model.force(T_main);
    key.add("ste_max_T3_um", max_ste(refined_main) * um, "um");
    key.add("mean_stiffness_T3_MN_per_m", mean_mesh_stiffness(refined_main, F3) / 1e6, "MN/m");
    {
      Table t({"position", "phase", "pairs_in_contact", "driving_node_A", "driven_node_A",
               "driving_node_B", "driven_node_B"});
      const int ne = refined_model.elements(), nn = ne + 1;
      for (const auto& q : refined_main)   // thesis-style global numbers: beams of nn nodes
        t.add_row({long(q.phase * P2 + 0.5) + 1L, q.phase, long(q.pairs), long(q.kA1 + 1), long(nn + q.kA2 + 1),
                   q.pairs == 2 ? long(2 * nn + q.kB1 + 1) : -1L, q.pairs == 2 ? long(3 * nn + q.kB2 + 1) : -1L});
      t.write(out + "mesh_scheme_P" + std::to_string(P2) + ".csv");
    }

    // ---- 8. Mean stiffness beside ISO 6336-1 (Method B). -------------------
    {
      const double line_load = F3 / (gear.face_width * mm);   // N/mm
      const Iso6336Stiffness iso = iso6336_mesh_stiffness(
          gear.teeth, gear.teeth, 0.0, 0.0, gear.pressure_angle_deg, gear.dedendum / gear.module,
          path.contact_ratio, gear.face_width, line_load);
      Table t({"quantity", "value", "unit"});
      t.add_row({std::string("mean_F_over_STE"), mean_mesh_stiffness(refined_main, F3), std::string("N/m")});
      t.add_row({std::string("F_over_mean_STE"), F3 * refined_main.size() /
                 [&] { double s = 0; for (auto& q : refined_main) s += q.ste; return s; }(), std::string("N/m")});
      t.add_row({std::string("iso6336_q_prime"), iso.q_prime, std::string("mm um/N")});
      t.add_row({std::string("iso6336_c_th"), iso.c_th, std::string("N/(mm um)")});
      t.add_row({std::string("iso6336_C_B"), iso.C_B, std::string("-")});
      t.add_row({std::string("iso6336_c_single"), iso.c_single_total, std::string("N/m")});
      t.add_row({std::string("iso6336_c_gamma_alpha"), iso.c_gamma_alpha_total, std::string("N/m")});
      t.write(out + "stiffness.csv");
      key.add("iso6336_c_gamma_alpha_MN_per_m", iso.c_gamma_alpha_total / 1e6, "MN/m");
    }

    // ---- 9. The open modelling choices, each with the numbers it gives. ----
    {
      Table t({"thickness_at", "hertz_count", "two_pair_hertz", "tooth_force", "positions_per_base_pitch",
               "tooth_elements", "ste_max_T1_um", "ste_max_T2_um", "ste_max_T3_um", "mean_stiffness_T3_MN_per_m"});
      for (int P : {P1, P2})
        for (int th = 0; th <= 2; ++th)
          for (int hc = 1; hc <= 2; ++hc)
            for (int tp = 0; tp <= 2; ++tp)
              for (int tf = 0; tf <= 1; ++tf) {
                Params q = p;
                q.reading = {th, hc, tp, tf};
                const SteModel m = model_of(q, P, false);
                std::vector<Table::Cell> row = {long(th), long(hc), long(tp), long(tf), long(P), long(m.elements())};
                double k3 = 0;
                for (double T : torques) {
                  const auto c = ste_over_mesh_cycle(m, T);
                  row.push_back(max_ste(c) * um);
                  if (T == T_main) k3 = mean_mesh_stiffness(c, m.force(T)) / 1e6;
                }
                row.push_back(k3);
                t.add_row(row);
              }
      t.write(out + "readings.csv");
    }

    // ---- 10. Convergence in the number of positions per base pitch. --------
    {
      Table t({"positions_per_base_pitch", "tooth_elements", "dofs", "ste_max_T3_um", "ste_min_T3_um",
               "mean_stiffness_T3_MN_per_m", "harmonic_1_um", "harmonic_2_um", "harmonic_3_um"});
      for (int P = P2; P <= p.mesh.convergence_max_positions; P *= 2) {
        const SteModel m = model_of(p, P, false);
        const auto c = ste_over_mesh_cycle(m, T_main);
        double mn = 1e300;
        for (const auto& q : c) mn = std::min(mn, q.ste);
        int H = 0;
        const Eigen::VectorXd a = ste_fourier(c, &H);
        auto amp = [&](int k) { return k <= H ? std::hypot(a[2 * k - 1], a[2 * k]) * um : std::nan(""); };
        t.add_row({long(P), long(m.elements()), long(8 * (m.elements() + 1)), max_ste(c) * um, mn * um,
                   mean_mesh_stiffness(c, m.force(T_main)) / 1e6, amp(1), amp(2), amp(3)});
      }
      t.write(out + "convergence.csv");
    }

    // ---- 11. Parameters and key numbers. ------------------------------------
    write_file_atomic(out + "params.json", ps.to_json().dump(2) + "\n");
    key.write(out + "key_numbers.json");
  });
}
