"""Scenes and sediments step by step (dilatant.Scene, dilatant.Sediment), and a
sweep's progress callback: the same states and numbers as the whole runs."""
import numpy as np
import pytest

import dilatant
from conftest import SOURCE_DIR, TINY

SEDIMENT = {"sediment": {"size": [6.0, 6.0, 16.0], "samples": 1, "exclusion": 3.0},
            "friction": {"mu0": 1.0}}


def test_a_sediment_stepped_by_hand_is_the_jam_runs_sample(tmp_path):
    whole = dilatant.run(SEDIMENT, out=tmp_path / "jam")
    pile = dilatant.Sediment(SEDIMENT)
    steps = 0
    while not (pile.settled or pile.timed_out):
        steps += pile.advance(time=5.0)
    assert pile.settled and steps == pile.steps
    sample = whole.samples
    assert int(sample["steps"][0]) == pile.steps
    # The same packing: the jam run's sample fraction, as written (6 decimals).
    assert pile.measure(exclusion=3.0)["phi"] == pytest.approx(float(sample["phi"][0]), abs=5e-7)
    assert pile.positions.shape == (len(pile.radii), 3)


def test_a_sediment_refuses_a_sample_it_does_not_have():
    with pytest.raises(dilatant.ConfigError, match=r"sample 1: must be in \[0, sediment.samples"):
        dilatant.Sediment(SEDIMENT, sample=1)
    with pytest.raises(dilatant.ConfigError, match="not a \\[sediment\\] config"):
        dilatant.Sediment(TINY)


def test_a_scene_stepped_by_hand_is_the_whole_run(tmp_path):
    config = SOURCE_DIR / "examples" / "pile" / "pile.toml"
    short = {"run.time": 0.1}
    whole = dilatant.run(config, out=tmp_path / "pile", overrides=short)
    scene = dilatant.Scene(config, overrides=short)
    assert scene.advance(time=0.05) > 0 and not scene.done
    scene.advance(steps=10**9)
    assert scene.done and scene.steps == whole.summary["steps"]
    last = whole.trajectory[whole.trajectory["t"] == whole.trajectory["t"].max()]
    order = np.argsort(last["id"])
    assert np.allclose(scene.positions[:, 0], last["x"][order], rtol=0, atol=1e-9)
    assert len(scene.contacts) == len(whole.contacts)


def test_a_scene_resumed_from_its_checkpoint_goes_on_bit_for_bit(tmp_path):
    # The engine is deterministic on one thread: a scene checkpointed half way
    # and resumed reaches the uninterrupted scene's state exactly; the
    # CLI's checkpoint of the same scene resumes it too.
    config = SOURCE_DIR / "examples" / "pile" / "pile.toml"
    short = {"run.time": 0.1}
    whole = dilatant.Scene(config, overrides=short)
    whole.advance(steps=10**9)
    half = dilatant.Scene(config, overrides=short)
    half.advance(time=0.05)
    half.write_checkpoint(tmp_path / "half.bin")
    resumed = dilatant.Scene.resumed(config, tmp_path / "half.bin", overrides=short)
    assert resumed.time == half.time and resumed.steps == half.steps
    resumed.advance(steps=10**9)
    assert resumed.done and resumed.steps == whole.steps
    assert np.array_equal(resumed.positions, whole.positions)
    assert np.array_equal(resumed.angular_velocities, whole.angular_velocities)
    dilatant.run(config, out=tmp_path / "cli", overrides={"run.time": 0.05})
    from_cli = dilatant.Scene.resumed(config, tmp_path / "cli" / "checkpoint.bin", overrides=short)
    from_cli.advance(steps=10**9)
    assert np.array_equal(from_cli.positions, whole.positions)


def test_a_scene_resumed_from_another_particles_file_is_refused(tmp_path):
    source = SOURCE_DIR / "examples" / "pile"
    scene = dilatant.Scene(source / "pile.toml", overrides={"run.time": 0.1})
    scene.advance(steps=5)
    scene.write_checkpoint(tmp_path / "c.bin")
    particles = (source / "particles.csv").read_text().splitlines()
    (tmp_path / "particles.csv").write_text("\n".join(particles[:-1]) + "\n")  # one sphere fewer
    moved = {"run.time": 0.1, "scene.particles": str(tmp_path / "particles.csv")}
    with pytest.raises(dilatant.ConfigError, match="particles.csv: the particles file changed"):
        dilatant.Scene.resumed(source / "pile.toml", tmp_path / "c.bin", overrides=moved)
    with pytest.raises(dilatant.ConfigError, match="missing.bin"):
        dilatant.Scene.resumed(source / "pile.toml", tmp_path / "missing.bin",
                               overrides={"run.time": 0.1})


def test_a_sweeps_progress_rises_to_one_and_false_stops_it(tmp_path):
    sweep = {**TINY, "fluid": {"lambda": [10.0, 100.0]}, "sweep": {"jobs": 1}}
    seen = []
    result = dilatant.sweep(sweep, tmp_path / "all", plots=False, progress=seen.append)
    assert result.outcome["done"] == 2
    assert seen and seen[-1] == 1.0
    assert all(0.0 <= f <= 1.0 for f in seen) and seen == sorted(seen)
    stopped = dilatant.sweep({**sweep, "run": {"strain": 1000.0, "transient_strain": 0.01}},
                             tmp_path / "stop", plots=False, progress=lambda f: False)
    assert stopped.outcome["interrupted"] and stopped.outcome["done"] == 0
