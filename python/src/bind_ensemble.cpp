// Bindings of the ensemble front end: poinsot.ensemble(path, ...) runs `poinsot ensemble` in process, with
// the GIL released, and returns NumPy arrays of the per-sample rows beside the summary (the same JSON text as
// summary.json, parsed). Docstrings from the headers.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <string>

#include "bindings.hpp"
#include "docstrings.hpp"
#include "poinsot/io/run/ensemble_output.hpp"

namespace poinsot::python {

namespace py = pybind11;

namespace {

py::dict run(const std::string& path, std::optional<std::uint64_t> samples, unsigned threads, bool simd,
             bool per_sample) {
  const io::EnsembleScenario sc = io::load_ensemble_scenario(path);
  ensemble::EnsembleOptions o = io::ensemble_options(sc);
  if (samples) o.samples = *samples;
  o.threads = threads;
  o.simd = simd ? ensemble::Simd::automatic : ensemble::Simd::off;
  o.keep_rows = per_sample;
  ensemble::EnsembleResult r;
  std::string summary;
  {
    const py::gil_scoped_release release;
    const ensemble::Sampler sampler(sc.nominal, sc.dispersions, sc.seed);
    r = ensemble::run_ensemble(sampler, o);
    summary = io::ensemble_summary_json(sc, o, r);
  }
  const auto n = static_cast<py::ssize_t>(r.rows.size());
  py::array_t<std::uint64_t> index(n);
  py::array_t<int> rejected(n);
  py::array_t<bool> repaired(n);
  py::array_t<double> misalignment(n);
  py::array_t<double> moments({n, py::ssize_t{3}}), omega0({n, py::ssize_t{3}}), omega({n, py::ssize_t{3}});
  py::array_t<double> quaternion({n, py::ssize_t{4}});
  std::vector<py::array_t<double>> outputs;
  for (int q = 0; q < ensemble::kOutputCount; ++q)
    outputs.emplace_back(n);
  for (py::ssize_t i = 0; i < n; ++i) {
    const ensemble::SampleRow& row = r.rows[static_cast<std::size_t>(i)];
    index.mutable_at(i) = row.index;
    rejected.mutable_at(i) = row.rejected;
    repaired.mutable_at(i) = row.repaired;
    misalignment.mutable_at(i) = row.misalignment;
    const Quat qf = row.final_state.quaternion();
    const double qv[4] = {qf.w(), qf.x(), qf.y(), qf.z()};
    for (py::ssize_t k = 0; k < 3; ++k) {
      moments.mutable_at(i, k) = row.moments[k];
      omega0.mutable_at(i, k) = row.omega0[k];
      omega.mutable_at(i, k) = row.final_state.omega_body[k];
    }
    for (py::ssize_t k = 0; k < 4; ++k)
      quaternion.mutable_at(i, k) = qv[k];
    for (std::size_t q = 0; q < outputs.size(); ++q)
      outputs[q].mutable_at(i) = row.out[q];
  }
  py::dict d;
  d["index"] = index;
  d["rejected"] = rejected;
  d["repaired"] = repaired;
  d["moments"] = moments;
  d["misalignment"] = misalignment;
  d["omega0"] = omega0;
  for (int q = 0; q < ensemble::kOutputCount; ++q)
    d[ensemble::kOutputNames[q]] = outputs[static_cast<std::size_t>(q)];
  d["quaternion_final"] = quaternion;
  d["omega_final"] = omega;
  d["summary"] = py::module_::import("json").attr("loads")(summary);
  return d;
}

}  // namespace

void bind_ensemble(py::module_& m) {
  m.def("ensemble", &run, py::arg("path"), py::kw_only(), py::arg("samples") = py::none(),
        py::arg("threads") = 1, py::arg("simd") = true, py::arg("per_sample") = true,
        (std::string("Runs `poinsot ensemble PATH` in process (the GIL released) and returns a dict of NumPy "
                     "arrays, one entry per sample: index, rejected, repaired, moments (N, 3), misalignment, "
                     "omega0 (N, 3), every output (first_flip_time, flip_interval, flip_interval_theory, "
                     "attitude_error, energy_error, L_space_error, for heavy tops precession_rate, "
                     "nutation_frequency, nutation_amplitude, and with [ensemble.slew] pointing_error, "
                     "rate_error, peak_torque, peak_feedback_torque, peak_wheel_momentum, "
                     "meets_requirement), quaternion_final (N, 4), omega_final "
                     "(N, 3); and 'summary', the dict of summary.json. Nothing is written to disk.\n\n") +
         POINSOT_DOC(file_io_scenario_ensemble_scenario))
            .c_str());
}

}  // namespace poinsot::python
