// Bindings of the multibody optimal-control problems: poinsot.optimal.MultibodyProblem around a
// poinsot.multibody.System, multibody scenario files with an [optimal_control] section, and a whole
// `poinsot optimize` on them (the direct transcription and its re-simulation) whose samples come back as
// NumPy arrays. poinsot.optimize (python/poinsot/_optimize.py) is the public entry point.
#include <pybind11/stl.h>

#include <string>

#include "bindings.hpp"
#include "convert.hpp"
#include "docstrings.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/io/run/multibody_optimal_run.hpp"
#include "poinsot/io/scenario/multibody_optimal_scenario.hpp"

namespace poinsot::python {

namespace {

namespace opt = poinsot::optimal;
namespace mb = poinsot::multibody;

optimal::MultibodyCoordinates to_coordinates(const std::string& name) {
  if (name == "minimal") return opt::MultibodyCoordinates::minimal;
  if (name != "rotation_matrix") {
    throw InvalidInput("optimal control: coordinates: got \"" + name +
                       "\"; expected \"rotation_matrix\" or \"minimal\"");
  }
  return opt::MultibodyCoordinates::rotation_matrix;
}

/// The index of the hinge named `name`, the message prefixed with `what`.
int hinge(const mb::System& system, const py::handle& name, const std::string& what) {
  try {
    return opt::hinge_index(system, name.cast<std::string>());
  } catch (const InvalidInput& e) {
    throw InvalidInput(what + ": joint: " + e.what());
  }
}

/// Actuators from a list of dicts {"joint": NAME, "torque_max": N·m} or {"body": NAME, "torque_max": N·m}.
std::vector<opt::Actuator> to_actuators(const mb::System& system, const py::list& list) {
  std::vector<opt::Actuator> out;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string what = "optimal control: actuators[" + std::to_string(i) + "]";
    if (!py::isinstance<py::dict>(list[i]))
      throw InvalidInput(what + ": expected a dict {\"joint\" or \"body\": name, \"torque_max\": N·m}");
    const py::dict d = list[i].cast<py::dict>();
    if (d.contains("joint") == d.contains("body") || !d.contains("torque_max") || d.size() != 2) {
      throw InvalidInput(what +
                         ": expected exactly the keys \"joint\" (a hinge's name) or \"body\" (a body's "
                         "name), and \"torque_max\" (N·m)");
    }
    opt::Actuator a;
    a.torque_max = d["torque_max"].cast<double>();
    if (d.contains("joint")) {
      try {
        a = opt::joint_motor(system, d["joint"].cast<std::string>(), a.torque_max);
      } catch (const InvalidInput& e) {
        throw InvalidInput(what + ": joint: " + e.what());
      }
    } else {
      a.kind = opt::ActuatorKind::body_torque;
      a.index = system.body_index(d["body"].cast<std::string>());
    }
    out.push_back(a);
  }
  return out;
}

/// Rate bounds from a list of dicts {"joint": HINGE, "rate_max": rad/s}.
std::vector<opt::RateBound> to_rate_bounds(const mb::System& system, const py::list& list) {
  std::vector<opt::RateBound> out;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string what = "optimal control: rate_bounds[" + std::to_string(i) + "]";
    const bool ok = py::isinstance<py::dict>(list[i]) && list[i].cast<py::dict>().size() == 2 &&
                    list[i].cast<py::dict>().contains("joint") &&
                    list[i].cast<py::dict>().contains("rate_max");
    if (!ok) throw InvalidInput(what + ": expected a dict {\"joint\": a hinge's name, \"rate_max\": rad/s}");
    const py::dict d = list[i].cast<py::dict>();
    out.push_back({hinge(system, d["joint"], what), d["rate_max"].cast<double>()});
  }
  return out;
}

/// No-twist conditions from a list of dicts {"joint": BALL, "axis_a": [x, y, z], "straight": 3×3 rotation}.
std::vector<opt::NoTwist> to_no_twist(const mb::System& system, const py::list& list) {
  std::vector<opt::NoTwist> out;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string what = "optimal control: no_twist[" + std::to_string(i) + "]";
    const bool ok = py::isinstance<py::dict>(list[i]) && list[i].cast<py::dict>().size() == 3 &&
                    list[i].cast<py::dict>().contains("joint") &&
                    list[i].cast<py::dict>().contains("axis_a") &&
                    list[i].cast<py::dict>().contains("straight");
    if (!ok) {
      throw InvalidInput(what +
                         ": expected a dict {\"joint\": a ball joint's name, \"axis_a\": body a's symmetry "
                         "axis [x, y, z], \"straight\": the straight relative rotation (3×3)}");
    }
    const py::dict d = list[i].cast<py::dict>();
    opt::NoTwist c;
    try {
      c.joint = opt::ball_index(system, d["joint"].cast<std::string>());
    } catch (const InvalidInput& e) {
      throw InvalidInput(what + ": joint: " + e.what());
    }
    c.axis_a = to_vec3(d["axis_a"], (what + ": axis_a").c_str());
    c.straight = to_mat3(d["straight"], (what + ": straight").c_str());
    out.push_back(c);
  }
  return out;
}

io::MultibodyOptimalScenario make_scenario(const mb::System& system, const mb::State& initial_state,
                                           const mb::State& final_state, double final_time,
                                           const py::list& actuators, int intervals,
                                           const std::string& coordinates, const py::list& rate_bounds,
                                           const py::list& no_twist, double stabilisation_step,
                                           const std::vector<int>& warm_start, const std::string& objective,
                                           const py::object& final_time_bounds, double energy_weight) {
  opt::MultibodyProblem p;
  p.system = system;
  p.initial_state = initial_state;
  p.final_state = final_state;
  p.final_time = final_time;
  p.intervals = intervals;
  p.actuators = to_actuators(system, actuators);
  p.rate_bounds = to_rate_bounds(system, rate_bounds);
  p.no_twist = to_no_twist(system, no_twist);
  if (objective == "minimum_time") {
    p.objective = opt::MultibodyObjective::minimum_time;
    if (final_time_bounds.is_none()) {
      throw InvalidInput(
          "optimal control: final_time_bounds: got None; expected [T_min, T_max] in seconds (minimum_time)");
    }
    const auto bounds = final_time_bounds.cast<std::vector<double>>();
    if (bounds.size() != 2) {
      throw InvalidInput("optimal control: final_time_bounds: got " + std::to_string(bounds.size()) +
                         " numbers; expected [T_min, T_max] in seconds");
    }
    p.final_time_min = bounds[0];
    p.final_time_max = bounds[1];
    p.energy_weight = energy_weight;
  } else if (objective != "minimum_energy") {
    throw InvalidInput("optimal control: objective: got \"" + objective +
                       "\"; expected \"minimum_energy\" or \"minimum_time\"");
  } else if (!final_time_bounds.is_none() || energy_weight != 0.0) {
    throw InvalidInput(
        "optimal control: final_time_bounds, energy_weight: given with objective \"minimum_energy\"; "
        "expected them only with \"minimum_time\"");
  }
  opt::MultibodyOptions o;
  o.coordinates = to_coordinates(coordinates);
  o.stabilisation_step = stabilisation_step;
  return io::multibody_optimal_scenario_of(p, o, warm_start);
}

/// Per point, per item: an (n, k, 3) or (n, k, 3, 3) array.
template <class Get>
py::array_t<double> stack(std::size_t n, std::size_t k, std::vector<py::ssize_t> tail, Get get) {
  std::size_t block = 1;
  for (auto t : tail)
    block *= static_cast<std::size_t>(t);
  std::vector<double> buf;
  buf.reserve(n * k * block);
  for (std::size_t p = 0; p < n; ++p) {
    for (std::size_t i = 0; i < k; ++i) {
      const auto v = get(p, i);  // a Vec3 or a Mat3, row by row
      for (Eigen::Index r = 0; r < v.rows(); ++r)
        for (Eigen::Index c = 0; c < v.cols(); ++c)
          buf.push_back(v(r, c));
    }
  }
  std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(k)};
  shape.insert(shape.end(), tail.begin(), tail.end());
  return array_from_buffer(std::move(buf), shape);
}

py::dict run_dict(const io::MultibodyOptimalRun& run) {
  const auto& o = run.optimum;
  const std::size_t n = o.time.size();
  const auto B = static_cast<std::size_t>(run.scenario.problem.system.body_count());
  const auto J = static_cast<std::size_t>(run.scenario.problem.system.joint_count());
  const auto m = static_cast<std::size_t>(opt::control_count(run.scenario.problem));
  py::dict d;
  d["summary"] = io::multibody_optimal_summary_json(run);
  d["report"] = io::multibody_optimal_report(run);
  d["scenario"] = run.scenario;  // with the last mesh's intervals (refined where the target was missed)
  d["optimal"] = run.optimal;
  d["status"] = run.status;
  d["cost"] = o.cost;
  d["nlp_iterations"] = o.nlp_iterations;
  d["nlp_restarts"] = o.nlp_restarts;
  d["t"] = array_from_buffer(std::vector<double>(o.time), {static_cast<py::ssize_t>(n)});
  d["x_space"] = stack(n, B, {3}, [&](auto p, auto i) { return o.states[p].bodies[i].x_space; });
  d["R_space_body"] = stack(n, B, {3, 3}, [&](auto p, auto i) { return o.states[p].bodies[i].R_space_body; });
  d["v_space"] = stack(n, B, {3}, [&](auto p, auto i) { return o.states[p].bodies[i].v_space; });
  d["omega_body"] = stack(n, B, {3}, [&](auto p, auto i) { return o.states[p].bodies[i].omega_body; });
  std::vector<double> u;
  for (const Eigen::VectorXd& c : o.controls)
    u.insert(u.end(), c.data(), c.data() + c.size());
  d["controls"] = array_from_buffer(std::move(u), {static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(m)});
  d["joint_force_space"] =
      stack(n, J, {3}, [&](auto p, auto j) { return o.multipliers[p].joint_force_space[j]; });
  d["joint_torque_space"] =
      stack(n, J, {3}, [&](auto p, auto j) { return o.multipliers[p].joint_torque_space[j]; });
  d["Lambda_body"] = stack(n, B, {3, 3}, [&](auto p, auto i) { return o.multipliers[p].Lambda_body[i]; });
  return d;
}

/// MultibodyProblem: a multibody optimal-control problem, from a file or built in Python.
void bind_multibody_problem(py::module_& m) {
  py::class_<io::MultibodyOptimalScenario>(m, "MultibodyProblem",
                                           POINSOT_DOC(file_io_scenario_multibody_optimal_scenario))
      .def(py::init(&make_scenario), py::kw_only(), py::arg("system"), py::arg("initial_state"),
           py::arg("final_state"), py::arg("final_time"), py::arg("actuators"), py::arg("intervals") = 20,
           py::arg("coordinates") = "rotation_matrix", py::arg("rate_bounds") = py::list(),
           py::arg("no_twist") = py::list(), py::arg("stabilisation_step") = 0.0,
           py::arg("warm_start") = std::vector<int>{}, py::arg("objective") = "minimum_energy",
           py::arg("final_time_bounds") = py::none(), py::arg("energy_weight") = 0.0,
           "An optimal-control problem on a poinsot.multibody.System (optimal/multibody_problem.hpp): from "
           "the "
           "consistent initial_state to the consistent final_state (poinsot.multibody.State) in final_time "
           "(s), with actuators a list of {\"joint\": HINGE, \"torque_max\": N·m} (a hinge motor) or "
           "{\"body\": BODY, \"torque_max\": N·m} (three body-frame torques), on `intervals` Hermite–Simpson "
           "intervals in \"rotation_matrix\" or \"minimal\" coordinates; rate_bounds a list of {\"joint\": "
           "HINGE, \"rate_max\": rad/s} (|q̇| ≤ rate_max at every collocation point but the first). A "
           "\"joint\" actuator on a ball joint is three motors (space-frame torques). no_twist: a list of "
           "{\"joint\": BALL, \"axis_a\": [x, y, z], \"straight\": 3×3 rotation} (Kane and Scher's "
           "condition, rotation_matrix only); stabilisation_step: c ∈ [0, 0.6), the bound c/h on the "
           "stabilising variables (0: unbounded; rotation_matrix only); warm_start: the mesh sequence, "
           "increasing numbers of intervals below `intervals` solved first, each from the previous optimum. "
           "objective=\"minimum_time\" frees T in final_time_bounds = [T_min, T_max] (s; final_time is then "
           "the guess) and minimises T + energy_weight ∫ Σ u² dt. Raises ValueError for an invalid problem "
           "(one line naming the field).")
      .def_readonly("name", &io::MultibodyOptimalScenario::name,
                    POINSOT_DOC(io_MultibodyOptimalScenario_name))
      .def_readonly("source", &io::MultibodyOptimalScenario::source,
                    POINSOT_DOC(io_MultibodyOptimalScenario_source))
      .def_readonly("title", &io::MultibodyOptimalScenario::title,
                    POINSOT_DOC(io_MultibodyOptimalScenario_title))
      .def_readonly("out_dir", &io::MultibodyOptimalScenario::out_dir,
                    POINSOT_DOC(io_MultibodyOptimalScenario_out_dir))
      .def_readonly("replay_steps", &io::MultibodyOptimalScenario::replay_steps,
                    POINSOT_DOC(io_MultibodyOptimalScenario_replay_steps))
      .def_readonly("target_tolerance", &io::MultibodyOptimalScenario::target_tolerance,
                    POINSOT_DOC(io_MultibodyOptimalScenario_target_tolerance))
      .def_property_readonly(
          "system", [](const io::MultibodyOptimalScenario& s) { return s.problem.system; }, "The system.")
      .def_property_readonly(
          "initial_state", [](const io::MultibodyOptimalScenario& s) { return s.problem.initial_state; },
          POINSOT_DOC(optimal_MultibodyProblem_initial_state))
      .def_property_readonly(
          "final_state", [](const io::MultibodyOptimalScenario& s) { return s.problem.final_state; },
          POINSOT_DOC(optimal_MultibodyProblem_final_state))
      .def_property_readonly(
          "final_time", [](const io::MultibodyOptimalScenario& s) { return s.problem.final_time; },
          POINSOT_DOC(optimal_MultibodyProblem_final_time))
      .def_property_readonly(
          "intervals", [](const io::MultibodyOptimalScenario& s) { return s.problem.intervals; },
          POINSOT_DOC(optimal_MultibodyProblem_intervals))
      .def_property_readonly(
          "coordinates",
          [](const io::MultibodyOptimalScenario& s) {
            return std::string(io::coordinates_name(s.options.coordinates));
          },
          "\"rotation_matrix\" or \"minimal\": the transcription (optimal/multibody_direct.hpp).")
      .def_property_readonly(
          "stabilisation_step",
          [](const io::MultibodyOptimalScenario& s) { return s.options.stabilisation_step; },
          "c, the bound c/h on the stabilising variables of the rotation-matrix transcription (0: "
          "unbounded; optimal/multibody_direct.hpp).")
      .def_readonly("warm_start", &io::MultibodyOptimalScenario::mesh_sequence,
                    POINSOT_DOC(io_MultibodyOptimalScenario_mesh_sequence))
      .def_property_readonly(
          "no_twist",
          [](const io::MultibodyOptimalScenario& s) {
            py::list out;
            for (const opt::NoTwist& c : s.problem.no_twist) {
              py::dict d;
              d["joint"] = s.problem.system.joints()[static_cast<std::size_t>(c.joint)].name;
              d["axis_a"] = from_vec3(c.axis_a);
              d["straight"] = from_mat3(c.straight);
              out.append(d);
            }
            return out;
          },
          "The no-twist conditions, as the constructor takes them.")
      .def(
          "with_options",
          [](const io::MultibodyOptimalScenario& s, const py::object& intervals,
             const py::object& coordinates, const py::object& out_dir, const py::object& no_twist,
             const py::object& stabilisation_step, const py::object& warm_start) {
            io::MultibodyOptimalScenario copy = s;
            if (!intervals.is_none()) copy.problem.intervals = intervals.cast<int>();
            if (!coordinates.is_none())
              copy.options.coordinates = to_coordinates(coordinates.cast<std::string>());
            if (!out_dir.is_none()) copy.out_dir = out_dir.cast<std::string>();
            if (!no_twist.is_none())
              copy.problem.no_twist = to_no_twist(copy.problem.system, no_twist.cast<py::list>());
            if (!stabilisation_step.is_none())
              copy.options.stabilisation_step = stabilisation_step.cast<double>();
            if (!warm_start.is_none()) copy.mesh_sequence = warm_start.cast<std::vector<int>>();
            opt::validate(copy.problem);
            io::check_multibody_options(copy);
            return copy;
          },
          py::kw_only(), py::arg("intervals") = py::none(), py::arg("coordinates") = py::none(),
          py::arg("out_dir") = py::none(), py::arg("no_twist") = py::none(),
          py::arg("stabilisation_step") = py::none(), py::arg("warm_start") = py::none(),
          "A copy with the number of intervals, the coordinates, the output folder, the no-twist conditions, "
          "the stabilisation step or the mesh sequence replaced (None: kept). Raises ValueError for "
          "intervals "
          "outside 2 … 2000, unknown coordinates or invalid options (one line naming the field).")
      .def("__repr__", [](const io::MultibodyOptimalScenario& s) {
        return "MultibodyProblem(source=" + s.source +
               ", bodies=" + std::to_string(s.problem.system.body_count()) +
               ", final_time=" + std::to_string(s.problem.final_time) +
               " s, coordinates=" + std::string(io::coordinates_name(s.options.coordinates)) + ")";
      });
}

/// Loading and solving multibody problems.
void bind_multibody_solvers(py::module_& m) {
  m.def("load_multibody_scenario", &io::load_multibody_optimal_scenario, py::arg("path"),
        POINSOT_DOC(io_load_multibody_optimal_scenario));
  m.def(
      "parse_multibody_scenario",
      [](const std::string& text, const std::string& source, const std::string& base_dir) {
        return io::parse_multibody_optimal_scenario(text, source, base_dir);
      },
      py::arg("text"), py::arg("source") = "<string>", py::arg("base_dir") = "",
      POINSOT_DOC(io_parse_multibody_optimal_scenario));
  m.def(
      "_run_multibody",
      [](const io::MultibodyOptimalScenario& sc, const std::string& out_dir) {
        io::MultibodyOptimalRun run;
        {
          py::gil_scoped_release release;
          run = io::run_multibody_optimal(sc);
          if (!out_dir.empty()) io::write_multibody_optimal_files(run, out_dir);
        }
        return run_dict(run);
      },
      py::arg("scenario"), py::arg("out_dir"),
      (std::string(POINSOT_DOC(io_run_multibody_optimal)) + "\n\n" +
       POINSOT_DOC(file_io_run_multibody_optimal_run))
          .c_str());
}

}  // namespace

void bind_optimal_multibody(py::module_& parent) {
  py::module_ m = parent.attr("optimal").cast<py::module_>();
  bind_multibody_problem(m);
  bind_multibody_solvers(m);
}

}  // namespace poinsot::python
