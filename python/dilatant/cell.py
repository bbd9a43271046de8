"""The shear cell step by step (drivers/shear_cell.hpp), for scripts and
notebooks that look inside a run (here a tiny cell; the default is the paper's):

>>> import dilatant, tempfile
>>> cell = dilatant.ShearCell({"cell": {"size": [6.0, 5.0, 7.0]},
...                            "run": {"strain": 0.03, "transient_strain": 0.01}})
>>> while not cell.done:
...     _ = cell.advance(strain=0.01)   # GIL released; Ctrl-C stops after a step
>>> cell.finish()
>>> round(cell.strain, 2), len(cell.contacts) > 0
(0.03, True)
>>> cell.write_results(tempfile.mkdtemp())   # the files `dilatant run` writes

State (code units R = rho_p = tau = 1): positions, velocities,
angular_velocities (N x 3), radii, ids, groups (0 particle, 1 bottom wall,
2 top wall); tables as numpy structured arrays: contacts (contacts.csv),
timeseries, velocity_profile, sommerfeld_hist (P(s)); summary() in the
paper's units. Writers are explicit: nothing is written unless asked.
"""
from . import _core
from .configs import load_config
from .tables import read_table


class _Stepped:
    """An engine object wrapped for Python (ShearCell here, Scene and Sediment
    in scene.py): everything the wrapper does not define (done, strain,
    positions, write_results, ...) is the compiled object's `_object`."""

    def __getattr__(self, name):
        if name == "_object":
            raise AttributeError(name)
        return getattr(self._object, name)

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(dir(self._object)))


class ShearCell(_Stepped):
    def __init__(self, config=None, overrides=None):
        self._object = _core.ShearCell(load_config(config, overrides))

    @classmethod
    def _wrap(cls, core_cell):
        cell = cls.__new__(cls)
        cell._object = core_cell
        return cell

    @classmethod
    def resumed(cls, config, checkpoint, overrides=None):
        """Exactly where the run that wrote `checkpoint` (of this config) stopped."""
        return cls._wrap(_core.ShearCell.resumed(load_config(config, overrides), checkpoint))

    @classmethod
    def continued(cls, config, checkpoint, overrides=None):
        """The final state of another run of the same cell, under this config."""
        return cls._wrap(_core.ShearCell.continued(load_config(config, overrides), checkpoint))

    # Stepping
    def step(self):
        """One time step."""
        self._object.step()

    def advance(self, strain=None, steps=None):
        """Steps on by `strain` or `steps` (whichever first), or until done;
        returns the steps taken."""
        return self._object.advance(strain=strain, steps=steps)

    def finish(self):
        """Closes the time series' last row: call once at the end of a run."""
        self._object.finish()

    # Tables
    @property
    def contacts(self):
        return read_table(self._object.contacts_csv())

    @property
    def timeseries(self):
        return read_table(self._object.timeseries_csv())

    @property
    def velocity_profile(self):
        return read_table(self._object.velocity_profile_csv())

    @property
    def sommerfeld_hist(self):
        return read_table(self._object.sommerfeld_hist_csv())

    def summary(self):
        """summary.json's fields for the run so far."""
        return self._object.summary()

    def __repr__(self):
        return (f"<dilatant.ShearCell {len(self.radii)} bodies, strain {self.strain:.4g}"
                f"{', jammed' if self.jammed else ''}>")
