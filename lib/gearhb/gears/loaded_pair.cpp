#include "gearhb/gears/loaded_pair.hpp"

#include <stdexcept>

namespace gearhb {

namespace {

class PhaseLoadedPair final : public LoadedPair {
 public:
  PhaseLoadedPair(const PairSteModel& m, int samples, const PairStiffnessFn& stiffness)
      : model_(m), plain_(m), stiffness_(stiffness) {
    plain_.relief1.amount = plain_.relief2.amount = 0.0;
    relieved_ = mesh_phases(model_, samples, stiffness_);
    unmodified_ = mesh_phases(plain_, samples, stiffness_);
  }
  double force(double torque) const override { return model_.force(torque); }
  std::vector<PairStePoint> ste(double torque, bool reliefs) const override {
    return reliefs ? pair_ste(model_, relieved_, torque) : pair_ste(plain_, unmodified_, torque);
  }
  double single_pair_ste(double s, double torque) const override {
    return gearhb::single_pair_ste(model_, s, torque, stiffness_);
  }

 private:
  PairSteModel model_, plain_;
  PairStiffnessFn stiffness_;
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

std::unique_ptr<LoadedPair> phase_loaded_pair(const PairSteModel& m, int samples, const PairStiffnessFn& stiffness) {
  return std::make_unique<PhaseLoadedPair>(m, samples, stiffness);
}

std::unique_ptr<LoadedPair> fe_loaded_pair(const PairSteModel& m, int samples, const FePairOptions& options) {
  if (m.tooth_force != ToothForce::over_base_radius)
    throw std::invalid_argument("fe_loaded_pair: the FE tooth force is T1 / rb1 along the line of action "
                                "(tooth_force must be over_base_radius)");
  return std::make_unique<FeLoadedPair>(m, samples, options);
}

}  // namespace gearhb
