#include "gearhb/tools/planetary_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "gearhb/app/bifurcation_input.hpp"
#include "gearhb/app/json_file.hpp"
#include "gearhb/hb/contact.hpp"
#include "gearhb/tools/planetary_stiffness.hpp"

namespace gearhb {

namespace {

using nlohmann::json;

constexpr double kDeg = M_PI / 180.0;

std::string key_of(const std::string& where, const char* key) { return where.empty() ? key : where + "." + key; }

const json& member(const json& root, const std::string& file, const char* key) {
  if (!root.contains(key)) fail_key(file, key, "is missing");
  if (!root[key].is_object()) fail_key(file, key, "must be an object");
  return root[key];
}

double number(const json& parent, const std::string& file, const std::string& where, const char* key, double lo,
              double hi, const char* range_text) {
  const std::string path = key_of(where, key);
  if (!parent.contains(key)) fail_key(file, path, "is missing");
  const double v = json_number(parent[key], file, path);
  if (!(v >= lo && v <= hi)) fail_key(file, path, std::string("must be in ") + range_text);
  return v;
}

int whole(const json& parent, const std::string& file, const std::string& where, const char* key, int lo, int hi) {
  if (!parent.contains(key)) fail_key(file, key_of(where, key), "is missing");
  return json_whole(parent[key], file, key_of(where, key), lo, hi);
}

CentralMember central_member(const json& root, const std::string& file, const char* name) {
  const json& j = member(root, file, name);
  only_keys(j, file, name, {"mass", "inertia_r2", "bearing", "torsional"});
  CentralMember m;
  m.mass = number(j, file, name, "mass", 1e-6, 1e6, "[1e-6, 1e6] kg");
  m.inertia_r2 = number(j, file, name, "inertia_r2", 1e-6, 1e6, "[1e-6, 1e6] kg");
  m.bearing = number(j, file, name, "bearing", 0.0, 1e13, "[0, 1e13] N/m");
  m.torsional = number(j, file, name, "torsional", 0.0, 1e13, "[0, 1e13] N/m");
  return m;
}

void read_teeth(PlanetaryFile& f, const json& j, const std::string& file) {
  const json& t = member(j, file, "teeth");
  only_keys(t, file, "teeth", {"sun", "planet", "ring"});
  f.teeth.sun = whole(t, file, "teeth", "sun", 6, 1000);
  f.teeth.planet = whole(t, file, "teeth", "planet", 6, 1000);
  f.teeth.ring = whole(t, file, "teeth", "ring", 12, 3000);
  if (f.teeth.ring != f.teeth.sun + 2 * f.teeth.planet)
    fail_key(file, "teeth.ring", "must be z_s + 2 z_p = " + std::to_string(f.teeth.sun + 2 * f.teeth.planet) +
                                     " (standard centre distances: profile shifts are not modelled)");
  f.teeth.module = number(j, file, "", "module", 1e-5, 1.0, "[1e-5, 1] m");
  f.teeth.addendum = j.contains("addendum") ? number(j, file, "", "addendum", 0.5, 2.0, "[0.5, 2] (units of m)") : 1.0;
}

// planets, planet_angles_deg, and the two checks of where the planets sit.
void read_planets(PlanetaryFile& f, const json& j, const std::string& file) {
  const int N = whole(j, file, "", "planets", 1, 16);
  f.equally_spaced = !j.contains("planet_angles_deg");
  if (f.equally_spaced) {
    f.set.planet_angles = equally_spaced(N);
  } else {
    const json& a = j["planet_angles_deg"];
    if (!a.is_array() || int(a.size()) != N)
      fail_key(file, "planet_angles_deg", "must be a list of `planets` = " + std::to_string(N) + " angles [deg]");
    double last = -1.0;
    for (int n = 0; n < N; ++n) {
      const std::string key = "planet_angles_deg." + std::to_string(n);
      const double psi = json_number(a[std::size_t(n)], file, key);
      if (n == 0 && psi != 0.0) fail_key(file, key, "must be 0 (the first planet defines the carrier's x axis)");
      if (n > 0 && !(psi > last && psi < 360.0)) fail_key(file, key, "must be above the previous angle and below 360");
      last = psi;
      f.set.planet_angles.push_back(psi * kDeg);
    }
  }
  const int n = planet_not_assembling(f.teeth, f.set.planet_angles);
  const int zz = f.teeth.sun + f.teeth.ring;
  if (n >= 0 && f.equally_spaced)
    fail_key(file, "planets", "cannot be equally spaced: (z_s + z_r) / N = " + std::to_string(zz) + " / " +
                                  std::to_string(N) + " is not a whole number");
  if (n >= 0)
    fail_key(file, "planet_angles_deg." + std::to_string(n),
             "does not assemble: (z_s + z_r) psi / 360 = " + std::to_string(zz) + " psi / 360 must be a whole number");
  const double clearance = planet_tip_clearance(f.teeth, f.set.planet_angles);
  if (clearance <= 0.0) {
    char b[160];
    std::snprintf(b, sizeof b, "puts neighbouring planets whose tip circles overlap by %.4g mm (they collide)",
                  -clearance * 1e3);
    fail_key(file, f.equally_spaced ? "planets" : "planet_angles_deg", b);
  }
}

double optional_number(const json& parent, const std::string& file, const std::string& where, const char* key,
                       double fallback, double lo, double hi, const char* range_text) {
  return parent.contains(key) ? number(parent, file, where, key, lo, hi, range_text) : fallback;
}

Body member_name(const json& parent, const std::string& file, const std::string& where, const char* key) {
  const std::string path = key_of(where, key);
  if (!parent.contains(key)) fail_key(file, path, "is missing");
  const json& v = parent[key];
  if (v.is_string() && v.get<std::string>() == "sun") return Body::sun;
  if (v.is_string() && v.get<std::string>() == "ring") return Body::ring;
  if (v.is_string() && v.get<std::string>() == "carrier") return Body::carrier;
  fail_key(file, path, "must be one of sun | ring | carrier");
}

// A value per planet at parent[key]: one number for every planet (if `one_for_all`) or a
// list of N numbers, each in [lo, hi] (key.n names a bad entry).
std::vector<double> per_planet(const json& parent, const std::string& file, const std::string& where, const char* key,
                               int N, bool one_for_all, double lo, double hi, const char* range_text) {
  const std::string path = key_of(where, key);
  const json& v = parent[key];
  if (one_for_all && v.is_number()) return std::vector<double>(std::size_t(N), number(parent, file, where, key, lo, hi, range_text));
  if (!v.is_array() || int(v.size()) != N)
    fail_key(file, path, std::string(one_for_all ? "must be a number or " : "must be ") + "a list of `planets` = " +
                             std::to_string(N) + " numbers");
  std::vector<double> out;
  for (int n = 0; n < N; ++n) {
    const std::string k = path + "." + std::to_string(n);
    const double x = json_number(v[std::size_t(n)], file, k);
    if (!(x >= lo && x <= hi)) fail_key(file, k, std::string("must be in ") + range_text);
    out.push_back(x);
  }
  return out;
}

// mesh.sun_planet_backlash, mesh.ring_planet_backlash (a back flank on each mesh of that kind),
// mesh.back_phase.
void read_backlash(PlanetaryFile& f, const json& m, const std::string& file) {
  const int N = f.set.planets();
  PlanetaryMeshes& r = f.meshes;
  r.backlash.clear();
  bool any = false;
  for (const char* key : {"sun_planet_backlash", "ring_planet_backlash"}) {
    std::vector<double> b(std::size_t(N), INFINITY);
    if (m.contains(key)) b = per_planet(m, file, "mesh", key, N, true, 0.0, 1e-2, "[0, 0.01] m"), any = true;
    r.backlash.insert(r.backlash.end(), b.begin(), b.end());
  }
  if (!any) r.backlash.clear();
  r.back_phase = optional_number(m, file, "mesh", "back_phase", 0.0, 0.0, 1.0, "[0, 1] mesh cycles");
}

// mesh.stiffness tooth_model: the keys of the rectangular waves are refused, the pair kept
// for the response's load (compute_tooth_stiffness).
void read_tooth_model(PlanetaryFile& f, const json& m, const std::string& file) {
  for (const char* key : {"sun_planet", "ring_planet", "sun_contact_ratio", "ring_contact_ratio", "stiffness_ratio"})
    if (m.contains(key))
      fail_key(file, std::string("mesh.") + key, "belongs to the rectangular wave: mesh.stiffness tooth_model computes it");
  if (!m.contains("sun_planet_pair"))
    fail_key(file, "mesh.sun_planet_pair", "is missing (the sun-planet pair's teeth for mesh.stiffness tooth_model)");
  f.sun_planet_pair = m["sun_planet_pair"];
  if (m.contains("ring_planet_stiffness")) {
    const json& k = m["ring_planet_stiffness"];
    if (!k.is_string() || (k != "potential_energy" && k != "iso6336"))
      fail_key(file, "mesh.ring_planet_stiffness", "must be one of potential_energy | iso6336");
    f.ring_planet_model = k == "iso6336" ? RingPlanetModel::iso6336 : RingPlanetModel::potential_energy;
  }
  // gamma_rs from the teeth unless the file gives it (an override)
  f.ring_sun_phase_from_teeth = ring_sun_phase_from_teeth(f.teeth, f.set.sun_pressure_angle);
  f.ring_sun_phase = optional_number(m, file, "mesh", "ring_sun_phase", f.ring_sun_phase_from_teeth, 0.0, 1.0,
                                     "[0, 1] mesh cycles");
  f.meshes.phases = mesh_phases(f.teeth, f.set.planet_angles, f.ring_sun_phase);
  f.back_phase_from_teeth = !m.contains("back_phase");   // else the file's back_phase overrides
  read_backlash(f, m, file);
}

void read_meshes(PlanetaryFile& f, const json& m, const std::string& file) {
  only_keys(m, file, "mesh", {"stiffness", "sun_planet_pair", "ring_planet_stiffness", "sun_planet", "ring_planet", "sun_contact_ratio",
                              "ring_contact_ratio", "stiffness_ratio", "ring_sun_phase", "sun_planet_backlash",
                              "ring_planet_backlash", "back_phase"});
  if (m.contains("stiffness")) {
    const json& k = m["stiffness"];
    if (!k.is_string() || (k != "rectangular" && k != "tooth_model"))
      fail_key(file, "mesh.stiffness", "must be one of rectangular | tooth_model");
    f.tooth_model = k == "tooth_model";
  }
  if (f.tooth_model) return read_tooth_model(f, m, file);
  for (const char* key : {"sun_planet_pair", "ring_planet_stiffness"})
    if (m.contains(key)) fail_key(file, std::string("mesh.") + key, "needs mesh.stiffness tooth_model");
  PlanetaryMeshes& r = f.meshes;
  r.sun.mean = f.set.sun_mesh = number(m, file, "mesh", "sun_planet", 1e3, 1e13, "[1e3, 1e13] N/m");
  r.ring.mean = f.set.ring_mesh = number(m, file, "mesh", "ring_planet", 1e3, 1e13, "[1e3, 1e13] N/m");
  r.sun.contact_ratio = optional_number(m, file, "mesh", "sun_contact_ratio", 1.6, 1.0, 2.0, "[1, 2]");
  r.ring.contact_ratio = optional_number(m, file, "mesh", "ring_contact_ratio", 1.8, 1.0, 2.0, "[1, 2]");
  r.sun.ratio = r.ring.ratio = optional_number(m, file, "mesh", "stiffness_ratio", 1.0, 1.0, 4.0, "[1, 4]");
  const double gamma_rs = optional_number(m, file, "mesh", "ring_sun_phase", 0.0, 0.0, 1.0, "[0, 1] mesh cycles");
  r.phases = mesh_phases(f.teeth, f.set.planet_angles, gamma_rs);
  read_backlash(f, m, file);
}

// mesh.stiffness tooth_model under the response's load (tools/planetary_stiffness.hpp): the
// sun-planet mesh by the pair model, the ring-planet mesh by ISO 6336-1; their means also
// the linear model's mesh stiffnesses.
void compute_tooth_stiffness(PlanetaryFile& f, const std::string& file) {
  const PlanetaryResponseInput& p = f.response;
  f.tooth = planetary_tooth_stiffness(f.sun_planet_pair, file, f.name, f.teeth, f.set.sun_pressure_angle,
                                      f.set.planets(), p.input, p.torque, f.ring_planet_model);
  const int J = int(f.tooth.sun.samples.size());
  if (p.harmonics > (J - 2) / 2)
    fail_key(file, "response.harmonics", "must be at most (mesh.sun_planet_pair.model.phases - 2) / 2 = " +
                                             std::to_string((J - 2) / 2) + " (the pair model's phases resolve no more)");
  PlanetaryMeshes& m = f.meshes;
  if (f.back_phase_from_teeth) m.sun_back_mirror = f.tooth.sun_back_mirror, m.ring_back_mirror = f.tooth.ring_back_mirror;
  m.sun_computed = f.tooth.sun;
  m.sun.mean = f.set.sun_mesh = f.tooth.sun.mean();
  m.sun.contact_ratio = f.tooth.sun_contact_ratio;
  if (f.ring_planet_model == RingPlanetModel::iso6336) {
    m.ring = f.tooth.ring;
  } else {
    m.ring_computed = f.tooth.ring_pe;
    m.ring.mean = f.tooth.ring_pe.mean();
    m.ring.contact_ratio = std::min(2.0, f.tooth.ring_contact_ratio);   // recorded; the samples are the stiffness
  }
  f.set.ring_mesh = m.ring.mean;
}

void read_response(PlanetaryFile& f, const json& j, const std::string& file) {
  if (!j.contains("response")) return;
  const json& r = member(j, file, "response");
  only_keys(r, file, "response", {"input", "torque", "output", "output_shaft", "f_mesh_hz", "zeta", "harmonics",
                                  "stability"});
  PlanetaryResponseInput& p = f.response;
  p.present = true;
  int contacts = 2 * f.set.planets();   // the drive flanks, and a back flank where a backlash is given
  for (double b : f.meshes.backlash) contacts += std::isfinite(b) ? 1 : 0;
  const int per_planet_flanks = (contacts + f.set.planets() - 1) / f.set.planets();
  if (contacts > kMaxContacts)
    fail_key(file, "planets", "must be at most " + std::to_string(kMaxContacts / per_planet_flanks) +
                                  " with a response and these flanks (" + std::to_string(contacts) +
                                  " contacts; the engine's contact limit is " + std::to_string(kMaxContacts) + ")");
  p.input = member_name(r, file, "response", "input");
  p.output = member_name(r, file, "response", "output");
  if (p.output == p.input) fail_key(file, "response.output", "must differ from response.input");
  p.torque = number(r, file, "response", "torque", 1e-3, 1e7, "[1e-3, 1e7] N m (> 0: the drive flanks carry it)");
  p.output_shaft = optional_number(r, file, "response", "output_shaft", 0.0, 0.0, 1e13, "[0, 1e13] N/m");
  if (!r.contains("f_mesh_hz") || !r["f_mesh_hz"].is_object())
    fail_key(file, "response.f_mesh_hz", "must be {\"from\", \"to\"} [Hz]");
  only_keys(r["f_mesh_hz"], file, "response.f_mesh_hz", {"from", "to"});
  p.f_mesh_hz_from = number(r["f_mesh_hz"], file, "response.f_mesh_hz", "from", 1.0, 1e6, "[1, 1e6] Hz");
  p.f_mesh_hz_to = number(r["f_mesh_hz"], file, "response.f_mesh_hz", "to", 1.0, 1e6, "[1, 1e6] Hz");
  if (!(p.f_mesh_hz_to > p.f_mesh_hz_from))
    fail_key(file, "response.f_mesh_hz.to", "must be above response.f_mesh_hz.from");
  p.zeta = optional_number(r, file, "response", "zeta", 0.02, 1e-4, 0.5, "[1e-4, 0.5]");
  p.harmonics = r.contains("harmonics") ? whole(r, file, "response", "harmonics", 1, 32) : 8;
  p.stability = r.contains("stability") ? json_flag(r["stability"], file, "response.stability") : true;
  if (f.tooth_model) compute_tooth_stiffness(f, file);
  try {   // the stiffness waves cut to H harmonics must stay stiffnesses (Gibbs undershoot)
    (void)planetary_mesh_contacts(f.set, f.meshes, p.harmonics);
  } catch (const std::invalid_argument&) {
    fail_key(file, f.tooth_model ? "response.harmonics" : "mesh.stiffness_ratio",
             "cut to response.harmonics = " + std::to_string(p.harmonics) +
                 " harmonics makes a mesh stiffness negative somewhere in the cycle");
  }
  // The held output must leave no free rotation: the loaded set needs a static equilibrium.
  PlanetarySet held = f.set;
  CentralMember& out = p.output == Body::sun ? held.sun : p.output == Body::ring ? held.ring : held.carrier;
  out.torsional += p.output_shaft;
  const std::vector<PlanetaryMode> modes = planetary_modes(held);
  if (!(modes.front().omega > 1e-6 * modes.back().omega))
    fail_key(file, "response.output_shaft", "leaves the set free to rotate (a natural frequency 0): hold the output");
}

// bifurcation_diagram: true | false | an object of options (read_bifurcation_diagram); only with
// the response's stability (the diagram's bands are the ranges the stability finds unstable).
// The options a key leaves out take the set's defaults (planetary_diagram_defaults), not the library's.
void read_diagram(PlanetaryFile& f, const json& j, const std::string& path) {
  f.diagram = planetary_diagram_defaults();
  if (!j.contains("bifurcation_diagram")) {
    f.diagram_on = f.response.present && f.response.stability;
    return;
  }
  const json& d = j["bifurcation_diagram"];
  if (d.is_boolean()) {
    f.diagram_on = d.get<bool>();
  } else {
    json merged = json::object();   // the set's defaults, then the file's options
    merged["bifurcation_diagram"] = {{"transient_periods", f.diagram.transient_periods}, {"periods", f.diagram.periods},
                                     {"max_period", f.diagram.max_period}, {"lyapunov_periods", f.diagram.lyapunov_periods}};
    if (!d.is_object()) fail_key(path, "bifurcation_diagram", "must be true, false or an object of options");
    merged["bifurcation_diagram"].update(d);
    f.diagram = read_bifurcation_diagram(merged, path).options;
    f.diagram_speeds_given = d.contains("speeds");
    f.diagram_on = true;
  }
  if (f.diagram_on && !(f.response.present && f.response.stability))
    fail_key(path, "bifurcation_diagram", "needs the response with its stability (response.stability 1)");
}

}  // namespace

BifurcationDiagramOptions planetary_diagram_defaults() {
  BifurcationDiagramOptions o;
  o.transient_periods = 200;
  o.periods = 16;
  o.max_period = 4;
  o.lyapunov_periods = 20;
  return o;
}

double member_radius(const PlanetaryTeeth& t, double pressure_angle, Body b) {
  if (b == Body::carrier) return t.centre_distance();
  return 0.5 * (b == Body::sun ? t.sun : t.ring) * t.module * std::cos(pressure_angle);
}

PlanetaryFile read_planetary_file(const std::string& path,
                                  const std::vector<std::pair<std::string, std::string>>& overrides) {
  json j = read_json_file(path);
  only_keys(j, path, "", {"name", "planets", "planet_angles_deg", "teeth", "module", "addendum", "pressure_angle_deg",
                          "sun", "ring", "carrier", "planet", "mesh", "response", "campbell", "period_doubling",
                          "bifurcation_diagram"});
  for (const auto& [key, text] : overrides) apply_override(j, path, key, text);
  PlanetaryFile f;
  f.resolved = j;
  f.name = json_name(j, path, "name", "planetary set");
  read_teeth(f, j, path);
  read_planets(f, j, path);
  PlanetarySet& s = f.set;
  s.sun_pressure_angle = s.ring_pressure_angle =
      number(j, path, "", "pressure_angle_deg", 10.0, 35.0, "[10, 35] deg") * kDeg;
  s.sun = central_member(j, path, "sun");
  s.ring = central_member(j, path, "ring");
  s.carrier = central_member(j, path, "carrier");
  const json& p = member(j, path, "planet");
  only_keys(p, path, "planet", {"mass", "inertia_r2", "bearing", "pin_errors"});
  s.planet_mass = number(p, path, "planet", "mass", 1e-6, 1e6, "[1e-6, 1e6] kg");
  s.planet_inertia_r2 = number(p, path, "planet", "inertia_r2", 1e-6, 1e6, "[1e-6, 1e6] kg");
  s.planet_bearing = number(p, path, "planet", "bearing", 0.0, 1e13, "[0, 1e13] N/m");
  read_meshes(f, member(j, path, "mesh"), path);
  if (p.contains("pin_errors"))
    f.meshes.pin_errors = per_planet(p, path, "planet", "pin_errors", s.planets(), false, -1e-3, 1e-3, "[-1e-3, 1e-3] m");
  read_response(f, j, path);
  f.period_doubling_depth = read_period_doubling_depth(j, path);
  if (j.contains("period_doubling") && !f.response.present)
    fail_key(path, "period_doubling", "needs the response over mesh frequency (response)");
  read_diagram(f, j, path);
  if (f.tooth_model && !f.response.present)
    fail_key(path, "mesh.stiffness", "tooth_model needs a response section (its torque is the meshes' static load)");
  if (j.contains("campbell")) {
    const json& c = member(j, path, "campbell");
    only_keys(c, path, "campbell", {"carrier_rpm_to", "points"});
    f.campbell_rpm_to = number(c, path, "campbell", "carrier_rpm_to", 1.0, 1e6, "[1, 1e6] rpm");
    f.campbell_points = whole(c, path, "campbell", "points", 2, 1001);
  }
  return f;
}

HarmonicBalance planetary_response_model(const PlanetaryFile& f) {
  const PlanetaryResponseInput& r = f.response;
  PlanetarySet s = f.set;
  (r.output == Body::sun ? s.sun : r.output == Body::ring ? s.ring : s.carrier).torsional += r.output_shaft;
  Eigen::VectorXd f0 = Eigen::VectorXd::Zero(s.dofs());
  // The torque that loads the drive flanks (defined by the sun driving): the sun's and the
  // ring's turn the same way in Lin & Parker's coordinates (each takes N F r_b), the carrier's
  // is their reaction, -N F (r_bs + r_br) (planetary_stiffness.hpp nominal_mesh_force).
  const double sign = r.input == Body::carrier ? -1.0 : 1.0;
  f0(coordinate(r.input, 2)) = sign * r.torque / member_radius(f.teeth, s.sun_pressure_angle, r.input);
  return planetary_harmonic_balance(s, f.meshes, r.zeta, f0, r.harmonics);
}

std::string planetary_file_help() {
  return "Planetary-set file (JSON, SI units; lib/gearhb/tools/planetary_file.hpp):\n"
         "  name                     title of the figures\n"
         "  planets                  N, 1..16, equally spaced unless planet_angles_deg is given\n"
         "  planet_angles_deg        optional: N angles [deg], the first 0, ascending below 360\n"
         "  teeth.sun/planet/ring    z_s, z_p, z_r = z_s + 2 z_p (no profile shifts)\n"
         "  module                   m [m]; addendum: h_a* (default 1), the planets' tip circles\n"
         "  pressure_angle_deg       operating pressure angle of both meshes [deg]\n"
         "  sun/ring/carrier         mass [kg], inertia_r2 = I / r^2 [kg], bearing (radial) [N/m],\n"
         "                           torsional = k_theta / r^2 [N/m] (0: free to rotate)\n"
         "  planet                   mass [kg], inertia_r2 [kg], bearing (radial and tangential) [N/m],\n"
         "                           pin_errors: optional N tangential pin position errors [m] (0)\n"
         "  mesh.sun_planet/ring_planet   mean mesh stiffness [N/m]\n"
         "  mesh.sun_contact_ratio/ring_contact_ratio   of the rectangular wave (1.6, 1.8)\n"
         "  mesh.stiffness_ratio     k_double / k_single of both meshes (1: constant)\n"
         "  mesh.ring_sun_phase      gamma_rs [mesh cycles] between the ring and sun meshes (0; with\n"
         "                           mesh.stiffness tooth_model: from the teeth unless given; so is the back\n"
         "                           flanks' wave, the mirror image of the drive flank's, unless back_phase is given)\n"
         "  mesh.stiffness           rectangular (default: the keys above) | tooth_model: the sun-planet mesh's\n"
         "                           k(theta) by gearhb_gear's pair model of mesh.sun_planet_pair (the gear-pair\n"
         "                           file's basic_rack, gears [sun, planet] without z, model), the ring-planet\n"
         "                           mesh by mesh.ring_planet_stiffness: potential_energy (default; the ring's\n"
         "                           tooth an internal involute cantilever) | iso6336 (ISO 6336-1, internal gear);\n"
         "                           both meshes at the response's static load\n"
         "  mesh.sun_planet_backlash/ring_planet_backlash   optional: normal backlash [m] of every\n"
         "                           mesh of that kind, or a list of N (one per planet): a back flank\n"
         "                           on each (none without); mesh.back_phase: its wave's lag [cycles] (0)\n"
         "  response                 optional: input (sun | ring | carrier), torque [N m] > 0, output,\n"
         "                           output_shaft [N/m] added to its torsional stiffness, f_mesh_hz.from/to,\n"
         "                           zeta (0.02), harmonics (8), stability (1: every point's)\n"
         "  campbell                 optional: carrier_rpm_to, points: natural frequencies over carrier speed\n" +
         period_doubling_help() +
         "  bifurcation_diagram      optional: true (the default with response.stability 1) | false | an object of\n"
         "                           options of gearhb_frc's key (speeds: per band and sweep, default from the band's\n"
         "                           width; transient_periods (200 here), periods (16), max_period (4), period_tol,\n"
         "                           lyapunov_periods (20), lyapunov_threshold): the diagram by time integration over each range with no\n"
         "                           stable period-1 orbit, padded (bifurcation_diagram.csv, bifurcation_diagram.png)\n" +
         "                        (with response.stability: the PDs located on the curve)\n"
         "Checks (exit 2 naming the key): z_r = z_s + 2 z_p, (z_s + z_r) / N whole (equal spacing) or\n"
         "(z_s + z_r) psi_n / 360 whole (given angles), tip circles of neighbouring planets apart.\n";
}

}  // namespace gearhb
