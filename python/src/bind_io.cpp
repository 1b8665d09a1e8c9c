// Bindings of the io layer: scenario files (load, parse, override) and a whole `poinsot run` (files, summary,
// report) from Python. Docstrings from the headers.
#include <pybind11/stl.h>

#include <string>

#include "bindings.hpp"
#include "convert.hpp"
#include "docstrings.hpp"
#include "poinsot/io/run/multibody_run.hpp"
#include "poinsot/io/run/report.hpp"
#include "poinsot/io/run/run.hpp"
#include "poinsot/io/run/summary.hpp"
#include "poinsot/io/scenario/multibody_scenario.hpp"
#include "poinsot/io/scenario/scenario.hpp"

namespace poinsot::python {

using io::Scenario;

namespace {

/// The keyword arguments of with_overrides and _run_multibody_scenario (None: unset), as the command line's.
io::ScenarioOverrides overrides_of(const std::string& method, const py::object& dt, const py::object& t_end,
                                   const py::object& sample_dt) {
  io::ScenarioOverrides o;
  o.method = method;
  if (!dt.is_none()) o.dt = dt.cast<double>();
  if (!t_end.is_none()) o.t_end = t_end.cast<double>();
  if (!sample_dt.is_none()) o.sample_dt = sample_dt.cast<double>();
  return o;
}

}  // namespace

void bind_io(py::module_& m) {
  py::class_<Scenario>(m, "Scenario", POINSOT_DOC(file_io_scenario_scenario))
      .def_readonly("name", &Scenario::name, POINSOT_DOC(io_Scenario_name))
      .def_readonly("source", &Scenario::source, POINSOT_DOC(io_Scenario_source))
      .def_readonly("title", &Scenario::title, POINSOT_DOC(io_Scenario_title))
      .def_readonly("body", &Scenario::body, POINSOT_DOC(io_Scenario_body))
      .def_readonly("body_description", &Scenario::body_description,
                    POINSOT_DOC(io_Scenario_body_description))
      .def_readonly("initial", &Scenario::initial, POINSOT_DOC(io_Scenario_initial))
      .def_readonly("torque_type", &Scenario::torque_type, POINSOT_DOC(io_Scenario_torque_type))
      .def_property_readonly(
          "torque",
          [](const Scenario& s) { return std::const_pointer_cast<dynamics::TorqueModel>(s.torque); },
          POINSOT_DOC(io_Scenario_torque))
      .def_property_readonly(
          "gravity_space", [](const Scenario& s) { return from_vec3(s.gravity_space); },
          POINSOT_DOC(io_Scenario_gravity_space))
      .def_readonly("method", &Scenario::method, POINSOT_DOC(io_Scenario_method))
      .def_property_readonly(
          "dt", [](const Scenario& s) { return s.integrator.dt; }, POINSOT_DOC(dynamics_IntegratorOptions_dt))
      .def_property_readonly(
          "max_step", [](const Scenario& s) { return s.integrator.max_step; },
          POINSOT_DOC(dynamics_IntegratorOptions_max_step))
      .def_property_readonly(
          "rtol", [](const Scenario& s) { return s.integrator.rtol; },
          POINSOT_DOC(dynamics_IntegratorOptions_rtol))
      .def_property_readonly(
          "atol", [](const Scenario& s) { return s.integrator.atol; },
          POINSOT_DOC(dynamics_IntegratorOptions_atol))
      .def_property_readonly(
          "newton_tolerance", [](const Scenario& s) { return s.integrator.newton_tolerance; },
          POINSOT_DOC(dynamics_IntegratorOptions_newton_tolerance))
      .def_property_readonly("newton_max_iterations",
                             [](const Scenario& s) { return s.integrator.newton_max_iterations; })
      .def_property_readonly(
          "t_end", [](const Scenario& s) { return s.simulation.t_end; },
          POINSOT_DOC(dynamics_SimulationOptions_t_end))
      .def_property_readonly(
          "sample_dt", [](const Scenario& s) { return s.simulation.sample_dt; },
          POINSOT_DOC(dynamics_SimulationOptions_sample_dt))
      .def_property_readonly(
          "locate_flips", [](const Scenario& s) { return s.simulation.locate_flips; },
          POINSOT_DOC(dynamics_SimulationOptions_locate_flips))
      .def_readonly("out_dir", &Scenario::out_dir, POINSOT_DOC(io_Scenario_out_dir))
      .def(
          "with_overrides",
          [](const Scenario& s, const std::string& method, py::object dt, py::object t_end,
             py::object sample_dt, const std::string& out_dir) {
            Scenario copy = s;
            io::ScenarioOverrides o = overrides_of(method, dt, t_end, sample_dt);
            o.out_dir = out_dir;
            io::apply_overrides(copy, o);
            return copy;
          },
          py::kw_only(), py::arg("method") = "", py::arg("dt") = py::none(), py::arg("t_end") = py::none(),
          py::arg("sample_dt") = py::none(), py::arg("out_dir") = "",
          (std::string(
               "A copy with the command line's overrides applied (validated as `poinsot run` does).\n\n") +
           POINSOT_DOC(io_apply_overrides))
              .c_str())
      .def("__repr__", [](const Scenario& s) {
        return "Scenario(name=" + s.name + ", method=" + s.method + ", torque=" + s.torque->describe() + ")";
      });

  m.def("load_scenario", &io::load_scenario, py::arg("path"), POINSOT_DOC(io_load_scenario));
  m.def(
      "parse_scenario",
      [](const std::string& text, const std::string& source, const std::string& base_dir) {
        return io::parse_scenario(text, source, base_dir);
      },
      py::arg("text"), py::arg("source") = "<string>", py::arg("base_dir") = "",
      POINSOT_DOC(io_parse_scenario));

  m.def(
      "_run_scenario",
      [](const Scenario& s, const std::string& out_dir) {
        io::RunOptions o;
        o.out_dir = out_dir;
        if (!out_dir.empty()) io::prepare_output_dir(out_dir);
        io::RunSummary summary;
        {
          py::gil_scoped_release release;
          summary = io::run_scenario(s, o);
        }
        return py::make_tuple(io::summary_json(summary), io::format_report(summary));
      },
      py::arg("scenario"), py::arg("out_dir"),
      (std::string(POINSOT_DOC(io_run_scenario)) + "\n\n" + POINSOT_DOC(file_io_run_run)).c_str());

  m.def(
      "_run_multibody_scenario",
      [](const multibody::Scenario& s, const std::string& out_dir, const std::string& method,
         const py::object& dt, const py::object& t_end, const py::object& sample_dt) {
        multibody::Scenario sc = s;
        io::apply_overrides(sc, overrides_of(method, dt, t_end, sample_dt));
        io::MultibodyRunOptions o;
        o.out_dir = out_dir;
        io::MultibodyRunSummary summary;
        {
          py::gil_scoped_release release;
          summary = io::run_multibody_scenario(sc, o);
        }
        return py::make_tuple(io::multibody_summary_json(sc, summary),
                              io::format_multibody_report(sc, summary));
      },
      py::arg("scenario"), py::arg("out_dir"), py::kw_only(), py::arg("method") = "",
      py::arg("dt") = py::none(), py::arg("t_end") = py::none(), py::arg("sample_dt") = py::none(),
      (std::string(POINSOT_DOC(io_run_multibody_scenario)) + "\n\n" + POINSOT_DOC(file_io_run_multibody_run))
          .c_str());
}

}  // namespace poinsot::python
