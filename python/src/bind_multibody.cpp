// Bindings of the multibody layer as the submodule poinsot.multibody: the model (System), the state, the
// integrators (RATTLE, the projected RK4), the exact multipliers, the observables and the scenario files.
// Bodies are named by index or by name ("world" or poinsot.multibody.WORLD for the fixed frame). Per-body
// results are NumPy arrays with the body index first: x (N, 3), R (N, 3, 3), Λ (N, 3, 3). Docstrings come
// from the headers' doc comments through the generated docstrings.hpp (python/tools/gen_docstrings.py).
#include <pybind11/stl.h>

#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "convert.hpp"
#include "docstrings.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/inertia/mass_properties.hpp"
#include "poinsot/io/robot/robot_system.hpp"
#include "poinsot/io/run/multibody_run.hpp"
#include "poinsot/io/scenario/multibody_scenario.hpp"
#include "poinsot/io/scenario/scenario_file.hpp"
#include "poinsot/multibody/loads.hpp"
#include "poinsot/multibody/methods.hpp"
#include "poinsot/multibody/model.hpp"
#include "poinsot/multibody/multipliers.hpp"
#include "poinsot/multibody/observables.hpp"
#include "poinsot/multibody/projected_rk4.hpp"
#include "poinsot/multibody/rattle.hpp"
#include "poinsot/multibody/scenario.hpp"
#include "poinsot/multibody/state.hpp"

namespace poinsot::python {

namespace mb = poinsot::multibody;

namespace {

template <class Get>
py::array_t<double> per_body_vec3(const mb::State& s, Get get) {
  std::vector<Vec3> v;
  v.reserve(s.bodies.size());
  for (const auto& b : s.bodies)
    v.push_back(get(b));
  return stack_vec3(v);
}

mb::BodyState make_body_state(ArrayLike x, ArrayLike R, ArrayLike v, ArrayLike omega) {
  mb::BodyState b;
  if (!x.obj.is_none()) b.x_space = to_vec3(x, "x_space");
  if (!R.obj.is_none()) b.R_space_body = to_mat3(R, "R_space_body");
  if (!v.obj.is_none()) b.v_space = to_vec3(v, "v_space");
  if (!omega.obj.is_none()) b.omega_body = to_vec3(omega, "omega_body");
  return b;
}

mb::BodyState& body_at(mb::State& s, py::ssize_t i) {
  const auto n = static_cast<py::ssize_t>(s.bodies.size());
  if (i < 0) i += n;
  if (i < 0 || i >= n) throw py::index_error("state: body index out of range");
  return s.bodies[static_cast<std::size_t>(i)];
}

void bind_multipliers(py::module_& m) {
  py::class_<mb::Multipliers>(m, "Multipliers", POINSOT_DOC(file_multibody_multipliers))
      .def_property_readonly(
          "Lambda_body", [](const mb::Multipliers& x) { return stack_mat3(x.Lambda_body); },
          POINSOT_DOC(multibody_Multipliers_Lambda_body))
      .def_property_readonly(
          "joint_force_space", [](const mb::Multipliers& x) { return stack_vec3(x.joint_force_space); },
          POINSOT_DOC(multibody_Multipliers_joint_force_space))
      .def_property_readonly(
          "joint_torque_space", [](const mb::Multipliers& x) { return stack_vec3(x.joint_torque_space); },
          POINSOT_DOC(multibody_Multipliers_joint_torque_space));
  py::class_<mb::ExactMultipliers, mb::Multipliers>(m, "ExactMultipliers",
                                                    POINSOT_DOC(multibody_ExactMultipliers))
      .def_property_readonly(
          "acceleration_space",
          [](const mb::ExactMultipliers& x) { return stack_vec3(x.acceleration_space); },
          "Acceleration of each body's centre of mass, space frame, m/s², shape (N, 3).")
      .def_property_readonly(
          "omega_dot_body", [](const mb::ExactMultipliers& x) { return stack_vec3(x.omega_dot_body); },
          "Angular acceleration of each body, body frame, rad/s², shape (N, 3).");
  m.def("exact_multipliers", &mb::exact_multipliers, py::arg("system"), py::arg("state"),
        POINSOT_DOC(multibody_ExactMultipliers));
}

void bind_state(py::module_& m) {
  py::class_<mb::BodyState>(m, "BodyState", "The state of one body (state.hpp).")
      .def(py::init(&make_body_state), py::kw_only(), py::arg("x_space") = py::none(),
           py::arg("R_space_body") = py::none(), py::arg("v_space") = py::none(),
           py::arg("omega_body") = py::none(),
           "A body state; defaults: x_space = 0 (m), R_space_body = I, v_space = 0 (m/s), omega_body = 0 "
           "(rad/s).")
      .def_property(
          "x_space", [](const mb::BodyState& b) { return from_vec3(b.x_space); },
          [](mb::BodyState& b, ArrayLike x) { b.x_space = to_vec3(x, "x_space"); },
          POINSOT_DOC(multibody_BodyState_x_space))
      .def_property(
          "R_space_body", [](const mb::BodyState& b) { return from_mat3(b.R_space_body); },
          [](mb::BodyState& b, ArrayLike R) { b.R_space_body = to_mat3(R, "R_space_body"); },
          POINSOT_DOC(multibody_BodyState_R_space_body))
      .def_property(
          "v_space", [](const mb::BodyState& b) { return from_vec3(b.v_space); },
          [](mb::BodyState& b, ArrayLike v) { b.v_space = to_vec3(v, "v_space"); },
          POINSOT_DOC(multibody_BodyState_v_space))
      .def_property(
          "omega_body", [](const mb::BodyState& b) { return from_vec3(b.omega_body); },
          [](mb::BodyState& b, ArrayLike w) { b.omega_body = to_vec3(w, "omega_body"); },
          POINSOT_DOC(multibody_BodyState_omega_body))
      .def("__repr__", [](const mb::BodyState& b) {
        return "BodyState(x_space=" + format_vector(b.x_space) + " m, v_space=" + format_vector(b.v_space) +
               " m/s, omega_body=" + format_vector(b.omega_body) + " rad/s)";
      });

  py::class_<mb::State>(m, "State", POINSOT_DOC(file_multibody_state))
      .def(py::init([](double time, std::vector<mb::BodyState> bodies) {
             return mb::State{time, std::move(bodies)};
           }),
           py::kw_only(), py::arg("time") = 0.0, py::arg("bodies") = std::vector<mb::BodyState>{},
           "A state at `time` (s) with one BodyState per body, in the System's body order.")
      .def_readwrite("time", &mb::State::time, POINSOT_DOC(multibody_State_time))
      .def_property(
          "bodies", [](const mb::State& s) { return s.bodies; },
          [](mb::State& s, std::vector<mb::BodyState> b) { s.bodies = std::move(b); },
          "A copy of the body states (a list); assign a list to replace them, or edit one in place through "
          "state[i].")
      .def("__len__", [](const mb::State& s) { return s.bodies.size(); })
      .def("__getitem__", &body_at, py::arg("i"), py::return_value_policy::reference_internal,
           "The i-th body's state, a view into this State (editing it edits the State).")
      .def_property_readonly(
          "x_space",
          [](const mb::State& s) { return per_body_vec3(s, [](const auto& b) { return b.x_space; }); },
          "Centres of mass, space frame, m, shape (N, 3).")
      .def_property_readonly(
          "R_space_body",
          [](const mb::State& s) {
            std::vector<Mat3> v;
            for (const auto& b : s.bodies)
              v.push_back(b.R_space_body);
            return stack_mat3(v);
          },
          "Rotations body → space, shape (N, 3, 3).")
      .def_property_readonly(
          "v_space",
          [](const mb::State& s) { return per_body_vec3(s, [](const auto& b) { return b.v_space; }); },
          "Velocities of the centres of mass, space frame, m/s, shape (N, 3).")
      .def_property_readonly(
          "omega_body",
          [](const mb::State& s) { return per_body_vec3(s, [](const auto& b) { return b.omega_body; }); },
          "Angular velocities, body frames, rad/s, shape (N, 3).")
      .def("__repr__", [](const mb::State& s) {
        return "State(time=" + format_number(s.time) + " s, bodies=" + std::to_string(s.bodies.size()) + ")";
      });
}

void bind_observables(py::module_& m) {
  m.def("kinetic_energy", &mb::kinetic_energy, py::arg("system"), py::arg("state"),
        POINSOT_DOC(multibody_kinetic_energy));
  m.def(
      "potential_energy",
      [](const mb::System& s, const mb::State& st) { return mb::potential_energy(s, st.bodies); },
      py::arg("system"), py::arg("state"), POINSOT_DOC(multibody_potential_energy));
  m.def("total_energy", &mb::total_energy, py::arg("system"), py::arg("state"),
        POINSOT_DOC(multibody_total_energy));
  m.def(
      "linear_momentum",
      [](const mb::System& s, const mb::State& st) { return from_vec3(mb::linear_momentum(s, st)); },
      py::arg("system"), py::arg("state"), POINSOT_DOC(multibody_linear_momentum));
  m.def(
      "angular_momentum",
      [](const mb::System& s, const mb::State& st) { return from_vec3(mb::angular_momentum(s, st)); },
      py::arg("system"), py::arg("state"), POINSOT_DOC(multibody_angular_momentum));
  py::class_<mb::ConstraintViolation>(m, "ConstraintViolation", "How far a state is from the constraints.")
      .def_readonly("orthogonality", &mb::ConstraintViolation::orthogonality,
                    POINSOT_DOC(multibody_ConstraintViolation_orthogonality))
      .def_readonly("joint_gap", &mb::ConstraintViolation::joint_gap,
                    POINSOT_DOC(multibody_ConstraintViolation_joint_gap))
      .def_readonly("joint_angle", &mb::ConstraintViolation::joint_angle,
                    POINSOT_DOC(multibody_ConstraintViolation_joint_angle))
      .def_readonly("joint_velocity", &mb::ConstraintViolation::joint_velocity,
                    POINSOT_DOC(multibody_ConstraintViolation_joint_velocity))
      .def("__repr__", [](const mb::ConstraintViolation& c) {
        return "ConstraintViolation(orthogonality=" + format_number(c.orthogonality) +
               ", joint_gap=" + format_number(c.joint_gap) +
               " m, joint_angle=" + format_number(c.joint_angle) +
               ", joint_velocity=" + format_number(c.joint_velocity) + " m/s)";
      });
  m.def("constraint_violation", &mb::constraint_violation, py::arg("system"), py::arg("state"),
        "Max violation of RᵀR = I, of the joints' positions (m) and angles, and of the ball rows' velocity "
        "(m/s).");
  m.def("check_consistent", &mb::check_consistent, py::arg("system"), py::arg("state"),
        POINSOT_DOC(multibody_check_consistent));
}

// `steps` steps of a multibody integrator (Rattle, ProjectedRk4) with the GIL released.
template <class Integrator>
void step_many(Integrator& integrator, mb::State& state, long steps) {
  if (steps < 1) throw InvalidInput("steps: got " + std::to_string(steps) + ", expected an integer >= 1");
  py::gil_scoped_release release;  // no Python callbacks in the multibody layer
  for (long i = 0; i < steps; ++i)
    integrator.step(state);
}

constexpr const char* kKktSolverDoc =
    "How the KKT systems are solved: 'ball_chain' (Schur complement on the joints, chains of ball joints), "
    "'tree' (Baraff's tree-order LDLᵀ) or 'sparse_lu' (closed loops).";

void bind_rattle(py::module_& m) {
  py::class_<mb::Rattle>(m, "Rattle", POINSOT_DOC(file_multibody_rattle))
      .def(py::init([](const mb::System& s, double dt, double tolerance, int max_iterations, int order) {
             mb::RattleOptions o;
             o.tolerance = tolerance;
             o.max_iterations = max_iterations;
             o.order = order;
             return mb::Rattle(s, dt, o);
           }),
           py::arg("system"), py::arg("dt"), py::kw_only(), py::arg("tolerance") = 1e-13,
           py::arg("max_iterations") = 50, py::arg("order") = 2, POINSOT_DOC(multibody_Rattle_Rattle))
      .def("step", &step_many<mb::Rattle>, py::arg("state"), py::arg("steps") = 1,
           POINSOT_DOC(multibody_Rattle_step))
      .def_property_readonly("dt", &mb::Rattle::dt, "The step size, s.")
      .def_property_readonly("order", &mb::Rattle::order,
                             "2 (RATTLE) or 4 (RATTLE composed by the triple jump, three substeps).")
      .def_property_readonly(
          "kkt_solver", [](const mb::Rattle& r) { return mb::kkt_method_name(r.kkt_method()); },
          kKktSolverDoc)
      .def_property_readonly("uses_tree_solver", &mb::Rattle::uses_tree_solver,
                             "True when the KKT solves use the O(N) tree factorisation.")
      .def_property_readonly("last_iterations", &mb::Rattle::last_iterations,
                             POINSOT_DOC(multibody_Rattle_last_iterations))
      .def_property_readonly("position_stage", &mb::Rattle::position_stage,
                             POINSOT_DOC(multibody_Rattle_position_stage))
      .def_property_readonly("velocity_stage", &mb::Rattle::velocity_stage,
                             POINSOT_DOC(multibody_Rattle_position_stage));
}

void bind_projected_rk4(py::module_& m) {
  py::class_<mb::ProjectedRk4>(m, "ProjectedRk4", POINSOT_DOC(file_multibody_projected_rk4))
      .def(py::init([](const mb::System& s, double dt, double tolerance, int max_iterations) {
             mb::ProjectedRk4Options o;
             o.tolerance = tolerance;
             o.max_iterations = max_iterations;
             return mb::ProjectedRk4(s, dt, o);
           }),
           py::arg("system"), py::arg("dt"), py::kw_only(), py::arg("tolerance") = 1e-13,
           py::arg("max_iterations") = 20, POINSOT_DOC(multibody_ProjectedRk4_ProjectedRk4))
      .def("step", &step_many<mb::ProjectedRk4>, py::arg("state"), py::arg("steps") = 1,
           POINSOT_DOC(multibody_ProjectedRk4_step))
      .def_property_readonly("dt", &mb::ProjectedRk4::dt, "The step size, s.")
      .def_property_readonly(
          "order", [](const mb::ProjectedRk4&) { return 4; },
          "4: the classical Runge–Kutta method (global error O(h⁴)).")
      .def_property_readonly(
          "kkt_solver", [](const mb::ProjectedRk4& r) { return mb::kkt_method_name(r.kkt_method()); },
          kKktSolverDoc)
      .def_property_readonly("last_iterations", &mb::ProjectedRk4::last_iterations,
                             POINSOT_DOC(multibody_ProjectedRk4_last_iterations))
      // A copy: the integrator's own storage changes at the next step.
      .def_property_readonly(
          "multipliers", [](const mb::ProjectedRk4& r) { return mb::ExactMultipliers(r.multipliers()); },
          POINSOT_DOC(multibody_ProjectedRk4_multipliers));
}

/// poinsot.multibody.MethodInfo, METHODS (name → entry) and DEFAULT_METHOD: the registry of methods.hpp.
void bind_multibody_methods(py::module_& m) {
  using mb::MultibodyMethodInfo;
  py::class_<MultibodyMethodInfo>(m, "MethodInfo", POINSOT_DOC(multibody_MultibodyMethodInfo))
      .def_property_readonly(
          "name", [](const MultibodyMethodInfo& i) { return std::string(i.name); },
          POINSOT_DOC(multibody_MultibodyMethodInfo_name))
      .def_readonly("order", &MultibodyMethodInfo::order, POINSOT_DOC(multibody_MultibodyMethodInfo_order))
      .def_readonly("max_order", &MultibodyMethodInfo::max_order,
                    POINSOT_DOC(multibody_MultibodyMethodInfo_max_order))
      .def_readonly("symplectic", &MultibodyMethodInfo::symplectic,
                    POINSOT_DOC(multibody_MultibodyMethodInfo_symplectic))
      .def_property_readonly(
          "preserves",
          [](const MultibodyMethodInfo& i) {
            std::vector<std::string> out;
            if (i.preserves.orthogonality) out.emplace_back("orthogonality");
            if (i.preserves.joints) out.emplace_back("joints");
            if (i.preserves.momentum) out.emplace_back("momentum");
            return out;
          },
          (std::string("What it keeps, among orthogonality, joints, momentum. ") +
           POINSOT_DOC(multibody_MultibodyPreserved))
              .c_str())
      .def_property_readonly(
          "description", [](const MultibodyMethodInfo& i) { return std::string(i.description); },
          POINSOT_DOC(multibody_MultibodyMethodInfo_description))
      .def("__repr__", [](const MultibodyMethodInfo& i) {
        return "MethodInfo(" + std::string(i.name) + ", order " + std::to_string(i.order) + ")";
      });
  py::dict methods;
  for (const MultibodyMethodInfo& i : mb::multibody_methods())
    methods[py::str(std::string(i.name))] = py::cast(&i, py::return_value_policy::reference);
  m.attr("METHODS") = methods;
  m.attr("DEFAULT_METHOD") = std::string(mb::multibody_method_name(mb::kDefaultMultibodyMethod));
}

namespace {

/// Scenario, and the scenario and robot files that give one.
void bind_scenario_files(py::module_& m) {
  py::class_<mb::Scenario>(m, "Scenario", POINSOT_DOC(file_multibody_scenario))
      .def_readwrite("system", &mb::Scenario::system, "The model.")
      .def_readwrite("initial", &mb::Scenario::initial, "The initial state (velocities already projected).")
      .def_readwrite("dt", &mb::Scenario::dt, POINSOT_DOC(multibody_Scenario_dt))
      .def_readwrite("duration", &mb::Scenario::duration, POINSOT_DOC(multibody_Scenario_duration))
      .def_readwrite("output_every", &mb::Scenario::output_every,
                     POINSOT_DOC(multibody_Scenario_output_every))
      .def_property(
          "method", [](const mb::Scenario& sc) { return std::string(mb::multibody_method_name(sc.method)); },
          [](mb::Scenario& sc, const std::string& name) {
            sc.method = mb::parse_multibody_method(name, "Scenario.method");
            sc.order = mb::order_for_method(sc.method, sc.order);
          },
          (std::string("The integrator of run_scenario, a name of multibody.METHODS (") +
           mb::multibody_method_names() +
           "). Setting it keeps order when the method offers it, else sets the method's order (rk4: 4). " +
           POINSOT_DOC(multibody_MultibodyMethod))
              .c_str())
      .def_readwrite("order", &mb::Scenario::order, POINSOT_DOC(multibody_Scenario_order))
      .def_readwrite("source", &mb::Scenario::source, POINSOT_DOC(multibody_Scenario_source))
      .def_readwrite("title", &mb::Scenario::title, POINSOT_DOC(multibody_Scenario_title))
      .def_readwrite("body_descriptions", &mb::Scenario::body_descriptions,
                     POINSOT_DOC(multibody_Scenario_body_descriptions))
      .def_readwrite("not_modelled", &mb::Scenario::not_modelled,
                     POINSOT_DOC(multibody_Scenario_not_modelled));
  m.def("is_multibody_scenario", &io::is_multibody_scenario, py::arg("toml_path"),
        POINSOT_DOC(io_is_multibody_scenario));
  m.def("load_scenario", &io::load_multibody_scenario, py::arg("toml_path"),
        POINSOT_DOC(io_load_multibody_scenario));
  m.def(
      "parse_scenario",
      [](const std::string& text, const std::string& source, const std::string& base_dir) {
        return io::parse_multibody_scenario(text, source, base_dir);
      },
      py::arg("toml_text"), py::arg("source_name") = "<string>", py::arg("base_dir") = "",
      POINSOT_DOC(io_parse_multibody_scenario));
  m.def(
      "load_robot",
      [](const std::string& path, const std::map<std::string, std::vector<double>>& positions,
         const std::map<std::string, std::vector<double>>& velocities, const py::object& gravity,
         bool floating_base, const std::string& inertia, const py::object& base_position,
         const py::object& base_rotation, const py::object& base_velocity,
         const py::object& base_omega_body) {
        io::RobotSystemOptions o;
        o.positions = positions;
        o.velocities = velocities;
        o.floating_base = floating_base;
        if (inertia != "file" && inertia != "geometry")
          throw InvalidInput("inertia: got \"" + inertia + "\", expected \"file\" or \"geometry\"");
        o.inertia = inertia == "file" ? io::RobotInertiaSource::file : io::RobotInertiaSource::geometry;
        const auto vec = [](const py::object& x, const char* what) -> std::optional<Vec3> {
          if (x.is_none()) return std::nullopt;
          return to_vec3(x, what);
        };
        o.gravity = vec(gravity, "gravity");
        o.base_position = vec(base_position, "base_position");
        o.base_velocity = vec(base_velocity, "base_velocity");
        o.base_omega_body = vec(base_omega_body, "base_omega_body");
        if (!base_rotation.is_none()) o.base_rotation = to_mat3(base_rotation, "base_rotation");
        return io::load_robot_scenario(path, o);
      },
      py::arg("path"), py::arg("positions") = std::map<std::string, std::vector<double>>{},
      py::arg("velocities") = std::map<std::string, std::vector<double>>{}, py::arg("gravity") = py::none(),
      py::arg("floating_base") = false, py::arg("inertia") = "file", py::arg("base_position") = py::none(),
      py::arg("base_rotation") = py::none(), py::arg("base_velocity") = py::none(),
      py::arg("base_omega_body") = py::none(),
      (std::string(
           "A robot file (URDF, MJCF, SDF) as a multibody Scenario: positions and velocities by joint "
           "name (lists of numbers), gravity (default: the file's), floating_base (URDF), inertia "
           "(\"file\" or \"geometry\"), the floating base's pose and rates. ") +
       POINSOT_DOC(io_load_robot_scenario))
          .c_str());
  m.def("project_velocities", &mb::project_velocities, py::arg("system"), py::arg("state"),
        POINSOT_DOC(multibody_project_velocities));
}

/// RunSummary and run(): a multibody run with its files.
void bind_multibody_run(py::module_& m) {
  py::class_<mb::RunSummary>(m, "RunSummary", POINSOT_DOC(multibody_RunSummary))
      .def_readonly("steps", &mb::RunSummary::steps)
      .def_readonly("energy_initial", &mb::RunSummary::energy_initial,
                    POINSOT_DOC(multibody_RunSummary_energy_initial))
      .def_readonly("energy_final", &mb::RunSummary::energy_final)
      .def_readonly("max_energy_error", &mb::RunSummary::max_energy_error,
                    POINSOT_DOC(multibody_RunSummary_max_energy_error))
      .def_readonly("max_joint_gap", &mb::RunSummary::max_joint_gap,
                    POINSOT_DOC(multibody_RunSummary_max_joint_gap))
      .def_readonly("max_joint_angle", &mb::RunSummary::max_joint_angle,
                    POINSOT_DOC(multibody_RunSummary_max_joint_angle))
      .def_readonly("max_orthogonality", &mb::RunSummary::max_orthogonality,
                    POINSOT_DOC(multibody_RunSummary_max_orthogonality))
      .def_readonly("mean_newton_iterations", &mb::RunSummary::mean_newton_iterations)
      .def_readonly("max_newton_iterations", &mb::RunSummary::max_newton_iterations)
      .def_readonly("tree_solver", &mb::RunSummary::tree_solver)
      .def_readonly("cpu_seconds_per_step", &mb::RunSummary::cpu_seconds_per_step)
      .def_readonly("interrupted", &mb::RunSummary::interrupted,
                    POINSOT_DOC(multibody_RunSummary_interrupted))
      .def_readonly("final_state", &mb::RunSummary::final_state,
                    POINSOT_DOC(multibody_RunSummary_final_state))
      .def("__repr__", [](const mb::RunSummary& r) {
        return "RunSummary(steps=" + std::to_string(r.steps) +
               ", max_energy_error=" + format_number(r.max_energy_error) +
               " J, max_joint_gap=" + format_number(r.max_joint_gap) +
               " m, max_orthogonality=" + format_number(r.max_orthogonality) + ")";
      });
  m.def(
      "run_scenario",
      [](const mb::Scenario& sc, const std::string& trajectory_csv, const py::object& report,
         const std::string& diagnostics_csv, const std::string& out_dir) {
        io::MultibodyRunOptions options;
        options.out_dir = out_dir;
        options.trajectory_csv = trajectory_csv;
        options.diagnostics_csv = diagnostics_csv;
        io::MultibodyRunSummary summary;
        {
          py::gil_scoped_release release;
          summary = io::run_multibody_scenario(sc, options);
        }
        if (!report.is_none()) report.attr("write")(io::format_multibody_report(sc, summary));
        return summary.run;
      },
      py::arg("scenario"), py::arg("trajectory_csv") = "", py::arg("report") = py::none(),
      py::arg("diagnostics_csv") = "", py::arg("out_dir") = "", POINSOT_DOC(io_run_multibody_scenario));
}

}  // namespace

void bind_multibody_scenario(py::module_& m) {
  bind_scenario_files(m);
  bind_multibody_run(m);
}

}  // namespace

void bind_multibody(py::module_& parent) {
  auto m = parent.def_submodule("multibody", POINSOT_DOC(file_multibody_model));
  m.attr("WORLD") = mb::kWorld;
  bind_multibody_system(m);
  bind_state(m);
  bind_multipliers(m);
  bind_observables(m);
  bind_rattle(m);
  bind_projected_rk4(m);
  bind_multibody_scenario(m);
  bind_multibody_methods(m);
}

}  // namespace poinsot::python
