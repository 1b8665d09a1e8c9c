// Bullet 3.24's side of the peer comparison: a btMultiBody (Featherstone's articulated-body algorithm in
// reduced coordinates, double precision: the -float64 libraries) with a fixed base at the world origin and
// one spherical link per rod, stepped by btMultiBodyDynamicsWorld::stepSimulation(dt, 0) (one step of dt, no
// sub-stepping). Bullet's defaults that would change the dynamics are turned off: the multibody's linear and
// angular damping (0.04 each by default) are set to 0, the clamp on joint speeds (100 rad/s by default) is
// raised out of reach, sleeping is disabled. No collision shapes, so no contacts.
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <btBulletDynamicsCommon.h>

#include <memory>

#include "chain_bench.hpp"

namespace poinsot::bench {
namespace {

class BulletChain {
 public:
  explicit BulletChain(int n) : n_(n) { build(); }
  ~BulletChain() { world_->removeMultiBody(body_.get()); }
  BulletChain(const BulletChain&) = delete;
  BulletChain& operator=(const BulletChain&) = delete;

  void step() { world_->stepSimulation(kChainDt, 0); }

  void reset() {  // released state: every spherical joint at the identity, at rest
    const double q[4] = {0, 0, 0, 1}, qd[3] = {0, 0, 0};
    for (int i = 0; i < n_; ++i) {
      body_->setJointPosMultiDof(i, q);
      body_->setJointVelMultiDof(i, qd);
    }
    body_->clearForcesAndTorques();
  }

  void poses(std::vector<BodyPose>& out) {
    const auto nn = static_cast<std::size_t>(n_);
    world_to_local_.resize(n_ + 1);
    local_origin_.resize(n_ + 1);
    body_->forwardKinematics(world_to_local_, local_origin_);  // index 0: the base, i + 1: link i
    omega_.resize(nn + 1);
    vel_.resize(nn + 1);
    body_->compTreeLinkVelocities(omega_.data(), vel_.data());  // in each link's frame, at its centre of mass
    out.resize(nn);
    for (std::size_t i = 0; i < nn; ++i) {
      const int k = static_cast<int>(i) + 1;
      const btMatrix3x3 R(world_to_local_[k].inverse());
      BodyPose& b = out[i];
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
          b.R_space_body(r, c) = R[r][c];
      const btVector3 w = R * omega_[i + 1], v = R * vel_[i + 1];
      b.x_space = {local_origin_[k].x(), local_origin_[k].y(), local_origin_[k].z()};
      b.v_space = {v.x(), v.y(), v.z()};
      b.omega_space = {w.x(), w.y(), w.z()};
    }
  }

 private:
  void build() {
    collision_config_ = std::make_unique<btDefaultCollisionConfiguration>();
    dispatcher_ = std::make_unique<btCollisionDispatcher>(collision_config_.get());
    broadphase_ = std::make_unique<btDbvtBroadphase>();
    solver_ = std::make_unique<btMultiBodyConstraintSolver>();
    world_ = std::make_unique<btMultiBodyDynamicsWorld>(dispatcher_.get(), broadphase_.get(), solver_.get(),
                                                        collision_config_.get());
    world_->setGravity(btVector3(0, 0, -kGravity));
    const double m = kRodMass, l = kRodLength, r = kRodRadius;
    const btVector3 inertia(m * r * r / 2.0, m * (3 * r * r + l * l) / 12.0, m * (3 * r * r + l * l) / 12.0);
    body_ =
        std::make_unique<btMultiBody>(n_, 0.0, btVector3(0, 0, 0), /*fixedBase=*/true, /*canSleep=*/false);
    body_->setBasePos(btVector3(0, 0, 0));
    const btVector3 half(l / 2.0, 0, 0);
    for (int i = 0; i < n_;
         ++i)  // pivot at the parent's +l/2 end (the base's origin for link 0), centre l/2 on
      body_->setupSpherical(i, m, inertia, i - 1, btQuaternion::getIdentity(),
                            i == 0 ? btVector3(0, 0, 0) : half, half, /*disableParentCollision=*/true);
    body_->finalizeMultiDof();
    body_->setLinearDamping(0.0);
    body_->setAngularDamping(0.0);
    body_->setMaxCoordinateVelocity(1e30);
    body_->setCanSleep(false);
    body_->setHasSelfCollision(false);
    world_->addMultiBody(body_.get());
  }

  int n_;
  std::unique_ptr<btDefaultCollisionConfiguration> collision_config_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;
  std::unique_ptr<btDbvtBroadphase> broadphase_;
  std::unique_ptr<btMultiBodyConstraintSolver> solver_;
  std::unique_ptr<btMultiBodyDynamicsWorld> world_;
  std::unique_ptr<btMultiBody> body_;
  btAlignedObjectArray<btQuaternion> world_to_local_;
  btAlignedObjectArray<btVector3> local_origin_;
  std::vector<btVector3> omega_, vel_;
};

}  // namespace

void register_bullet() {
  register_chain<BulletChain>("bullet_multibody");
}

}  // namespace poinsot::bench
