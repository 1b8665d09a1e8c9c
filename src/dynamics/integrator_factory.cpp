// make_integrator: the one place that maps a method's name to its class.
#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/dynamics/dlm.hpp"
#include "poinsot/dynamics/dop853.hpp"
#include "poinsot/dynamics/dopri5.hpp"
#include "poinsot/dynamics/exact_integrator.hpp"
#include "poinsot/dynamics/integrator.hpp"
#include "poinsot/dynamics/rattle.hpp"
#include "poinsot/dynamics/rk4.hpp"

namespace poinsot::dynamics {

std::unique_ptr<Integrator> make_integrator(std::string_view name, const RigidBody& body,
                                            std::shared_ptr<const TorqueModel> torque,
                                            const IntegratorOptions& options) {
  if (!torque) torque = TorqueModel::none();
  if (name == "rk4") return std::make_unique<Rk4Integrator>(body, std::move(torque), options);
  if (name == "dopri5") return std::make_unique<Dopri5Integrator>(body, std::move(torque), options);
  if (name == "dop853") return std::make_unique<Dop853Integrator>(body, std::move(torque), options);
  if (name == "dlm") return std::make_unique<DlmIntegrator>(body, std::move(torque), options);
  if (name == "rattle") return std::make_unique<RattleIntegrator>(body, std::move(torque), options);
  if (name == "exact") return make_exact_integrator(body, std::move(torque));  // refuses a torque
  throw InvalidInput(fmt::format(
      "integrator: unknown method \"{}\"; expected one of rk4, dopri5, dop853, dlm, rattle, exact", name));
}

}  // namespace poinsot::dynamics
