// Whole runs from Python, each the library's own run loop (the CLI's, so the
// same files and the same bits): run_shear_cell, run_scene, run_sediment and
// run_sweep, quiet, with the GIL released and Ctrl-C turned into a clean stop
// (interruptible.hpp). The Python package (dilatant/runs.py) reads the
// results back as numpy arrays.
#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <atomic>
#include <functional>

#include "bindings.hpp"
#include "drivers/scene_run.hpp"
#include "drivers/sediment_run.hpp"
#include "drivers/setup_monitor.hpp"
#include "drivers/shear_cell_run.hpp"
#include "interruptible.hpp"
#include "io/input_error.hpp"
#include "sweep/sweep_analysis.hpp"
#include "sweep/sweep_plan.hpp"
#include "sweep/sweep_runner.hpp"

namespace py = pybind11;

namespace dilatant::python {

namespace {

// A poll for run_interruptibly: calls `progress` (may be None) with `fraction`
// whenever it changed; only an explicit False from it stops the work (a
// callback that returns nothing goes on).
std::function<bool()> progress_reporter(const py::object& progress,
                                        const std::atomic<double>& fraction) {
  return [&progress, &fraction, reported = -1.0]() mutable {
    if (progress.is_none()) return true;
    const double now = fraction.load();
    if (now == reported) return true;
    reported = now;
    const py::object answer = progress(now);
    return !(py::isinstance<py::bool_>(answer) && !answer.cast<bool>());
  };
}

// `progress` (may be None) gets the fraction of run.strain done, whenever it
// changed; returning False stops the run (checkpoint written).
py::dict run_cell(const Config& config, const std::filesystem::path& out, bool resume,
                  const std::filesystem::path& start_from, const py::object& progress) {
  if (config.cell() == nullptr) throw InputError(config.source + ": not a shear-cell config");
  std::atomic<bool> stop{false};
  std::atomic<double> fraction{0.0};
  CellRunOptions options{RunOptions{out, /*quiet=*/true}, resume, &stop};
  options.start_from = start_from;
  options.stop_setup = &stop;
  options.progress = &fraction;
  const auto report = progress_reporter(progress, fraction);
  const CellOutcome outcome = run_interruptibly<CellOutcome>(
      [&] {
        try {
          return run_shear_cell(config, options);
        } catch (const SetupInterrupted&) {  // stopped before the first step: nothing to resume
          CellOutcome o;
          o.interrupted = true;
          return o;
        }
      },
      stop, report);
  if (!outcome.interrupted) report();
  py::dict d;
  d["steps"] = outcome.steps;
  d["unconverged_steps"] = outcome.unconverged_steps;
  d["interrupted"] = outcome.interrupted;
  d["jammed"] = outcome.jammed;
  return d;
}

// `progress` (may be None) gets the fraction of run.time done, whenever it
// changed; returning False stops the run (checkpoint written).
py::dict run_scene_py(const Config& config, const std::filesystem::path& out, bool resume,
                      const py::object& progress) {
  if (config.scene() == nullptr) throw InputError(config.source + ": not a scene config");
  std::atomic<bool> stop{false};
  std::atomic<double> fraction{0.0};
  SceneRunOptions options{RunOptions{out, /*quiet=*/true}, resume, &stop, &fraction};
  const auto report = progress_reporter(progress, fraction);
  const SceneOutcome outcome =
      run_interruptibly<SceneOutcome>([&] { return run_scene(config, options); }, stop, report);
  if (!outcome.interrupted) report();
  py::dict d;
  d["steps"] = outcome.steps;
  d["unconverged_steps"] = outcome.unconverged_steps;
  d["interrupted"] = outcome.interrupted;
  return d;
}

// Ctrl-C, or False from `progress` (may be None; called with the fraction of
// the samples finished), stops the run: the running sample is abandoned, the
// finished ones stay in its checkpoint.
py::dict run_sediment_py(const Config& config, const std::filesystem::path& out, bool resume,
                         const py::object& progress) {
  if (config.sediment() == nullptr) throw InputError(config.source + ": not a sediment config");
  std::atomic<bool> stop{false};
  std::atomic<double> fraction{0.0};
  SedimentRunOptions options{RunOptions{out, /*quiet=*/true}, resume, &stop, &fraction};
  const auto report = progress_reporter(progress, fraction);
  const SedimentOutcome outcome = run_interruptibly<SedimentOutcome>(
      [&] { return run_sediment(config, options); }, stop, report);
  if (!outcome.interrupted) report();
  py::dict d;
  d["steps"] = outcome.steps;
  d["unconverged_steps"] = outcome.unconverged_steps;
  d["interrupted"] = outcome.interrupted;
  d["phi_max"] = outcome.phi_max;
  d["phi_max_err"] = outcome.phi_max_err;
  d["settled"] = outcome.settled;
  return d;
}

// `progress` (may be None) gets the fraction of the sweep done whenever it
// changed (sweep_runner.hpp); returning False stops the sweep (the running
// points checkpointed, as Ctrl-C).
py::dict run_sweep_py(const sweep::SweepPlan& plan, const std::filesystem::path& out, int jobs,
                      const py::object& progress) {
  std::atomic<bool> stop{false};
  std::atomic<double> fraction{0.0};
  sweep::SweepRunOptions options;
  options.out = out;
  options.jobs = jobs;
  options.stop = &stop;
  options.progress = &fraction;
  const auto report = progress_reporter(progress, fraction);
  const sweep::SweepOutcome o = run_interruptibly<sweep::SweepOutcome>(
      [&] { return sweep::run_sweep(plan, options); }, stop, report);
  if (!o.interrupted) report();
  py::dict d;
  d["points"] = o.points;
  d["done"] = o.done;
  d["skipped"] = o.skipped;
  d["failed"] = o.failed;
  d["pending"] = o.pending;
  d["above_jam"] = o.above_jam;
  d["interrupted"] = o.interrupted;
  return d;
}

}  // namespace

void bind_runs(py::module_& m) {
  m.def("run_cell", &run_cell, py::arg("config"), py::arg("out"), py::arg("resume"),
        py::arg("start_from"), py::arg("progress"));
  m.def("run_scene", &run_scene_py, py::arg("config"), py::arg("out"), py::arg("resume"),
        py::arg("progress"));
  m.def("run_sediment", &run_sediment_py, py::arg("config"), py::arg("out"), py::arg("resume"),
        py::arg("progress"));

  py::class_<sweep::SweepSettings>(m, "SweepSettings")
      .def_readonly("jobs", &sweep::SweepSettings::jobs)
      .def_readonly("continuation", &sweep::SweepSettings::continuation);
  py::class_<sweep::SweepPlan>(m, "SweepPlan", "The points of a sweep file (sweep/sweep_plan.hpp)")
      .def_readonly("source", &sweep::SweepPlan::source)
      .def_readonly("settings", &sweep::SweepPlan::settings)
      .def_readonly("keys", &sweep::SweepPlan::keys)
      .def_property_readonly("labels",
                             [](const sweep::SweepPlan& p) {
                               std::vector<std::string> labels;
                               for (const auto& point : p.points) labels.push_back(point.label);
                               return labels;
                             })
      .def("to_toml", &sweep::resolved_sweep_toml)
      .def("__len__", [](const sweep::SweepPlan& p) { return p.points.size(); });
  m.def("sweep_from_path", &sweep::load_sweep, py::arg("path"), py::arg("overrides"));
  m.def("sweep_from_text", &sweep::parse_sweep, py::arg("text"), py::arg("source"),
        py::arg("base_dir"), py::arg("overrides"));
  m.def("run_sweep", &run_sweep_py, py::arg("plan"), py::arg("out"), py::arg("jobs"),
        py::arg("progress"));
  m.def(
      "analyse_sweep",
      [](const std::filesystem::path& dir) {
        py::gil_scoped_release release;
        return sweep::analyse_sweep(dir);
      },
      py::arg("dir"));
}

}  // namespace dilatant::python
