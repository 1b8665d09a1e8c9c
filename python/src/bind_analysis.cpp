// Bindings of the analysis layer as poinsot.analysis: the multipliers Λ (from the state, in closed form,
// along a whole sampled trajectory), the axisymmetric closed form of the paper, the constraint stress and the
// property tracker. Docstrings from the headers.
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "convert.hpp"
#include "docstrings.hpp"
#include "poinsot/analysis/axisymmetric.hpp"
#include "poinsot/analysis/closed_form.hpp"
#include "poinsot/analysis/lambda_report.hpp"
#include "poinsot/analysis/lambda_tracker.hpp"
#include "poinsot/analysis/multipliers.hpp"
#include "poinsot/analysis/stress.hpp"
#include "poinsot/io/run/lambda_json.hpp"

namespace poinsot::python {

using dynamics::RigidBody;
using dynamics::State;

namespace {

/// The JSON text of io/run/lambda_json.hpp as Python objects: the same keys and values as `poinsot lambda
/// --json`.
py::dict from_json(const std::string& text) {
  return py::module_::import("json").attr("loads")(text).cast<py::dict>();
}

analysis::ClosedForm closed_form_of(const std::string& name) {
  if (name == "property2" || name == "3.7") return analysis::ClosedForm::property2;
  if (name == "eq38" || name == "3.8") return analysis::ClosedForm::eq38;
  if (name == "symmetric") return analysis::ClosedForm::symmetric;
  throw py::value_error("form: got \"" + name +
                        "\", expected \"property2\" (eq. 3.7), \"eq38\" (eq. 3.8) or "
                        "\"symmetric\"");
}

/// Views of a sampled trajectory: t (n,), R (n, 3, 3), omega_body (n, 3), checked for matching n.
struct Trajectory {
  py::array_t<double, py::array::c_style | py::array::forcecast> t, R, w;
  py::ssize_t n = 0;
  Trajectory(const py::handle& t_obj, const py::handle& R_obj, const py::handle& w_obj) {
    t = to_float_array(t_obj, "t", {-1});
    n = t.shape(0);
    R = to_float_array(R_obj, "R", {n, 3, 3});
    w = to_float_array(w_obj, "omega_body", {n, 3});
  }
  State state(py::ssize_t i) const {
    State s;
    s.time = t.data()[i];
    const double* r = R.data() + 9 * i;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        s.R_space_body(a, b) = r[3 * a + b];
    const double* p = w.data() + 3 * i;
    s.omega_body = Vec3(p[0], p[1], p[2]);
    return s;
  }
};

/// The orthogonality multiplier Λ of one body and its pieces.
void bind_body_multipliers(py::module_& m) {
  m.def(
      "angular_acceleration_body",
      [](const RigidBody& body, const State& s, const py::object& torque) {
        const auto tm = as_torque(torque);
        return from_vec3(analysis::angular_acceleration_body(body, s, tm.get()));
      },
      py::arg("body"), py::arg("state"), py::arg("torque") = py::none(),
      POINSOT_DOC(analysis_angular_acceleration_body));
  m.def(
      "lambda_from_omega",
      [](const RigidBody& body, ArrayLike w, ArrayLike wdot) {
        return from_mat3(
            analysis::lambda_from_omega(body, to_vec3(w, "omega_body"), to_vec3(wdot, "omega_dot_body")));
      },
      py::arg("body"), py::arg("omega_body"), py::arg("omega_dot_body"),
      POINSOT_DOC(analysis_lambda_from_omega));
  m.def(
      "lambda_from_state",
      [](const RigidBody& body, const State& s, const py::object& torque) {
        const auto tm = as_torque(torque);
        return from_mat3(analysis::lambda_from_state(body, s, tm.get()));
      },
      py::arg("body"), py::arg("state"), py::arg("torque") = py::none(),
      POINSOT_DOC(analysis_lambda_from_state));
  m.def(
      "lambda_trajectory",
      [](const RigidBody& body, ArrayLike t, ArrayLike R, ArrayLike w, const py::object& torque) {
        const Trajectory tr(t.obj, R.obj, w.obj);
        const auto tm = as_torque(torque);
        std::vector<double> out;
        out.reserve(static_cast<std::size_t>(9 * tr.n));
        for (py::ssize_t i = 0; i < tr.n; ++i) {
          const Mat3 L = analysis::lambda_from_state(body, tr.state(i), tm.get());
          for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
              out.push_back(L(a, b));
        }
        return array_from_buffer(std::move(out), {tr.n, 3, 3});
      },
      py::arg("body"), py::arg("t"), py::arg("R"), py::arg("omega_body"), py::arg("torque") = py::none(),
      (std::string("Λ (n, 3, 3) (J, body frame) at every sample of a trajectory (t (n,), R (n, 3, 3), "
                   "omega_body (n, 3), e.g. the arrays of a poinsot.SimulationResult), by "
                   "lambda_from_state:\n\n") +
       POINSOT_DOC(analysis_lambda_from_state))
          .c_str());
  m.def(
      "lambda_closed_form",
      [](ArrayLike J, ArrayLike w, const std::string& form) {
        return from_mat3(
            analysis::lambda_closed_form(to_mat3(J, "J"), to_vec3(w, "omega_body"), closed_form_of(form)));
      },
      py::arg("J"), py::arg("omega_body"), py::arg("form") = "property2",
      (std::string(POINSOT_DOC(analysis_lambda_closed_form)) +
       "\n\nform: \"property2\" (eq. 3.7), \"eq38\" (eq. 3.8) or \"symmetric\".\n\n" +
       POINSOT_DOC(file_analysis_closed_form))
          .c_str());
  m.def(
      "symmetry_error",
      [](ArrayLike L, ArrayLike tau) {
        return analysis::symmetry_error(to_mat3(L, "lambda_body"), to_vec3(tau, "torque_body"));
      },
      py::arg("lambda_body"), py::arg("torque_body") = py::make_tuple(0.0, 0.0, 0.0),
      POINSOT_DOC(analysis_symmetry_error));
  m.def(
      "sorted_eigenvalues",
      [](ArrayLike L) { return from_vec3(analysis::sorted_eigenvalues(to_mat3(L, "lambda_body"))); },
      py::arg("lambda_body"), POINSOT_DOC(analysis_sorted_eigenvalues));
}

/// The constraint stress: ∫σ dv and its principal values.
void bind_stress(py::module_& m) {
  m.def(
      "stress_integral_space",
      [](const RigidBody& body, const State& s, const py::object& torque) {
        const auto tm = as_torque(torque);
        return from_mat3(analysis::stress_integral_space(body, s, tm.get()));
      },
      py::arg("body"), py::arg("state"), py::arg("torque") = py::none(),
      (std::string(POINSOT_DOC(analysis_stress_integral_space_2)) + "\n\n" +
       POINSOT_DOC(file_analysis_stress))
          .c_str());
  m.def(
      "stress_integral_from_lambda",
      [](ArrayLike L, ArrayLike R) {
        return from_mat3(analysis::stress_integral_space(to_mat3(L, "lambda_body"), to_mat3(R, "R")));
      },
      py::arg("lambda_body"), py::arg("R"), POINSOT_DOC(analysis_stress_integral_space));
  m.def(
      "steady_spin_stress_integral_body",
      [](ArrayLike K, ArrayLike k, double rate) {
        return from_mat3(
            analysis::steady_spin_stress_integral_body(to_mat3(K, "poinsot_K"), to_vec3(k, "k_body"), rate));
      },
      py::arg("poinsot_K"), py::arg("k_body"), py::arg("rate"),
      POINSOT_DOC(analysis_steady_spin_stress_integral_body));
  m.def(
      "summarize_stress",
      [](ArrayLike T) {
        return from_json(io::stress_summary_json(analysis::summarize_stress(to_mat3(T, "tensor"))));
      },
      py::arg("tensor"),
      (std::string(POINSOT_DOC(analysis_StressSummary)) +
       "\n\nReturns a dict (io/run/lambda_json.hpp): tensor, principal (ascending), principal_axes "
       "(columns), "
       "tresca, von_mises, trace; arrays as lists.")
          .c_str());
  m.def(
      "constraint_stress",
      [](ArrayLike L, ArrayLike R, double volume) {
        return from_json(io::constraint_stress_json(
            analysis::constraint_stress(to_mat3(L, "lambda_body"), to_mat3(R, "R"), volume)));
      },
      py::arg("lambda_body"), py::arg("R"), py::arg("volume_m3") = 0.0,
      (std::string(POINSOT_DOC(analysis_constraint_stress)) +
       "\n\nReturns a dict: integral (N·m) and mean (Pa, None without a volume), each as summarize_stress.")
          .c_str());
}

/// The axisymmetric closed form of Λ.
void bind_axisymmetric_lambda(py::module_& m) {
  py::class_<analysis::AxisymmetricInertia>(m, "AxisymmetricInertia",
                                            POINSOT_DOC(analysis_AxisymmetricInertia))
      .def(py::init([](double A, double C, ArrayLike k) {
             analysis::AxisymmetricInertia a;
             a.A = A;
             a.C = C;
             a.k = to_vec3(k, "k");
             return a;
           }),
           py::arg("A"), py::arg("C"), py::arg("k") = py::make_tuple(0.0, 0.0, 1.0))
      .def_readonly("A", &analysis::AxisymmetricInertia::A)
      .def_readonly("C", &analysis::AxisymmetricInertia::C)
      .def_property_readonly("k", [](const analysis::AxisymmetricInertia& a) { return from_vec3(a.k); })
      .def(
          "inertia", [](const analysis::AxisymmetricInertia& a) { return from_mat3(a.inertia()); },
          POINSOT_DOC(analysis_AxisymmetricInertia_inertia))
      .def("__repr__", [](const analysis::AxisymmetricInertia& a) {
        return "AxisymmetricInertia(A=" + std::to_string(a.A) + ", C=" + std::to_string(a.C) + ")";
      });
  m.def("detect_axisymmetry", &analysis::detect_axisymmetry, py::arg("body"),
        py::arg("relative_tolerance") = 1e-12, POINSOT_DOC(analysis_detect_axisymmetry));

  using AL = analysis::AxisymmetricLambda;
  py::class_<AL>(m, "AxisymmetricLambda", POINSOT_DOC(file_analysis_axisymmetric))
      .def(py::init([](const analysis::AxisymmetricInertia& in, ArrayLike w, double t0, double tol) {
             return AL(in, to_vec3(w, "omega0_body"), t0, tol);
           }),
           py::arg("inertia"), py::arg("omega0_body"), py::arg("t0") = 0.0,
           py::arg("relative_tolerance") = 1e-12, POINSOT_DOC(analysis_AxisymmetricLambda_AxisymmetricLambda))
      .def_property_readonly("mu", &AL::mu, POINSOT_DOC(analysis_AxisymmetricLambda_mu))
      .def_property_readonly("eta0", &AL::eta0, POINSOT_DOC(analysis_AxisymmetricLambda_eta0))
      .def_property_readonly("r", &AL::r, POINSOT_DOC(analysis_AxisymmetricLambda_r))
      .def_property_readonly(
          "n", [](const AL& a) { return from_vec3(a.n()); }, POINSOT_DOC(analysis_AxisymmetricLambda_n))
      .def_property_readonly("c1", &AL::c1, POINSOT_DOC(analysis_AxisymmetricLambda_c1))
      .def_property_readonly("c2", &AL::c2, POINSOT_DOC(analysis_AxisymmetricLambda_c2))
      .def_property_readonly("Delta", &AL::Delta, POINSOT_DOC(analysis_AxisymmetricLambda_Delta))
      .def_property_readonly("lambda1", &AL::lambda1, POINSOT_DOC(analysis_AxisymmetricLambda_lambda1))
      .def_property_readonly("lambda2", &AL::lambda2, POINSOT_DOC(analysis_AxisymmetricLambda_lambda2))
      .def_property_readonly("lambda3", &AL::lambda3, POINSOT_DOC(analysis_AxisymmetricLambda_lambda3))
      .def(
          "eigenvalues", [](const AL& a) { return from_vec3(a.eigenvalues_sorted()); },
          POINSOT_DOC(analysis_AxisymmetricLambda_eigenvalues_sorted))
      .def_property_readonly(
          "special_cases", [](const AL& a) { return from_json(io::special_cases_json(a.special_cases())); },
          POINSOT_DOC(analysis_AxisymmetricSpecialCases))
      .def_property_readonly("precession_rate", &AL::precession_rate,
                             POINSOT_DOC(analysis_AxisymmetricLambda_precession_rate))
      .def(
          "E", [](const AL& a, double t) { return from_mat3(a.E(t)); }, py::arg("t"),
          POINSOT_DOC(analysis_AxisymmetricLambda_E))
      .def(
          "omega", [](const AL& a, double t) { return from_vec3(a.omega(t)); }, py::arg("t"),
          POINSOT_DOC(analysis_AxisymmetricLambda_omega))
      .def(
          "lambda3_eigenvector", [](const AL& a, double t) { return from_vec3(a.lambda3_eigenvector(t)); },
          py::arg("t"), POINSOT_DOC(analysis_AxisymmetricLambda_lambda3_eigenvector))
      .def(
          "constant_matrix", [](const AL& a) { return from_mat3(a.constant_matrix_53()); },
          POINSOT_DOC(analysis_AxisymmetricLambda_constant_matrix_53))
      .def(
          "lambda_at", [](const AL& a, double t) { return from_mat3(a.lambda_at(t)); }, py::arg("t"),
          POINSOT_DOC(analysis_AxisymmetricLambda_lambda_at));
}

/// The properties of Λ along a trajectory.
void bind_lambda_properties(py::module_& m) {
  m.def(
      "lambda_properties",
      [](const RigidBody& body, ArrayLike t, ArrayLike R, ArrayLike w, const py::object& torque,
         double volume, double axisymmetry_tolerance) {
        const Trajectory tr(t.obj, R.obj, w.obj);
        if (tr.n == 0) throw py::value_error("t: expected at least one sample, got none");
        analysis::LambdaTrackerOptions o;
        o.volume_m3 = volume;
        o.axisymmetry_tolerance = axisymmetry_tolerance;
        std::shared_ptr<const dynamics::TorqueModel> tm = as_torque(torque);
        analysis::LambdaTracker tracker(body, tm, tr.state(0), o);
        for (py::ssize_t i = 1; i < tr.n; ++i)
          tracker.observe(tr.state(i));
        return from_json(io::lambda_properties_json(tracker.properties()));
      },
      py::arg("body"), py::arg("t"), py::arg("R"), py::arg("omega_body"), py::arg("torque") = py::none(),
      py::arg("volume_m3") = 0.0, py::arg("axisymmetry_tolerance") = 1e-12,
      (std::string("The properties of Λ checked along a sampled trajectory (t (n,), R (n, 3, 3), omega_body "
                   "(n, 3)), as a dict (arrays as lists) with the keys of `poinsot lambda --json` that "
                   "describe the trajectory (closed_form: a dict for an axisymmetric torque-free body, else "
                   "None):\n\n") +
       POINSOT_DOC(io_lambda_properties_json) + "\n\n" + POINSOT_DOC(file_analysis_lambda_tracker))
          .c_str());

  m.def(
      "lambda_report",
      [](const RigidBody& body, const State& initial, const std::string& method, double dt, double max_step,
         double rtol, double atol, double t_end, double sample_dt, const py::object& torque, double volume,
         double axisymmetry_tolerance) {
        analysis::LambdaAnalysisOptions o;
        o.method = method;
        o.integrator.dt = dt;
        o.integrator.max_step = max_step;
        o.integrator.rtol = rtol;
        o.integrator.atol = atol;
        o.t_end = t_end;
        o.sample_dt = sample_dt;
        o.torque = as_torque(torque);
        o.volume_m3 = volume;
        o.axisymmetry_tolerance = axisymmetry_tolerance;
        const auto r = analysis::analyse_lambda(body, initial, o);  // with the GIL: a Python torque may run
        py::dict d = from_json(io::lambda_report_json(r));
        d["text"] = analysis::format_lambda_report(r);
        return d;
      },
      py::arg("body"), py::arg("initial"), py::kw_only(),
      py::arg("method") = std::string(dynamics::kDefaultLambdaMethod),
      py::arg("dt") = dynamics::IntegratorOptions{}.dt,
      py::arg("max_step") = dynamics::IntegratorOptions{}.max_step,
      py::arg("rtol") = dynamics::IntegratorOptions{}.rtol,
      py::arg("atol") = dynamics::IntegratorOptions{}.atol, py::arg("t_end") = 10.0,
      py::arg("sample_dt") = 0.01, py::arg("torque") = py::none(), py::arg("volume_m3") = 0.0,
      py::arg("axisymmetry_tolerance") = 1e-12,
      (std::string(POINSOT_DOC(analysis_analyse_lambda)) +
       "\n\nThe engine of `poinsot lambda`. Returns the dict of `poinsot lambda --json` (the same JSON "
       "text, arrays as lists) and `text`, the report it prints without --json:\n\n" +
       POINSOT_DOC(io_lambda_report_json) + "\n\n" + POINSOT_DOC(file_analysis_lambda_report))
          .c_str());
}

}  // namespace

void bind_analysis(py::module_& parent) {
  auto m = parent.def_submodule("analysis", POINSOT_DOC(file_analysis_multipliers));
  bind_body_multipliers(m);
  bind_stress(m);
  bind_axisymmetric_lambda(m);
  bind_lambda_properties(m);
}

}  // namespace poinsot::python
