#include "poinsot/dynamics/exact_integrator.hpp"

#include <fmt/format.h>
#include <optional>

#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/dynamics/exact_free_body.hpp"

namespace poinsot::dynamics {
namespace {

bool same_state(const State& a, const State& b) {
  return a.time == b.time && a.R_space_body == b.R_space_body && a.omega_body == b.omega_body;
}

class ExactIntegrator final : public Integrator {
 public:
  explicit ExactIntegrator(const RigidBody& body) : body_(body) {}

  std::string_view name() const override { return kExactMethodName; }
  int order() const override { return 0; }
  bool has_dense_output() const override { return true; }

  StepResult step(State& state, double dt) override {
    require_finite("exact: step dt (s)", dt);
    if (!solution_ || !same_state(state, last_)) solution_.emplace(body_, state);  // no heap allocation
    state = solution_->state_at(state.time + dt);
    last_ = state;
    return StepResult{dt, dt, 0};
  }

  /// The closed form at any time t (s), not only inside the last step.
  State dense_output(double t) const override {
    if (!solution_) {
      throw InvalidInput(fmt::format("exact: no dense output at t = {} s before the first step", t));
    }
    return solution_->state_at(t);
  }

 private:
  RigidBody body_;
  std::optional<ExactFreeBody> solution_;
  State last_;
};

}  // namespace

std::unique_ptr<Integrator> make_exact_integrator(const RigidBody& body,
                                                  std::shared_ptr<const TorqueModel> torque) {
  if (torque && !torque->is_zero()) {
    throw InvalidInput(fmt::format(
        "exact: the closed-form solution is torque-free; got torque {}; expected none (choose rk4, dopri5, "
        "dop853, dlm or rattle for a body under torque)",
        torque->describe()));
  }
  return std::make_unique<ExactIntegrator>(body);
}

}  // namespace poinsot::dynamics
