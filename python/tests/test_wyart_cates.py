"""The Wyart–Cates fit from Python (dilatant.fit_wyart_cates, and
dilatant.predict(model=...)): it recovers the parameters of noisy synthetic
flow curves it did not see, writes the CLI's files, fits in the fraction
(phi_basis=) and with the weights (weights=) asked for as the CLI's --wc-phi and
--wc-weights do, and refuses what it cannot fit with the CLI's reason."""
import json
import math
import random

import pytest

import dilatant
import dilatant.analysis
from conftest import run_cli

PHI_0, PHI_M, SIGMA_STAR, A = 0.64, 0.56, 2.0, 1.3  # Singh et al. 2018's mu = 1 fractions


def viscosity(phi, sigma):
    """Wyart & Cates (2014), alpha 2, beta 1; None where phi >= phi_J (jammed)."""
    f = math.exp(-SIGMA_STAR / sigma)
    phi_j = f * PHI_M + (1 - f) * PHI_0
    return A * (1 - phi / phi_j) ** -2 if phi < phi_j else None


def write_sweep(path, phis, seed=5, dilation=None):
    """A sweep table as `dilatant sweep` writes it: 5% log-normal noise on the rate.
    With dilation (d, d_stress), each point's fraction, its phi_bulk, sits d
    below the curve's phi and a further d_stress x its place in the ramp, as
    the bulk of a wall cell dilates (tests/analysis/wyart_cates_phi_basis_test.cpp)."""
    rng = random.Random(seed)
    rows = ["phi,mu0,shear_stress,gamma_dot,gamma_dot_err,valid,jammed"
            + (",phi_bulk" if dilation else "")]
    for phi in phis:
        for k in range(25):
            sigma = 0.02 * 10 ** (k / 6)
            bulk = phi - dilation[0] - dilation[1] * k / 24 if dilation else phi
            extra = f",{bulk:.6f}" if dilation else ""
            eta = viscosity(bulk, sigma)
            if eta is None:
                rows.append(f"{phi},1,{sigma:.6g},0,,true,true{extra}")
                continue
            rate = sigma / eta * math.exp(0.05 * rng.gauss(0, 1))
            rows.append(f"{phi},1,{sigma:.6g},{rate:.6g},{0.05 * rate:.3g},true,false{extra}")
    path.write_text("\n".join(rows) + "\n")
    return path


# Nominal fractions 0.010-0.013 above the true ones 0.451-0.576 (as the C++ test).
NOMINAL = [0.461, 0.511, 0.541, 0.561, 0.586]
DILATION = (0.010, 0.003)


def test_the_fit_recovers_the_parameters_and_writes_the_files(tmp_path):
    table = write_sweep(tmp_path / "flowcurves.csv", [0.45, 0.50, 0.53, 0.55, 0.575])
    result = dilatant.fit_wyart_cates(table, tmp_path / "out", plots=False)
    s = result.fit["samples"]["mu0=1"]
    assert s["fitted"]
    for key, truth in (("phi_0", PHI_0), ("phi_m", PHI_M), ("sigma_star", SIGMA_STAR), ("A", A)):
        assert abs(s[key] - truth) < 4 * s[key + "_err"], key
    assert s["phi_0_err"] < 0.003 and s["phi_m_err"] < 0.001  # bounded, not just consistent
    assert s["alpha_source"] == "fixed" and s["alpha_err"] is None
    assert PHI_M - 0.03 < s["dst"]["phi_dst"] < PHI_M
    assert set(result.curves["kind"]) == {"data", "model"}
    assert set(result.map["regime"]) >= {"cst", "dst", "shear_jamming"}
    assert (tmp_path / "out" / "wyart_cates.json").is_file()
    assert dilatant.analysis.fit_wyart_cates is dilatant.fit_wyart_cates

    answer = dilatant.predict(phi=0.55, model=result.out / "wyart_cates.json", stress=5.0)
    assert answer["source"] == "wyart-cates fit"
    assert (answer["regime"], answer["state"]) == ("dst", "turns_back")
    assert dilatant.predict(phi=0.60, model=result.out / "wyart_cates.json")["regime"] == \
        "shear_jamming"


def test_free_exponents_and_the_same_numbers_as_the_cli(cli, tmp_path):
    table = write_sweep(tmp_path / "flowcurves.csv", [0.45, 0.50, 0.53, 0.55, 0.575])
    py = dilatant.fit_wyart_cates(table, fit_beta=True)
    assert py.out is None
    run_cli(cli, "analyze", table, "--out", tmp_path / "cli", "--model", "wyart-cates",
            "--fit-beta", "-q", "--no-plots")
    cli_fit = json.loads((tmp_path / "cli" / "wyart_cates.json").read_text())
    a, b = py.fit["samples"]["mu0=1"], cli_fit["samples"]["mu0=1"]
    assert a["beta_source"] == "fitted" and abs(a["beta"] - 1) < 4 * a["beta_err"]
    for key in ("phi_0", "phi_m", "sigma_star", "A", "beta", "chi2_per_dof"):
        assert a[key] == b[key], key


def test_what_cannot_be_fitted_raises_the_reason(tmp_path):
    one_phi = write_sweep(tmp_path / "flowcurves.csv", [0.53])
    with pytest.raises(dilatant.ConfigError, match="2 or more phi"):
        dilatant.fit_wyart_cates(one_phi)
    with pytest.raises(dilatant.ConfigError, match="alpha = -1"):
        dilatant.fit_wyart_cates(one_phi, alpha=-1)
    with pytest.raises(TypeError, match="need model"):
        dilatant.predict(mu0=0.4, phi=0.55, stress=2.0)
    with pytest.raises(dilatant.ConfigError, match="not a Wyart-Cates fit"):
        dilatant.predict(phi=0.5, model=one_phi)


def test_phi_bulk_and_nominal_fit_different_fractions(tmp_path):
    table = write_sweep(tmp_path / "flowcurves.csv", NOMINAL, dilation=DILATION)
    fits = {phi: dilatant.fit_wyart_cates(table, phi_basis=phi).fit
            for phi in ("auto", "bulk", "nominal")}
    bulk, nominal = fits["bulk"]["samples"]["mu0=1"], fits["nominal"]["samples"]["mu0=1"]
    assert (bulk["phi_basis"], nominal["phi_basis"]) == ("bulk", "nominal")
    assert fits["nominal"]["settings"]["phi"] == "nominal"
    # In the points' own fractions the truth comes back; in the nominal ones
    # phi_m sits about the dilation too high, far outside its error.
    assert abs(bulk["phi_m"] - PHI_M) < 4 * bulk["phi_m_err"]
    assert nominal["phi_m"] - PHI_M > 0.005
    assert nominal["phi_m"] - bulk["phi_m"] > 4 * nominal["phi_m_err"]
    assert fits["auto"]["samples"]["mu0=1"]["phi_m"] == bulk["phi_m"]  # every point has phi_bulk
    # A table without phi_bulk: auto falls back to nominal, bulk refuses.
    plain = write_sweep(tmp_path / "plain.csv", [0.45, 0.50, 0.53, 0.55, 0.575])
    assert dilatant.fit_wyart_cates(plain).fit["samples"]["mu0=1"]["phi_basis"] == "nominal"
    with pytest.raises(dilatant.ConfigError, match="phi_bulk"):
        dilatant.fit_wyart_cates(plain, phi_basis="bulk")


def test_weights_uniform_and_errors(tmp_path):
    table = write_sweep(tmp_path / "flowcurves.csv", [0.45, 0.50, 0.53, 0.55, 0.575])
    weighted = dilatant.fit_wyart_cates(table).fit["samples"]["mu0=1"]
    uniform = dilatant.fit_wyart_cates(table, weights="uniform").fit
    assert uniform["settings"]["weights"] == "uniform"
    assert weighted["weights"].startswith("the errors of eta")
    assert uniform["samples"]["mu0=1"]["weights"].startswith("uniform")
    assert uniform["samples"]["mu0=1"]["chi2_per_dof"] != weighted["chi2_per_dof"]
    # 'errors' refuses a point without an error, naming it; auto falls back to uniform.
    lines = table.read_text().splitlines()
    fields = lines[3].split(",")  # line 4 of the file
    fields[4] = ""  # gamma_dot_err
    lines[3] = ",".join(fields)
    table.write_text("\n".join(lines) + "\n")
    assert dilatant.fit_wyart_cates(table).fit["samples"]["mu0=1"]["weights"].startswith("uniform")
    with pytest.raises(dilatant.ConfigError,
                       match="gamma_dot_err or eta_err; the point of line 4 of "):
        dilatant.fit_wyart_cates(table, weights="errors")


def test_phi_and_weights_give_the_cli_numbers(cli, tmp_path):
    table = write_sweep(tmp_path / "flowcurves.csv", NOMINAL, dilation=DILATION)
    py = dilatant.fit_wyart_cates(table, phi_basis="nominal", weights="uniform")
    run_cli(cli, "analyze", table, "--out", tmp_path / "cli", "--model", "wyart-cates",
            "--wc-phi", "nominal", "--wc-weights", "uniform", "-q", "--no-plots")
    cli_fit = json.loads((tmp_path / "cli" / "wyart_cates.json").read_text())
    assert py.fit["settings"] == cli_fit["settings"]
    a, b = py.fit["samples"]["mu0=1"], cli_fit["samples"]["mu0=1"]
    for key in ("phi_0", "phi_m", "sigma_star", "A", "chi2_per_dof", "phi_basis", "weights",
                "phi"):
        assert a[key] == b[key], key
    # As the CLI, the names are read case aside.
    assert dilatant.fit_wyart_cates(table, phi_basis="Nominal", weights="UNIFORM").fit == py.fit


@pytest.mark.parametrize("argument, value, allowed", [
    ("phi_basis", "median", "auto, nominal, bulk"),
    ("phi_basis", 0.55, "auto, nominal, bulk"),  # a volume fraction is not a basis
    ("weights", "poisson", "auto, uniform, errors"),
])
def test_a_bad_phi_or_weights_raises_naming_the_argument(tmp_path, argument, value, allowed):
    table = write_sweep(tmp_path / "flowcurves.csv", [0.45, 0.50, 0.53, 0.55, 0.575])
    message = f"{argument} = '{value}': must be one of {allowed}"
    with pytest.raises(dilatant.ConfigError, match=message.replace(".", r"\.")):
        dilatant.fit_wyart_cates(table, tmp_path / "out", **{argument: value})
    assert not (tmp_path / "out").exists()
