// poinsot's side of the peer comparison: multibody::Rattle and ProjectedRk4 on bench/rod_chain.hpp's chain,
// dt = 1e-3 s
// (the same model and solver as bench_multibody.cpp, measured here with the peers' pose-based counters).
#include <type_traits>
#include "../rod_chain.hpp"
#include "chain_bench.hpp"

#include "poinsot/multibody/projected_rk4.hpp"
#include "poinsot/multibody/rattle.hpp"

namespace poinsot::bench {
namespace {

// Method 2: RATTLE; 4: its triple-jump composition (three RATTLE substeps per step); 0: the projected RK4
// (four stages, projected onto the joints).
template <int Method>
class PoinsotChain {
  using Integrator = std::conditional_t<Method == 0, multibody::ProjectedRk4, multibody::Rattle>;

 public:
  explicit PoinsotChain(int n)
      : system_(rod_chain(n)), released_(released_chain(n)), state_(released_), integrator_(make(system_)) {}
  void step() { integrator_.step(state_); }
  void reset() {
    state_ = released_;
    integrator_ = make(system_);
  }
  static Integrator make(const multibody::System& system) {
    if constexpr (Method == 0) {
      return multibody::ProjectedRk4(system, kChainDt);
    } else {
      multibody::RattleOptions o;
      o.order = Method;
      return multibody::Rattle(system, kChainDt, o);
    }
  }
  void poses(std::vector<BodyPose>& out) const {
    out.resize(state_.bodies.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
      const multibody::BodyState& b = state_.bodies[i];
      out[i] = {b.x_space, b.R_space_body, b.v_space, b.R_space_body * b.omega_body};
    }
  }

 private:
  multibody::System system_;
  multibody::State released_, state_;
  Integrator integrator_;
};

}  // namespace

void register_poinsot() {
  register_chain<PoinsotChain<2>>("poinsot_rattle");
  register_chain<PoinsotChain<4>>("poinsot_rattle_order4");
  register_chain<PoinsotChain<0>>("poinsot_rk4");
}

}  // namespace poinsot::bench
