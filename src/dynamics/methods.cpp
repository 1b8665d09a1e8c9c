// The registry of single-body methods (methods.hpp) and make_integrator, which reads it.
#include "poinsot/dynamics/methods.hpp"

#include <array>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/dynamics/dlm.hpp"
#include "poinsot/dynamics/dop853.hpp"
#include "poinsot/dynamics/dopri5.hpp"
#include "poinsot/dynamics/exact_integrator.hpp"
#include "poinsot/dynamics/rattle.hpp"
#include "poinsot/dynamics/rk4.hpp"

namespace poinsot::dynamics {
namespace {

template <class T>
std::unique_ptr<Integrator> make(const RigidBody& body, std::shared_ptr<const TorqueModel> torque,
                                 const IntegratorOptions& options) {
  return std::make_unique<T>(body, std::move(torque), options);
}

std::unique_ptr<Integrator> make_exact(const RigidBody& body, std::shared_ptr<const TorqueModel> torque,
                                       const IntegratorOptions&) {
  return make_exact_integrator(body, std::move(torque));  // refuses a torque
}

// What each method keeps to round-off is stated (with its reason) in its header and checked for every entry
// by tests/dynamics/test_integrator_contract.cpp.
const std::array kMethods{
    MethodInfo{.name = kExactMethodName,
               .order = 0,
               .dense_output = true,
               .takes_torque = false,
               .preserves = {.energy = true, .L_space = true, .L_body_norm = true, .orthogonality = true},
               .description = "closed-form torque-free motion (Jacobi elliptic functions)",
               .make = make_exact},
    MethodInfo{.name = Rk4Integrator::kName,
               .order = 4,
               .preserves = {.orthogonality = true},
               .description = "classical Runge–Kutta on ω and the quaternion, renormalised each step",
               .make = make<Rk4Integrator>},
    MethodInfo{.name = Dopri5Integrator::kName,
               .order = 5,
               .adaptive = true,
               .dense_output = true,
               .preserves = {.orthogonality = true},
               .description = "Dormand–Prince 5(4), adaptive, dense output of order 4",
               .make = make<Dopri5Integrator>},
    MethodInfo{.name = Dop853Integrator::kName,
               .order = 8,
               .adaptive = true,
               .dense_output = true,
               .preserves = {.orthogonality = true},
               .description = "Hairer's DOP853 8(5,3), adaptive, dense output of order 7",
               .make = make<Dop853Integrator>},
    MethodInfo{.name = DlmIntegrator::kName,
               .order = 2,
               .symplectic = true,
               .preserves = {.L_space = true, .L_body_norm = true, .orthogonality = true},
               .description = "Dullweber–Leimkuhler–McLachlan symplectic splitting",
               .make = make<DlmIntegrator>},
    MethodInfo{.name = RattleIntegrator::kName,
               .order = 2,
               .symplectic = true,
               .preserves = {.L_space = true, .L_body_norm = true, .orthogonality = true},
               .description = "RATTLE / Moser–Veselov variational method for R̈K = RΛ, RᵀR = I",
               .make = make<RattleIntegrator>},
};

}  // namespace

std::span<const MethodInfo> methods() {
  return kMethods;
}

std::string method_names(std::string_view separator) {
  std::string out;
  for (const MethodInfo& m : kMethods) {
    if (!out.empty()) out += separator;
    out += m.name;
  }
  return out;
}

const MethodInfo& method_info(std::string_view name, std::string_view what) {
  for (const MethodInfo& m : kMethods)
    if (m.name == name) return m;
  throw InvalidInput(fmt::format("{}: got \"{}\", expected one of {}", what, name, method_names()));
}

std::string preserved_names(const Preserved& p) {
  std::string out;
  const auto add = [&out](bool on, std::string_view label) {
    if (!on) return;
    if (!out.empty()) out += ", ";
    out += label;
  };
  add(p.energy, "energy");
  add(p.L_space, "L_space");
  add(p.L_body_norm, "|L|");
  add(p.orthogonality, "RᵀR = I");
  return out.empty() ? "nothing" : out;
}

std::unique_ptr<Integrator> make_integrator(std::string_view name, const RigidBody& body,
                                            std::shared_ptr<const TorqueModel> torque,
                                            const IntegratorOptions& options) {
  if (!torque) torque = TorqueModel::none();
  return method_info(name, "integrator: method").make(body, std::move(torque), options);
}

}  // namespace poinsot::dynamics
