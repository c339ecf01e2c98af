#include "gearhb/tools/planetary_stiffness.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "gearhb/app/cli.hpp"
#include "gearhb/app/json_file.hpp"
#include "gearhb/gears/dynamics/mesh_dynamics.hpp"
#include "gearhb/gears/tooth/potential_energy.hpp"
#include "gearhb/tools/gear_file.hpp"

namespace gearhb {

namespace {

using nlohmann::json;

const char* const kPairKey = "mesh.sun_planet_pair";

double base_radius(int z, double module, double alpha) { return 0.5 * z * module * std::cos(alpha); }

// The gear-pair file of the sun-planet mesh: the file's tooth data, the set's teeth, module,
// pressure angle and addendum; torques [T1].
json sun_planet_pair_file(const json& pair, const std::string& file, const std::string& name, const PlanetaryTeeth& t,
                          double pressure_angle, double T1) {
  const std::string where = kPairKey;
  if (!pair.is_object()) fail_key(file, where, "must be an object {basic_rack, gears, model} (gear-pair file keys)");
  only_keys(pair, file, where, {"basic_rack", "gears", "model"});
  json g = pair;
  g["name"] = name.substr(0, 100) + ", sun-planet";
  g["module"] = t.module;
  g["pressure_angle_deg"] = pressure_angle * 180.0 / M_PI;
  if (!g.contains("basic_rack")) g["basic_rack"] = json::object();
  if (!g["basic_rack"].is_object()) fail_key(file, where + ".basic_rack", "must be an object");
  if (g["basic_rack"].contains("addendum"))
    fail_key(file, where + ".basic_rack.addendum", "is the set's addendum (key addendum)");
  g["basic_rack"]["addendum"] = t.addendum;
  if (!g.contains("gears") || !g["gears"].is_array() || g["gears"].size() != 2)
    fail_key(file, where + ".gears", "must be a list of 2 gears (the sun, the planet)");
  for (int i = 0; i < 2; ++i) {
    json& gi = g["gears"][std::size_t(i)];
    const std::string key = where + ".gears." + std::to_string(i);
    if (!gi.is_object()) fail_key(file, key, "must be an object");
    if (gi.contains("z")) fail_key(file, key + ".z", "is the set's (teeth.sun, teeth.planet)");
    if (gi.contains("x") && !(gi["x"].is_number() && gi["x"].get<double>() == 0.0))
      fail_key(file, key + ".x", "must be 0: the set's centre distances are standard (z_r = z_s + 2 z_p)");
    gi["z"] = i == 0 ? t.sun : t.planet;
  }
  g["torques"] = json::array({T1});
  return g;
}

// read_gear_json's error, its key named where the set file has it: the teeth the set's
// (gears.0.z: teeth.sun, gears.1.z: teeth.planet), the others mesh.sun_planet_pair.<key>.
GearFile read_pair(const json& g, const std::string& file) {
  try {
    return read_gear_json(g, file);
  } catch (const UsageError& e) {
    std::string m = e.what();
    const std::string head = file + ": '";
    if (m.compare(0, head.size(), head) != 0) throw;
    const std::pair<const char*, const char*> teeth[] = {{"gears.0.z'", "teeth.sun'"}, {"gears.1.z'", "teeth.planet'"}};
    for (const auto& [pair_key, set_key] : teeth)
      if (m.compare(head.size(), std::string(pair_key).size(), pair_key) == 0)
        throw UsageError(head + set_key + m.substr(head.size() + std::string(pair_key).size()));
    m.insert(head.size(), std::string(kPairKey) + ".");
    throw UsageError(m);
  }
}

// The sun-planet mesh by the pair model, loaded by F.
void sun_planet_mesh(PlanetaryToothStiffness& s, const json& pair, const std::string& file, const std::string& name,
                     const PlanetaryTeeth& t, double alpha) {
  const GearFile unit = read_pair(sun_planet_pair_file(pair, file, name, t, alpha, 1.0), file);
  const std::unique_ptr<LoadedPair> model = gear_file_loaded_pair(unit);
  s.sun_planet_torque = s.tooth_force / model->force(1.0);   // the force is linear in the torque
  if (!(s.sun_planet_torque >= 1e-3 && s.sun_planet_torque <= 1e7))
    fail_key(file, "response.torque", "gives one sun-planet pair T1 = " + std::to_string(s.sun_planet_torque) +
                                          " N m, outside the pair model's [1e-3, 1e7] N m");
  s.sun_planet_pair = sun_planet_pair_file(pair, file, name, t, alpha, s.sun_planet_torque);
  const double F = model->force(s.sun_planet_torque);
  for (const PairStePoint& p : model->ste(s.sun_planet_torque)) s.sun.samples.push_back(F / p.ste);
  s.sun_contact_ratio = unit.pair.path().contact_ratio;
}

// The ring-planet mesh by ISO 6336-1 (the internal gear's zn = infinity), as a rectangular wave.
void ring_planet_iso(PlanetaryToothStiffness& s, const GearFile& pair, const std::string& file, const PlanetaryTeeth& t,
                     double alpha) {
  const double eps = internal_contact_ratio(t, alpha);
  if (!(eps >= 1.0 && eps <= 2.0))
    fail_key(file, "teeth.ring", "gives the ring-planet pair a contact ratio " + std::to_string(eps) +
                                     " outside [1, 2] (the rectangular wave of its ISO 6336-1 stiffness)");
  Iso6336Input in;
  in.z1 = t.planet;
  in.internal2 = true;
  in.normal_pressure_angle_deg = alpha * 180.0 / M_PI;
  in.hfP_over_mn = pair.dedendum_coefficient;
  in.eps_alpha = eps;
  in.face_width_m = pair.pair.gear2.face_width;
  in.line_load_N_per_mm = s.tooth_force * std::cos(alpha) / (in.face_width_m * 1e3);   // F_t / b, K_A = 1
  s.ring_iso = iso6336_mesh_stiffness(in);
  s.ring.mean = s.ring_iso.c_gamma_alpha_total;
  s.ring.contact_ratio = eps;
  s.ring.ratio = 1.75;   // c_gamma_alpha = c' (1 + 0.75 (eps - 1)): k_double = 1.75 c' b
  s.ring_contact_ratio = eps;
}

// The planet (external) and the ring (internal) in the potential-energy vocabulary: the
// pair's planet (gear 2: its face width, material, bore), the ring of the same material and
// face width, the set's addendum, the pair's basic-rack dedendum and root radius.
void ring_planet_pe_gears(const GearFile& pair, const std::string& file, const PlanetaryTeeth& t, double alpha,
                          PeGear& planet, PeGear& ring) {
  planet.teeth = t.planet;
  planet.module = t.module;
  planet.pressure_angle = alpha;
  planet.addendum_coefficient = t.addendum;
  planet.dedendum_coefficient = pair.dedendum_coefficient;
  planet.root_radius_coefficient = pair.root_radius_coefficient;
  planet.face_width = pair.pair.gear2.face_width;
  planet.youngs_modulus = pair.pair.youngs_modulus2;
  planet.poisson_ratio = pair.gear[1].poisson_ratio;
  planet.bore_radius = pair.gear[1].rim_radius;
  if (!(planet.bore_radius > 0.0))
    fail_key(file, std::string(kPairKey) + ".gears.1.rim_radius",
             "is needed by the ring-planet mesh's potential-energy model (the planet's fillet foundation)");
  ring = planet;
  ring.teeth = t.ring;
  ring.bore_radius = 0.0;
}

// The ring-planet mesh by the potential-energy method (pe_internal_tooth_compliance for the
// ring's tooth, pe_tooth_compliance for the planet's, linear Hertz): at each of the J phases
// the pairs at s = (j / J + k) p_b from A (the planet's root) in parallel, as gearhb_gear's
// potential_energy pair without relief.
void ring_planet_pe(PlanetaryToothStiffness& s, const GearFile& pair, const std::string& file, const PlanetaryTeeth& t,
                    double alpha, int J) {
  PeGear planet, ring;
  ring_planet_pe_gears(pair, file, t, alpha, planet, ring);
  const InternalPath p = internal_path(t, alpha);
  const double r_low = std::hypot(p.rbp, p.T1A);
  if (!(p.T1A >= 0.0) || !(r_low >= pe_tooth_geometry(planet).r_min_contact))
    fail_key(file, "teeth.planet", "meets the ring below its base or root circle (involute interference of the ring-planet pair)");
  s.ring_contact_ratio = (p.T1E - p.T1A) / p.pb;
  if (!(s.ring_contact_ratio >= 1.0))
    fail_key(file, "teeth.ring", "gives the ring-planet pair a contact ratio below 1");
  const double hertz = pe_hertz_compliance(planet, ring);
  for (int j = 0; j < J; ++j) {
    double k = 0.0;
    for (double T1P = p.T1A + p.pb * j / J; T1P <= p.T1E * (1.0 + 1e-12); T1P += p.pb) {
      const double r1 = std::min(std::hypot(p.rbp, T1P), pe_tooth_geometry(planet).ra);
      const double r2 = std::hypot(p.rbr, T1P + p.a_sin);
      k += 1.0 / (pe_tooth_compliance(planet, r1).total() + pe_internal_tooth_compliance(ring, r2).total() + hertz);
    }
    s.ring_pe.samples.push_back(k);
  }
}

}  // namespace

double PlanetaryToothStiffness::ring_stiffness(int j, int J) const {
  if (ring_model == RingPlanetModel::potential_energy) return ring_pe.samples[std::size_t(j)];
  return ring.stiffness(2.0 * M_PI * j / J);
}

double nominal_mesh_force(const PlanetaryTeeth& t, double alpha, int planets, Body input, double torque) {
  const double rs = base_radius(t.sun, t.module, alpha), rr = base_radius(t.ring, t.module, alpha);
  const double r = input == Body::sun ? rs : input == Body::ring ? rr : rs + rr;
  return torque / (planets * r);
}

InternalPath internal_path(const PlanetaryTeeth& t, double alpha) {
  InternalPath p;
  const double m = t.module, a = 0.5 * (t.ring - t.planet) * m;
  p.rbp = base_radius(t.planet, m, alpha);
  p.rbr = base_radius(t.ring, m, alpha);
  p.a_sin = a * std::sin(alpha);
  p.pb = M_PI * m * std::cos(alpha);
  const double rap = 0.5 * t.planet * m + t.addendum * m, rar = 0.5 * t.ring * m - t.addendum * m;
  p.T1E = std::sqrt(rap * rap - p.rbp * p.rbp);
  p.T1A = rar > p.rbr ? std::sqrt(rar * rar - p.rbr * p.rbr) - p.a_sin : NAN;
  return p;
}

double internal_contact_ratio(const PlanetaryTeeth& t, double alpha) {
  const InternalPath p = internal_path(t, alpha);
  return (p.T1E - p.T1A) / p.pb;
}

double ring_sun_phase_from_teeth(const PlanetaryTeeth& t, double alpha) {
  const InternalPath p = internal_path(t, alpha);
  const double theta_b = 0.5 * M_PI / t.planet + involute(alpha);
  const double g = t.planet / (2.0 * M_PI) * (M_PI - 2.0 * alpha - 2.0 * theta_b + (p.T1E + p.T1A) / p.rbp);
  return g - std::floor(g);
}

double ring_back_mirror_phase(const PlanetaryTeeth& t, double alpha) {
  const InternalPath p = internal_path(t, alpha);
  const double s_b = p.rbp * (M_PI / t.planet + 2.0 * involute(alpha));
  const double phi = (s_b + 2.0 * alpha * p.rbp - 2.0 * p.T1A) / p.pb;
  return 2.0 * M_PI * (phi - std::floor(phi));
}

PlanetaryToothStiffness planetary_tooth_stiffness(const json& pair, const std::string& file, const std::string& name,
                                                  const PlanetaryTeeth& t, double alpha, int planets, Body input,
                                                  double torque, RingPlanetModel ring_model) {
  PlanetaryToothStiffness s;
  s.tooth_force = nominal_mesh_force(t, alpha, planets, input, torque);
  sun_planet_mesh(s, pair, file, name, t, alpha);
  const GearFile loaded = read_pair(s.sun_planet_pair, file);
  s.sun_back_mirror = back_flank_phase(loaded.pair);
  s.ring_back_mirror = ring_back_mirror_phase(t, alpha);
  s.ring_model = ring_model;
  if (ring_model == RingPlanetModel::iso6336) {
    ring_planet_iso(s, loaded, file, t, alpha);
  } else {
    try {
      ring_planet_pe(s, loaded, file, t, alpha, int(s.sun.samples.size()));
    } catch (const UsageError&) {
      throw;
    } catch (const std::exception& e) {   // a tooth the potential-energy method does not take
      fail_key(file, "teeth.planet", std::string("gives a ring-planet pair the potential-energy method does not take: ") +
                                         e.what());
    }
  }
  return s;
}

}  // namespace gearhb
