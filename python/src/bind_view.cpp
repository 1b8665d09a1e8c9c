// Bindings of view.html (io/view/view_page.hpp): the same writer as `poinsot view` and `poinsot run --html`;
// python/poinsot/_view.py wraps it as poinsot.view. Docstrings from the header.
#include <string>

#include "bindings.hpp"
#include "docstrings.hpp"
#include "poinsot/io/view/view_page.hpp"

namespace poinsot::python {

void bind_view(pybind11::module_& m) {
  namespace py = pybind11;
  m.attr("VIEW_FRAMES_DEFAULT") = io::kViewFramesDefault;
  m.def(
      "write_view_page",
      [](const std::string& run_dir, int frames, const std::string& scenario) {
        io::ViewOptions o;
        o.frames = frames;
        o.scenario_path = scenario;
        py::gil_scoped_release release;
        return io::write_view_page(run_dir, o);
      },
      py::arg("run_dir"), py::arg("frames") = io::kViewFramesDefault, py::arg("scenario") = "",
      (std::string(POINSOT_DOC(io_write_view_page)) + "\n\n" + POINSOT_DOC(file_io_view_view_page)).c_str());
  m.def(
      "view_data_json",
      [](const std::string& run_dir, int frames, const std::string& scenario) {
        io::ViewOptions o;
        o.frames = frames;
        o.scenario_path = scenario;
        return io::view_data_json(run_dir, o);
      },
      py::arg("run_dir"), py::arg("frames") = io::kViewFramesDefault, py::arg("scenario") = "",
      POINSOT_DOC(io_view_data_json));
}

}  // namespace poinsot::python
