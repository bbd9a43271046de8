"""The figures of dilatant, drawn from result folders (no fitting here: the
numbers come from the C++ library):

  dilatant.plots.sweep.draw(DIR)          a sweep's flow curves, Figs. 1b-d and 2
  dilatant.plots.analysis.draw(DIR)       `analyze`: flow curves, n(phi), collapse
  dilatant.plots.phase_diagram.draw(DIR)  `predict --grid`: the regime over (mu0, phi)
  dilatant.plots.wyart_cates              `analyze --model wyart-cates`: the fit drawn
  (pressure_sweep and sweep_curves are the sweep figure's parts, imported by sweep)

Each of these is also a script the CLI runs as `python3 FILE DIR`.

The figures and tables of the docs, each a module run from the source tree as
`PYTHONPATH=python python3 -m dilatant.plots.NAME ARGS` (scripts/docs-*.sh;
its docstring gives the arguments) or called from Python:

  shear_cell            docs/shear-cell.md: velocity profiles, P(s), time series, table
  coulomb_control       docs/paper-reproduction.md: fig2's Stribeck curves against the
                        `coulomb` control, with the share of contacts beyond s_lim
  newtonian             the Newtonian branch: eta(gamma_dot), eta_N(phi) and its fit
  dst_map               the DST map: every ramp to the jam at its (mu0, phi_bulk)
  sc_scaling            the onset's s_c scaling: eta and P_BL against J / s_c
  lees_edwards          walls against Lees–Edwards at the same bulk fraction
  paper_tables          the Markdown tables of every point (tables.md)
  jamming               docs/jamming.md: phi_max_BL(mu0), shear-jamming phi_c(mu0)
  onset_table           the onsets of thickening (data/jamming/onsets.csv)
  bulk_flow_states      the Lees–Edwards ramps' flow states (data/jamming/bulk_flow_states.csv)
  predictor_checks      `dilatant predict` against every flow curve
  analysis_truth_table  docs/analysis.md: recovered against true values
  decisive_fig2         the decisive study's Fig. 2: every mu0 of its sweeps in one figure
  ramp_table            a ramp sweep's finished points as the decisive study's table
  contact_states        the share of sticking contacts, point by point
  curve_pairs           two flow curves point by point: z of each pair, chi^2 over them
                        (do two seeds agree, does a rerun repeat a run)

common holds what the figures share (labels, the Agg backend from a command
line, files written to NAME.part and renamed), table_rows the reading of result
tables that the tables share with them. The figures need matplotlib and numpy
(Debian's python3-matplotlib, python3-numpy; a command line exits 3 without
them); the tables need the standard library only.
"""
