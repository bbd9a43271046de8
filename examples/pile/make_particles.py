#!/usr/bin/env python3
"""Writes particles.csv for the pile example: 300 polydisperse spheres on a
loose jittered lattice above the floor of a 10 x 10 box, at rest.
Deterministic (fixed seed); stdlib only. Usage: python3 make_particles.py > particles.csv"""
import random

rng = random.Random(7)
spacing, n_side, layers = 1.1, 8, 5
print("id,x,y,z,r")
pid = 0
for k in range(layers):
    for j in range(n_side):
        for i in range(n_side):
            if pid >= 300:
                break
            r = rng.uniform(0.4, 0.5)
            jitter = lambda: rng.uniform(-0.04, 0.04)
            x = 0.8 + spacing * i + jitter()
            y = 0.8 + spacing * j + jitter()
            z = 0.6 + spacing * k + 0.3 * k + jitter()
            print(f"{pid},{x:.6f},{y:.6f},{z:.6f},{r:.6f}")
            pid += 1
