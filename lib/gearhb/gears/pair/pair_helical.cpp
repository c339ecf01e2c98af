#include "gearhb/gears/pair/pair_helical.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <tuple>

#include "gearhb/gears/pair/coupled_load_sharing.hpp"
#include "gearhb/gears/pair/load_sharing.hpp"

namespace gearhb {

double lead_modification_at(const LeadModification& lead, double y, double b) {
  const double u = 2.0 * y / b - 1.0;
  double c = lead.crowning * u * u;
  const double d = std::min(y, b - y);
  if (lead.end_relief > 0.0 && d < lead.end_relief_length)
    c += lead.end_relief * (lead.end_relief_length - d) / lead.end_relief_length;
  return c;
}

double HelicalPair::base_helix_angle() const {
  return std::asin(std::sin(helix_angle) * std::cos(normal_pressure_angle_deg * M_PI / 180.0));
}

GearGeometry transverse_section(const GearGeometry& normal, double helix_angle) {
  if (helix_angle == 0.0) return normal;
  GearGeometry t = normal;
  const double c = std::cos(helix_angle);
  t.module = normal.module / c;
  t.pressure_angle_deg = std::atan(std::tan(normal.pressure_angle_rad()) / c) * 180.0 / M_PI;
  t.profile_shift = normal.profile_shift * c;   // the shift x m_n as a length
  return t;
}

double overlap_ratio(const PairSteModel& section, const HelicalPair& h) {
  const double helix = h.double_helical ? 0.5 * section.contact_length() : section.contact_length();
  return helix * std::tan(h.base_helix_angle()) / section.path().base_pitch;
}

double axial_force(const PairSteModel& section, const HelicalPair& h, double torque) {
  if (h.double_helical) return 0.0;
  return torque / section.gear1.base_radius() * std::tan(h.base_helix_angle());
}

std::vector<double> slice_phase_leads(const PairSteModel& section, const HelicalPair& h) {
  const int n = h.sliced() ? h.slices : 1;
  const double eps_beta = overlap_ratio(section, h);
  std::vector<double> lead(std::size_t(n), 0.0);
  for (int j = 0; j < n; ++j)
    lead[std::size_t(j)] = h.double_helical ? std::fabs((j + 0.5) / n - 0.5) * 2.0 * eps_beta : (j + 0.5) / n * eps_beta;
  return lead;
}

double sliced_loaded_contact_ratio(const std::vector<PairStePoint>& cycle, const PathOfContact& path, int slices) {
  if (slices <= 1) return loaded_contact_ratio(cycle, path);
  double sum = 0.0;
  for (int j = 0; j < slices; ++j) {
    std::vector<PairStePoint> one = cycle;
    for (PairStePoint& p : one) {
      std::vector<PairContact> mine;
      for (const PairContact& c : p.mesh.pairs)
        if (c.slice == j) mine.push_back(c);
      p.mesh.pairs = std::move(mine);
    }
    sum += loaded_contact_ratio(one, path);
  }
  return sum / slices;
}

namespace {

// The part of a slice's contact line, centred at s and spread over ds along the path, that lies
// on the path [0, AE]: its centre and its fraction (0: off the path). ds = 0: the point itself.
std::pair<double, double> on_path(double s, double ds, double AE) {
  if (!(ds > 0.0)) return {s, s >= 0.0 && s <= AE ? 1.0 : 0.0};
  const double lo = std::max(0.0, s - 0.5 * ds), hi = std::min(AE, s + 0.5 * ds);
  return {0.5 * (lo + hi), hi - lo > 1e-9 * ds ? std::min(1.0, (hi - lo) / ds) : 0.0};
}

// The face in slices, whatever the tooth model: each slice's phase lead and lead modification,
// its contact lines cut to the path.
class SliceLayout {
 public:
  struct Segment {
    PairContact contact;   // at the centre of its part on the path; stiffness the full-width section's
    double weight = 1.0;   // that part's fraction of the slice's contact line
    int tooth = 0;
    double from = 0.0, to = 1.0;   // that part across the slice's width (fractions; to - from = weight)
  };
  SliceLayout(const PairSteModel& m, const HelicalPair& h) : model_(m), path_(m.path()) {
    slices = h.sliced() ? h.slices : 1;
    const double b = m.contact_length();
    leads = slice_phase_leads(m, h);
    spread = b / slices * std::tan(h.base_helix_angle());   // one slice's contact line along the path
    // Hertz of each contact: that of its (half's) line at its line load, scaled by S = line / slice.
    line = h.double_helical ? 0.5 * b : b;
    scale = h.double_helical ? 0.5 * slices : double(slices);
    for (int j = 0; j < slices; ++j) {
      double y = (j + 0.5) / slices * b;
      if (h.double_helical && y > line) y -= line;   // across its own half
      lead_gap.push_back(lead_modification_at(h.lead1, y, line) + lead_modification_at(h.lead2, y, line));
    }
  }
  // Slice j at sample k of `samples`: the slice's contact lines (one per tooth pair near the
  // path), each spread over `spread` along the path, cut to the path (no stiffness).
  // spread 0 (beta = 0): the section's pairs at the sample's phase, whole (mesh_phases_at).
  std::vector<Segment> segments(int k, int samples, int j) const {
    const double pb = path_.base_pitch, x = double(k) / samples + leads[std::size_t(j)];
    const double wrap = std::floor(x), psi = x - wrap;
    std::vector<Segment> out;
    for (int q = int(std::ceil(-psi - 0.5 * spread / pb)); (psi + q) * pb - 0.5 * spread <= path_.AE; ++q) {
      const double c = (psi + q) * pb;
      const auto [sm, w] = on_path(c, spread, path_.AE);
      if (w == 0.0) continue;
      Segment seg{pair_contact_at(model_, path_, sm), w, q - int(wrap)};
      seg.from = spread > 0.0 ? std::max(0.0, (0.5 * spread - c) / spread) : 0.0;
      seg.to = seg.from + w;
      out.push_back(seg);
    }
    return out;
  }
  // The tooth pair whose mid-face contact is at s: each slice's part of it on the path
  // (slice, centre, fraction).
  std::vector<std::tuple<int, double, double>> alone(double s) const {
    const double mean = std::accumulate(leads.begin(), leads.end(), 0.0) / double(slices);
    std::vector<std::tuple<int, double, double>> out;
    for (int j = 0; j < slices; ++j) {
      const auto [sm, w] = on_path(s + (leads[std::size_t(j)] - mean) * path_.base_pitch, spread, path_.AE);
      if (w > 0.0) out.emplace_back(j, sm, w);
    }
    if (out.empty()) throw std::invalid_argument("single_pair_ste: no slice of the pair on the path of contact");
    return out;
  }
  int slices = 1;
  double spread = 0.0;               // one slice's contact line along the path: (b / N) tan(beta_b) [m]
  double line = 0.0;                 // the Hertz line: b, or a half b/2 (double helical) [m]
  double scale = 1.0;                // line over slice width: N, or N/2 (double helical)
  std::vector<double> lead_gap;      // both gears' lead modification at each slice [m]
  std::vector<double> leads;         // each slice's phase lead [mesh cycles]

 private:
  PairSteModel model_;
  PathOfContact path_;
};

class SlicedLoadedPair final : public LoadedPair {
 public:
  SlicedLoadedPair(const PairSteModel& m, const HelicalPair& h, int samples, const PairStiffnessFn& stiffness)
      : model_(m), layout_(m, h), samples_(samples), stiffness_(stiffness ? stiffness : beam_pair_stiffness(m)) {
    const int n = layout_.slices;
    if (layout_.spread > 0.0) {
      for (int k = 0; k < samples; ++k)
        for (int j = 0; j < n; ++j) {
          std::vector<SliceLayout::Segment> seg = layout_.segments(k, samples, j);
          const bool sharing = seg.size() > 1;
          for (auto& c : seg) c.contact.stiffness = stiffness_(c.contact.r1, c.contact.r2, sharing);
          sections_.push_back(seg);
        }
      return;
    }
    // No stagger (beta = 0): every slice is the section at the sample's phase, its contacts whole.
    std::vector<double> phases;
    for (int k = 0; k < samples; ++k) phases.push_back(double(k) / samples);
    const std::vector<MeshPhase> at = mesh_phases_at(m, phases, stiffness_);
    for (int k = 0; k < samples; ++k)
      for (int j = 0; j < n; ++j) {
        std::vector<SliceLayout::Segment> seg;
        int q = 0;
        for (const PairContact& c : at[std::size_t(k)].pairs) seg.push_back({c, 1.0, q++});
        sections_.push_back(seg);
      }
  }
  double force(double torque) const override { return model_.force(torque); }

  std::vector<PairStePoint> ste(double torque, bool reliefs) const override {
    const int slices = layout_.slices;
    const double n = double(slices), F = model_.force(torque), line_share = layout_.line / model_.contact_length();
    std::vector<PairStePoint> out;
    out.reserve(std::size_t(samples_));
    std::vector<ContactPair> contacts;
    for (int k = 0; k < samples_; ++k) {
      PairStePoint p;
      p.mesh.phase = double(k) / samples_;
      contacts.clear();
      for (int j = 0; j < slices; ++j)
        for (const SliceLayout::Segment& seg : sections_[std::size_t(k * slices + j)]) {
          PairContact c = seg.contact;
          c.slice = j;
          c.tooth = seg.tooth;
          c.separation = reliefs ? c.separation + layout_.lead_gap[std::size_t(j)] : 0.0;
          // The scaled problem: stiffness w k (line / b), force S F, Hertz of the line at the line load.
          contacts.push_back({seg.weight * c.stiffness * line_share, c.separation, seg.weight});
          c.stiffness *= seg.weight / n;
          p.mesh.pairs.push_back(c);
        }
      take_share(p, share_load(contacts, layout_.scale * F, model_.hertz, model_.pair_hertz, layout_.line),
                 layout_.scale);
      out.push_back(std::move(p));
    }
    return out;
  }

  // The tooth pair whose mid-face contact is at s, alone: its slices on the path, unmodified.
  double single_pair_ste(double s, double torque) const override {
    const double line_share = layout_.line / model_.contact_length();
    const PathOfContact path = model_.path();
    std::vector<ContactPair> contacts;
    for (const auto& [j, sm, w] : layout_.alone(s)) {
      const ContactRadii r = contact_radii(model_.gear1, model_.gear2, path, sm);
      contacts.push_back({w * stiffness_(r.r1, r.r2, false) * line_share, 0.0, w});
    }
    return share_load(contacts, layout_.scale * model_.force(torque), model_.hertz, model_.pair_hertz, layout_.line).ste;
  }

 private:
  PairSteModel model_;
  SliceLayout layout_;
  int samples_ = 0;
  PairStiffnessFn stiffness_;
  std::vector<std::vector<SliceLayout::Segment>> sections_;   // sample k, slice j at k * slices + j
};

// The FE section in slices (pair_helical.hpp, "method fe"): one plane FE model per gear, its
// compliances read at every slice contact's own point; slice j's block of the contact problem
// N o_il / (w_i w_l) C_il (C the full-width section's, o_il the overlap of the two contacts'
// parts across the slice), no coupling between slices.
class SlicedFeLoadedPair final : public LoadedPair {
 public:
  SlicedFeLoadedPair(const PairSteModel& m, const HelicalPair& h, int samples, const FePairOptions& options)
      : model_(m), layout_(m, h), samples_(samples) {
    const PathOfContact path = m.path();
    const int teeth = int(std::ceil(path.contact_ratio + overlap_ratio(m, h) - 1e-12)) + 1;
    std::vector<std::vector<PairContact>> sets;
    for (int k = 0; k < samples; ++k)
      for (int j = 0; j < layout_.slices; ++j) {
        segments_.push_back(layout_.segments(k, samples, j));
        if (int(segments_.back().size()) > teeth) throw std::logic_error("sliced FE: more contacts a slice than loaded teeth");
        sets.emplace_back();
        for (const auto& seg : segments_.back()) sets.back().push_back(seg.contact);
      }
    FePairOptions o = options;   // every slice's contacts on the loaded teeth, whatever N
    o.gear1.loaded_teeth = std::max(o.gear1.loaded_teeth, teeth);
    o.gear2.loaded_teeth = std::max(o.gear2.loaded_teeth, teeth);
    fe_ = std::make_unique<FePairModel>(m, 0, o);
    phases_ = fe_->phases_at(sets);
  }
  double force(double torque) const override { return fe_->force(torque); }
  std::vector<PairStePoint> ste(double torque, bool reliefs) const override {
    std::vector<PairStePoint> out;
    for (int k = 0; k < samples_; ++k) {
      std::vector<const FePhase*> phase;
      std::vector<std::vector<SliceLayout::Segment>> seg;
      std::vector<Eigen::VectorXd> gap;
      for (int j = 0; j < layout_.slices; ++j) {
        const std::size_t at = std::size_t(k * layout_.slices + j);
        phase.push_back(&phases_[at]);
        seg.push_back(segments_[at]);
        gap.push_back(Eigen::VectorXd::Zero(long(seg.back().size())));
        for (std::size_t i = 0; i < seg.back().size(); ++i)
          if (reliefs) gap.back()(long(i)) = seg.back()[i].contact.separation + layout_.lead_gap[std::size_t(j)];
      }
      out.push_back(solve(double(k) / samples_, phase, seg, gap, fe_->force(torque)));
    }
    return out;
  }
  // The tooth pair whose mid-face contact is at s, alone: its slices on the path, unmodified.
  double single_pair_ste(double s, double torque) const override {
    std::vector<std::vector<PairContact>> sets;
    std::vector<std::vector<SliceLayout::Segment>> seg;
    for (const auto& [j, sm, w] : layout_.alone(s)) {
      (void)j;
      const SliceLayout::Segment one{pair_contact_at(model_, fe_->path(), sm), w, 0, 0.0, w};
      seg.push_back({one});
      sets.push_back({one.contact});
    }
    const std::vector<FePhase> at = fe_->phases_at(sets);
    std::vector<const FePhase*> phase;
    std::vector<Eigen::VectorXd> gap;
    for (const FePhase& p : at) phase.push_back(&p), gap.push_back(Eigen::VectorXd::Zero(1));
    return solve(0.0, phase, seg, gap, fe_->force(torque)).ste;
  }
  const FePairModel* fe_model() const override { return fe_.get(); }

 private:
  // The contact problem over the slices' blocks for tooth force F: the local (Hertz)
  // compliance of each contact that of its line at its line load, N f_i / w_i on b (fixed point
  // as FePairModel::solve_phase, 1e-12 F), the load shared exactly (share_load_blocks).
  PairStePoint solve(double phase, const std::vector<const FePhase*>& p,
                     const std::vector<std::vector<SliceLayout::Segment>>& seg, const std::vector<Eigen::VectorXd>& gap,
                     double F) const {
    const double n = double(layout_.slices);
    std::vector<Eigen::MatrixXd> base, C;
    std::size_t count = 0;
    for (std::size_t j = 0; j < p.size(); ++j) {
      const auto& s = seg[j];
      Eigen::MatrixXd B(long(s.size()), long(s.size()));
      for (std::size_t i = 0; i < s.size(); ++i)
        for (std::size_t l = 0; l < s.size(); ++l) {
          const double o = std::max(0.0, std::min(s[i].to, s[l].to) - std::max(s[i].from, s[l].from));
          B(long(i), long(l)) = n * o / (s[i].weight * s[l].weight) * p[j]->compliance(long(i), long(l));
        }
      base.push_back(B);
      count += s.size();
    }
    Eigen::VectorXd f = Eigen::VectorXd::Constant(long(count), F / double(count));
    CoupledShare share;
    for (int pass = 0;; ++pass) {
      C = base;
      long at = 0;
      for (std::size_t j = 0; j < p.size(); ++j)
        for (std::size_t i = 0; i < seg[j].size(); ++i, ++at) {
          const double w = seg[j][i].weight;
          C[j](long(i), long(i)) += n / w * fe_->contact_compliance(int(i), *p[j], std::max(n * f(at) / w, 1e-6 * F));
        }
      share = share_load_blocks(C, gap, F);
      const double change = (share.force - f).cwiseAbs().maxCoeff();
      f = share.force;
      if (change <= 1e-12 * F) break;
      if (pass == 100) throw std::runtime_error("sliced FE: the contact compliance did not converge");
    }
    PairStePoint out;
    out.mesh.phase = phase;
    long at = 0;
    for (std::size_t j = 0; j < p.size(); ++j)
      for (std::size_t i = 0; i < seg[j].size(); ++i, ++at) {
        PairContact c = seg[j][i].contact;
        c.slice = int(j);
        c.tooth = seg[j][i].tooth;
        c.separation = gap[j](long(i));
        c.force = f(at);
        c.stiffness = 1.0 / C[j](long(i), long(i));   // the contact's own compliance at its force
        out.mesh.pairs.push_back(c);
      }
    out.loaded = share.loaded;
    out.approach = out.ste = share.approach;
    return out;
  }
  PairSteModel model_;
  SliceLayout layout_;
  int samples_ = 0;
  std::unique_ptr<FePairModel> fe_;
  std::vector<std::vector<SliceLayout::Segment>> segments_;   // sample k, slice j at k * slices + j
  std::vector<FePhase> phases_;                               // the same
};

}  // namespace

namespace {

void check_slicing(const PairSteModel& section, const HelicalPair& h, int samples) {
  if (h.slices < 1 || h.slices > 1000) throw std::invalid_argument("sliced_loaded_pair: slices outside [1, 1000]");
  if (section.positions_per_base_pitch > 0)
    throw std::invalid_argument("sliced_loaded_pair: the node reading (positions_per_base_pitch) has no slices");
  if (h.double_helical && (h.helix_angle == 0.0 || h.slices % 2 != 0))
    throw std::invalid_argument("sliced_loaded_pair: double helical needs a helix angle and an even slice count");
  if (samples < 4 || samples > 1 << 16)
    throw std::invalid_argument("sliced_loaded_pair: samples per mesh cycle must be in [4, 65536]");
}

}  // namespace

std::unique_ptr<LoadedPair> sliced_loaded_pair(const PairSteModel& section, const HelicalPair& h, int samples,
                                               const PairStiffnessFn& stiffness) {
  check_slicing(section, h, samples);
  if (h.sliced() && h.slices > 1 && section.hertz != HertzCount::none && section.pair_hertz != TwoPairHertz::consistent)
    throw std::invalid_argument("sliced_loaded_pair: Hertz over slices needs the consistent split (or none)");
  return std::make_unique<SlicedLoadedPair>(section, h, samples, stiffness);
}

std::unique_ptr<LoadedPair> sliced_fe_loaded_pair(const PairSteModel& section, const HelicalPair& h, int samples,
                                                  const FePairOptions& options) {
  check_slicing(section, h, samples);
  if (section.tooth_force != ToothForce::over_base_radius)
    throw std::invalid_argument("sliced_fe_loaded_pair: the FE tooth force is T1 / rb1 (tooth_force over_base_radius)");
  return std::make_unique<SlicedFeLoadedPair>(section, h, samples, options);
}

}  // namespace gearhb
