// Scenes and sediments step by step, as the shear cell (shear_cell_binding.cpp):
// build one from its config, advance it by time or steps, read its state as
// numpy arrays. A scene is drivers/scene.hpp (particles from a CSV, planes,
// gravity); a sediment is one sample of `dilatant jam` (drivers/sediment.hpp:
// spheres settling onto a floor until they stop; measure() gives its fraction).
#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <limits>
#include <memory>
#include <optional>

#include "arrays.hpp"
#include "bindings.hpp"
#include "drivers/scene.hpp"
#include "drivers/scene_checkpoint.hpp"
#include "drivers/sediment.hpp"
#include "drivers/sediment_run.hpp"
#include "io/contacts_csv.hpp"
#include "io/input_error.hpp"
#include "stepping.hpp"

namespace py = pybind11;

namespace dilatant::python {

namespace {

std::unique_ptr<Scene> build_scene(const Config& config) {
  if (config.scene() == nullptr) throw InputError(config.source + ": not a scene config");
  py::gil_scoped_release release;
  return std::make_unique<Scene>(config);
}

std::unique_ptr<Sediment> build_sediment(const Config& config, int sample) {
  const SedimentConfig* sediment = config.sediment();
  if (sediment == nullptr) throw InputError(config.source + ": not a [sediment] config");
  if (sample < 0 || sample >= sediment->samples)
    throw InputError(
        fmt::format("sample {}: must be in [0, sediment.samples = {})", sample, sediment->samples));
  const SedimentSettings settings = sediment_settings(config, sample);
  py::gil_scoped_release release;
  return std::make_unique<Sediment>(settings);
}

// Steps on by `time` or `steps` (whichever first), or until `finished()`.
template <class Object, class Finished>
long advance_in_time(Object& object, std::optional<double> time, std::optional<long> steps,
                     Finished finished) {
  const long max_steps = step_budget("time", time, steps);
  const double until = time ? object.world().time + *time : std::numeric_limits<double>::infinity();
  return step_while(object, max_steps, [&] { return object.world().time < until && !finished(); });
}

// The per-body state both objects share, as numpy copies.
template <class Object, class Class>
void bind_bodies(Class& c) {
  c.def_property_readonly("time", [](const Object& o) { return o.world().time; })
      .def_property_readonly("dt", &Object::dt)
      .def_property_readonly("positions",
                             [](const Object& o) { return vectors(o.world().bodies.position); })
      .def_property_readonly("velocities",
                             [](const Object& o) { return vectors(o.world().bodies.velocity); })
      .def_property_readonly(
          "angular_velocities",
          [](const Object& o) { return vectors(o.world().bodies.angular_velocity); })
      .def_property_readonly("radii",
                             [](const Object& o) { return values(o.world().bodies.radius); })
      .def_property_readonly("ids", [](const Object& o) { return values(o.world().bodies.id); });
}

}  // namespace

void bind_scenes(py::module_& m) {
  py::class_<Scene> scene(m, "Scene",
                          "A scene step by step (drivers/scene.hpp): particles from "
                          "scene.particles, planes, gravity, to run.time");
  scene.def(py::init(&build_scene), py::arg("config"))
      .def_static(
          "resumed",
          [](const Config& config, const std::filesystem::path& checkpoint) {
            auto s = build_scene(config);
            restore_scene(*s, load_scene_checkpoint(checkpoint), config, checkpoint);
            return s;
          },
          py::arg("config"), py::arg("checkpoint"),
          "Exactly where the scene that wrote `checkpoint` (a `dilatant run`'s or "
          "write_checkpoint()'s) stopped; the particles file must be the one it was built from")
      .def(
          "write_checkpoint",
          [](const Scene& s, const std::filesystem::path& file) {
            // No output files belong to a scene stepped by hand: no frame due,
            // no bytes of series written.
            save_scene_checkpoint(
                file, SceneCheckpoint{s.progress(), scene_particles_crc(s.config()), 0.0, 0, 0});
          },
          py::arg("file"),
          "The scene's state, atomically, as `dilatant run` checkpoints it: Scene.resumed() "
          "goes on from it bit for bit")
      .def(
          "step",
          [](Scene& s) {
            py::gil_scoped_release release;
            s.step();
          },
          "One time step (or the rest of one a redo shortened)")
      .def(
          "advance",
          [](Scene& s, std::optional<double> time, std::optional<long> steps) {
            return advance_in_time(s, time, steps, [&] { return s.done(); });
          },
          py::arg("time") = py::none(), py::arg("steps") = py::none(),
          "Steps on by `time` or `steps`, whichever comes first, or until done; returns the "
          "number of steps taken")
      .def_property_readonly("done", &Scene::done)
      .def_property_readonly("steps", [](const Scene& s) { return s.statistics().steps; })
      .def_property_readonly("config", &Scene::config)
      .def("contacts_csv",
           [](const Scene& s) { return contacts_csv(s.world().bodies, s.contacts(), s.dt()); })
      .def(
          "summary",
          [](const Scene& s) {
            return py::module_::import("json").attr("loads")(s.summary(0.0).dump());
          },
          "summary.json's fields so far (wall_time_s is 0 here)");
  bind_bodies<Scene>(scene);

  py::class_<Sediment> sediment(m, "Sediment",
                                "One sample of `dilatant jam` step by step (drivers/sediment.hpp): "
                                "spheres settling onto a floor until they stop");
  sediment.def(py::init(&build_sediment), py::arg("config"), py::arg("sample") = 0)
      .def(
          "step",
          [](Sediment& s) {
            py::gil_scoped_release release;
            s.step();
          },
          "One time step")
      .def(
          "advance",
          [](Sediment& s, std::optional<double> time, std::optional<long> steps) {
            return advance_in_time(s, time, steps, [&] { return s.settled() || s.timed_out(); });
          },
          py::arg("time") = py::none(), py::arg("steps") = py::none(),
          "Steps on by `time` (units sqrt(R/g)) or `steps`, whichever comes first, or until "
          "settled or timed out; returns the number of steps taken")
      .def_property_readonly("settled", &Sediment::settled)
      .def_property_readonly("timed_out", &Sediment::timed_out)
      .def_property_readonly("steps", &Sediment::steps)
      .def_property_readonly("terminal_speed", &Sediment::terminal_speed)
      .def_property_readonly("mean_height", &Sediment::mean_height)
      .def_property_readonly("max_overlap", &Sediment::max_overlap)
      .def(
          "measure",
          [](const Sediment& s, double exclusion) {
            const SedimentFraction f = s.measure(exclusion);
            py::dict d;
            d["phi"] = f.phi;
            d["surface"] = f.surface;
            d["top"] = f.top;
            return d;
          },
          py::arg("exclusion") = 4.0,
          "The sediment's fraction between `exclusion` R above the floor and below its surface "
          "(measure/sediment_fraction.hpp), with the surface height and the highest top");
  bind_bodies<Sediment>(sediment);
}

}  // namespace dilatant::python
