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
#include "poinsot/dynamics/exact_free_body.hpp"
#include "poinsot/dynamics/free_body_theory.hpp"
#include "poinsot/dynamics/integrator.hpp"
#include "poinsot/dynamics/methods.hpp"
#include "poinsot/dynamics/rigid_body.hpp"
#include "poinsot/dynamics/simulation.hpp"
#include "poinsot/dynamics/state.hpp"
#include "poinsot/dynamics/top_theory.hpp"

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
    t.push_back(s.time);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        R.push_back(s.R_space_body(i, j));
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
  if (keep_samples && simulation_options.sample_dt > 0.0 && simulation_options.t_end > initial.time) {
    const double n =
        std::ceil((simulation_options.t_end - initial.time) / simulation_options.sample_dt) + 2.0;
    if (n < 1e8) samples.reserve(static_cast<std::size_t>(n));
  }
  // The observer keeps the samples (when asked) and, about ten times a second, takes the GIL to let Python
  // handle a pending signal: Ctrl-C stops the run (the driver marks it interrupted) and raises
  // KeyboardInterrupt here, as a long computation in Python would.
  bool signalled = false;
  auto last_check = std::chrono::steady_clock::now();
  const dynamics::Observer observer = [&](const State& s) {
    if (keep_samples) samples.add(body, g, s);
    const auto now = std::chrono::steady_clock::now();
    if (now - last_check > std::chrono::milliseconds(100)) {
      last_check = now;
      py::gil_scoped_acquire gil;
      if (PyErr_CheckSignals() != 0) {
        signalled = true;
        return false;
      }
    }
    return true;
  };
  dynamics::SimulationResult result;
  {
    // The C++ loop runs without the GIL; a Python torque callback takes it back for each call, and a Python
    // exception raised there travels up as py::error_already_set and is re-raised as itself.
    py::gil_scoped_release release;
    result = dynamics::simulate(body, torque, initial, *integrator, simulation_options, observer);
  }
  if (signalled)
    throw py::error_already_set();  // the exception set by the signal handler (KeyboardInterrupt)
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
  out["flip_times"] =
      py::array_t<double>(static_cast<py::ssize_t>(result.flip_times.size()), result.flip_times.data());
  out["wall_time_s"] = result.wall_time_s;
  out["interrupted"] = result.interrupted;
  out["method"] = std::string(integrator->name());
  out["torque"] = torque->describe();
  out["torque_is_zero"] = torque->is_zero();
  return out;
}

namespace {

/// The torque-free body in closed form: its theory (FreeBodyTheory) and its exact motion (ExactFreeBody).
void bind_free_body_closed_forms(py::module_& m) {
  using dynamics::ExactFreeBody;
  using dynamics::FreeBodyTheory;
  py::class_<FreeBodyTheory>(m, "FreeBodyTheory", POINSOT_DOC(file_dynamics_free_body_theory))
      .def_property_readonly(
          "moments", [](const FreeBodyTheory& t) { return from_vec3(t.moments); },
          POINSOT_DOC(dynamics_FreeBodyTheory_moments))
      .def_property_readonly(
          "omega", [](const FreeBodyTheory& t) { return from_vec3(t.omega); },
          POINSOT_DOC(dynamics_FreeBodyTheory_omega))
      .def_readonly("energy", &FreeBodyTheory::energy, POINSOT_DOC(dynamics_FreeBodyTheory_energy))
      .def_readonly("momentum", &FreeBodyTheory::momentum, POINSOT_DOC(dynamics_FreeBodyTheory_momentum))
      .def_readonly("separatrix_gap", &FreeBodyTheory::separatrix_gap,
                    POINSOT_DOC(dynamics_FreeBodyTheory_separatrix_gap))
      .def_property_readonly(
          "regime", [](const FreeBodyTheory& t) { return std::string(dynamics::to_string(t.regime)); },
          POINSOT_DOC(dynamics_to_string))
      .def_readonly("modulus", &FreeBodyTheory::modulus, POINSOT_DOC(dynamics_FreeBodyTheory_modulus))
      .def_readonly("modulus_complement2", &FreeBodyTheory::modulus_complement2,
                    POINSOT_DOC(dynamics_FreeBodyTheory_modulus_complement2))
      .def_readonly("omega_p", &FreeBodyTheory::omega_p, POINSOT_DOC(dynamics_FreeBodyTheory_omega_p))
      .def_readonly("quarter_period", &FreeBodyTheory::quarter_period,
                    POINSOT_DOC(dynamics_FreeBodyTheory_quarter_period))
      .def_property_readonly("flip_interval", &FreeBodyTheory::flip_interval,
                             POINSOT_DOC(dynamics_FreeBodyTheory_flip_interval))
      .def_property_readonly("omega_period", &FreeBodyTheory::omega_period,
                             POINSOT_DOC(dynamics_FreeBodyTheory_omega_period))
      .def("__repr__", [](const FreeBodyTheory& t) {
        return std::string("FreeBodyTheory(regime=") + dynamics::to_string(t.regime) +
               ", k=" + std::to_string(t.modulus) + ", omega_p=" + std::to_string(t.omega_p) +
               " rad/s, flip_interval=" + std::to_string(t.flip_interval()) + " s)";
      });
  m.def(
      "free_body_theory",
      [](const py::object& body_or_moments, ArrayLike omega) {
        if (py::isinstance<RigidBody>(body_or_moments))
          return dynamics::free_body_theory(body_or_moments.cast<const RigidBody&>(),
                                            to_vec3(omega, "omega_body"));
        return dynamics::free_body_theory(to_vec3(body_or_moments, "principal_moments"),
                                          to_vec3(omega, "omega_principal"));
      },
      py::arg("body"), py::arg("omega_body"),
      (std::string(
           "The closed-form theory of the torque-free motion for a poinsot.RigidBody and ω in its body "
           "frame (rad/s), or for principal moments (ascending, kg·m²) and ω in the principal frame.\n\n") +
       POINSOT_DOC(dynamics_free_body_theory_2) + "\n\n" + POINSOT_DOC(file_dynamics_free_body_theory))
          .c_str());

  py::class_<ExactFreeBody>(m, "ExactFreeBody", POINSOT_DOC(file_dynamics_exact_free_body))
      .def(
          py::init([](const RigidBody& body, const State& initial, const std::string& method) {
            if (method != "automatic" && method != "elliptic")
              throw py::value_error("method: got \"" + method + "\", expected \"automatic\" or \"elliptic\"");
            return ExactFreeBody(
                body, initial,
                method == "elliptic" ? dynamics::ExactMethod::elliptic : dynamics::ExactMethod::automatic);
          }),
          py::arg("body"), py::arg("initial"), py::arg("method") = "automatic",
          POINSOT_DOC(dynamics_ExactFreeBody_ExactFreeBody))
      .def("state_at", &ExactFreeBody::state_at, py::arg("t"), POINSOT_DOC(dynamics_ExactFreeBody_state_at))
      .def(
          "states_at",
          [](const ExactFreeBody& e, ArrayLike t_obj) {
            auto t = to_float_array(t_obj.obj, "t", {-1});
            const py::ssize_t n = t.shape(0);
            std::vector<double> R(static_cast<std::size_t>(9 * n)), w(static_cast<std::size_t>(3 * n));
            {
              py::gil_scoped_release release;
              for (py::ssize_t i = 0; i < n; ++i) {
                const State s = e.state_at(t.data()[i]);
                for (int a = 0; a < 3; ++a) {
                  for (int b = 0; b < 3; ++b)
                    R[static_cast<std::size_t>(9 * i + 3 * a + b)] = s.R_space_body(a, b);
                  w[static_cast<std::size_t>(3 * i + a)] = s.omega_body[a];
                }
              }
            }
            return py::make_tuple(array_from_buffer(std::move(R), {n, 3, 3}),
                                  array_from_buffer(std::move(w), {n, 3}));
          },
          py::arg("t"), "The closed-form (R (n, 3, 3), omega_body (n, 3)) at the times t (n,) (s).")
      .def_property_readonly("theory", &ExactFreeBody::theory, POINSOT_DOC(dynamics_ExactFreeBody_theory))
      .def_property_readonly("omega_period", &ExactFreeBody::omega_period,
                             POINSOT_DOC(dynamics_ExactFreeBody_omega_period))
      .def_property_readonly("flip_interval", &ExactFreeBody::flip_interval,
                             POINSOT_DOC(dynamics_ExactFreeBody_flip_interval));
  m.def(
      "axisymmetric_free_motion",
      [](double A, double C, ArrayLike axis, const State& initial, double t) {
        return dynamics::axisymmetric_free_motion(A, C, to_vec3(axis, "axis_body"), initial, t);
      },
      py::arg("A"), py::arg("C"), py::arg("axis_body"), py::arg("initial"), py::arg("t"),
      POINSOT_DOC(dynamics_axisymmetric_free_motion));
}

/// The heavy symmetric top (top_theory.hpp).
void bind_heavy_top(py::module_& m) {
  using dynamics::HeavyTop;
  py::class_<HeavyTop>(m, "HeavyTop", POINSOT_DOC(dynamics_HeavyTop))
      .def(py::init([](double I1, double I3, double mass, double length, double gravity) {
             HeavyTop t{I1, I3, mass, length, gravity};
             dynamics::validate(t);
             return t;
           }),
           py::arg("I1"), py::arg("I3"), py::arg("mass"), py::arg("length"), py::arg("gravity") = 9.81,
           POINSOT_DOC(dynamics_validate))
      .def_readonly("I1", &HeavyTop::I1, POINSOT_DOC(dynamics_HeavyTop_I1))
      .def_readonly("I3", &HeavyTop::I3, POINSOT_DOC(dynamics_HeavyTop_I3))
      .def_readonly("mass", &HeavyTop::mass, POINSOT_DOC(dynamics_HeavyTop_mass))
      .def_readonly("length", &HeavyTop::length, POINSOT_DOC(dynamics_HeavyTop_length))
      .def_readonly("gravity", &HeavyTop::gravity, POINSOT_DOC(dynamics_HeavyTop_gravity))
      .def_property_readonly("mgl", &HeavyTop::mgl, POINSOT_DOC(dynamics_HeavyTop_mgl))
      .def("__repr__", [](const HeavyTop& t) {
        return "HeavyTop(I1=" + std::to_string(t.I1) + " kg·m², I3=" + std::to_string(t.I3) +
               " kg·m², mass=" + std::to_string(t.mass) + " kg, length=" + std::to_string(t.length) +
               " m, gravity=" + std::to_string(t.gravity) + " m/s²)";
      });
  m.attr("_doc_top_theory") = POINSOT_DOC(file_dynamics_top_theory);
  m.def("fast_top_precession_rate", &dynamics::fast_top_precession_rate, py::arg("top"), py::arg("omega3"),
        POINSOT_DOC(dynamics_fast_top_precession_rate));
  m.def(
      "steady_precession_rates",
      [](const HeavyTop& top, double theta, double omega3) {
        const auto r = dynamics::steady_precession_rates(top, theta, omega3);
        py::dict d;
        d["count"] = r.count;
        d["slow"] = r.slow;
        d["fast"] = r.fast;
        return d;
      },
      py::arg("top"), py::arg("theta"), py::arg("omega3"),
      (std::string(POINSOT_DOC(dynamics_SteadyPrecession)) + "\n\nReturns a dict: count, slow, fast (rad/s).")
          .c_str());
  m.def("sleeping_top_threshold", &dynamics::sleeping_top_threshold, py::arg("top"),
        POINSOT_DOC(dynamics_sleeping_top_threshold));
  m.def("is_sleeping_top_stable", &dynamics::is_sleeping_top_stable, py::arg("top"), py::arg("omega3"),
        POINSOT_DOC(dynamics_sleeping_top_threshold));
  m.def(
      "top_motion",
      [](const HeavyTop& top, double theta0, double theta_dot0, double phi_dot0, double omega3) {
        const auto t = dynamics::top_motion(top, theta0, theta_dot0, phi_dot0, omega3);
        py::dict d;
        d["u1"] = t.u1;
        d["u2"] = t.u2;
        d["u3"] = t.u3;
        d["theta_min"] = t.theta_min;
        d["theta_max"] = t.theta_max;
        d["nutation_period"] = t.nutation_period;
        d["nutation_frequency"] = t.nutation_frequency;
        d["precession_per_nutation"] = t.precession_per_nutation;
        d["mean_precession_rate"] = t.mean_precession_rate;
        return d;
      },
      py::arg("top"), py::arg("theta0"), py::arg("theta_dot0"), py::arg("phi_dot0"), py::arg("omega3"),
      (std::string(POINSOT_DOC(dynamics_top_motion)) +
       "\n\nReturns a dict with the fields of TopMotion: u1, u2, u3, theta_min, theta_max (rad), "
       "nutation_period "
       "(s), nutation_frequency (rad/s), precession_per_nutation (rad), mean_precession_rate (rad/s).\n\n" +
       POINSOT_DOC(file_dynamics_top_theory))
          .c_str());
  m.def(
      "heavy_top_from",
      [](const RigidBody& body, ArrayLike g) {
        return dynamics::heavy_top_from(body, to_vec3(g, "gravity_space"));
      },
      py::arg("body"), py::arg("gravity_space"), POINSOT_DOC(dynamics_heavy_top_from));
  m.def(
      "top_initial_conditions",
      [](const RigidBody& body, const State& s, ArrayLike g) {
        const auto c = dynamics::top_initial_conditions(body, s, to_vec3(g, "gravity_space"));
        py::dict d;
        d["theta"] = c.theta;
        d["theta_dot"] = c.theta_dot;
        d["phi_dot"] = c.phi_dot;
        d["omega3"] = c.omega3;
        return d;
      },
      py::arg("body"), py::arg("state"), py::arg("gravity_space"),
      (std::string(POINSOT_DOC(dynamics_TopInitialConditions)) +
       "\n\nReturns a dict: theta (rad), theta_dot, phi_dot, omega3 (rad/s).")
          .c_str());
}

/// The integrators as Python objects (Integrator).
void bind_integrator_class(py::module_& m) {
  using dynamics::Integrator;
  py::class_<Integrator>(m, "Integrator", POINSOT_DOC(file_dynamics_integrator))
      .def_property_readonly(
          "name", [](const Integrator& i) { return std::string(i.name()); },
          POINSOT_DOC(dynamics_Integrator_name))
      .def_property_readonly("order", &Integrator::order, POINSOT_DOC(dynamics_Integrator_order))
      .def_property_readonly("is_adaptive", &Integrator::is_adaptive)
      .def_property_readonly("has_dense_output", &Integrator::has_dense_output)
      .def(
          "step",
          [](Integrator& i, State& s, double dt) {
            const auto r = i.step(s, dt);
            py::dict d;
            d["dt_taken"] = r.dt_taken;
            d["dt_next"] = r.dt_next;
            d["rejected"] = r.rejected;
            return d;
          },
          py::arg("state"), py::arg("dt"),
          (std::string(POINSOT_DOC(dynamics_Integrator_step)) +
           "\n\nAdvances `state` in place; returns a dict: dt_taken (s), dt_next (s), rejected.")
              .c_str())
      .def(
          "advance",
          [](Integrator& i, State& s, double dt, long long n) {
            const auto r = i.advance(s, dt, n);
            py::dict d;
            d["dt_taken"] = r.dt_taken;
            d["dt_next"] = r.dt_next;
            d["rejected"] = r.rejected;
            return d;
          },
          py::arg("state"), py::arg("dt"), py::arg("n"),
          (std::string(POINSOT_DOC(dynamics_Integrator_advance)) +
           "\n\nAdvances `state` in place; returns a dict: dt_taken (s), dt_next (s), rejected (summed).")
              .c_str())
      .def("dense_output", &Integrator::dense_output, py::arg("t"),
           POINSOT_DOC(dynamics_Integrator_dense_output))
      .def(
          "last_multiplier",
          [](const Integrator& i) -> py::object {
            Mat3 L;
            if (!i.last_multiplier(L)) return py::none();
            return from_mat3(L);
          },
          (std::string(POINSOT_DOC(dynamics_Integrator_last_multiplier)) +
           "\n\nReturns None when there is none.")
              .c_str());
  m.def(
      "make_integrator",
      [](const std::string& name, const RigidBody& body, const py::object& torque, double dt, double max_step,
         double rtol, double atol, double newton_tolerance, int newton_max_iterations) {
        dynamics::IntegratorOptions o;
        o.dt = dt;
        o.max_step = max_step;
        o.rtol = rtol;
        o.atol = atol;
        o.newton_tolerance = newton_tolerance;
        o.newton_max_iterations = newton_max_iterations;
        return dynamics::make_integrator(name, body, as_torque(torque), o);
      },
      py::arg("name"), py::arg("body"), py::arg("torque") = py::none(), py::kw_only(),
      py::arg("dt") = dynamics::IntegratorOptions{}.dt,
      py::arg("max_step") = dynamics::IntegratorOptions{}.max_step,
      py::arg("rtol") = dynamics::IntegratorOptions{}.rtol,
      py::arg("atol") = dynamics::IntegratorOptions{}.atol,
      py::arg("newton_tolerance") = dynamics::IntegratorOptions{}.newton_tolerance,
      py::arg("newton_max_iterations") = dynamics::IntegratorOptions{}.newton_max_iterations,
      py::keep_alive<0, 2>(), POINSOT_DOC(dynamics_make_integrator));
}

void bind_exact(py::module_& m) {
  bind_free_body_closed_forms(m);
  bind_heavy_top(m);
  bind_integrator_class(m);
}

/// poinsot.MethodInfo and poinsot.METHODS (name → entry, the registry's order), DEFAULT_METHOD and
/// DEFAULT_LAMBDA_METHOD: the registry of methods.hpp.
void bind_simulation_methods(py::module_& m) {
  using dynamics::MethodInfo;
  py::class_<MethodInfo>(m, "MethodInfo", POINSOT_DOC(dynamics_MethodInfo))
      .def_property_readonly(
          "name", [](const MethodInfo& i) { return std::string(i.name); },
          POINSOT_DOC(dynamics_MethodInfo_name))
      .def_readonly("order", &MethodInfo::order, POINSOT_DOC(dynamics_MethodInfo_order))
      .def_readonly("adaptive", &MethodInfo::adaptive, POINSOT_DOC(dynamics_MethodInfo_adaptive))
      .def_readonly("dense_output", &MethodInfo::dense_output, "Offers dense output inside its last step.")
      .def_readonly("takes_torque", &MethodInfo::takes_torque, POINSOT_DOC(dynamics_MethodInfo_takes_torque))
      .def_readonly("symplectic", &MethodInfo::symplectic, POINSOT_DOC(dynamics_MethodInfo_symplectic))
      .def_property_readonly(
          "preserves",
          [](const MethodInfo& i) {
            std::vector<std::string> out;
            if (i.preserves.energy) out.emplace_back("energy");
            if (i.preserves.L_space) out.emplace_back("L_space");
            if (i.preserves.L_body_norm) out.emplace_back("L_body_norm");
            if (i.preserves.orthogonality) out.emplace_back("orthogonality");
            return out;
          },
          (std::string(
               "The invariants kept to round-off, among energy, L_space, L_body_norm, orthogonality. ") +
           POINSOT_DOC(dynamics_Preserved))
              .c_str())
      .def_property_readonly(
          "description", [](const MethodInfo& i) { return std::string(i.description); },
          POINSOT_DOC(dynamics_MethodInfo_description))
      .def("__repr__", [](const MethodInfo& i) {
        return "MethodInfo(" + std::string(i.name) + ", order " + std::to_string(i.order) + ")";
      });
  py::dict methods;
  for (const MethodInfo& i : dynamics::methods())
    methods[py::str(std::string(i.name))] = py::cast(&i, py::return_value_policy::reference);
  m.attr("METHODS") = methods;
  m.attr("DEFAULT_METHOD") = std::string(dynamics::kDefaultMethod);
  m.attr("DEFAULT_LAMBDA_METHOD") = std::string(dynamics::kDefaultLambdaMethod);
}

}  // namespace

void bind_simulate(py::module_& m) {
  bind_exact(m);
  bind_simulation_methods(m);
  m.def(
      "_simulate",
      [](const RigidBody& body, const State& initial, const py::object& torque, const std::string& method,
         double dt, double max_step, double rtol, double atol, double newton_tolerance,
         int newton_max_iterations, double t_end, double sample_dt, bool locate_flips, bool keep_samples) {
        dynamics::IntegratorOptions io;
        io.dt = dt;
        io.max_step = max_step;
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
      py::arg("body"), py::arg("initial"), py::arg("torque"), py::arg("method"), py::arg("dt"),
      py::arg("max_step"), py::arg("rtol"), py::arg("atol"), py::arg("newton_tolerance"),
      py::arg("newton_max_iterations"), py::arg("t_end"), py::arg("sample_dt"), py::arg("locate_flips"),
      py::arg("keep_samples") = true,
      "Low-level driver of poinsot.simulate (use that): returns a dict of NumPy arrays and the run's "
      "summary.");

  const dynamics::IntegratorOptions io;
  const dynamics::SimulationOptions so;
  auto defaults = py::dict();
  defaults["dt"] = io.dt;
  defaults["max_step"] = io.max_step;
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
