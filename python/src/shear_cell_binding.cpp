// The shear cell step by step (drivers/shear_cell.hpp): build it, advance it
// by steps or strain, read its state as numpy arrays, write its files. Each
// step runs with the GIL released; between steps Ctrl-C is checked, so a long
// advance() stops with KeyboardInterrupt after the current step (the cell
// stays consistent: write_checkpoint() then saves it).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <limits>
#include <optional>

#include "arrays.hpp"
#include "bindings.hpp"
#include "drivers/shear_cell.hpp"
#include "drivers/shear_cell_summary.hpp"
#include "io/contacts_csv.hpp"
#include "io/input_error.hpp"
#include "io/output_folder.hpp"
#include "stepping.hpp"

namespace py = pybind11;

namespace dilatant::python {

namespace {

std::unique_ptr<ShearCell> build(const Config& config) {
  if (config.cell() == nullptr) throw InputError(config.source + ": not a shear-cell config");
  py::gil_scoped_release release;
  return std::make_unique<ShearCell>(config);
}

// Steps on by `strain` or `steps` (whichever first), or until done(); returns
// the steps taken.
long advance(ShearCell& cell, std::optional<double> strain, std::optional<long> steps) {
  const long max_steps = step_budget("strain", strain, steps);
  const double until =
      strain ? cell.state().strain + *strain : std::numeric_limits<double>::infinity();
  return step_while(cell, max_steps, [&] { return cell.state().strain < until && !cell.done(); });
}

std::string timeseries_csv(const ShearCell& cell) {
  std::string csv = flow_csv_header();
  for (const FlowRow& r : cell.state().measurements.rows)
    csv += flow_csv_row(r, cell.config().cell()->size[2]);
  return csv;
}

py::object summary(const ShearCell& cell) {
  const std::string text =
      cell_summary(cell.config(), cell.units(), cell.state(), cell.cost()).dump();
  return py::module_::import("json").attr("loads")(text);
}

}  // namespace

void bind_shear_cell(py::module_& m) {
  py::class_<ShearCell>(m, "ShearCell",
                        "The paper's shear cell, step by step (drivers/shear_cell.hpp). Code "
                        "units inside (R = rho_p = tau = 1); summary() in the paper's units.")
      .def(py::init(&build), py::arg("config"),
           "A new cell: rough walls and a packing at cell.phi, from cell.seed")
      .def_static(
          "resumed",
          [](const Config& c, const std::filesystem::path& checkpoint) {
            py::gil_scoped_release release;
            return std::make_unique<ShearCell>(ShearCell::resumed(c, checkpoint));
          },
          py::arg("config"), py::arg("checkpoint"),
          "Exactly where the run that wrote `checkpoint` stopped")
      .def_static(
          "continued",
          [](const Config& c, const std::filesystem::path& checkpoint) {
            py::gil_scoped_release release;
            return std::make_unique<ShearCell>(ShearCell::continued(c, checkpoint));
          },
          py::arg("config"), py::arg("checkpoint"),
          "The final state of another run of the same cell, under this config, strain from 0")
      .def(
          "step",
          [](ShearCell& c) {
            py::gil_scoped_release release;
            c.step();
          },
          "One time step and its measurements")
      .def("advance", &advance, py::arg("strain") = py::none(), py::arg("steps") = py::none(),
           "Steps on by `strain` (units of strain) or `steps`, whichever comes first, or until "
           "done; returns the number of steps taken")
      .def("finish", &ShearCell::finish, "Closes the time series' last row (end of a run)")
      .def_property_readonly("done", &ShearCell::done)
      .def_property_readonly("snapshot_due", &ShearCell::snapshot_due)
      .def_property_readonly("checkpoint_due", &ShearCell::checkpoint_due)
      .def_property_readonly("fraction_done", &ShearCell::fraction_done)
      .def_property_readonly("strain", [](const ShearCell& c) { return c.state().strain; })
      .def_property_readonly("time", [](const ShearCell& c) { return c.state().world.time; })
      .def_property_readonly("steps", [](const ShearCell& c) { return c.state().steps; })
      .def_property_readonly("dt", [](const ShearCell& c) { return c.state().dt; })
      .def_property_readonly("jammed", [](const ShearCell& c) { return c.state().jam.jammed; })
      .def_property_readonly("wall_velocity",
                             [](const ShearCell& c) { return c.state().drive_speed(); })
      .def_property_readonly(
          "box_height",
          // The box's height Lz (R): under cell.control = "pressure" the lid's,
          // which follows the normal stress; else cell.size[2] (walls: the
          // cell's height as configured).
          [](const ShearCell& c) {
            const auto& box = c.state().world.box;
            return box.lees_edwards ? box.length[2] : c.config().cell()->size[2];
          },
          "The box's height (code units, R): the lid's under pressure control, else cell.size[2]")
      .def_property_readonly("config", &ShearCell::config)
      .def_property_readonly(
          "positions", [](const ShearCell& c) { return vectors(c.state().world.bodies.position); })
      .def_property_readonly(
          "velocities", [](const ShearCell& c) { return vectors(c.state().world.bodies.velocity); })
      .def_property_readonly(
          "angular_velocities",
          [](const ShearCell& c) { return vectors(c.state().world.bodies.angular_velocity); })
      .def_property_readonly(
          "radii", [](const ShearCell& c) { return values(c.state().world.bodies.radius); })
      .def_property_readonly("ids",
                             [](const ShearCell& c) { return values(c.state().world.bodies.id); })
      .def_property_readonly(
          "groups",
          // Each body's owner (boundary/wall_owner.hpp); 0 for every body
          // without walls (Lees–Edwards).
          [](const ShearCell& c) { return values(c.state().world.bodies.owner); },
          "Per body: 0 mobile particle, 1 bottom wall, 2 top wall")
      .def("summary", &summary, "summary.json's fields so far, as a dict")
      .def("contacts_csv",
           [](const ShearCell& c) {
             return contacts_csv(c.state().world.bodies, c.contacts(), c.state().dt);
           })
      .def("timeseries_csv", &timeseries_csv)
      .def("velocity_profile_csv",
           [](const ShearCell& c) { return c.state().measurements.profile.csv(); })
      .def("sommerfeld_hist_csv",
           [](const ShearCell& c) {
             return sommerfeld_histogram_csv(c.state().measurements.histogram);
           })
      .def("write_checkpoint", &ShearCell::write_checkpoint, py::arg("file"))
      .def("write_snapshot", &ShearCell::write_snapshot, py::arg("out"))
      .def("write_series", &ShearCell::write_series, py::arg("out"))
      .def(
          "write_results",
          [](const ShearCell& c, const std::filesystem::path& out) {
            prepare_output_folder(out);
            c.write_results(out, c.cost());
          },
          py::arg("out"),
          "timeseries.csv, velocity_profile.csv, sommerfeld_hist.csv, contacts.csv, "
          "summary.json");
}

}  // namespace dilatant::python
