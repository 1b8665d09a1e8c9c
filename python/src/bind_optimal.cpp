// Bindings of the optimal layer: the reorientation problem, scenario files with an [optimal_control] section,
// and a whole `poinsot optimize` (direct method, indirect method, verification, interpretation) whose samples
// come back as NumPy arrays. poinsot.optimize (python/poinsot/_optimize.py) is the public entry point.
#include <pybind11/stl.h>

#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "bindings.hpp"
#include "convert.hpp"
#include "docstrings.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/io/run/optimal_run.hpp"
#include "poinsot/io/scenario/optimal_scenario.hpp"
#include "poinsot/optimal/problem.hpp"
#include "poinsot/so3/quaternion.hpp"
#include "poinsot/so3/rotation_check.hpp"

namespace poinsot::python {

namespace {

namespace opt = poinsot::optimal;

/// An attitude given as a quaternion (w, x, y, z), shape (4,), or a rotation matrix (body → space), (3, 3).
Quat to_attitude(const py::handle& obj, const char* what) {
  const py::array a = py::array::ensure(obj);
  if (a && a.ndim() == 2) {
    const Mat3 R = to_mat3(obj, what);
    so3::require_rotation(std::string("optimal_control.") + what, R, so3::kRotationInputTolerance);
    return so3::quaternion_from_rotation(R);
  }
  const Eigen::Vector4d q = to_vec4(obj, what);
  return so3::quaternion_wxyz(q[0], q[1], q[2], q[3]);
}

/// J from principal moments (3,) or a tensor (3, 3) (kg·m²).
Mat3 to_inertia(const py::handle& obj) {
  const py::array a = py::array::ensure(obj);
  if (a && a.ndim() == 1) return to_vec3(obj, "inertia").asDiagonal();
  return to_mat3(obj, "inertia");
}

/// The cones of `kind` from a list of dicts {boresight_body, direction_space, half_angle (rad) or
/// half_angle_deg, name (optional)}; vectors of any non-zero length, normalised.
void read_cones(const py::object& list, opt::PointingKind kind, std::vector<opt::PointingConstraint>& out) {
  if (list.is_none()) return;
  const std::string key(opt::pointing_kind_name(kind));
  int index = 0;
  for (const py::handle item : list) {
    const std::string field = "optimal_control." + key + "[" + std::to_string(++index) + "]";
    if (!py::isinstance<py::dict>(item))
      throw poinsot::InvalidInput(field +
                                  ": expected a dict with boresight_body, direction_space and "
                                  "half_angle (rad) or half_angle_deg");
    const py::dict d = py::reinterpret_borrow<py::dict>(item);
    for (const auto& [k, v] : d) {
      const std::string name = py::str(k);
      if (name != "name" && name != "boresight_body" && name != "direction_space" && name != "half_angle" &&
          name != "half_angle_deg")
        throw poinsot::InvalidInput(field + "." + name +
                                    ": unknown key; expected name, boresight_body, direction_space, "
                                    "half_angle or half_angle_deg");
    }
    opt::PointingConstraint c;
    c.kind = kind;
    if (d.contains("name")) c.name = py::str(d["name"]);
    for (const char* v : {"boresight_body", "direction_space"}) {
      if (!d.contains(v)) throw poinsot::InvalidInput(field + "." + v + ": missing; expected [x, y, z]");
      const Vec3 u = to_vec3(d[v], v);
      if (!(u.norm() > 0.0))
        throw poinsot::InvalidInput(field + "." + v + ": got " + format_vector(u) +
                                    ", expected a non-zero vector");
      (std::string_view(v) == "boresight_body" ? c.boresight_body : c.direction_space) = u.normalized();
    }
    if (d.contains("half_angle") == d.contains("half_angle_deg"))
      throw poinsot::InvalidInput(field + ": expected exactly one of half_angle (rad) and half_angle_deg");
    c.half_angle = d.contains("half_angle") ? d["half_angle"].cast<double>()
                                            : d["half_angle_deg"].cast<double>() * std::numbers::pi / 180.0;
    out.push_back(std::move(c));
  }
}

/// The wheels from a dict {axes (3, 3: one wheel's spin axis a row, any non-zero length; default the body
/// axes), spin_inertia (3,) kg·m², momentum_max (one number or (3,), N·m·s; optional), momentum_initial (3,)
/// N·m·s (default 0)}; None: no wheels.
std::optional<opt::ReactionWheels> read_wheels(const py::object& obj) {
  if (obj.is_none()) return std::nullopt;
  const std::string field = "optimal_control.reaction_wheels";
  if (!py::isinstance<py::dict>(obj))
    throw poinsot::InvalidInput(field +
                                ": expected a dict with spin_inertia and optionally axes, "
                                "momentum_max and momentum_initial");
  const py::dict d = py::reinterpret_borrow<py::dict>(obj);
  for (const auto& [k, v] : d) {
    const std::string name = py::str(k);
    if (name != "axes" && name != "spin_inertia" && name != "momentum_max" && name != "momentum_initial")
      throw poinsot::InvalidInput(
          field + "." + name +
          ": unknown key; expected axes, spin_inertia, momentum_max or momentum_initial");
  }
  opt::ReactionWheels w;
  if (d.contains("axes")) {
    const Mat3 rows = to_mat3(d["axes"], "reaction_wheels.axes");
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = rows.row(k).transpose();
      if (!(a.norm() > 0.0))
        throw poinsot::InvalidInput(field + ".axes[" + std::to_string(k + 1) + "]: " + format_vector(a) +
                                    "; expected a nonzero axis");
      w.axes_body.col(k) = a.normalized();
    }
  }
  if (!d.contains("spin_inertia"))
    throw poinsot::InvalidInput(field + ".spin_inertia: missing; expected [I1, I2, I3] (kg·m²)");
  w.spin_inertia = to_vec3(d["spin_inertia"], "reaction_wheels.spin_inertia");
  if (d.contains("momentum_max")) {
    const py::array a = py::array::ensure(d["momentum_max"]);
    w.momentum_max = a && a.ndim() == 0 ? Vec3::Constant(d["momentum_max"].cast<double>())
                                        : to_vec3(d["momentum_max"], "reaction_wheels.momentum_max");
  }
  if (d.contains("momentum_initial"))
    w.momentum_initial = to_vec3(d["momentum_initial"], "reaction_wheels.momentum_initial");
  return w;
}

opt::ReorientationProblem make_problem(const ArrayLike& inertia, const ArrayLike& torque_max,
                                       const std::string& torque_bound, const py::object& rate_max,
                                       const std::string& objective, const py::object& final_time,
                                       const py::object& energy_weight, const py::object& attitude_initial,
                                       const py::object& attitude_final, const py::object& omega_initial,
                                       const py::object& omega_final, bool free_final_attitude,
                                       const py::object& keep_out, const py::object& keep_in,
                                       const py::object& reaction_wheels) {
  opt::ReorientationProblem p;
  p.inertia_body = to_inertia(inertia.obj);
  if (torque_bound != "per_axis" && torque_bound != "norm")
    throw poinsot::InvalidInput("optimal_control.torque_bound: \"" + torque_bound +
                                "\"; expected \"per_axis\" or \"norm\"");
  p.bound = torque_bound == "norm" ? opt::TorqueBound::norm : opt::TorqueBound::per_axis;
  if (p.bound == opt::TorqueBound::norm) {
    const py::array a = py::array::ensure(torque_max.obj);
    if (!a || a.ndim() != 0)
      throw poinsot::InvalidInput("optimal_control.torque_max: expected one number (N·m) with a norm bound");
    p.torque_max = Vec3::Constant(torque_max.obj.cast<double>());
  } else {
    p.torque_max = to_vec3(torque_max, "torque_max");
  }
  if (!rate_max.is_none()) p.rate_max = rate_max.cast<double>();
  p.objective = opt::parse_objective(objective, "optimal_control.objective");
  if (!final_time.is_none()) {
    if (p.objective != opt::Objective::minimum_energy)
      throw poinsot::InvalidInput(
          "optimal_control.final_time: given for a free-final-time objective; only "
          "minimum_energy takes final_time");
    p.final_time = final_time.cast<double>();
  } else if (p.objective == opt::Objective::minimum_energy) {
    throw poinsot::InvalidInput(
        "optimal_control.final_time: missing; expected the fixed final time in seconds "
        "(minimum_energy)");
  }
  if (!energy_weight.is_none()) p.energy_weight = energy_weight.cast<double>();
  if (!attitude_initial.is_none()) p.attitude_initial = to_attitude(attitude_initial, "attitude_initial");
  if (!attitude_final.is_none()) {
    if (free_final_attitude)
      throw poinsot::InvalidInput(
          "optimal_control.attitude_final: given with free_final_attitude = True; expected "
          "one of them");
    p.attitude_final = to_attitude(attitude_final, "attitude_final");
  }
  if (!omega_initial.is_none()) p.omega_initial = to_vec3(omega_initial, "omega_initial");
  if (!omega_final.is_none()) p.omega_final = to_vec3(omega_final, "omega_final");
  p.free_final_attitude = free_final_attitude;
  read_cones(keep_out, opt::PointingKind::keep_out, p.pointing);
  read_cones(keep_in, opt::PointingKind::keep_in, p.pointing);
  p.wheels = read_wheels(reaction_wheels);
  opt::validate(p);
  return p;
}

/// A scenario around a problem given directly (no file): default collocation options, no output folder.
io::OptimalScenario scenario_of(const opt::ReorientationProblem& p) {
  opt::validate(p);
  io::OptimalScenario sc;
  sc.name = "problem";
  sc.source = "<ReorientationProblem>";
  sc.body_description = "inertia " + format_matrix(p.inertia_body) + " kg·m²";
  sc.problem = p;
  return sc;
}

py::array_t<double> stack_quat(const std::vector<Quat>& qs) {
  std::vector<double> buf;
  buf.reserve(4 * qs.size());
  for (const Quat& q : qs)
    buf.insert(buf.end(), {q.w(), q.x(), q.y(), q.z()});
  return array_from_buffer(std::move(buf), {static_cast<py::ssize_t>(qs.size()), 4});
}

py::array_t<double> as_array(std::vector<double> v) {
  const auto n = static_cast<py::ssize_t>(v.size());
  return array_from_buffer(std::move(v), {n});
}

py::dict direct_dict(const opt::DirectSolution& d) {
  py::dict o;
  o["converged"] = d.converged;
  o["status"] = d.status;
  o["final_time"] = d.final_time;
  o["cost"] = d.cost;
  o["t"] = as_array(d.time);
  o["quaternion"] = stack_quat(d.attitude);
  o["omega_body"] = stack_vec3(d.omega_body);
  o["torque_body"] = stack_vec3(d.torque_body);
  o["node_time"] = as_array(d.node_time);
  o["costate_time"] = as_array(d.costate_time);
  o["costate_attitude_body"] = stack_vec3(d.costate_attitude_body);
  o["costate_omega"] = stack_vec3(d.costate_omega);
  std::vector<double> multipliers;
  for (const auto& row : d.pointing_multiplier)
    multipliers.insert(multipliers.end(), row.begin(), row.end());
  o["pointing_multiplier"] = array_from_buffer(
      std::move(multipliers),
      {static_cast<py::ssize_t>(d.pointing_multiplier.size()), static_cast<py::ssize_t>(d.time.size())});
  o["pointing_widening"] = d.pointing_widening;
  o["wheel_momentum"] = d.wheel_momentum.empty() ? py::object(py::none()) : stack_vec3(d.wheel_momentum);
  o["wheel_momentum_margin"] = d.wheel_momentum_margin;
  o["mesh_error"] = as_array(d.mesh_error);
  o["max_mesh_error"] = d.max_mesh_error;
  o["mesh_iterations"] = d.mesh_iterations;
  o["nlp_iterations"] = d.nlp_iterations;
  return o;
}

py::dict indirect_dict(const opt::IndirectSolution& s) {
  py::dict o;
  o["converged"] = s.converged;
  o["status"] = s.status;
  o["bang_bang"] = s.bang_bang;
  o["final_time"] = s.final_time;
  o["cost"] = s.cost;
  o["residual"] = s.residual;
  o["iterations"] = s.iterations;
  o["costate_attitude_initial"] = from_vec3(s.costate_attitude_initial);
  o["costate_omega_initial"] = from_vec3(s.costate_omega_initial);
  o["switch_times"] = as_array(s.switch_times);
  o["switch_axes"] = s.switch_axes;
  std::vector<double> bounds, torques;
  for (const auto& a : s.arcs) {
    bounds.insert(bounds.end(), {a.t_begin, a.t_end});
    torques.insert(torques.end(), {a.torque_body[0], a.torque_body[1], a.torque_body[2]});
  }
  const auto n_arcs = static_cast<py::ssize_t>(s.arcs.size());
  o["arc_times"] = array_from_buffer(std::move(bounds), {n_arcs, 2});
  o["arc_torque_body"] = array_from_buffer(std::move(torques), {n_arcs, 3});
  py::list rate_arcs, singular_arcs;
  for (const auto& a : s.rate_bound_arcs)
    rate_arcs.append(py::dict(py::arg("axis") = a.axis, py::arg("side") = a.side,
                              py::arg("t_entry") = a.t_entry, py::arg("t_exit") = a.t_exit));
  for (const auto& a : s.singular_arcs)
    singular_arcs.append(
        py::dict(py::arg("axis") = a.axis, py::arg("t_entry") = a.t_entry, py::arg("t_exit") = a.t_exit));
  o["rate_bound_arcs"] = rate_arcs;
  o["singular_arcs"] = singular_arcs;
  o["t"] = as_array(s.time);
  o["R"] = stack_mat3(s.attitude);
  o["omega_body"] = stack_vec3(s.omega_body);
  o["torque_body"] = stack_vec3(s.torque_body);
  o["costate_attitude"] = stack_mat3(s.costate_attitude);
  o["costate_attitude_body"] = stack_vec3(s.costate_attitude_body);
  o["costate_omega"] = stack_vec3(s.costate_omega);
  o["switching_function"] = stack_vec3(s.switching_function);
  o["hamiltonian"] = as_array(s.hamiltonian);
  return o;
}

py::dict interpretation_dict(const io::OptimalRun& r) {
  py::dict o;
  if (!r.has_interpretation) return o;
  const auto& m = r.interpretation;
  o["lambda_body"] = stack_mat3(m.lambda_body);
  o["stress_space"] = stack_mat3(m.stress_space);
  o["momentum_space"] = stack_vec3(m.momentum_space);
  return o;
}

void bind_problem(py::module_& m) {
  py::class_<opt::ReorientationProblem>(m, "ReorientationProblem", POINSOT_DOC(file_optimal_problem))
      .def(
          py::init(&make_problem), py::kw_only(), py::arg("inertia"), py::arg("torque_max"),
          py::arg("torque_bound") = "per_axis", py::arg("rate_max") = py::none(),
          py::arg("objective") = "minimum_time", py::arg("final_time") = py::none(),
          py::arg("energy_weight") = py::none(), py::arg("attitude_initial") = py::none(),
          py::arg("attitude_final") = py::none(), py::arg("omega_initial") = py::none(),
          py::arg("omega_final") = py::none(), py::arg("free_final_attitude") = false,
          py::arg("keep_out") = py::none(), py::arg("keep_in") = py::none(),
          py::arg("reaction_wheels") = py::none(),
          "A validated problem. inertia: principal moments (3,) or J (3, 3) about the centre of mass, body "
          "frame (kg·m²); torque_max: (3,) per-axis bounds or one number with torque_bound=\"norm\" (N·m); "
          "rate_max: |ω_i| bound (rad/s) or None; objective: \"minimum_time\", \"minimum_energy\" (needs "
          "final_time, s) or \"minimum_time_regularised\" (needs energy_weight, s/(N·m)²); attitudes: "
          "quaternions (w, x, y, z) or rotation matrices (body → space), default identity; omega_initial, "
          "omega_final: body frame (rad/s), default 0; free_final_attitude: detumbling (no attitude_final); "
          "keep_out, keep_in: lists of cones, each a dict {boresight_body (body frame), direction_space "
          "(space frame), half_angle (rad) or half_angle_deg, name (optional)}: the boresight stays at least "
          "(keep_out) or at most (keep_in) the half-angle from the direction; reaction_wheels: a dict "
          "{spin_inertia (3,) kg·m², axes (3, 3) one spin axis a row (default the body axes), momentum_max "
          "(N·m·s, one number or (3,); optional), momentum_initial (3,) N·m·s}: the controls are then the "
          "wheels' motor torques (torque_max per wheel) and inertia is the whole spacecraft's with the "
          "wheels "
          "locked. Raises ValueError naming the field for invalid input (optimal::validate).")
      .def_property_readonly(
          "inertia_body", [](const opt::ReorientationProblem& p) { return from_mat3(p.inertia_body); },
          POINSOT_DOC(optimal_ReorientationProblem_inertia_body))
      .def_property_readonly("torque_bound",
                             [](const opt::ReorientationProblem& p) {
                               return p.bound == opt::TorqueBound::norm ? "norm" : "per_axis";
                             })
      .def_property_readonly(
          "torque_max",
          [](const opt::ReorientationProblem& p) -> py::object {
            if (p.bound == opt::TorqueBound::norm) return py::float_(p.torque_max[0]);
            return from_vec3(p.torque_max);
          },
          POINSOT_DOC(optimal_ReorientationProblem_torque_max))
      .def_property_readonly(
          "rate_max",
          [](const opt::ReorientationProblem& p) -> py::object {
            return p.has_rate_bound() ? py::object(py::float_(p.rate_max)) : py::none();
          },
          POINSOT_DOC(optimal_ReorientationProblem_rate_max))
      .def_property_readonly(
          "attitude_initial",
          [](const opt::ReorientationProblem& p) { return from_quat(p.attitude_initial); },
          POINSOT_DOC(optimal_ReorientationProblem_attitude_initial))
      .def_property_readonly(
          "attitude_final", [](const opt::ReorientationProblem& p) { return from_quat(p.attitude_final); },
          POINSOT_DOC(optimal_ReorientationProblem_attitude_final))
      .def_property_readonly(
          "omega_initial", [](const opt::ReorientationProblem& p) { return from_vec3(p.omega_initial); },
          POINSOT_DOC(optimal_ReorientationProblem_omega_initial))
      .def_property_readonly(
          "omega_final", [](const opt::ReorientationProblem& p) { return from_vec3(p.omega_final); },
          POINSOT_DOC(optimal_ReorientationProblem_omega_final))
      .def_readonly("free_final_attitude", &opt::ReorientationProblem::free_final_attitude,
                    POINSOT_DOC(optimal_ReorientationProblem_free_final_attitude))
      .def_property_readonly(
          "pointing",
          [](const opt::ReorientationProblem& p) {
            py::list out;
            for (const auto& c : p.pointing) {
              py::dict d;
              d["name"] = c.name;
              d["kind"] = std::string(opt::pointing_kind_name(c.kind));
              d["boresight_body"] = from_vec3(c.boresight_body);
              d["direction_space"] = from_vec3(c.direction_space);
              d["half_angle"] = c.half_angle;
              out.append(d);
            }
            return out;
          },
          POINSOT_DOC(optimal_ReorientationProblem_pointing))
      .def_property_readonly(
          "reaction_wheels",
          [](const opt::ReorientationProblem& p) -> py::object {
            if (!p.wheels) return py::none();
            py::dict d;
            d["axes"] = from_mat3(p.wheels->axes_body.transpose());
            d["spin_inertia"] = from_vec3(p.wheels->spin_inertia);
            d["momentum_max"] = from_vec3(p.wheels->momentum_max);
            d["momentum_initial"] = from_vec3(p.wheels->momentum_initial);
            d["total_momentum_space"] = from_vec3(p.wheel_system_momentum());
            return d;
          },
          POINSOT_DOC(optimal_ReorientationProblem_wheels))
      .def_property_readonly(
          "objective",
          [](const opt::ReorientationProblem& p) { return std::string(opt::objective_name(p.objective)); })
      .def_readonly("final_time", &opt::ReorientationProblem::final_time,
                    POINSOT_DOC(optimal_ReorientationProblem_final_time))
      .def_readonly("energy_weight", &opt::ReorientationProblem::energy_weight,
                    POINSOT_DOC(optimal_ReorientationProblem_energy_weight))
      .def("torque_norm_limit", &opt::ReorientationProblem::torque_norm_limit,
           POINSOT_DOC(optimal_ReorientationProblem_torque_norm_limit))
      .def("minimum_duration_bound", &opt::minimum_duration_bound,
           POINSOT_DOC(optimal_minimum_duration_bound))
      .def("__repr__", [](const opt::ReorientationProblem& p) {
        return "ReorientationProblem(objective=" + std::string(opt::objective_name(p.objective)) +
               ", inertia=" + format_matrix(p.inertia_body) + ", torque_max=" +
               (p.bound == opt::TorqueBound::norm ? "norm " + format_number(p.torque_max[0])
                                                  : format_vector(p.torque_max)) +
               ")";
      });
}

void bind_optimal_scenario(py::module_& m) {
  py::class_<io::OptimalScenario>(m, "OptimalScenario", POINSOT_DOC(file_io_scenario_optimal_scenario))
      .def(py::init(&scenario_of), py::arg("problem"),
           "A scenario around a problem given in Python (default collocation options, no output folder).")
      .def_readonly("name", &io::OptimalScenario::name, POINSOT_DOC(io_OptimalScenario_name))
      .def_readonly("source", &io::OptimalScenario::source, POINSOT_DOC(io_OptimalScenario_source))
      .def_readonly("title", &io::OptimalScenario::title, POINSOT_DOC(io_OptimalScenario_title))
      .def_readonly("body_description", &io::OptimalScenario::body_description,
                    POINSOT_DOC(io_OptimalScenario_body_description))
      .def_readonly("problem", &io::OptimalScenario::problem, POINSOT_DOC(io_OptimalScenario_problem))
      .def_readonly("out_dir", &io::OptimalScenario::out_dir, POINSOT_DOC(io_OptimalScenario_out_dir))
      .def_property_readonly(
          "mesh_tolerance", [](const io::OptimalScenario& s) { return s.collocation.mesh_tolerance; },
          POINSOT_DOC(optimal_CollocationOptions_mesh_tolerance))
      .def_property_readonly("initial_intervals",
                             [](const io::OptimalScenario& s) { return s.collocation.initial_intervals; })
      .def_property_readonly("max_mesh_iterations",
                             [](const io::OptimalScenario& s) { return s.collocation.max_mesh_iterations; })
      .def_property_readonly(
          "starts", [](const io::OptimalScenario& s) { return s.collocation.starts; },
          POINSOT_DOC(optimal_CollocationOptions_starts))
      .def(
          "with_options",
          [](const io::OptimalScenario& s, const py::object& mesh_tolerance,
             const py::object& initial_intervals, const py::object& max_mesh_iterations,
             const py::object& starts, const py::object& out_dir) {
            io::OptimalScenario copy = s;
            if (!mesh_tolerance.is_none()) copy.collocation.mesh_tolerance = mesh_tolerance.cast<double>();
            if (!initial_intervals.is_none())
              copy.collocation.initial_intervals = initial_intervals.cast<int>();
            if (!max_mesh_iterations.is_none())
              copy.collocation.max_mesh_iterations = max_mesh_iterations.cast<int>();
            if (!starts.is_none()) copy.collocation.starts = starts.cast<int>();
            if (!out_dir.is_none()) copy.out_dir = out_dir.cast<std::string>();
            opt::validate(copy.collocation);
            return copy;
          },
          py::kw_only(), py::arg("mesh_tolerance") = py::none(), py::arg("initial_intervals") = py::none(),
          py::arg("max_mesh_iterations") = py::none(), py::arg("starts") = py::none(),
          py::arg("out_dir") = py::none(),
          "A copy with the direct method's options replaced (None: kept). Raises ValueError for "
          "initial_intervals < 2, max_mesh_iterations < 1, starts outside 1 … 64 or a tolerance that is not "
          "finite and positive.")
      .def("__repr__", [](const io::OptimalScenario& s) {
        return "OptimalScenario(source=" + s.source +
               ", objective=" + std::string(opt::objective_name(s.problem.objective)) + ")";
      });

  m.def("load_scenario", &io::load_optimal_scenario, py::arg("path"), POINSOT_DOC(io_load_optimal_scenario));
  m.def(
      "parse_scenario",
      [](const std::string& text, const std::string& source, const std::string& base_dir) {
        return io::parse_optimal_scenario(text, source, base_dir);
      },
      py::arg("text"), py::arg("source") = "<string>", py::arg("base_dir") = "",
      POINSOT_DOC(io_parse_optimal_scenario));
}

}  // namespace

void bind_optimal(py::module_& parent) {
  auto m =
      parent.def_submodule("optimal",
                           "Optimal reorientation of one rigid body (the layer optimal/; "
                           "poinsot.optimize runs it): problems, scenario files with [optimal_control].");
  bind_problem(m);
  bind_optimal_scenario(m);
  m.def(
      "_run",
      [](const io::OptimalScenario& sc, const std::string& out_dir) {
        io::OptimalRun run;
        {
          py::gil_scoped_release release;
          run = io::run_optimal(sc);
          if (!out_dir.empty()) io::write_optimal_files(run, out_dir);
        }
        py::dict o;
        o["summary"] = io::optimal_summary_json(run);
        o["report"] = io::optimal_report(run);
        o["optimal"] = run.optimal;
        o["status"] = run.status;
        o["direct"] = direct_dict(run.direct);
        o["indirect"] = indirect_dict(run.indirect);
        o["interpretation"] = interpretation_dict(run);
        return o;
      },
      py::arg("scenario"), py::arg("out_dir"),
      (std::string(POINSOT_DOC(io_run_optimal)) + "\n\n" + POINSOT_DOC(file_io_run_optimal_run)).c_str());
}

}  // namespace poinsot::python
