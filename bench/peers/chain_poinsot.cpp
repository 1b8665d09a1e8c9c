// poinsot's side of the peer comparison: multibody::Rattle on bench/rod_chain.hpp's chain, dt = 1e-3 s
// (the same model and solver as bench_multibody.cpp, measured here with the peers' pose-based counters).
#include "../rod_chain.hpp"
#include "chain_bench.hpp"
#include "poinsot/multibody/rattle.hpp"

namespace poinsot::bench {
namespace {

// Order 2: RATTLE; order 4: its triple-jump composition (three RATTLE substeps per step).
template <int Order>
class PoinsotChain {
 public:
  explicit PoinsotChain(int n)
      : system_(rod_chain(n)),
        released_(released_chain(n)),
        state_(released_),
        rattle_(system_, kChainDt, options()) {}
  void step() { rattle_.step(state_); }
  void reset() {
    state_ = released_;
    rattle_ = multibody::Rattle(system_, kChainDt, options());
  }
  static multibody::RattleOptions options() {
    multibody::RattleOptions o;
    o.order = Order;
    return o;
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
  multibody::Rattle rattle_;
};

}  // namespace

void register_poinsot() {
  register_chain<PoinsotChain<2>>("poinsot_rattle");
  register_chain<PoinsotChain<4>>("poinsot_rattle_order4");
}

}  // namespace poinsot::bench
