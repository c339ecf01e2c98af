#include "gearhb/tools/gear_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "gearhb/app/json_file.hpp"

namespace gearhb {

namespace {

using nlohmann::json;

struct Reader {
  const std::string& file;

  double number(const json& parent, const std::string& where, const char* key, double lo, double hi,
                const char* range_text) const {
    const std::string path = where.empty() ? key : where + "." + key;
    if (!parent.contains(key)) fail_key(file, path, "is missing");
    const double v = json_number(parent[key], file, path);
    if (!(v >= lo && v <= hi)) fail_key(file, path, std::string("must be in ") + range_text);
    return v;
  }
  double optional(const json& parent, const std::string& where, const char* key, double fallback, double lo,
                  double hi, const char* range_text) const {
    return parent.contains(key) ? number(parent, where, key, lo, hi, range_text) : fallback;
  }
  // One of `names` (a string); returns its index.
  int choice(const json& parent, const std::string& where, const char* key, const std::vector<std::string>& names,
             int fallback) const {
    const std::string path = where.empty() ? key : where + "." + key;
    if (!parent.contains(key)) return fallback;
    std::string all;
    for (const auto& n : names) all += (all.empty() ? "" : " | ") + n;
    if (!parent[key].is_string()) fail_key(file, path, "must be one of " + all);
    const auto it = std::find(names.begin(), names.end(), parent[key].get<std::string>());
    if (it == names.end()) fail_key(file, path, "must be one of " + all);
    return int(it - names.begin());
  }
};

std::string mm(double v) {
  char b[48];
  std::snprintf(b, sizeof b, "%.6g mm", v * 1e3);
  return b;
}

// Method potential_energy: each gear in the PE vocabulary, its bore radius the file's rim
// radius (Sainsot's fillet foundation is clamped there: required); the teeth must be a
// valid PE tooth and the extrapolated fillet fit must stay a compliance (> 0) at both ends
// of each gear's contact.
void check_potential_energy(GearFile& f, const std::string& path, const PathOfContact& p) {
  const GearGeometry* geo[2] = {&f.pair.gear1, &f.pair.gear2};
  const double E[2] = {f.pair.youngs_modulus1, f.pair.youngs_modulus2};
  const ContactRadii lowest = contact_radii(f.pair.gear1, f.pair.gear2, p, 0.0);
  const ContactRadii highest = contact_radii(f.pair.gear1, f.pair.gear2, p, p.AE);
  const double r_low[2] = {lowest.r1, highest.r2}, r_tip[2] = {highest.r1, lowest.r2};
  for (int i = 0; i < 2; ++i) {
    const std::string prefix = "gears." + std::to_string(i);
    const GearGeometry& G = *geo[i];
    PeGear& g = f.pe[i];
    g.teeth = G.teeth;
    g.module = G.module;
    g.pressure_angle = G.pressure_angle_deg * M_PI / 180.0;
    g.profile_shift = G.profile_shift;
    g.addendum_coefficient = G.addendum / G.module;
    // The section's coefficients (pair_helical.hpp: lengths in m_n, module m_t; exact at beta = 0).
    const double c = std::cos(f.helical.helix_angle);
    g.dedendum_coefficient = f.dedendum_coefficient * c;
    g.root_radius_coefficient = f.root_radius_coefficient * c;
    g.face_width = G.face_width;
    g.youngs_modulus = E[i];
    g.poisson_ratio = f.gear[i].poisson_ratio;
    g.bore_radius = f.gear[i].rim_radius;
    if (!(g.bore_radius > 0.0))
      fail_key(path, prefix + ".rim_radius",
               "is needed by method potential_energy (the bore radius of Sainsot's fillet foundation) and is missing or 0");
    for (double r_c : {r_low[i], r_tip[i]}) {
      PeToothCompliance c;
      try {
        c = pe_tooth_compliance(g, r_c);
      } catch (const std::exception& e) {
        fail_key(path, prefix + ".z", std::string("is not a tooth of the potential-energy method: ") + e.what());
      }
      if (!(c.fillet > 0.0) || !std::isfinite(c.total()))
        fail_key(path, prefix + ".rim_radius", "takes Sainsot's fillet fit so far out of its range (h_f = rf / rim_radius = " +
                                              std::to_string(G.root_radius() / g.bore_radius) +
                                              ", fitted 1.4..7) that it gives no positive compliance");
    }
  }
}

// Method fe: the FE model of each gear (fe_tooth_contact.hpp) down to the file's rim radius
// (0: max(rf - 3 m, 0.5 rf)), graded by `model.fe_mesh` (element sizes in units of m, the
// defaults the converged ones of reference/fe_tooth_contact.md, and `scale` multiplying
// all); the mesh is refused here, before it is built, where its estimated size exceeds
// kFeMaxNodes (fe_gear_node_estimate).
constexpr double kFeMaxNodes = 2e6;

void read_fe_model(GearFile& f, const json& model, const std::string& path) {
  const Reader r{path};
  const json mesh = model.value("fe_mesh", json::object());
  if (!mesh.is_object()) fail_key(path, "model.fe_mesh", "must be an object");
  only_keys(mesh, path, "model.fe_mesh", {"contact_size", "tooth_size", "far_tooth_size", "body_size", "scale"});
  FeMeshDensity d;
  d.contact_size = r.optional(mesh, "model.fe_mesh", "contact_size", d.contact_size, 0.005, 0.1, "[0.005, 0.1] (units of m)");
  d.tooth_size = r.optional(mesh, "model.fe_mesh", "tooth_size", d.tooth_size, 0.02, 0.5, "[0.02, 0.5] (units of m)");
  d.far_tooth_size = r.optional(mesh, "model.fe_mesh", "far_tooth_size", d.far_tooth_size, 0.02, 0.25, "[0.02, 0.25] (units of m)");
  d.body_size = r.optional(mesh, "model.fe_mesh", "body_size", d.body_size, 0.05, 3.0, "[0.05, 3] (units of m)");
  d.scale = r.optional(mesh, "model.fe_mesh", "scale", d.scale, 0.25, 4.0, "[0.25, 4]");
  const GearGeometry* geo[2] = {&f.pair.gear1, &f.pair.gear2};
  FeGearOptions* o[2] = {&f.fe.gear1, &f.fe.gear2};
  for (int i = 0; i < 2; ++i) {
    const std::string prefix = "gears." + std::to_string(i);
    const double rf = geo[i]->root_radius(), m = geo[i]->module;
    o[i]->density = d;
    o[i]->root_radius_coefficient = f.root_radius_coefficient;
    o[i]->rim_radius = f.gear[i].rim_radius;
    o[i]->max_nodes = kFeMaxNodes;
    if (f.gear[i].rim_radius > 0.0 && !(f.gear[i].rim_radius < rf - m))
      fail_key(path, prefix + ".rim_radius", "must be below rf - m = " + mm(rf - m) + " for method fe (a rim of a module at least)");
    double nodes = 0.0;
    try {
      nodes = fe_gear_node_estimate(*geo[i], *o[i]);
    } catch (const std::invalid_argument& e) {
      fail_key(path, "model.fe_mesh", std::string("gives no mesh for gear ") + std::to_string(i + 1) + ": " + e.what());
    }
    if (!(nodes <= kFeMaxNodes))
      fail_key(path, "model.fe_mesh", "gives gear " + std::to_string(i + 1) + " an estimated " + std::to_string(long(nodes)) +
                                          " nodes, above the limit of " + std::to_string(long(kFeMaxNodes)) +
                                          ": coarsen it (larger sizes or scale)");
  }
  f.fe.poisson_ratio1 = f.gear[0].poisson_ratio;
  f.fe.poisson_ratio2 = f.gear[1].poisson_ratio;
}

// `speed` and `dynamics`: the response over the speed range (absent `speed`: none).
void read_dynamics(GearFile& f, const json& j, const std::string& path) {
  const Reader r{path};
  const json dyn = j.value("dynamics", json::object());
  if (j.contains("dynamics") && !j.contains("speed"))
    fail_key(path, "speed", "is missing: `dynamics` needs a speed range {unit, from, to}");
  if (!j.contains("speed")) return;
  GearDynamicsInput& d = f.dynamics;
  d.present = true;
  const json& sp = j["speed"];
  if (!sp.is_object()) fail_key(path, "speed", "must be an object {unit, from, to}");
  only_keys(sp, path, "speed", {"unit", "from", "to"});
  if (!sp.contains("unit")) fail_key(path, "speed.unit", "is missing (mesh_hz | rpm)");
  d.speed_in_rpm = r.choice(sp, "speed", "unit", {"mesh_hz", "rpm"}, 0) == 1;
  const double lo = r.number(sp, "speed", "from", 1e-3, 1e7, "[1e-3, 1e7]");
  const double hi = r.number(sp, "speed", "to", 1e-3, 1e7, "[1e-3, 1e7]");
  if (!(hi > lo)) fail_key(path, "speed.to", "must exceed speed.from");
  const double to_hz = d.speed_in_rpm ? f.pair.gear1.teeth / 60.0 : 1.0;   // f_mesh = z1 n1 / 60
  d.f_min_hz = lo * to_hz, d.f_max_hz = hi * to_hz;
  if (!(d.f_max_hz <= 1e6)) fail_key(path, "speed.to", "gives a mesh frequency above 1 MHz");
  only_keys(dyn, path, "dynamics", {"model", "mesh", "zeta", "bearing_zeta", "harmonics", "sweep", "back_flank",
                                    "time_check_points", "iso_quality_grade"});
  d.dofs = r.choice(dyn, "dynamics", "model", {"one_dof", "six_dof"}, 0) == 1 ? MeshDofs::bearings : MeshDofs::one_dof;
  d.mesh = r.choice(dyn, "dynamics", "mesh", {"constant", "parametric"}, 0) == 1 ? DteModel::parametric
                                                                                 : DteModel::constant;
  d.zeta = r.optional(dyn, "dynamics", "zeta", 0.08, 1e-4, 1.0, "[1e-4, 1]");
  d.bearing_zeta = r.optional(dyn, "dynamics", "bearing_zeta", 0.02, 1e-4, 1.0, "[1e-4, 1]");
  d.harmonics = dyn.contains("harmonics") ? json_whole(dyn["harmonics"], path, "dynamics.harmonics", 1, 64) : 5;
  d.direction = r.choice(dyn, "dynamics", "sweep", {"up", "down"}, 0) == 1 ? SweepDirection::down : SweepDirection::up;
  d.back_flank = r.choice(dyn, "dynamics", "back_flank", {"yes", "no"}, 0) == 0;
  d.time_check_points =
      dyn.contains("time_check_points") ? json_whole(dyn["time_check_points"], path, "dynamics.time_check_points", 0, 64) : 8;
  d.iso_quality_grade =
      dyn.contains("iso_quality_grade") ? json_whole(dyn["iso_quality_grade"], path, "dynamics.iso_quality_grade", 1, 12) : 5;
  for (int i = 0; i < 2; ++i) {
    const std::string prefix = "gears." + std::to_string(i);
    if (!(f.gear[i].inertia > 0.0)) fail_key(path, prefix + ".inertia", "is needed by the dynamics (speed) and is missing or 0");
    if (d.dofs == MeshDofs::bearings && !(f.gear[i].mass > 0.0))
      fail_key(path, prefix + ".mass", "is needed by dynamics.model six_dof and is missing or 0");
    if (d.dofs == MeshDofs::bearings && !(f.gear[i].bearing_stiffness > 0.0))
      fail_key(path, prefix + ".bearing_stiffness", "is needed by dynamics.model six_dof and is missing or 0");
    const bool axial = d.dofs == MeshDofs::bearings && f.helical.helix_angle > 0.0 && !f.helical.double_helical;
    if (axial && !(f.gear[i].axial_bearing_stiffness > 0.0))
      fail_key(path, prefix + ".axial_bearing_stiffness",
               "is needed by dynamics.model six_dof with a helix angle (the axial DOFs) and is missing or 0");
  }
}

// gears[i].lead: crowning [m], end_relief {amount [m], length [m]} (pair_helical.hpp).
void read_lead(const json& lead, const std::string& path, const std::string& where, LeadModification& l) {
  const Reader r{path};
  if (!lead.is_object()) fail_key(path, where, "must be an object {crowning, end_relief}");
  only_keys(lead, path, where, {"crowning", "end_relief"});
  l.crowning = r.optional(lead, where, "crowning", 0.0, 0.0, 1e-3, "[0, 1e-3] m");
  if (!lead.contains("end_relief")) return;
  const std::string e = where + ".end_relief";
  const json& er = lead["end_relief"];
  if (!er.is_object()) fail_key(path, e, "must be an object {amount, length}");
  only_keys(er, path, e, {"amount", "length"});
  l.end_relief = r.number(er, e, "amount", 0.0, 1e-3, "[0, 1e-3] m");
  l.end_relief_length = r.number(er, e, "length", 0.0, 10.0, "[0, 10] m");
  if (l.end_relief > 0.0 && !(l.end_relief_length > 0.0)) fail_key(path, e + ".length", "must be > 0 with an amount");
}

// A helical pair or a lead modification (the face in slices): the keys that do not apply.
void check_helical(GearFile& f, const json& model, const std::string& path) {
  HelicalPair& h = f.helical;
  h.slices = model.contains("slices") ? json_whole(model["slices"], path, "model.slices", 1, 200) : h.slices;
  // The work of a sliced face grows with slices x phases x the STE solves (torques and twice the
  // Harris points): bounded so that no file runs for minutes (at the bound about 15 s CPU, Ex. 01).
  const double solves = double(f.torques.size() + 2 * std::size_t(f.harris_points));
  if (h.sliced() && h.slices * f.phases > 200 * 64)
    fail_key(path, "model.slices", "times model.phases (" + std::to_string(h.slices) + " x " + std::to_string(f.phases) +
                                       ") exceeds 200 x 64: fewer slices or phases");
  if (h.sliced() && double(h.slices) * f.phases * solves > 1.6e6)
    fail_key(path, "model.slices", "x model.phases x (torques + 2 harris.points) = " +
                                       std::to_string(long(double(h.slices) * f.phases * solves)) +
                                       " exceeds 1.6e6 (a run of minutes): fewer slices, phases or Harris points");
  const double b = f.pair.contact_length();
  const LeadModification* lead[2] = {&h.lead1, &h.lead2};
  for (int i = 0; i < 2; ++i)
    if (lead[i]->end_relief > 0.0 && !(lead[i]->end_relief_length <= 0.5 * b))
      fail_key(path, "gears." + std::to_string(i) + ".lead.end_relief.length",
               "is longer than half the contact width b/2 = " + mm(0.5 * b) + " (a relief at each end of the face)");
  // (double helical: each half's own ends, half of that)
  for (int i = 0; i < 2; ++i)
    if (h.double_helical && lead[i]->end_relief > 0.0 && !(lead[i]->end_relief_length <= 0.25 * b))
      fail_key(path, "gears." + std::to_string(i) + ".lead.end_relief.length",
               "is longer than half a helix, b/4 = " + mm(0.25 * b) + " (a relief at each end of each half)");
  if (!h.sliced()) return;
  const double eps_beta = overlap_ratio(f.pair, h);
  if (!(eps_beta <= 20.0))
    fail_key(path, "helix_angle_deg", "gives an overlap ratio eps_beta = b sin(beta) / (pi m_n) = " + std::to_string(eps_beta) +
                                          " above 20 (the slices would not resolve the face)");
  // method fe: every slice contact of every phase is an FE solve per gear (pair_helical.hpp);
  // 20 x 64 of the thesis pair about 30 s CPU.
  if (f.method == ToothModel::fe && h.slices * f.phases > 40 * 64)
    fail_key(path, "model.slices", "times model.phases (" + std::to_string(h.slices) + " x " + std::to_string(f.phases) +
                                       ") exceeds 40 x 64 with method fe (an FE solve per slice contact): fewer slices or phases");
  if (f.pair.positions_per_base_pitch > 0)
    fail_key(path, "model.positions_per_base_pitch", "(ch. 7's node reading) takes no helix angle or lead modification");
  if (f.pe_coupling) fail_key(path, "model.pe_coupling", "takes no helix angle or lead modification");
  if (h.double_helical && h.slices % 2 != 0) fail_key(path, "model.slices", "must be even for double_helical (half of them a half)");
  if (h.slices > 1 && f.pair.hertz != HertzCount::none && f.pair.pair_hertz != TwoPairHertz::consistent)
    fail_key(path, "model.pair_hertz", "must be consistent over the slices of a helical face (or model.hertz none)");
  }

// The pair's basic numbers the gears are built from.
struct PairBasics {
  double m = 0.0, alpha = 0.0, ha = 0.0, hf = 0.0, gap = 0.0;
};

// The pair's drawing keys: module, pressure angle, helix, the basic rack, the backlash.
PairBasics read_pair_keys(GearFile& f, const json& j, const Reader& r, const std::string& path) {
  PairBasics b;
  const double m = b.m = r.number(j, "", "module", 1e-5, 1.0, "[1e-5, 1] m");
  const double alpha = b.alpha = r.number(j, "", "pressure_angle_deg", 10.0, 35.0, "[10, 35] deg");
  // Helical (pair_helical.hpp): module and pressure angle are then the normal ones.
  HelicalPair& h = f.helical;
  h.helix_angle = r.optional(j, "", "helix_angle_deg", 0.0, 0.0, 45.0, "[0, 45] deg") * M_PI / 180.0;
  h.left_hand = r.choice(j, "", "hand", {"right", "left"}, 0) == 1;
  h.normal_module = m;
  h.normal_pressure_angle_deg = alpha;
  double& gap = b.gap;   // double helical: the gap between the halves [m], out of both face widths
  if (j.contains("double_helical")) {
    const json& d = j["double_helical"];
    if (!d.is_object()) fail_key(path, "double_helical", "must be an object {gap}");
    only_keys(d, path, "double_helical", {"gap"});
    if (!(h.helix_angle > 0.0)) fail_key(path, "double_helical", "needs helix_angle_deg > 0");
    h.double_helical = true;
    gap = r.number(d, "double_helical", "gap", 0.0, 10.0, "[0, 10] m");
  }
  const json rack = j.value("basic_rack", json::object());
  only_keys(rack, path, "basic_rack", {"addendum", "dedendum", "root_radius"});
  b.ha = r.optional(rack, "basic_rack", "addendum", 1.0, 0.5, 2.0, "[0.5, 2] (units of m)");
  const double hf = b.hf = r.optional(rack, "basic_rack", "dedendum", 1.25, 0.5, 2.5, "[0.5, 2.5] (units of m)");
  f.root_radius_coefficient = r.optional(rack, "basic_rack", "root_radius", 0.38, 0.0, 0.6, "[0, 0.6] (units of m)");
  f.dedendum_coefficient = hf;
  if (!(hf >= b.ha)) fail_key(path, "basic_rack.dedendum", "must be >= the addendum (no negative tip clearance)");
  f.backlash = r.optional(j, "", "backlash", 0.0, 0.0, 0.5 * M_PI * m, "[0, pi m / 2] m");

  return b;
}

// The torques [N m], 1 to 16.
void read_torques(GearFile& f, const json& j, const std::string& path) {
  if (!j.contains("torques")) fail_key(path, "torques", "is missing");
  if (!j["torques"].is_array() || j["torques"].empty() || j["torques"].size() > 16)
    fail_key(path, "torques", "must be a list of 1 to 16 torques [N m]");
  for (std::size_t i = 0; i < j["torques"].size(); ++i) {
    const std::string key = "torques." + std::to_string(i);
    const double T = json_number(j["torques"][i], path, key);
    if (!(T >= 1e-3 && T <= 1e7)) fail_key(path, key, "must be in [1e-3, 1e7] N m");
    f.torques.push_back(T);
  }

}

// A gear's tip relief (gears.<i>.tip_relief): amount, shape, and where it starts.
struct ReliefInput {
  double amount = 0.0, start = 0.0;
  ReliefStart kind = ReliefStart::length;
  ReliefShape shape = ReliefShape::linear;
};
ReliefInput read_tip_relief(const json& tr, const Reader& r, const std::string& t) {
  ReliefInput ri;
  only_keys(tr, r.file, t, {"amount", "start", "shape"});
  ri.amount = r.number(tr, t, "amount", 0.0, 1e-3, "[0, 1e-3] m");
  ri.shape = r.choice(tr, t, "shape", {"linear", "parabolic"}, 0) == 0 ? ReliefShape::linear : ReliefShape::parabolic;
  if (!tr.contains("start")) fail_key(r.file, t + ".start", "is missing (one of roll_angle_deg, diameter, length)");
  const json& st = tr["start"];
  only_keys(st, r.file, t + ".start", {"roll_angle_deg", "diameter", "length"});
  if (st.size() != 1) fail_key(r.file, t + ".start", "must give exactly one of roll_angle_deg, diameter, length");
  if (st.contains("roll_angle_deg")) {
    ri.kind = ReliefStart::roll_angle_deg;
    ri.start = r.number(st, t + ".start", "roll_angle_deg", 0.0, 90.0, "[0, 90] deg");
  } else if (st.contains("diameter")) {
    ri.kind = ReliefStart::diameter;
    ri.start = r.number(st, t + ".start", "diameter", 0.0, 20.0, "[0, 20] m");
  } else {
    ri.kind = ReliefStart::length;
    ri.start = r.number(st, t + ".start", "length", 0.0, 1.0, "[0, 1] m");
  }
  return ri;
}

// The two gears (driver, driven), their tip reliefs and the centre distance.
void read_gears(GearFile& f, const json& j, const Reader& r, const PairBasics& pb, const std::string& path) {
  const double m = pb.m, alpha = pb.alpha, ha = pb.ha, hf = pb.hf, gap = pb.gap;
  HelicalPair& h = f.helical;
  if (!j.contains("gears")) fail_key(path, "gears", "is missing");
  if (!j["gears"].is_array() || j["gears"].size() != 2) fail_key(path, "gears", "must be a list of 2 gears (driver, driven)");
  GearGeometry* geo[2] = {&f.pair.gear1, &f.pair.gear2};
  double* E[2] = {&f.pair.youngs_modulus1, &f.pair.youngs_modulus2};
  ReliefInput relief[2];
  for (int i = 0; i < 2; ++i) {
    const std::string prefix = "gears." + std::to_string(i);
    const json& g = j["gears"][i];
    only_keys(g, path, prefix, {"z", "x", "b", "E", "nu", "inertia", "rim_radius", "thickness_allowance", "tip_relief", "mass",
                           "bearing_stiffness", "axial_bearing_stiffness", "lead"});
    GearGeometry& G = *geo[i];
    G.module = m;
    G.pressure_angle_deg = alpha;
    G.addendum = ha * m;
    G.dedendum = hf * m;
    if (!g.contains("z")) fail_key(path, prefix + ".z", "is missing");
    G.teeth = json_whole(g["z"], path, prefix + ".z", 5, 1000);
    G.profile_shift = r.optional(g, prefix, "x", 0.0, -1.0, 2.0, "[-1, 2]");
    G.face_width = r.number(g, prefix, "b", 1e-4, 10.0, "[1e-4, 10] m");
    (i == 0 ? h.shift1 : h.shift2) = G.profile_shift;
    if (!(G.face_width - gap >= 1e-4)) fail_key(path, "double_helical.gap", "leaves less than 0.1 mm of face on " + prefix);
    G.face_width -= gap;   // double helical: the two halves' width (the gap carries nothing)
    G = transverse_section(G, h.helix_angle);
    if (g.contains("lead")) read_lead(g["lead"], path, prefix + ".lead", i == 0 ? h.lead1 : h.lead2);
    *E[i] = r.number(g, prefix, "E", 1e9, 1e13, "[1e9, 1e13] Pa");
    f.gear[i].poisson_ratio = r.optional(g, prefix, "nu", 0.3, 0.0, 0.4999, "[0, 0.5)");
    f.gear[i].inertia = r.optional(g, prefix, "inertia", 0.0, 0.0, 1e6, "[0, 1e6] kg m^2 (0: not given)");
    f.gear[i].rim_radius = r.optional(g, prefix, "rim_radius", 0.0, 0.0, 10.0, "[0, 10] m");
    f.gear[i].mass = r.optional(g, prefix, "mass", 0.0, 0.0, 1e6, "[0, 1e6] kg (0: not given)");
    f.gear[i].bearing_stiffness = r.optional(g, prefix, "bearing_stiffness", 0.0, 0.0, 1e13, "[0, 1e13] N/m (0: not given)");
    f.gear[i].axial_bearing_stiffness =
        r.optional(g, prefix, "axial_bearing_stiffness", 0.0, 0.0, 1e13, "[0, 1e13] N/m (0: not given)");
    f.gear[i].thickness_allowance = r.optional(g, prefix, "thickness_allowance", 0.0, -0.5 * m, 0.0, "[-m/2, 0] m");
    if (f.gear[i].rim_radius > 0.0 && !(f.gear[i].rim_radius < G.root_radius()))
      fail_key(path, prefix + ".rim_radius", "must be below the root circle (rf = " + mm(G.root_radius()) + ")");
    if (G.root_radius() <= 0.0) fail_key(path, prefix + ".z", "gives no root circle (rf <= 0)");
    if (g.contains("tip_relief")) relief[i] = read_tip_relief(g["tip_relief"], r, prefix + ".tip_relief");
  }
  const double rb_sum = f.pair.gear1.base_radius() + f.pair.gear2.base_radius();
  f.pair.centre_distance = r.optional(j, "", "centre_distance", 0.0, 0.0, 100.0, "[0, 100] m");
  if (f.pair.centre_distance > 0.0 && !(f.pair.centre_distance > rb_sum))
    fail_key(path, "centre_distance", "must exceed rb1 + rb2 = " + mm(rb_sum));
  for (int i = 0; i < 2; ++i) {
    const TipRelief t = tip_relief(*geo[i], relief[i].amount, relief[i].kind, relief[i].start, relief[i].shape);
    if (relief[i].amount > 0.0 && !(t.start_roll >= 0.0))
      fail_key(path, "gears." + std::to_string(i) + ".tip_relief.start", "lies inside the base circle");
    (i == 0 ? f.pair.relief1 : f.pair.relief2) = t;
  }

}

// The tooth model and its readings (model.*): the defaults are the tooth-model chart's choice
// (figures/tooth_model_chart.py).
json read_model_keys(GearFile& f, const json& j, const Reader& r, const std::string& path) {
  const json model = j.value("model", json::object());
  only_keys(model, path, "model", {"method", "phases", "positions_per_base_pitch", "tooth_elements", "thickness_at",
                                   "hertz", "pair_hertz", "pair_stiffness", "tooth_force", "fe_mesh", "pe_coupling",
                                   "slices"});
  // Defaults (issue 33 §4, figures/tooth_model_chart.py): the method the tooth-model chart
  // recommends (fe: the fast models are 3-170 % off the converged FE in mean stiffness, 20-80 %
  // in STE peak-to-peak) and the physically consistent readings; the thesis files write the
  // thesis' readings out.
  f.method = ToothModel(r.choice(model, "model", "method", {"beam", "potential_energy", "fe"}, 2));
  if (model.contains("fe_mesh") && f.method != ToothModel::fe) fail_key(path, "model.fe_mesh", "needs method fe");
  f.pe_coupling = r.choice(model, "model", "pe_coupling", {"none", "body_torsion"}, 0) == 1;
  if (f.pe_coupling && f.method != ToothModel::potential_energy)
    fail_key(path, "model.pe_coupling", "needs method potential_energy");
  f.phases = model.contains("phases") ? json_whole(model["phases"], path, "model.phases", 16, 4096) : 64;
  f.pair.positions_per_base_pitch =
      model.contains("positions_per_base_pitch")
          ? json_whole(model["positions_per_base_pitch"], path, "model.positions_per_base_pitch", 0, 128)
          : 0;
  if (f.pair.positions_per_base_pitch == 1) fail_key(path, "model.positions_per_base_pitch", "must be 0 or in [2, 128]");
  f.pair.tooth_elements =
      model.contains("tooth_elements") ? json_whole(model["tooth_elements"], path, "model.tooth_elements", 0, 64) : 0;
  if (f.pair.tooth_elements == 1) fail_key(path, "model.tooth_elements", "must be 0 (8 eps_alpha) or in [2, 64]");
  f.pair.thickness_at = ThicknessAt(r.choice(model, "model", "thickness_at", {"root_node", "midpoint", "tip_node"}, 0));
  f.pair.hertz = HertzCount(r.choice(model, "model", "hertz", {"none", "per_contact", "per_tooth"},
                                      f.method == ToothModel::beam ? 1 : 0));
  // The PE pair stiffness holds its own (linear, Yang & Sun) Hertz, the FE its resolved
  // contact: a Palmgren term on top would count the contact twice.
  if (f.method != ToothModel::beam && f.pair.hertz != HertzCount::none)
    fail_key(path, "model.hertz", std::string("must be none with method ") +
                                      (f.method == ToothModel::fe ? "fe (the contact is inside the FE compliance)"
                                                                  : "potential_energy (its linear Hertz is inside the pair stiffness)"));
  f.pair.pair_hertz = TwoPairHertz(r.choice(model, "model", "pair_hertz", {"equal_split", "fe_split_mean", "consistent"}, 2));
  f.pair.pair_stiffness = PairStiffness(r.choice(model, "model", "pair_stiffness", {"fused", "cantilevers"}, 1));
  f.pair.tooth_force = ToothForce(r.choice(model, "model", "tooth_force", {"pitch_radius", "base_radius"}, 1));
  if (f.method == ToothModel::fe && f.pair.tooth_force != ToothForce::over_base_radius)
    fail_key(path, "model.tooth_force", "must be base_radius with method fe (its force acts along the line of action)");

  return model;
}

// The Harris map's torque range.
void read_harris(GearFile& f, const json& j, const Reader& r, const std::string& path) {
  const json harris = j.value("harris", json::object());
  only_keys(harris, path, "harris", {"from", "to", "points"});
  const double Tmax = *std::max_element(f.torques.begin(), f.torques.end());
  f.harris_from = r.optional(harris, "harris", "from", std::max(1e-3, Tmax / 6.0), 1e-3, 1e7, "[1e-3, 1e7] N m");
  f.harris_to = r.optional(harris, "harris", "to", 5.0 * Tmax / 3.0, 1e-3, 1e7, "[1e-3, 1e7] N m");
  f.harris_points = harris.contains("points") ? json_whole(harris["points"], path, "harris.points", 2, 200) : 19;
  if (!(f.harris_to > f.harris_from)) fail_key(path, "harris.to", "must exceed harris.from");

}

// The checks of the whole pair, each naming its key: geometry, backlash, the method's own.
void check_pair(GearFile& f, const json& j, const json& model, const std::string& path) {
  // --- geometry checks (each names its key) ---------------------------------------------
  const PathOfContact p = f.pair.path();
  const GeometryProblem problem = gear_pair_problem(f.pair.gear1, f.pair.gear2, p, f.pair.relief1, f.pair.relief2);
  if (!problem.key.empty()) fail_key(path, problem.key, problem.why);
  // Normal backlash: given, or from the tooth-thickness allowances at this centre distance.
  const bool allowances = j["gears"][0].contains("thickness_allowance") || j["gears"][1].contains("thickness_allowance");
  if (allowances && j.contains("backlash"))
    fail_key(path, "backlash", "is given twice: give either backlash or the gears' thickness_allowance");
  if (allowances) {
    f.backlash = normal_backlash(f.pair.gear1, f.pair.gear2, p, f.gear[0].thickness_allowance,
                                 f.gear[1].thickness_allowance);
    if (!(f.backlash >= 0.0))
      fail_key(path, "gears.0.thickness_allowance", "gives a negative normal backlash (" + mm(f.backlash) +
                                                        ") at this centre distance: the teeth would interpenetrate");
  }
  check_helical(f, model, path);
  if (f.method == ToothModel::potential_energy) check_potential_energy(f, path, p);
  if (f.method == ToothModel::fe) read_fe_model(f, model, path);
  const int ne = f.pair.elements();
  if (ne < 2 || ne > 64) fail_key(path, "model.tooth_elements", "8 eps_alpha gives " + std::to_string(ne) + " elements: give 2..64");
  const int P = f.pair.positions_per_base_pitch;
  if (P > 0) {
    if (f.pair.gear1.teeth != f.pair.gear2.teeth || f.pair.gear1.profile_shift != f.pair.gear2.profile_shift ||
        f.pair.gear1.face_width != f.pair.gear2.face_width || f.pair.youngs_modulus1 != f.pair.youngs_modulus2)
      fail_key(path, "model.positions_per_base_pitch", "(ch. 7's node reading) needs two identical gears");
    if (f.pair.relief1.amount > 0.0 || f.pair.relief2.amount > 0.0)
      fail_key(path, "model.positions_per_base_pitch", "(ch. 7's node reading) cannot carry a tip relief");
    if (f.method != ToothModel::beam)
      fail_key(path, "model.positions_per_base_pitch", "(ch. 7's node reading of the beams) needs method beam");
    if (ne < P || ne >= 2 * P)
      fail_key(path, "model.positions_per_base_pitch", "needs P <= tooth elements (" + std::to_string(ne) + ") < 2 P");
  }
}

}  // namespace

BearingSupport gear_file_bearings(const GearFile& f) {
  BearingSupport b;
  for (int i = 0; i < 2; ++i) b.mass[i] = f.gear[i].mass, b.stiffness[i] = f.gear[i].bearing_stiffness;
  b.zeta = f.dynamics.bearing_zeta;
  b.pressure_angle = f.pair.path().mesh.pressure_angle;
  if (!f.helical.double_helical) b.helix_tan = std::tan(f.helical.base_helix_angle());   // 0 for spur
  for (int i = 0; i < 2; ++i) b.axial_stiffness[i] = f.gear[i].axial_bearing_stiffness;
  return b;
}

GearFile read_gear_file(const std::string& path, const std::vector<std::pair<std::string, std::string>>& overrides) {
  json j = read_json_file(path);
  only_keys(j, path, "", gear_file_keys());
  for (const auto& [key, text] : overrides) apply_override(j, path, key, text);
  return read_gear_json(j, path);
}

const std::vector<std::string>& gear_file_keys() {
  static const std::vector<std::string> keys{"name", "module", "pressure_angle_deg", "helix_angle_deg", "hand",
                                             "double_helical", "basic_rack", "centre_distance", "backlash", "torques",
                                             "gears", "model", "harris", "speed", "dynamics", "bifurcation_diagram",
                                             "period_doubling"};
  return keys;
}

GearFile read_gear_json(const nlohmann::json& j, const std::string& path) {
  only_keys(j, path, "", gear_file_keys());
  const Reader r{path};
  GearFile f;
  f.resolved = j;
  f.name = json_name(j, path, "name", "gear pair");
  const PairBasics basics = read_pair_keys(f, j, r, path);
  read_torques(f, j, path);
  read_gears(f, j, r, basics, path);
  const json model = read_model_keys(f, j, r, path);
  read_harris(f, j, r, path);
  read_dynamics(f, j, path);
  check_pair(f, j, model, path);
  f.diagram = read_bifurcation_diagram(j, path);
  if (f.diagram.given && f.diagram.on && !f.dynamics.present)
    fail_key(path, "bifurcation_diagram", "needs the speed range of the dynamics (speed)");
  f.period_doubling_depth = read_period_doubling_depth(j, path);
  if (j.contains("period_doubling") && !f.dynamics.present)
    fail_key(path, "period_doubling", "needs the speed range of the dynamics (speed)");
  return f;
}

std::unique_ptr<LoadedPair> gear_file_loaded_pair(const GearFile& f) {
  const PairSteModel& m = f.pair;
  if (f.method == ToothModel::fe && f.helical.sliced()) return sliced_fe_loaded_pair(m, f.helical, f.phases, f.fe);
  if (f.method == ToothModel::fe) return fe_loaded_pair(m, f.phases, f.fe);
  PairStiffnessFn k;
  if (f.method == ToothModel::potential_energy) {
    const PeGear g1 = f.pe[0], g2 = f.pe[1];
    k = [g1, g2](double r1, double r2, bool) { return pe_pair_stiffness(g1, g2, r1, r2); };
  }
  if (f.helical.sliced()) return sliced_loaded_pair(m, f.helical, f.phases, k);
  return phase_loaded_pair(m, f.phases, k, gear_file_pe_coupling(f));
}

double gear_file_pe_coupling(const GearFile& f) {
  return f.method == ToothModel::potential_energy && f.pe_coupling ? pe_body_coupling(f.pe[0]) + pe_body_coupling(f.pe[1])
                                                                   : 0.0;
}

std::string gear_file_help() {
  return "Gear-pair file keys (JSON; SI units; gear 1 drives):\n"
         "  name                         text shown in titles (1..120 characters)\n"
         "  module                       m [m], in [1e-5, 1] (a helical pair: the normal module m_n)\n"
         "  pressure_angle_deg           alpha [deg], in [10, 35] (a helical pair: the normal alpha_n)\n"
         "  helix_angle_deg              beta on the reference circle [deg], in [0, 45] (default 0: spur); the pair\n"
         "                               is then its transverse section, the face in model.slices slices staggered\n"
         "                               by the base helix (overlap ratio b sin(beta) / (pi m_n) <= 20)\n"
         "  hand                         right (default) | left: gear 1's hand (recorded: the axial force's direction)\n"
         "  double_helical.gap           two mirrored halves with a gap [m] between them, out of gears[i].b\n"
         "                               (each half (b - gap) / 2; eps_beta per helix; needs helix_angle_deg > 0)\n"
         "  basic_rack.addendum          ha* (units of m, default 1)\n"
         "  basic_rack.dedendum          hf* (default 1.25, >= ha*)\n"
         "  basic_rack.root_radius       rho_f* (default 0.38; used for the undercut limit)\n"
         "  centre_distance              a [m]; 0 or absent: from the shifts,\n"
         "                               inv(alpha_w) = inv(alpha) + 2 tan(alpha) (x1 + x2)/(z1 + z2)\n"
         "  backlash                     normal backlash j_n [m] (recorded; the STE is computed without), or:\n"
         "  gears[i].thickness_allowance A_sn [m] <= 0 on the reference circle: j_n follows exactly,\n"
         "                               m cos a [(z1+z2)(inv a_w - inv a) - 2 tan a (x1+x2)] - (A_sn1+A_sn2) cos a\n"
         "  torques                      list of 1..16 driver torques T1 [N m], each in [1e-3, 1e7]\n"
         "  gears[i].z                   teeth (whole, 5..1000); i = 0 driver, 1 driven\n"
         "  gears[i].x                   profile shift coefficient (default 0, in [-1, 2])\n"
         "  gears[i].b                   face width [m]\n"
         "  gears[i].E, gears[i].nu      Young's modulus [Pa], Poisson's ratio (nu used by method fe; recorded\n"
         "                               only by beam and potential_energy: their Hertz laws are for steel)\n"
         "  gears[i].inertia             polar moment of inertia [kg m^2] (recorded, for the dynamics)\n"
         "  gears[i].rim_radius          rim/bore radius [m] (beam: recorded, the tooth root is clamped;\n"
         "                               potential_energy: required, the fillet foundation's bore; fe: the\n"
         "                               fixed bore, below rf - m, 0 = max(rf - 3 m, 0.5 rf))\n"
         "  gears[i].tip_relief.amount   Ca [m] at the tip circle (0: none)\n"
         "  gears[i].tip_relief.start    exactly one of {roll_angle_deg: xi [deg]}, {diameter: d [m]},\n"
         "                               {length: L [m] along the path of contact, measured from the tip}\n"
         "  gears[i].tip_relief.shape    linear (default) | parabolic\n"
         "  gears[i].lead.crowning       C_beta [m] at each end of the face, C_beta (2 y / b - 1)^2 (0..1e-3)\n"
         "  gears[i].lead.end_relief     {amount: C_I [m], length: L_I [m] <= b / 2}: linear over L_I at each end\n"
         "  model.method                 fe (default) | beam (thesis ch. 7's beams) | potential_energy (bending, shear,\n"
         "                               compression of the involute tooth, Sainsot's fillet foundation clamped at\n"
         "                               gears[i].rim_radius, which it needs; linear Hertz inside the pair stiffness,\n"
         "                               so model.hertz must be none, its default then; tooth_elements, thickness_at,\n"
         "                               pair_stiffness and pair_hertz do not apply; no node reading)\n"
         "                               | fe (tooth contact by plane-strain finite elements on the generated tooth\n"
         "                               form, each gear whole and fixed at gears[i].rim_radius, 0: max(rf - 3 m,\n"
         "                               0.5 rf); contact inside, so model.hertz none, its default then; about 2-5 s\n"
         "                               per pair to build; reference/fe_tooth_contact.md). The default because the\n"
         "                               tooth-model chart (figures/tooth_model_chart.py) finds the fast models 3-170 %\n"
         "                               off the converged FE in mean stiffness; the thesis files say method beam\n"
         "  model.fe_mesh.contact_size   element size along the loaded flanks (units of m, default 0.025), and\n"
         "  model.fe_mesh.tooth_size     ... on the loaded teeth and their neighbours (default 0.1),\n"
         "  model.fe_mesh.far_tooth_size ... on the other teeth (default 0.25), body_size in the body (default 1);\n"
         "  model.fe_mesh.scale          all sizes times scale (default 1; the defaults are within 0.05 % of the\n"
         "                               extrapolated mean stiffness). A mesh estimated above 2e6 nodes is refused\n"
         "  model.pe_coupling            none (default) | body_torsion: method potential_energy with the structural\n"
         "                               coupling of the loaded pairs through the bodies' torsion (the annulus rim_radius..rf,\n"
         "                               potential_energy.hpp pe_body_coupling): the rigid part of the FE's coupling\n"
         "  model.phases                 phases per mesh cycle (default 64, 16..4096)\n"
         "  model.slices                 slices of the face of a helical or lead-modified pair (default 20, 1..200,\n"
         "                               slices x model.phases <= 200 x 64, x (torques + 2 harris.points) <= 1.6e6;\n"
         "                               beam or potential_energy: model.pair_hertz consistent or model.hertz none;\n"
         "                               fe: the plane FE section per unit width read at every slice contact,\n"
         "                               slices x model.phases <= 40 x 64)\n"
         "  model.positions_per_base_pitch  0 (default): load moving continuously; P: ch. 7's node reading\n"
         "                               (identical gears, no relief)\n"
         "  model.tooth_elements         beam elements per tooth (0 = floor(8 eps_alpha): 14 for the thesis)\n"
         "  model.thickness_at           root_node (default) | midpoint | tip_node: where s(r) is read per element\n"
         "  model.hertz                  per_contact (default for beam: Palmgren once per contact) | per_tooth (thesis)\n"
         "                               | none (the default and the only choice for potential_energy and fe)\n"
         "  model.pair_hertz             consistent (default: Hertz inside the load sharing) | equal_split (thesis)\n"
         "                               | fe_split_mean\n"
         "  model.pair_stiffness         cantilevers (default) | fused (thesis section 7.2)\n"
         "  model.tooth_force            base_radius (default: T1 / rb1 along the line of action) | pitch_radius\n"
         "                               (thesis: T1 / r1; not with method fe)\n"
         "  harris.from, harris.to, harris.points  torques of the Harris map [N m] (default T_max/6 .. 5 T_max/3, 19)\n"
         "  speed.unit, speed.from, speed.to  the speed range of the dynamics: mesh_hz (mesh frequency\n"
         "                               f_mesh [Hz]) | rpm (of gear 1; f_mesh = z1 n1 / 60); absent: no dynamics\n"
         "  dynamics.model               one_dof (default: chapter 8's torsional model along the line of action)\n"
         "                               | six_dof (x, y, theta per gear, centres on bearings: needs gears[i].mass\n"
         "                               and gears[i].bearing_stiffness; the rigid rotation of the pair removed)\n"
         "  dynamics.mesh                constant (default: chapter 8, constant kc, the STE as excitation) |\n"
         "                               parametric (k(theta) = F0 / (STE - no-load TE) in contact)\n"
         "  dynamics.zeta                mesh damping ratio, c = 2 zeta sqrt(kc me) (default 0.08, chapter 8)\n"
         "  dynamics.bearing_zeta        damping ratio of each bearing mode, six_dof (default 0.02)\n"
         "  dynamics.harmonics           H of the harmonic balance, also the STE harmonics kept (default 5, 1..64).\n"
         "                               The cost grows with H (measured on 2 shared cores, all torques, with the\n"
         "                               checks): thesis_pair.json 1.4 s at H = 5, 14 s at 64; the six_dof model\n"
         "                               thesis_pair_six_dof.json 8 s at 5, 36 s at 16, about 2 min at 64\n"
         "  dynamics.sweep               up (default: from speed.from) | down (from speed.to)\n"
         "  dynamics.back_flank          yes (default: contact where the mesh deflection < -(backlash + back\n"
         "                               relief)) | no (drive flank only, chapter 8)\n"
         "  dynamics.time_check_points   stable points per curve checked by GSL time integration (default 8)\n"
         "  dynamics.iso_quality_grade   ISO 1328-1 grade of ISO 6336-1 method B's K_v (default 5)\n" +
         bifurcation_diagram_help() +
         "                        (per torque, over the speed range, the DTE at each mesh period; needs speed)\n" +
         period_doubling_help() +
         "                        (per torque, frc_<i>.csv and bifurcations_<i>.csv; needs speed)\n"
         "  gears[i].mass, gears[i].bearing_stiffness  [kg], [N/m]: the six_dof model\n"
         "  gears[i].axial_bearing_stiffness  [N/m]: six_dof with a helix angle (single helical): one axial\n"
         "                               translation per gear on it, the mesh force's axial part N tan(beta_b)\n"
         "Checks (exit 2, one line naming the key): tip thickness s(ra) >= 0.2 m, tip clearance, involute\n"
         "interference, contact ratio >= 1, relief start inside the path of contact and above the base circle.\n"
         "--set PATH=VALUE overrides a number at a dotted path: torques.2=250, gears.0.x=0.3,\n"
         "gears.1.tip_relief.amount=15e-6, model.phases=128\n";
}

}  // namespace gearhb
