// ODE 0.16's side of the peer comparison: one dBody per rod (maximal coordinates) and one ball joint per
// pivot, stepped by dWorldQuickStep (projected Gauss-Seidel/SOR on the joint rows, 20 iterations,
// over-relaxation 1.3: ODE's defaults) and, where cheap, dWorldStep (the dense "big matrix" LCP solve, exact
// for the linearised rows each step). Joint drift is corrected by ODE's error reduction: ERP = 0.2 and CFM =
// 1e-10, the defaults the ODE manual documents for double precision (section "Joint error and the ERP", "Soft
// constraint and CFM"); the gaps left are what the counters report. Linear and angular damping are 0 (ODE's
// default, set explicitly), auto-disable off, the gyroscopic term on (ODE's default); no geoms, so no
// contacts.
#include <ode/ode.h>

#include "chain_bench.hpp"

namespace poinsot::bench {
namespace {

struct OdeInit {  // dInitODE2 once per process
  OdeInit() { dInitODE2(0); }
  ~OdeInit() { dCloseODE(); }
};

template <bool kQuick>
class OdeChain {
 public:
  explicit OdeChain(int n) {
    static const OdeInit init;
    world_ = dWorldCreate();
    dWorldSetGravity(world_, 0, 0, -kGravity);
    dWorldSetERP(world_, 0.2);
    dWorldSetCFM(world_, 1e-10);
    dWorldSetQuickStepNumIterations(world_, 20);
    dWorldSetQuickStepW(world_, 1.3);
    dWorldSetLinearDamping(world_, 0);
    dWorldSetAngularDamping(world_, 0);
    dWorldSetAutoDisableFlag(world_, 0);
    const double m = kRodMass, l = kRodLength, r = kRodRadius;
    dMass mass;
    dMassSetParameters(&mass, m, 0, 0, 0, m * r * r / 2.0, m * (3 * r * r + l * l) / 12.0,
                       m * (3 * r * r + l * l) / 12.0, 0, 0, 0);
    for (int i = 0; i < n; ++i) {
      const dBodyID b = dBodyCreate(world_);
      dBodySetMass(b, &mass);
      bodies_.push_back(b);
    }
    reset();
    for (int i = 0; i < n; ++i) {  // anchors given in the space frame of the released state
      const dJointID j = dJointCreateBall(world_, nullptr);
      dJointAttach(j, bodies_[static_cast<std::size_t>(i)],
                   i == 0 ? nullptr : bodies_[static_cast<std::size_t>(i) - 1]);
      dJointSetBallAnchor(j, i * l, 0, 0);
    }
  }
  ~OdeChain() { dWorldDestroy(world_); }
  OdeChain(const OdeChain&) = delete;
  OdeChain& operator=(const OdeChain&) = delete;

  void step() {
    if constexpr (kQuick)
      dWorldQuickStep(world_, kChainDt);
    else
      dWorldStep(world_, kChainDt);
  }

  void reset() {
    dMatrix3 identity;
    dRSetIdentity(identity);
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      dBodySetPosition(bodies_[i], (static_cast<double>(i) + 0.5) * kRodLength, 0, 0);
      dBodySetRotation(bodies_[i], identity);
      dBodySetLinearVel(bodies_[i], 0, 0, 0);
      dBodySetAngularVel(bodies_[i], 0, 0, 0);
    }
  }

  void poses(std::vector<BodyPose>& out) const {
    out.resize(bodies_.size());
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      const dReal* x = dBodyGetPosition(bodies_[i]);
      const dReal* R = dBodyGetRotation(bodies_[i]);  // 3×4, row major
      const dReal* v = dBodyGetLinearVel(bodies_[i]);
      const dReal* w = dBodyGetAngularVel(bodies_[i]);  // space frame
      BodyPose& b = out[i];
      b.x_space = {x[0], x[1], x[2]};
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
          b.R_space_body(r, c) = R[4 * r + c];
      b.v_space = {v[0], v[1], v[2]};
      b.omega_space = {w[0], w[1], w[2]};
    }
  }

 private:
  dWorldID world_;
  std::vector<dBodyID> bodies_;
};

}  // namespace

void register_ode() {
  register_chain<OdeChain<true>>("ode_quickstep");
  register_chain<OdeChain<false>>("ode_step",
                                  64);  // dense LCP, cubic in N: 256 links would take seconds a step
}

}  // namespace poinsot::bench
