// The registry of multibody methods (methods.hpp).
#include "poinsot/multibody/methods.hpp"

#include <array>
#include <utility>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/multibody/projected_rk4.hpp"
#include "poinsot/multibody/rattle.hpp"

namespace poinsot::multibody {
namespace {

/// A method class (Rattle, ProjectedRk4) behind MultibodyIntegrator.
template <class T>
class Adapter final : public MultibodyIntegrator {
 public:
  explicit Adapter(T integrator) : integrator_(std::move(integrator)) {}
  void step(State& state) override { integrator_.step(state); }
  int last_iterations() const override { return integrator_.last_iterations(); }
  KktMethod kkt_method() const override { return integrator_.kkt_method(); }

 private:
  T integrator_;
};

std::unique_ptr<MultibodyIntegrator> make_rattle(const System& system, double dt, int order) {
  RattleOptions options;
  options.order = order;
  return std::make_unique<Adapter<Rattle>>(Rattle(system, dt, options));
}

std::unique_ptr<MultibodyIntegrator> make_projected_rk4(const System& system, double dt, int) {
  return std::make_unique<Adapter<ProjectedRk4>>(ProjectedRk4(system, dt));
}

// What each method keeps is stated (with its reason) in its header and checked for every entry by
// tests/multibody/test_method_contract.cpp.
const std::array kMethods{
    MultibodyMethodInfo{
        .method = MultibodyMethod::rattle,
        .name = "rattle",
        .order = 2,
        .max_order = 4,
        .symplectic = true,
        .preserves = {.orthogonality = true, .joints = true, .momentum = true},
        .label = "RATTLE, symplectic",
        .description =
            "RATTLE: symplectic, symmetric, momentum-conserving, for long runs (order 2, or 4 by the "
            "triple jump)",
        .make = make_rattle},
    MultibodyMethodInfo{
        .method = MultibodyMethod::projected_rk4,
        .name = "rk4",
        .order = 4,
        .max_order = 4,
        .preserves = {.orthogonality = true, .joints = true},
        .label = "RK4 projected onto the joints",
        .description =
            "RK4 projected onto the joints (order 4, not symplectic): accurate bounded runs, exact "
            "multipliers at every sample",
        .make = make_projected_rk4},
};

}  // namespace

std::span<const MultibodyMethodInfo> multibody_methods() {
  return kMethods;
}

const MultibodyMethodInfo& multibody_method_info(MultibodyMethod method) {
  for (const MultibodyMethodInfo& m : kMethods)
    if (m.method == method) return m;
  throw InvalidInput(fmt::format("multibody: method {} has no registry entry", static_cast<int>(method)));
}

MultibodyMethod parse_multibody_method(std::string_view name, std::string_view what) {
  std::string expected;
  for (std::size_t i = 0; i < kMethods.size(); ++i) {
    if (kMethods[i].name == name) return kMethods[i].method;
    if (i > 0) expected += i + 1 == kMethods.size() ? " or " : ", ";
    expected += fmt::format("\"{}\" ({})", kMethods[i].name, kMethods[i].label);
  }
  throw InvalidInput(fmt::format("{}: got \"{}\", expected {}", what, name, expected));
}

std::string multibody_method_names(std::string_view separator) {
  std::string out;
  for (const MultibodyMethodInfo& m : kMethods)
    out += (out.empty() ? "" : std::string(separator)) + std::string(m.name);
  return out;
}

const char* multibody_method_name(MultibodyMethod method) {
  return multibody_method_info(method).name.data();  // the entries' names are literals
}

int order_for_method(MultibodyMethod method, int order) {
  const MultibodyMethodInfo& m = multibody_method_info(method);
  return order >= m.order && order <= m.max_order && (order - m.order) % 2 == 0 ? order : m.order;
}

}  // namespace poinsot::multibody
