#include "gearhb/app/model_file.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <fstream>
#include <sstream>

#include "gearhb/app/cli.hpp"
#include "gearhb/app/json_file.hpp"
#include "gearhb/app/solver_settings.hpp"
#include "gearhb/core/fourier.hpp"
#include "gearhb/core/text_file.hpp"

namespace gearhb {

namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& file, const std::string& key, const std::string& why) { fail_key(file, key, why); }
double number(const json& j, const std::string& file, const std::string& key) { return json_number(j, file, key); }
int whole(const json& j, const std::string& file, const std::string& key, int lo, int hi) {
  return json_whole(j, file, key, lo, hi);
}

Eigen::VectorXd vector(const json& j, const std::string& file, const std::string& key, int n) {
  if (!j.is_array() || int(j.size()) != n) fail(file, key, "must be a list of " + std::to_string(n) + " numbers");
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) v[i] = number(j[i], file, key + "." + std::to_string(i));
  return v;
}

Eigen::MatrixXd matrix(const json& j, const std::string& file, const std::string& key, int n) {
  if (!j.is_array() || int(j.size()) != n)
    fail(file, key, "must be a list of " + std::to_string(n) + " rows");
  Eigen::MatrixXd m(n, n);
  for (int r = 0; r < n; ++r) m.row(r) = vector(j[r], file, key + "." + std::to_string(r), n).transpose();
  return m;
}

void symmetric(const Eigen::MatrixXd& m, const std::string& file, const std::string& key) {
  for (int r = 0; r < m.rows(); ++r)
    for (int c = 0; c < r; ++c)
      if (std::fabs(m(r, c) - m(c, r)) > 1e-12 * (std::fabs(m(r, c)) + std::fabs(m(c, r)) + 1e-300))
        fail(file, key, "is not symmetric (entry " + std::to_string(r) + "," + std::to_string(c) + ")");
}

// One period of a quantity from a CSV `phase,<value>` (uniform phases from 0): its mean and first
// H harmonics [a0, a1, b1, ...] (core/fourier.hpp periodic_fourier; exact for a band-limited one).
Eigen::VectorXd read_periodic_file(const std::string& path, const std::string& key, const std::string& value, int H) {
  std::vector<std::string> lines;
  try {
    lines = read_text_lines(path);
  } catch (const TextFileError& e) {
    fail(path, key, e.what());
  }
  if (lines.empty() || lines[0] != "phase," + value) fail(path, key, "needs the header 'phase," + value + "'");
  std::vector<double> phase, v;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    const std::string row = std::to_string(i + 1);
    if (line.empty()) continue;
    const auto comma = line.find(',');
    if (comma == std::string::npos) fail(path, key, "row " + row + ": expected phase," + value);
    const std::string where = path + " row " + row;
    phase.push_back(parse_decimal(line.substr(0, comma), where + " phase"));
    v.push_back(parse_decimal(line.substr(comma + 1), where + " " + value));
  }
  const int n = int(v.size());
  if (n < 2 * H + 1) fail(path, key, "has " + std::to_string(n) + " rows; needs at least 2H+1 = " + std::to_string(2 * H + 1));
  for (int i = 0; i < n; ++i)
    if (std::fabs(phase[i] - double(i) / n) > 1e-6)
      fail(path, key, "row " + std::to_string(i + 2) + ": phases must be uniform in [0, 1) from 0 (expected " +
                          std::to_string(double(i) / n) + ")");
  return periodic_fourier(v, H);
}

// A stiffness factor s(theta) > 0 from a CSV `phase,factor`: the contact's stiffness is kc s(theta)
// with s cut to H harmonics (contact.hpp stiffness_profile), which must stay positive.
std::function<double(double)> read_stiffness_file(const std::string& path, const std::string& key, int H) {
  const Eigen::VectorXd c = read_periodic_file(path, key, "factor", H);
  const Aft aft(H, 64 * (2 * H + 1));
  const double lo = aft.to_time(c).minCoeff();
  if (!(lo > 0.0))
    fail(path, key, "the stiffness factor cut to H = " + std::to_string(H) + " harmonics must stay > 0 (min " +
                        std::to_string(lo) + ")");
  return [c](double th) { return trig_series(c, th); };
}

}  // namespace

namespace {

// The file path of a contact's gap_file / kc_file (relative to the model file).
std::string contact_file(const json& contact, const std::string& path, const std::string& key) {
  if (!contact[key.substr(key.rfind('.') + 1)].is_string()) fail(path, key, "must be a file name");
  std::filesystem::path f = contact[key.substr(key.rfind('.') + 1)].get<std::string>();
  if (f.is_relative()) f = std::filesystem::path(path).parent_path() / f;
  return f.string();
}

// M, K and C (a damping matrix or Rayleigh's alpha M + beta K) of n DOFs.
LinearSystem read_system(const json& j, const std::string& path, int n) {
  LinearSystem s;
  s.M = matrix(j["mass"], path, "mass", n);
  s.K = matrix(j["stiffness"], path, "stiffness", n);
  symmetric(s.M, path, "mass");
  if (Eigen::LLT<Eigen::MatrixXd>(s.M).info() != Eigen::Success) fail(path, "mass", "is not positive definite");
  if (j.contains("damping") == j.contains("rayleigh")) fail(path, "damping", "or 'rayleigh' must be given, not both");
  if (j.contains("damping")) {
    s.C = matrix(j["damping"], path, "damping", n);
  } else {
    only_keys(j["rayleigh"], path, "rayleigh", {"alpha", "beta"});
    s.C = rayleigh_damping(s.M, s.K, number(j["rayleigh"].value("alpha", json(0.0)), path, "rayleigh.alpha"),
                           number(j["rayleigh"].value("beta", json(0.0)), path, "rayleigh.beta"));
  }
  return s;
}

// The contacts (at most kMaxContacts), their gap and stiffness files cut to H harmonics.
std::vector<UnilateralContact> read_contacts(const json& j, const std::string& path, int n, int H) {
  const json contacts = j.value("contacts", json::array());
  if (!contacts.is_array()) fail(path, "contacts", "must be a list");
  if (contacts.size() > std::size_t(kMaxContacts))
    fail(path, "contacts", "has " + std::to_string(contacts.size()) + " contacts; at most " + std::to_string(kMaxContacts) +
                               " (the exact flow indexes contact states by the bits of one word)");
  std::vector<UnilateralContact> out;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const std::string key = "contacts." + std::to_string(i);
    only_keys(contacts[i], path, key, {"direction", "kc", "gap", "gap_file", "kc_file"});
    UnilateralContact c;
    c.normal = vector(contacts[i].value("direction", json()), path, key + ".direction", n);
    c.kc = number(contacts[i].value("kc", json()), path, key + ".kc");
    if (c.kc < 0) fail(path, key + ".kc", "must be >= 0");
    c.gap = number(contacts[i].value("gap", json(0.0)), path, key + ".gap");
    if (contacts[i].contains("gap_file"))
      c.gap_harmonics = read_periodic_file(contact_file(contacts[i], path, key + ".gap_file"), key + ".gap_file", "gap", H);
    if (contacts[i].contains("kc_file"))
      c.stiffness_profile = read_stiffness_file(contact_file(contacts[i], path, key + ".kc_file"), key + ".kc_file", H);
    out.push_back(c);
  }
  return out;
}

// H, the AFT samples, the frequency range, the output direction, the forcing and the solver keys.
// The optional `torus` object (hb/quasi_periodic.hpp): present = a torus branch from each NS point.
void read_torus(const json& j, const std::string& path, ModelFile& m) {
  if (!j.contains("torus")) return;
  const json& t = j["torus"];
  if (!t.is_object()) fail(path, "torus", "must be an object of options ({} for the defaults)");
  only_keys(t, path, "torus",
            {"harmonics1", "harmonics2", "lines", "amplitude", "max_points", "stability_every", "stability_periods"});
  TorusOptions& o = m.torus;
  o.harmonics1 = std::min(o.harmonics1, m.harmonics);
  if (t.contains("harmonics1")) o.harmonics1 = whole(t["harmonics1"], path, "torus.harmonics1", 1, m.harmonics);
  if (t.contains("harmonics2")) o.harmonics2 = whole(t["harmonics2"], path, "torus.harmonics2", 1, 20);
  if (t.contains("lines")) o.lines = whole(t["lines"], path, "torus.lines", 0, 1024);
  if (t.contains("amplitude")) o.amplitude = number(t["amplitude"], path, "torus.amplitude");
  if (t.contains("max_points")) o.max_points = whole(t["max_points"], path, "torus.max_points", 2, 10000);
  TorusStabilityOptions& so = m.torus_stability;
  if (t.contains("stability_every")) so.every = whole(t["stability_every"], path, "torus.stability_every", 0, 10000);
  if (t.contains("stability_periods"))
    so.periods = whole(t["stability_periods"], path, "torus.stability_periods", 10, 10000);
  std::string why;
  const std::string key = check_torus_options(o, m.harmonics, &why);
  if (!key.empty()) fail(path, "torus." + key, why);
  // The torus' Newton steps factor a dense matrix of its unknowns: bounded so that no file
  // asks for hours or gigabytes (3000 unknowns: about 20 s and 72 MB a step).
  const long unknowns = long(m.system.dofs()) * (2L * (o.harmonics2 + long(o.harmonics1) * (2 * o.harmonics2 + 1)) + 1);
  if (unknowns > 3000)
    fail(path, "torus.harmonics1", "and torus.harmonics2 give " + std::to_string(unknowns) +
                                       " torus unknowns (n (2 (H2 + H1 (2 H2 + 1)) + 1)); at most 3000");
  for (const auto& ct : m.contacts)
    if (ct.stiffness_profile) fail(path, "torus", "needs constant contact stiffnesses (no kc_file)");
  m.torus_on = true;
}

void read_settings(const json& j, const std::string& path, int n, ModelFile& m) {
  m.harmonics = whole(j["harmonics"], path, "harmonics", 1, max_harmonics(n));
  m.samples = j.contains("samples") ? whole(j["samples"], path, "samples", 0, max_aft_samples) : 0;
  if (m.samples != 0 && m.samples < 4 * m.harmonics + 2) fail(path, "samples", "must be 0 or >= 4H+2");
  only_keys(j["omega"], path, "omega", {"from", "to"});
  m.omega_from = number(j["omega"].value("from", json()), path, "omega.from");
  m.omega_to = number(j["omega"].value("to", json()), path, "omega.to");
  if (m.omega_from <= 0 || m.omega_to <= 0 || m.omega_from == m.omega_to)
    fail(path, "omega", "needs 0 < from != to");
  only_keys(j["output"], path, "output", {"direction"});
  m.output = vector(j["output"].value("direction", json()), path, "output.direction", n);
  const json forcing = j.value("forcing", json::object());
  only_keys(forcing, path, "forcing", {"static", "cos", "sin"});
  auto force = [&](const char* k) {
    return forcing.contains(k) ? vector(forcing[k], path, std::string("forcing.") + k, n) : Eigen::VectorXd::Zero(n);
  };
  m.forcing = {force("static"), force("cos"), force("sin")};
  const json solver = j.value("solver", json::object());
  only_keys(solver, path, "solver", {"exact_contact", "ds_max"});
  if (solver.contains("exact_contact")) m.exact_contact = json_flag(solver["exact_contact"], path, "solver.exact_contact");
  if (solver.contains("ds_max")) {
    m.ds_max = number(solver["ds_max"], path, "solver.ds_max");
    if (m.ds_max < 1e-6 || m.ds_max > 1) fail(path, "solver.ds_max", "must be in [1e-6, 1]");
  }
  m.period_doubling_depth = read_period_doubling_depth(j, path);
}

}  // namespace

ModelFile read_model_file(const std::string& path,
                          const std::vector<std::pair<std::string, std::string>>& overrides) {
  json j = read_json_file(path);
  only_keys(j, path, "", {"name", "mass", "stiffness", "damping", "rayleigh", "contacts", "forcing", "harmonics",
                          "samples", "omega", "output", "solver", "bifurcation_diagram", "period_doubling",
                          "torus"});
  for (const auto& [key, text] : overrides) apply_override(j, path, key, text);
  for (const char* k : {"mass", "stiffness", "harmonics", "omega", "output"})
    if (!j.contains(k)) fail(path, k, "is missing");
  ModelFile m;
  m.resolved = j;
  m.name = json_name(j, path, "name", "model");
  if (!j["mass"].is_array() || j["mass"].empty()) fail(path, "mass", "must be a non-empty list of rows");
  const int n = int(j["mass"].size());
  if (max_harmonics(n) < 1)
    fail(path, "mass", "has " + std::to_string(n) + " DOFs: too many for any number of harmonics (at most " +
                           std::to_string(max_hb_unknowns / 3) + " DOFs)");
  m.system = read_system(j, path, n);
  read_settings(j, path, n, m);
  m.contacts = read_contacts(j, path, n, m.harmonics);
  m.diagram = read_bifurcation_diagram(j, path);
  read_torus(j, path, m);
  return m;
}

HarmonicBalance ModelFile::harmonic_balance() const {
  return HarmonicBalance(system, contacts, forcing, harmonics, samples,
                         exact_contact ? ContactQuadrature::exact : ContactQuadrature::sampled);
}

std::string model_file_help() {
  return "Model file keys (JSON; SI units; n = number of DOFs):\n"
         "  name                  text shown in titles (1..120 characters)\n"
         "  mass                  n x n, symmetric positive definite [kg]\n"
         "  stiffness             n x n [N/m]\n"
         "  damping               n x n [N s/m], or instead\n"
         "  rayleigh.alpha/beta   C = alpha M + beta K [1/s, s]\n"
         "  contacts[i].direction n numbers: the contact normal (penetration g + direction'x)\n"
         "  contacts              at most 30\n"
         "  contacts[i].kc        contact stiffness >= 0 [N/m]\n"
         "  contacts[i].gap       g [m]: < 0 clearance, > 0 preload (F = max(kc (g + direction'x), 0))\n"
         "  contacts[i].gap_file  optional CSV 'phase,gap' (one period, uniform phases from 0, gap [m])\n"
         "  contacts[i].kc_file   optional CSV 'phase,factor': a time-varying stiffness kc s(theta), s the\n"
         "                        factor's first H harmonics (> 0 over the period; e.g. a gear mesh's k(t) / kc)\n"
         "  forcing.static/cos/sin  n numbers each: f0 + fc cos(omega t) + fs sin(omega t) [N]\n"
         "  harmonics             H >= 1\n"
         "  samples               AFT samples per period (0 = 4(2H+1); else >= 4H+2)\n"
         "  omega.from, omega.to  frequency range [rad/s], swept from 'from' to 'to'\n"
         "  output.direction      n numbers: the plotted coordinate q'x\n"
         "  solver.exact_contact  flag (true | false, or 1 | 0): exact projection of the contact law (default), else sampled AFT\n"
         "  solver.ds_max         largest arc-length step (default 0.02)\n"
         "  torus                 optional object: a torus branch (quasi-periodic motion) by two-frequency\n"
         "                        harmonic balance from each Neimark-Sacker point of the curve (absent: none)\n"
         "  torus.harmonics1      H1 harmonics of omega on the torus (default min(10, H); 1..H)\n"
         "  torus.harmonics2      H2 harmonics of the second frequency omega2 (default 4; 1..20;\n"
         "                        n (2 (H2 + H1 (2 H2 + 1)) + 1) <= 3000 unknowns)\n"
         "  torus.lines           lines in the second angle for the contact forces (default 0 = 4 (2 H2 + 1))\n"
         "  torus.amplitude       first point's quasi-periodic part over the orbit's size (default 0.005; (0, 0.5])\n"
         "  torus.max_points      most points per torus branch (default 200)\n"
         "  torus.stability_every the torus' stability by the flow's two largest Lyapunov exponents at every\n"
         "                        k-th point of a branch and its last (default 5; 0 = none; 0..10000)\n"
         "  torus.stability_periods  forcing periods of that variational integration (default 400; 10..10000)\n" +
         period_doubling_help() + bifurcation_diagram_help() +
         "--set PATH=VALUE overrides a number at a dotted path: harmonics=10, omega.to=0.4, contacts.0.kc=50\n"
         "Cost (README 'Cost of a run'): each Newton step of each continuation point factors the n(2H+1)\n"
         "  unknowns: densely when the contacts touch every DOF (1 DOF: about 0.15 s a point at H = 255,\n"
         "  0.5 s at H = 511, 4 s at H = 1023, 40 s at H = 2047 on 2 cores), otherwise H+1 blocks of\n"
         "  2n x 2n and the contact coordinates (n = 200, H = 5, one contact: about 70 ms a point). The\n"
         "  number of points grows with the resonances in the range. Stability: each point's Floquet\n"
         "  multipliers by shooting, and each crossing of the unit circle located by up to 30 more (to 1e-9\n"
         "  of a step; 1e-7 where a multiplier jumps across). With a kc_file the shooting integrates the\n"
         "  period (GSL rk8pd) through every oscillation of the stiffest contact, sqrt(kc s |direction|^2\n"
         "  / m) / omega of them: the parametric example with contacts.0.direction.0=2047 (7500 a period\n"
         "  at omega = 0.3, 26 crossings) takes about 160 s on 2 cores (a progress line a second).\n";
}

}  // namespace gearhb
