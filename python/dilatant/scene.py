"""Scenes and sediments step by step, as dilatant.ShearCell for the shear cell:

>>> import dilatant
>>> pile = dilatant.Sediment({"sediment": {"size": [6.0, 6.0, 12.0], "samples": 1}})
>>> pile.advance(steps=20)
20
>>> pile.positions.shape[1], pile.time > 0
(3, True)
>>> while not (pile.settled or pile.timed_out):
...     _ = pile.advance(time=10.0)     # GIL released; Ctrl-C stops after a step
>>> 0.4 < pile.measure(exclusion=2.0)["phi"] < 0.66
True

A Scene reads its particles from scene.particles (a CSV file) and steps to
run.time (examples/pile/pile.toml of the source tree: `dilatant.Scene(path)`);
its contacts are a numpy table. State in code units, as the CLI's files.
write_checkpoint(file) saves a scene's state and Scene.resumed(config, file)
goes on from it bit for bit (a long scene stepped by hand survives its
session); a Sediment stepped by hand has no checkpoint (`dilatant.run` of a
[sediment] config keeps its finished samples).
"""
from . import _core
from .cell import _Stepped
from .configs import load_config
from .tables import read_table


class Scene(_Stepped):
    def __init__(self, config, overrides=None):
        self._object = _core.Scene(load_config(config, overrides))

    @classmethod
    def resumed(cls, config, checkpoint, overrides=None):
        """Exactly where the scene that wrote `checkpoint` stopped: a `dilatant
        run`'s checkpoint.bin or write_checkpoint()'s file, for the same
        particles file (its CRC-32 is checked; ConfigError otherwise)."""
        scene = cls.__new__(cls)
        scene._object = _core.Scene.resumed(load_config(config, overrides), checkpoint)
        return scene

    def advance(self, time=None, steps=None):
        """Steps on by `time` or `steps` (whichever first), or until done;
        returns the steps taken."""
        return self._object.advance(time=time, steps=steps)

    @property
    def contacts(self):
        return read_table(self._object.contacts_csv())

    def __repr__(self):
        return f"<dilatant.Scene {len(self.radii)} bodies, t = {self.time:.4g}>"


class Sediment(_Stepped):
    def __init__(self, config, sample=0, overrides=None):
        """Sample `sample` (seed + sample) of a [sediment] config."""
        self._object = _core.Sediment(load_config(config, overrides), sample)

    def advance(self, time=None, steps=None):
        """Steps on by `time` (sqrt(R/g)) or `steps` (whichever first), or until
        settled or timed out; returns the steps taken."""
        return self._object.advance(time=time, steps=steps)

    def __repr__(self):
        state = "settled" if self.settled else "timed out" if self.timed_out else "settling"
        return f"<dilatant.Sediment {len(self.radii)} spheres, t = {self.time:.4g}, {state}>"
