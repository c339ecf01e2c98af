#include "gearhb/gears/pair/pair_helical.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

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

class SlicedLoadedPair final : public LoadedPair {
 public:
  SlicedLoadedPair(const PairSteModel& m, const HelicalPair& h, int samples, const PairStiffnessFn& stiffness)
      : model_(m), helix_(h), path_(m.path()), samples_(samples),
        stiffness_(stiffness ? stiffness : beam_pair_stiffness(m)) {
    slices_ = h.sliced() ? h.slices : 1;
    const double b = m.contact_length();
    leads_ = slice_phase_leads(m, h);
    spread_ = b / slices_ * std::tan(h.base_helix_angle());   // one slice's contact line along the path
    // Hertz of each contact: that of its (half's) line at its line load, scaled by S = line / slice.
    line_ = h.double_helical ? 0.5 * b : b;
    scale_ = h.double_helical ? 0.5 * slices_ : double(slices_);
    for (int j = 0; j < slices_; ++j) {
      double y = (j + 0.5) / slices_ * b;
      if (h.double_helical && y > line_) y -= line_;   // across its own half
      lead_.push_back(lead_modification_at(h.lead1, y, line_) + lead_modification_at(h.lead2, y, line_));
    }
    if (spread_ > 0.0) {
      for (int k = 0; k < samples; ++k)
        for (int j = 0; j < slices_; ++j) sections_.push_back(segments(k, j));
      return;
    }
    // No stagger (beta = 0): every slice is the section at the sample's phase, its contacts whole.
    std::vector<double> phases;
    for (int k = 0; k < samples; ++k) phases.push_back(double(k) / samples);
    const std::vector<MeshPhase> at = mesh_phases_at(m, phases, stiffness_);
    for (int k = 0; k < samples; ++k)
      for (int j = 0; j < slices_; ++j) {
        std::vector<Segment> seg;
        int q = 0;
        for (const PairContact& c : at[std::size_t(k)].pairs) seg.push_back({c, 1.0, q++});
        sections_.push_back(seg);
      }
  }
  double force(double torque) const override { return model_.force(torque); }

  std::vector<PairStePoint> ste(double torque, bool reliefs) const override {
    const double n = double(slices_), F = model_.force(torque), line_share = line_ / model_.contact_length();
    std::vector<PairStePoint> out;
    out.reserve(std::size_t(samples_));
    std::vector<ContactPair> contacts;
    for (int k = 0; k < samples_; ++k) {
      PairStePoint p;
      p.mesh.phase = double(k) / samples_;
      contacts.clear();
      for (int j = 0; j < slices_; ++j)
        for (const Segment& seg : sections_[std::size_t(k * slices_ + j)]) {
          PairContact c = seg.contact;
          c.slice = j;
          c.tooth = seg.tooth;
          c.separation = reliefs ? c.separation + lead_[std::size_t(j)] : 0.0;
          // The scaled problem: stiffness w k (line / b), force S F, Hertz of the line at the line load.
          contacts.push_back({seg.weight * c.stiffness * line_share, c.separation, seg.weight});
          c.stiffness *= seg.weight / n;
          p.mesh.pairs.push_back(c);
        }
      const LoadShare share = share_load(contacts, scale_ * F, model_.hertz, model_.pair_hertz, line_);
      for (std::size_t i = 0; i < contacts.size(); ++i) p.mesh.pairs[i].force = share.force[i] / scale_;
      p.loaded = share.loaded;
      p.approach = share.approach;
      p.hertz = share.hertz;
      p.ste = share.ste;
      out.push_back(std::move(p));
    }
    return out;
  }

  // The tooth pair whose mid-face contact is at s, alone: its slices on the path, unmodified.
  double single_pair_ste(double s, double torque) const override {
    const double mean = std::accumulate(leads_.begin(), leads_.end(), 0.0) / double(slices_);
    const double line_share = line_ / model_.contact_length();
    std::vector<ContactPair> contacts;
    for (int j = 0; j < slices_; ++j) {
      const auto [sm, w] = on_path(s + (leads_[std::size_t(j)] - mean) * path_.base_pitch, spread_, path_.AE);
      if (w == 0.0) continue;
      const ContactRadii r = contact_radii(model_.gear1, model_.gear2, path_, sm);
      contacts.push_back({w * stiffness_(r.r1, r.r2, false) * line_share, 0.0, w});
    }
    if (contacts.empty()) throw std::invalid_argument("single_pair_ste: no slice of the pair on the path of contact");
    return share_load(contacts, scale_ * model_.force(torque), model_.hertz, model_.pair_hertz, line_).ste;
  }

 private:
  struct Segment {
    PairContact contact;   // at the centre of its part on the path; stiffness the full-width section's
    double weight = 1.0;   // that part's fraction of the slice's contact line
    int tooth = 0;
  };
  // Slice j at sample k: the slice's contact lines (one per tooth pair near the path), each
  // spread over spread_ along the path, cut to the path.
  std::vector<Segment> segments(int k, int j) const {
    const double pb = path_.base_pitch, x = double(k) / samples_ + leads_[std::size_t(j)];
    const double wrap = std::floor(x), psi = x - wrap;
    std::vector<Segment> out;
    for (int q = int(std::ceil(-psi - 0.5 * spread_ / pb)); (psi + q) * pb - 0.5 * spread_ <= path_.AE; ++q) {
      const auto [sm, w] = on_path((psi + q) * pb, spread_, path_.AE);
      if (w > 0.0) out.push_back({pair_contact_at(model_, path_, sm), w, q - int(wrap)});
    }
    const bool sharing = out.size() > 1;
    for (Segment& seg : out) seg.contact.stiffness = stiffness_(seg.contact.r1, seg.contact.r2, sharing);
    return out;
  }

  PairSteModel model_;
  HelicalPair helix_;
  PathOfContact path_;
  int samples_ = 0, slices_ = 1;
  double spread_ = 0.0;               // one slice's contact line along the path: (b / N) tan(beta_b) [m]
  double line_ = 0.0;                 // the Hertz line: b, or a half b/2 (double helical) [m]
  double scale_ = 1.0;                // line over slice width: N, or N/2 (double helical)
  PairStiffnessFn stiffness_;
  std::vector<std::vector<Segment>> sections_;   // sample k, slice j at k * slices_ + j
  std::vector<double> lead_;          // both gears' lead modification at each slice [m]
  std::vector<double> leads_;         // each slice's phase lead [mesh cycles]
};

}  // namespace

std::unique_ptr<LoadedPair> sliced_loaded_pair(const PairSteModel& section, const HelicalPair& h, int samples,
                                               const PairStiffnessFn& stiffness) {
  if (h.slices < 1 || h.slices > 1000) throw std::invalid_argument("sliced_loaded_pair: slices outside [1, 1000]");
  if (section.positions_per_base_pitch > 0)
    throw std::invalid_argument("sliced_loaded_pair: the node reading (positions_per_base_pitch) has no slices");
  if (h.double_helical && (h.helix_angle == 0.0 || h.slices % 2 != 0))
    throw std::invalid_argument("sliced_loaded_pair: double helical needs a helix angle and an even slice count");
  if (h.sliced() && h.slices > 1 && section.hertz != HertzCount::none && section.pair_hertz != TwoPairHertz::consistent)
    throw std::invalid_argument("sliced_loaded_pair: Hertz over slices needs the consistent split (or none)");
  if (samples < 4 || samples > 1 << 16)
    throw std::invalid_argument("sliced_loaded_pair: samples per mesh cycle must be in [4, 65536]");
  return std::make_unique<SlicedLoadedPair>(section, h, samples, stiffness);
}

}  // namespace gearhb
