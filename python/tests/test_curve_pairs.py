"""Two flow curves point by point (dilatant.plots.curve_pairs): each pair's
distance in combined standard errors, read through Student's t since each error
bar is estimated from 10 block means, the chi^2 of the counted pairs and its
p-value, and bad use as exit 2."""
import json
import math
import random
import statistics

import pytest

from dilatant.plots import curve_pairs

COLUMNS = "cell.seed,mu0,lambda,status,valid,steady,eta,eta_err"


def table(path, rows):
    path.write_text(COLUMNS + "\n" + "\n".join(rows) + "\n")
    return str(path)


@pytest.mark.parametrize("x, k, p", [
    # chi^2 tables' 5% points (Abramowitz & Stegun table 26.8), and two medians
    (3.841459, 1, 0.05), (5.991465, 2, 0.05), (7.814728, 3, 0.05), (9.487729, 4, 0.05),
    (11.070498, 5, 0.05), (18.307038, 10, 0.05), (19.675138, 11, 0.05),
    (0.454936, 1, 0.5), (4.351460, 5, 0.5)])
def test_the_p_value_is_the_chi2_tail(x, k, p):
    assert curve_pairs.chi2_sf(x, k) == pytest.approx(p, abs=2e-6)


@pytest.mark.parametrize("t, nu", [
    # Student's t two-sided 5% points (Abramowitz & Stegun table 26.10)
    (12.706205, 1), (4.302653, 2), (3.182446, 3), (2.776445, 4), (2.262157, 9),
    (2.228139, 10), (2.100922, 18)])
def test_the_t_tail_is_students(t, nu):
    assert curve_pairs.t_two_sided(t, nu) == pytest.approx(0.05, abs=2e-7)
    assert curve_pairs.t_two_sided(-t, nu) == curve_pairs.t_two_sided(t, nu)
    # its normal equivalent has the normal law's 5% point, 1.959964, and z's sign
    assert curve_pairs.normal_equivalent(-t, nu) == pytest.approx(-1.959964, abs=1e-5)


def test_welch_degrees_of_freedom():
    # equal error bars from 10 blocks each: 18; one dominating: towards 9
    assert curve_pairs.welch_nu(2.0, 2.0, 10) == 18
    assert curve_pairs.welch_nu(1.0, 5.0, 10) == 9
    assert curve_pairs.welch_nu(3.0, 0.0, 10) == 9


def test_even_orders_are_the_exponential_sum():
    # k = 2: P(chi^2 > x) = exp(-x/2) exactly; k = 4: (1 + x/2) exp(-x/2)
    assert curve_pairs.chi2_sf(3.0, 2) == pytest.approx(math.exp(-1.5), rel=1e-14)
    assert curve_pairs.chi2_sf(3.0, 4) == pytest.approx(2.5 * math.exp(-1.5), rel=1e-14)
    assert curve_pairs.chi2_sf(0.0, 3) == 1.0


def test_pairs_by_lambda_count_only_valid_steady_points(tmp_path):
    flow = table(tmp_path / "flowcurves.csv", [
        "1,0.4,0.1,done,true,true,60,3",
        "1,0.4,1,done,true,true,90,4",
        "1,0.4,10,done,false,false,150,3",   # seed 1 not steady here
        "1,0.4,100,pending,,,,",
        "2,0.4,0.1,done,true,true,64,4",
        "2,0.4,1.0,done,true,true,81,3",     # 1.0 pairs with 1
        "2,0.4,10,done,true,true,140,4",
        "2,0.4,100,done,true,true,1800,40",  # no partner: seed 1 pending
        "2,0.1,0.1,done,true,true,50,2"])    # another mu0: filtered out
    out = tmp_path / "pairs"
    where = ["--a-where", "cell.seed=1", "--b-where", "cell.seed=2", "--b-where", "mu0=0.4"]
    assert curve_pairs.main([flow, flow, *where, "--blocks", "0", "--out", str(out)]) == 0
    lines = (tmp_path / "pairs.csv").read_text().splitlines()
    assert lines[0] == "lambda,a,a_err,b,b_err,b_over_a,z,nu,z_normal,counted,reason"
    rows = [line.split(",") for line in lines[1:]]
    assert [r[0] for r in rows] == ["0.1", "1.0", "10.0"]
    assert float(rows[0][6]) == pytest.approx(4 / 5)      # (64 - 60) / sqrt(3^2 + 4^2)
    assert float(rows[1][6]) == pytest.approx(-9 / 5)
    assert float(rows[1][5]) == pytest.approx(0.9)
    assert rows[1][7:9] == ["", rows[1][6]]               # --blocks 0: error bars exact
    assert rows[2][9:] == ["false", "a invalid"]
    result = json.loads((tmp_path / "pairs.json").read_text())
    assert result["pairs"] == 3 and result["counted"] == 2
    chi2 = (4 / 5) ** 2 + (9 / 5) ** 2
    assert result["chi2"] == pytest.approx(chi2)
    assert result["p_value"] == pytest.approx(math.exp(-chi2 / 2))
    assert result["scale"] == pytest.approx(math.sqrt(chi2 / 2))
    assert result["mean_z"] == pytest.approx((4 / 5 - 9 / 5) / 2)
    assert result["mean_z_err"] == pytest.approx(1 / math.sqrt(2))
    assert not list(tmp_path.glob("*.part"))
    # error bars from 10 blocks each (the default): the same z, read through
    # Student's t with the pair's Welch degrees of freedom, is a smaller z'
    assert curve_pairs.main([flow, flow, *where, "--out", str(out)]) == 0
    rows = [line.split(",") for line in (tmp_path / "pairs.csv").read_text().splitlines()[1:]]
    nu = curve_pairs.welch_nu(4.0, 3.0, 10)
    assert rows[1][7] == str(nu) and 9 <= nu <= 18
    assert float(rows[1][8]) == pytest.approx(curve_pairs.normal_equivalent(-9 / 5, nu))
    assert -9 / 5 < float(rows[1][8]) < -9 / 5 * 0.85
    result = json.loads((tmp_path / "pairs.json").read_text())
    assert result["chi2_raw"] == pytest.approx(chi2) and result["chi2"] < chi2


def test_range_filters_keep_the_rows_below_or_above_a_number(tmp_path):
    """lambda<VALUE and lambda>VALUE compare numbers (1.0 is not below 1), a
    row whose field is empty passes neither, and = still matches 1 with 1.0."""
    flow = table(tmp_path / "flowcurves.csv", [
        "1,0.4,0.1,done,true,true,60,3",
        "1,0.4,1,done,true,true,90,4",
        "1,0.4,10,done,true,true,150,3",
        "2,0.4,0.1,done,true,true,64,4",
        "2,0.4,1.0,done,true,true,81,3",
        "2,0.4,10,done,true,true,140,4"])
    rows, result = curve_pairs.compare(flow, flow, ["cell.seed=1", "lambda<1"],
                                       ["cell.seed=2"], blocks=0)
    assert [r["key"] for r in rows] == [0.1] and result["counted"] == 1
    rows, _ = curve_pairs.compare(flow, flow, ["cell.seed=1", "lambda>0.1", "lambda<10"],
                                  ["cell.seed=2", "lambda=1"], blocks=0)
    assert [r["key"] for r in rows] == [1.0]
    rows, _ = curve_pairs.compare(flow, flow, ["cell.seed=1", "lambda>0.5"],
                                  ["cell.seed=2", "mu0>0.3"], blocks=0)
    assert [r["key"] for r in rows] == [1.0, 10.0]


def test_curves_that_differ_by_their_noise_give_chi2_per_pair_one(tmp_path):
    """Two curves about one truth, each point the mean of 10 block means with
    the standard error of those means as its error bar, as the engine measures
    (one side's blocks 5 times noisier). chi2 / n is 1 within its standard
    deviation sqrt(2/n) (four allowed); read as exact, the estimated error bars
    give chi2_raw / n about nu/(nu - 2) = 1.29 at nu 9, which the test tells
    apart, as it would a z divided by the sum of the errors or by one."""
    draw = random.Random(7)
    n = 3000
    rows = []
    for i in range(n):
        truth = 100 + i
        for seed, spread in ((1, 1.0), (2, 5.0)):
            blocks = [truth + draw.gauss(0, spread) for _ in range(10)]
            err = statistics.stdev(blocks) / math.sqrt(10)
            rows.append(f"{seed},0.4,{i + 1},done,true,true,{statistics.fmean(blocks)},{err}")
    flow = table(tmp_path / "flowcurves.csv", rows)
    out = tmp_path / "noise"
    assert curve_pairs.main([flow, flow, "--a-where", "cell.seed=1", "--b-where", "cell.seed=2",
                             "--out", str(out)]) == 0
    result = json.loads((tmp_path / "noise.json").read_text())
    assert result["counted"] == n
    assert abs(result["chi2"] / n - 1) < 4 * math.sqrt(2 / n)
    assert result["chi2_raw"] / n - 1 > 8 * math.sqrt(2 / n)
    assert abs(result["mean_z"]) < 4 * result["mean_z_err"]


@pytest.mark.parametrize("args, says", [
    (["missing.csv", "T", "--out", "o"], "missing.csv: no such file"),
    (["T", "T", "--a-where", "cell.seed=3", "--out", "o"], "no finished row matches --a-where cell.seed=3"),
    (["T", "T", "--out", "o"], "lambda 1 a second time among the rows of a"),
    (["T", "T", "--a-where", "nocolumn=1", "--out", "o"], "no column nocolumn"),
    (["T", "T", "--a-where", "seed", "--out", "o"], "--a-where 'seed': expected COLUMN=VALUE"),
    (["T", "T", "--a-where", "=1", "--out", "o"], "--a-where '=1': expected COLUMN=VALUE"),
    (["T", "T", "--b-where", "lambda<x", "--out", "o"],
     "--b-where 'lambda<x': < compares numbers, and 'x' is none"),
    (["T", "T", "--a-where", "cell.seed=1", "--b-where", "cell.seed=2", "--quantity", "gamma_dot",
      "--out", "o"], "no column gamma_dot, gamma_dot_err"),
    (["T", "T", "--a-where", "cell.seed=1", "--b-where", "mu0=0.1", "--out", "o"],
     "no lambda in common"),
    (["T", "T", "--blocks", "1", "--out", "o"], "--blocks 1: an error bar needs at least 2 blocks"),
])
def test_bad_use_is_exit_2_with_one_line_and_no_file(tmp_path, capsys, args, says):
    flow = table(tmp_path / "flowcurves.csv", [
        "1,0.4,1,done,true,true,90,4", "2,0.4,1,done,true,true,81,3",
        "2,0.1,10,done,true,true,81,3"])
    args = [flow if a == "T" else str(tmp_path / a) if a in ("missing.csv", "o") else a
            for a in args]
    assert curve_pairs.main(args) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and says in err, err
    assert not (tmp_path / "o.csv").exists() and not (tmp_path / "o.json").exists()


def test_from_python_the_same_numbers_without_files(tmp_path):
    flow = table(tmp_path / "flowcurves.csv", [
        "1,0.4,1,done,true,true,90,4", "2,0.4,1,done,true,true,81,3"])
    rows, result = curve_pairs.compare(flow, flow, ["cell.seed=1"], ["cell.seed=2"], blocks=0)
    assert [r["key"] for r in rows] == [1.0] and rows[0]["z"] == pytest.approx(-9 / 5)
    assert result["chi2"] == pytest.approx(81 / 25) and result["counted"] == 1
    assert list(tmp_path.iterdir()) == [tmp_path / "flowcurves.csv"]
    with pytest.raises(ValueError, match="no finished row matches --a-where cell.seed=3"):
        curve_pairs.compare(flow, flow, ["cell.seed=3"])
