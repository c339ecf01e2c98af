#include "gearhb/gears/pair/loaded_pair.hpp"

#include <stdexcept>

#include "gearhb/gears/pair/coupled_load_sharing.hpp"

namespace gearhb {

namespace {

// The pairs of each phase sharing the load through one compliance matrix (coupling > 0).
std::vector<PairStePoint> coupled_ste(const std::vector<MeshPhase>& phases, double F, double coupling) {
  std::vector<PairStePoint> out;
  for (const MeshPhase& ph : phases) {
    const long n = long(ph.pairs.size());
    Eigen::MatrixXd C = Eigen::MatrixXd::Constant(n, n, coupling);
    Eigen::VectorXd g(n);
    for (long i = 0; i < n; ++i) C(i, i) = 1.0 / ph.pairs[std::size_t(i)].stiffness, g(i) = ph.pairs[std::size_t(i)].separation;
    const CoupledShare share = share_load_coupled(C, g, F);
    PairStePoint p;
    p.mesh = ph;
    for (long i = 0; i < n; ++i) p.mesh.pairs[std::size_t(i)].force = share.force(i);
    p.loaded = share.loaded;
    p.approach = p.ste = share.approach;
    out.push_back(std::move(p));
  }
  return out;
}

class PhaseLoadedPair final : public LoadedPair {
 public:
  PhaseLoadedPair(const PairSteModel& m, int samples, const PairStiffnessFn& stiffness, double coupling)
      : model_(m), plain_(m), stiffness_(stiffness), coupling_(coupling) {
    plain_.relief1.amount = plain_.relief2.amount = 0.0;
    relieved_ = mesh_phases(model_, samples, stiffness_);
    unmodified_ = mesh_phases(plain_, samples, stiffness_);
  }
  double force(double torque) const override { return model_.force(torque); }
  std::vector<PairStePoint> ste(double torque, bool reliefs) const override {
    if (coupling_ > 0.0) return coupled_ste(reliefs ? relieved_ : unmodified_, model_.force(torque), coupling_);
    return reliefs ? pair_ste(model_, relieved_, torque) : pair_ste(plain_, unmodified_, torque);
  }
  double single_pair_ste(double s, double torque) const override {
    return gearhb::single_pair_ste(model_, s, torque, stiffness_);
  }

 private:
  PairSteModel model_, plain_;
  PairStiffnessFn stiffness_;
  double coupling_ = 0.0;
  std::vector<MeshPhase> relieved_, unmodified_;
};

class FeLoadedPair final : public LoadedPair {
 public:
  FeLoadedPair(const PairSteModel& m, int samples, const FePairOptions& options) : fe_(m, samples, options) {}
  double force(double torque) const override { return fe_.force(torque); }
  std::vector<PairStePoint> ste(double torque, bool reliefs) const override { return fe_.pair_ste(torque, reliefs); }
  double single_pair_ste(double s, double torque) const override {
    const double F = fe_.force(torque);
    return F / fe_.single_pair_stiffness(s, F);
  }
  const FePairModel* fe_model() const override { return &fe_; }

 private:
  FePairModel fe_;
};

}  // namespace

std::unique_ptr<LoadedPair> phase_loaded_pair(const PairSteModel& m, int samples, const PairStiffnessFn& stiffness,
                                              double coupling) {
  if (coupling > 0.0 && m.hertz != HertzCount::none)
    throw std::invalid_argument("phase_loaded_pair: a structural coupling needs hertz none (a linear pair stiffness)");
  return std::make_unique<PhaseLoadedPair>(m, samples, stiffness, coupling);
}

std::unique_ptr<LoadedPair> fe_loaded_pair(const PairSteModel& m, int samples, const FePairOptions& options) {
  if (m.tooth_force != ToothForce::over_base_radius)
    throw std::invalid_argument("fe_loaded_pair: the FE tooth force is T1 / rb1 along the line of action "
                                "(tooth_force must be over_base_radius)");
  return std::make_unique<FeLoadedPair>(m, samples, options);
}

}  // namespace gearhb
