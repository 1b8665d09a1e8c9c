// simulate() from Python: runs dynamics::simulate with the GIL released, samples each observed state into
// C++ buffers, and hands the buffers to NumPy without copying (arrays owned by capsules).
#include <pybind11/stl.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "convert.hpp"
#include "docstrings.hpp"
#include "poinsot/dynamics/integrator.hpp"
#include "poinsot/dynamics/rigid_body.hpp"
#include "poinsot/dynamics/simulation.hpp"
#include "poinsot/dynamics/state.hpp"

namespace poinsot::python {

using dynamics::RigidBody;
using dynamics::State;
using dynamics::TorqueModel;

namespace {

/// The sampled trajectory, row-major: R is n×3×3 (R[i] maps body to space), quaternion n×4 (w, x, y, z).
struct Samples {
  std::vector<double> t, R, quaternion, omega_body, energy, L_space;
  void reserve(std::size_t n) {
    t.reserve(n);
    R.reserve(9 * n);
    quaternion.reserve(4 * n);
    omega_body.reserve(3 * n);
    energy.reserve(n);
    L_space.reserve(3 * n);
  }
  void add(const RigidBody& body, const Vec3& g, const State& s) {
    t.push_back(s.t);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) R.push_back(s.R(i, j));
    const Quat q = s.quaternion();
    quaternion.insert(quaternion.end(), {q.w(), q.x(), q.y(), q.z()});
    omega_body.insert(omega_body.end(), {s.omega_body[0], s.omega_body[1], s.omega_body[2]});
    energy.push_back(dynamics::total_energy(body, s, g));
    const Vec3 L = dynamics::angular_momentum_space(body, s);
    L_space.insert(L_space.end(), {L[0], L[1], L[2]});
  }
};

}  // namespace

py::dict run_simulation(const RigidBody& body, const State& initial, const py::object& torque_obj,
                        const std::string& method, const dynamics::IntegratorOptions& integrator_options,
                        const dynamics::SimulationOptions& simulation_options, bool keep_samples) {
  std::shared_ptr<const TorqueModel> torque = as_torque(torque_obj);
  auto integrator = dynamics::make_integrator(method, body, torque, integrator_options);
  const Vec3 g = torque->gravity_space();
  Samples samples;
  if (keep_samples && simulation_options.sample_dt > 0.0 &&
      simulation_options.t_end > initial.t) {
    const double n = std::ceil((simulation_options.t_end - initial.t) / simulation_options.sample_dt) + 2.0;
    if (n < 1e8) samples.reserve(static_cast<std::size_t>(n));
  }
  dynamics::Observer observer;
  if (keep_samples) {
    observer = [&](const State& s) {
      samples.add(body, g, s);
      return true;
    };
  }
  dynamics::SimulationResult result;
  {
    // The C++ loop runs without the GIL; a Python torque callback takes it back for each call, and a Python
    // exception raised there travels up as py::error_already_set and is re-raised as itself.
    py::gil_scoped_release release;
    result = dynamics::simulate(body, torque, initial, *integrator, simulation_options, observer);
  }
  const auto n = static_cast<py::ssize_t>(samples.t.size());
  py::dict out;
  out["t"] = array_from_buffer(std::move(samples.t), {n});
  out["R"] = array_from_buffer(std::move(samples.R), {n, 3, 3});
  out["quaternion"] = array_from_buffer(std::move(samples.quaternion), {n, 4});
  out["omega_body"] = array_from_buffer(std::move(samples.omega_body), {n, 3});
  out["energy"] = array_from_buffer(std::move(samples.energy), {n});
  out["L_space"] = array_from_buffer(std::move(samples.L_space), {n, 3});
  out["final_state"] = result.final_state;
  out["steps"] = result.steps;
  out["rejected_steps"] = result.rejected_steps;
  py::dict errors;
  errors["energy_rel_max"] = result.errors.energy_rel_max;
  errors["L_space_rel_max"] = result.errors.L_space_rel_max;
  errors["L_norm_rel_max"] = result.errors.L_norm_rel_max;
  errors["orthogonality_max"] = result.errors.orthogonality_max;
  out["errors"] = errors;
  out["flip_times"] = py::array_t<double>(static_cast<py::ssize_t>(result.flip_times.size()),
                                          result.flip_times.data());
  out["wall_time_s"] = result.wall_time_s;
  out["interrupted"] = result.interrupted;
  out["method"] = std::string(integrator->name());
  out["torque"] = torque->describe();
  out["torque_is_zero"] = torque->is_zero();
  return out;
}

void bind_simulate(py::module_& m) {
  m.def(
      "_simulate",
      [](const RigidBody& body, const State& initial, const py::object& torque, const std::string& method,
         double dt, double rtol, double atol, double newton_tolerance, int newton_max_iterations, double t_end,
         double sample_dt, bool locate_flips, bool keep_samples) {
        dynamics::IntegratorOptions io;
        io.dt = dt;
        io.rtol = rtol;
        io.atol = atol;
        io.newton_tolerance = newton_tolerance;
        io.newton_max_iterations = newton_max_iterations;
        dynamics::SimulationOptions so;
        so.t_end = t_end;
        so.sample_dt = sample_dt;
        so.locate_flips = locate_flips;
        return run_simulation(body, initial, torque, method, io, so, keep_samples);
      },
      py::arg("body"), py::arg("initial"), py::arg("torque"), py::arg("method"), py::arg("dt"), py::arg("rtol"),
      py::arg("atol"), py::arg("newton_tolerance"), py::arg("newton_max_iterations"), py::arg("t_end"),
      py::arg("sample_dt"), py::arg("locate_flips"), py::arg("keep_samples") = true,
      "Low-level driver of poinsot.simulate (use that): returns a dict of NumPy arrays and the run's summary.");

  const dynamics::IntegratorOptions io;
  const dynamics::SimulationOptions so;
  auto defaults = py::dict();
  defaults["dt"] = io.dt;
  defaults["rtol"] = io.rtol;
  defaults["atol"] = io.atol;
  defaults["newton_tolerance"] = io.newton_tolerance;
  defaults["newton_max_iterations"] = io.newton_max_iterations;
  defaults["t_end"] = so.t_end;
  defaults["sample_dt"] = so.sample_dt;
  defaults["locate_flips"] = so.locate_flips;
  m.attr("_simulation_defaults") = defaults;
  m.attr("_doc_simulate") = POINSOT_DOC(dynamics_simulate);
  m.attr("_doc_simulation") = POINSOT_DOC(file_dynamics_simulation);
  m.attr("_doc_integrators") = POINSOT_DOC(file_dynamics_integrator);
}

}  // namespace poinsot::python
