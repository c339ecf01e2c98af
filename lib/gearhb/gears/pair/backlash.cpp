#include "gearhb/gears/pair/backlash.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gearhb {

namespace {

// 0.1 mm, the resolution of the lengths the thesis prints in §7.7 and §9.
double round_like_thesis(double x) { return std::round(x / 1e-4) * 1e-4; }

struct Sample {
  double phase, s;
  int pairs;
  double ste;
};

std::vector<BacklashPoint> apply_backlash(const SteModel& m, double torque, const std::vector<Sample>& cycle,
                                          const BacklashSettings& set) {
  const BacklashGeometry bg = backlash_geometry(m.gear, set.b, set.values);
  const double F = m.force(torque);
  double kA = 0.0, kE = 0.0;   // secant stiffness of a single pair at A and at E
  if (set.model == BacklashModel::contact) {
    const ToothBeam tooth = tooth_beam(m);
    kA = F / single_pair_ste(m, tooth, 0.0, F);
    kE = F / single_pair_ste(m, tooth, bg.AE, F);
  }
  std::vector<BacklashPoint> out;
  for (const Sample& c : cycle) {
    BacklashPoint p;
    p.phase = c.phase;
    p.s = c.s;
    p.pairs = c.pairs;
    p.ste_free = p.ste = c.ste;
    if (c.pairs == 1) {
      p.bn = normal_backlash(set.b, backlash_angle(bg, c.s, set.angle));
      if (set.model == BacklashModel::clip) {
        p.ste = std::min(c.ste, p.bn);
      } else {
        // The adjacent pair nearer to its path end: E' side -> the incoming pair at A.
        const bool e_side = bg.s_E_prime - c.s < c.s - bg.s_A_prime;
        const TwoSpringSolution t = two_spring_deflection(F, F / c.ste, e_side ? kA : kE, p.bn);
        p.ste = t.d;
        p.adjacent_force = t.force_2;
      }
      p.limited = p.ste < p.ste_free;
    }
    out.push_back(p);
  }
  return out;
}

}  // namespace

double normal_backlash(double b, double mu) { return b * std::cos(mu); }

BacklashGeometry backlash_geometry(const GearGeometry& g, double b, BacklashValues values) {
  const PathOfContact path = path_of_contact(g, g);
  BacklashGeometry r;
  r.b = b;
  r.alpha = g.pressure_angle_rad();
  r.rb = g.base_radius();
  r.pb = path.base_pitch;
  r.T2C = path.T2C;
  r.AC = path.AC;
  r.CE = path.CE;
  r.AE = path.AE;
  r.s_A_prime = path.AE - path.base_pitch;
  r.s_E_prime = path.base_pitch;
  if (values == BacklashValues::exact) {
    r.CE_prime = r.pb - r.AC;
    r.CA_prime = r.pb - r.CE;
    r.epsilon = std::atan((path.T2C + r.AC) / r.rb) - r.alpha;
    r.epsilon_A = std::atan((path.T1C + r.CE) / r.rb) - r.alpha;
  } else {
    // §7.7's eps (printed T2C = rb sin(alpha), lengths rounded); identical gears: A' mirrors E'.
    r.epsilon = r.epsilon_A = tooth_axis_angles(g, path, T2CFormula::thesis_rb_sin, true).epsilon;
    r.CE_prime = round_like_thesis(r.pb - r.AC);
    r.CA_prime = round_like_thesis(r.pb - r.CE);
  }
  r.epsilon_prime = std::atan(r.CE_prime / r.rb);
  r.epsilon_prime_A = std::atan(r.CA_prime / r.rb);
  r.mu_C = r.alpha;
  r.mu_E_prime = r.alpha + r.epsilon + r.epsilon_prime;
  r.mu_A_prime = r.alpha + r.epsilon_A + r.epsilon_prime_A;
  r.bn_C = normal_backlash(b, r.mu_C);
  r.bn_E_prime = normal_backlash(b, r.mu_E_prime);
  r.bn_A_prime = normal_backlash(b, r.mu_A_prime);
  return r;
}

double backlash_angle(const BacklashGeometry& bg, double s, BacklashAngle reading) {
  if (reading == BacklashAngle::involute) return bg.alpha;
  // Roll angle from C of the gear whose tangency point lies beyond C from P: angle C O P.
  const double T1C = bg.rb * std::tan(bg.alpha);
  auto roll = [&](double CP) { return std::atan((T1C + CP) / bg.rb) - bg.alpha; };
  if (s >= bg.AC) return bg.alpha + (bg.mu_E_prime - bg.alpha) * roll(s - bg.AC) / roll(bg.s_E_prime - bg.AC);
  return bg.alpha + (bg.mu_A_prime - bg.alpha) * roll(bg.AC - s) / roll(bg.AC - bg.s_A_prime);
}

TwoSpringSolution two_spring_deflection(double F, double k1, double k2, double bn) {
  if (!(k1 > 0.0) || !(k2 >= 0.0) || !(bn >= 0.0))
    throw std::invalid_argument("two_spring_deflection: need k1 > 0, k2 >= 0, bn >= 0");
  TwoSpringSolution t;
  t.d = F / k1;
  if (t.d > bn) {
    t.d = (F + k2 * bn) / (k1 + k2);
    t.engaged = k2 > 0.0;
  }
  t.force_1 = k1 * t.d;
  t.force_2 = F - t.force_1;
  return t;
}

std::vector<BacklashPoint> ste_with_backlash(const SteModel& m, double torque, const std::vector<StePoint>& cycle,
                                             const BacklashSettings& set) {
  const double pb = path_of_contact(m.gear, m.gear).base_pitch;
  std::vector<Sample> v;
  for (const auto& p : cycle) v.push_back({p.phase, p.phase * pb, p.pairs, p.ste});
  return apply_backlash(m, torque, v, set);
}

std::vector<BacklashPoint> ste_with_backlash(const SteModel& m, double torque,
                                             const std::vector<MeshPosition>& cycle, const BacklashSettings& set) {
  // Pair A's contact point from the height of its node on the driving tooth.
  const PathOfContact path = path_of_contact(m.gear, m.gear);
  const ToothBeam tooth = tooth_beam(m);
  const double rb = m.gear.base_radius(), rf = m.gear.root_radius();
  std::vector<Sample> v;
  for (const auto& p : cycle) {
    const double r1 = rf + tooth.x.at(std::size_t(p.kA1));
    v.push_back({p.phase, std::sqrt(r1 * r1 - rb * rb) - path.T1A, p.pairs, p.ste});
  }
  return apply_backlash(m, torque, v, set);
}

std::vector<double> ste_values(const std::vector<BacklashPoint>& cycle) {
  std::vector<double> v;
  for (const auto& p : cycle) v.push_back(p.ste);
  return v;
}

}  // namespace gearhb
