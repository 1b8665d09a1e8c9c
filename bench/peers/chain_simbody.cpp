// Simbody 3.7's side of the peer comparison: one MobilizedBody::Ball per rod (reduced coordinates, a
// quaternion per joint, O(N) articulated-body algorithm), gravity as Force::UniformGravity, no other force
// element. Integrated from one dt = 1e-3 s report time to the next with a fixed step of dt, so that a
// benchmark iteration is one step as in the other libraries:
//   simbody_rkm:       RungeKuttaMersonIntegrator, setFixedStepSize(1e-3) (4th order, 5 evaluations a step;
//                      with a fixed step the error control and its accuracy setting are not used),
//   simbody_semieuler: SemiExplicitEulerIntegrator(system, 1e-3) (1st order, 1 evaluation a step, the
//                      counterpart of Bullet's and MuJoCo's semi-implicit Euler).
// Quaternions are renormalised by Simbody's projection at its default constraint tolerance.
#include <Simbody.h>

#include <memory>

#include "chain_bench.hpp"

namespace poinsot::bench {
namespace {

template <bool kMerson>
class SimbodyChain {
 public:
  explicit SimbodyChain(int n)
      : matter_(system_), forces_(system_), gravity_(forces_, matter_, SimTK::Vec3(0, 0, -kGravity)) {
    const double m = kRodMass, l = kRodLength, r = kRodRadius;
    const SimTK::Body::Rigid rod(SimTK::MassProperties(
        m, SimTK::Vec3(0),
        SimTK::Inertia(m * r * r / 2.0, m * (3 * r * r + l * l) / 12.0, m * (3 * r * r + l * l) / 12.0)));
    SimTK::MobilizedBody parent = matter_.Ground();
    for (int i = 0; i < n; ++i) {  // body frame at the centre of mass; the ball at (-l/2, 0, 0) in it, at the
                                   // parent's (+l/2, 0, 0) (the ground's origin for link 0)
      SimTK::MobilizedBody::Ball link(parent, SimTK::Transform(SimTK::Vec3(i == 0 ? 0.0 : l / 2.0, 0, 0)),
                                      rod, SimTK::Transform(SimTK::Vec3(-l / 2.0, 0, 0)));
      links_.push_back(link);
      parent = link;
    }
    system_.realizeTopology();
    released_ = system_.getDefaultState();  // every ball at the identity, at rest: the released state
    if constexpr (kMerson) {
      auto rkm = std::make_unique<SimTK::RungeKuttaMersonIntegrator>(system_);
      rkm->setFixedStepSize(kChainDt);
      integrator_ = std::move(rkm);
    } else {
      integrator_ = std::make_unique<SimTK::SemiExplicitEulerIntegrator>(system_, kChainDt);
    }
    reset();
  }

  // One step of dt a call. After initialize(), the first stepTo returns at t = 0 without stepping (status
  // StartOfContinuousInterval), so reset() takes that return itself. Report times t + dt rather than k dt:
  // with k dt (rounded differently from the integrator's own t + dt) Simbody 3.7 took 6x longer a step.
  void step() { integrator_->stepTo(integrator_->getTime() + kChainDt); }
  void reset() {
    integrator_->initialize(released_);
    integrator_->stepTo(0.0);
  }

  void poses(std::vector<BodyPose>& out) const {
    const SimTK::State& s = integrator_->getState();
    out.resize(links_.size());
    for (std::size_t i = 0; i < links_.size(); ++i) {
      const SimTK::Transform& X = links_[i].getBodyTransform(s);
      const SimTK::SpatialVec& V = links_[i].getBodyVelocity(s);  // [ω; v of the body origin], ground frame
      BodyPose& b = out[i];
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c)
          b.R_space_body(r, c) = X.R()[r][c];
        b.x_space[r] = X.p()[r];
        b.omega_space[r] = V[0][r];
        b.v_space[r] = V[1][r];
      }
    }
  }

 private:
  SimTK::MultibodySystem system_;
  SimTK::SimbodyMatterSubsystem matter_;
  SimTK::GeneralForceSubsystem forces_;
  SimTK::Force::UniformGravity gravity_;
  std::vector<SimTK::MobilizedBody> links_;
  SimTK::State released_;
  std::unique_ptr<SimTK::Integrator> integrator_;
};

}  // namespace

void register_simbody() {
  register_chain<SimbodyChain<true>>("simbody_rkm");
  register_chain<SimbodyChain<false>>("simbody_semieuler");
}

}  // namespace poinsot::bench
