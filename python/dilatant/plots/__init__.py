"""The figures of dilatant, drawn from result folders (no fitting here: the
numbers come from the C++ library):

  dilatant.plots.sweep.draw(DIR)          a sweep's flow curves, Figs. 1b-d and 2
  dilatant.plots.analysis.draw(DIR)       `analyze`: flow curves, n(phi), collapse
  dilatant.plots.phase_diagram.draw(DIR)  `predict --grid`: the regime over (mu0, phi)

Each module is also a script the CLI runs as `python3 FILE DIR`. Importing
them needs matplotlib and numpy (Debian's python3-matplotlib, python3-numpy).
"""
