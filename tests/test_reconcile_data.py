"""`hdcad reconcile`: bad files, the command line, the JSON and the report folder.

The small data sets here come from this file's own generator (catalog curve or ideal
transmission plus one effect written out by hand, plus seeded white noise); the statistical
proof on independently simulated data is in test_reconcile_proof.py.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from hdcad.catalog import load_catalog
from hdcad.cli import main
from hdcad.errors import InputError
from hdcad.models import resolve
from hdcad.reconcile import COLUMNS, EFFECT_NAMES, MIN_ROWS, read_data, reconcile, validate_data
from hdcad.resources import examples_dir

EXAMPLE = examples_dir() / "reconcile_torsion_synthetic.csv"
JSON_KEYS = {"kind", "model", "disagreements", "missing_effects", "rmse_before", "rmse_after",
             "measurement_effects", "nuisances", "equivalent_readings", "noise_rms", "outliers",
             "steps", "unexplained", "notes"}


def write_csv(path, header, rows):
    path.write_text(",".join(header) + "\n" + "\n".join(",".join(map(str, r)) for r in rows)
                    + "\n", encoding="utf-8")
    return path


def transmission_rows(n=600, ratio=100, te2=0.0, seed=0):
    """Ideal output = input/R plus a hand-written 2× error a·sin(2φ + 0.4) and white noise."""
    rng = np.random.default_rng(seed)
    phi = np.linspace(0, 6 * math.pi, n)
    out = phi / ratio + te2 * np.sin(2 * phi + 0.4) + 2e-6 * rng.standard_normal(n)
    return [(f"{a:.9g}", f"{b:.9g}") for a, b in zip(phi, out)]


def run(capsys, *argv):
    code = main([str(a) for a in argv])
    captured = capsys.readouterr()
    return code, captured.out, captured.err


# --------------------------------------------------------------------------- bad files
@pytest.mark.parametrize("header,rows,field,words", [
    (("torque_Nm",), [(1,)] * 200, "twist_rad", "column missing"),
    (("torque_Nm", "twist_rad"), [(1, 2)] * 150 + [(1, "abc")] + [(1, 2)] * 10, "twist_rad",
     "line 152"),
    (("torque_Nm", "twist_rad"), [(1, 2)] * 150 + [("nan", 2)], "torque_Nm", "finite"),
    (("torque_Nm", "twist_rad"), [(i, 2) for i in range(20)], "torsion", "at least"),
])
def test_bad_torsion_files_raise_input_error_naming_the_column(tmp_path, header, rows,
                                                               field, words):
    path = write_csv(tmp_path / "d.csv", header, rows)
    with pytest.raises(InputError) as err:
        read_data("torsion", path)
    assert err.value.field == field and words in str(err.value)


def test_min_rows_is_stated_per_kind_and_extra_columns_are_ignored(tmp_path):
    assert set(MIN_ROWS) == set(COLUMNS)
    rows = [(r[0], "x", r[1]) for r in transmission_rows()]
    path = write_csv(tmp_path / "d.csv", ("input_angle_rad", "comment", "output_angle_rad"),
                     rows)
    data = read_data("transmission", path)
    assert set(data) == set(COLUMNS["transmission"]) and len(data["input_angle_rad"]) == 600


def _efficiency_grid() -> dict:
    """3 temperatures × 3 speeds × 4 loads at 75 % efficiency: 36 rows."""
    grid = np.array([(n, t, c) for c in (20.0, 40.0, 60.0) for n in (500.0, 1000.0, 2000.0)
                     for t in (10.0, 30.0, 60.0, 100.0)])
    return {"input_speed_rpm": grid[:, 0], "load_torque_Nm": grid[:, 1],
            "temperature_C": grid[:, 2], "efficiency_pct": np.full(len(grid), 75.0)}


def test_an_efficiency_grid_of_three_temperatures_speeds_and_four_loads_is_enough():
    """3 temperatures × 3 speeds × 4 loads = 36 rows, a common small test grid: accepted;
    below MIN_ROWS (30: 24 rows to fit on in each of the 5 folds, 3× the largest model's
    parameters) the error names the count."""
    data = _efficiency_grid()
    assert len(validate_data("efficiency", data)["efficiency_pct"]) == 36
    with pytest.raises(InputError, match="29 rows; efficiency needs at least 30"):
        validate_data("efficiency", {k: v[:29] for k, v in data.items()})


def test_an_efficiency_read_a_little_outside_0_to_100_percent_is_kept():
    """Output over input power reads below 0 % or above 100 % where the torques' errors are
    large against the power: suite P's Richards low-load case at seed 11 has one glitch row
    at −7.9 % among 468 (its noise 3.5 points) and was refused as a whole file. Such rows are
    kept, as is suite K's torque reading that creeps above 100 % after each tare; a row
    beyond −100…200 %, or a median at or below 0 %, is no efficiency."""
    data = _efficiency_grid()
    data["efficiency_pct"][[0, 1]] = (-7.9, 101.5)
    assert validate_data("efficiency", data)["efficiency_pct"][0] == -7.9
    for bad in (-120.0, 250.0):
        data["efficiency_pct"][0] = bad
        with pytest.raises(InputError, match="must lie in -100…200 %") as err:
            validate_data("efficiency", data)
        assert err.value.field == "efficiency_pct"
    data["efficiency_pct"] = np.full(36, -5.0)
    with pytest.raises(InputError, match="median must be > 0 %"):
        validate_data("efficiency", data)


def test_validate_data_checks_in_memory_columns():
    with pytest.raises(InputError, match="different lengths"):
        validate_data("torsion", {"torque_Nm": np.ones(200), "twist_rad": np.ones(199)})
    with pytest.raises(InputError, match="not a reconcile kind"):
        validate_data("stiffness", {})


@pytest.mark.parametrize("argv,field", [
    (["torsion", "{csv}", "--model", "CSF-20-80-2A-GR"], "no stiffness data"),
    (["efficiency", "{eff}", "--model", "CSF-25-100-2A-GR"], "no rated torque"),
    (["vibration", "{vib}", "--model", "CSF-32-100-GH"], "--load-inertia"),
    (["torsion", "{missing}", "--model", "CSF-32-100-GH"], "cannot read"),
    (["transmission", "{csv}", "--model", "CSF-32-100-GH"], "input_angle_rad"),
])
def test_cli_bad_input_exits_2_with_one_line_and_writes_nothing(tmp_path, capsys, argv, field):
    eff = write_csv(tmp_path / "eff.csv", COLUMNS["efficiency"],
                    [(1000, 10 + i % 20, 20, 70) for i in range(100)])
    vib = write_csv(tmp_path / "vib.csv", COLUMNS["vibration"],
                    [(0.001 * i, i, 0.0) for i in range(300)])
    paths = {"csv": EXAMPLE, "eff": eff, "vib": vib, "missing": tmp_path / "none.csv"}
    argv = [a.format(**{k: str(v) for k, v in paths.items()}) for a in argv]
    out_json, out_dir = tmp_path / "r.json", tmp_path / "report"
    code, _, err = run(capsys, "reconcile", *argv, "--json", out_json, "--out", out_dir)
    assert code == 2
    assert err.count("\n") == 1 and field in err
    assert not out_json.exists() and not out_dir.exists()


# --------------------------------------------------------------------------- CLI output
def test_cli_json_shape_on_the_shipped_example(tmp_path, capsys):
    """The shipped synthetic example hides a hysteresis loop (Bouc–Wen, 1.5×10⁻⁴ rad) on the
    CSF-32-100-GH catalog curve."""
    out = tmp_path / "r.json"
    code, text, _ = run(capsys, "reconcile", "torsion", EXAMPLE, "--model", "CSF-32-100-GH",
                        "--json", out)
    assert code == 0 and "hysteresis" in text and "RMSE" in text
    doc = json.loads(out.read_text(encoding="utf-8"))
    assert set(doc) == JSON_KEYS and doc["kind"] == "torsion"
    assert doc["model"] == "CSF-32-100-GH"
    assert doc["missing_effects"] == ["hysteresis"]
    assert doc["rmse_after"] < 0.2 * doc["rmse_before"]
    for step in doc["steps"]:
        assert step["effect"] in EFFECT_NAMES
        assert set(step) == {"effect", "params", "criterion_gain", "rmse", "form"}
        assert all(set(v) == {"value", "unit"} for v in step["params"].values())
    assert all(set(d) == {"where", "rms", "noise_rms"} for d in doc["disagreements"])


def test_cli_out_writes_plots_and_report(tmp_path, capsys):
    pypdf = pytest.importorskip("pypdf")
    pytest.importorskip("weasyprint")
    csv = write_csv(tmp_path / "t.csv", COLUMNS["transmission"],
                    transmission_rows(te2=3e-5))
    out = tmp_path / "rep"
    code, text, _ = run(capsys, "reconcile", "transmission", csv, "--model", "CSF-32-100-GH",
                        "--out", out)
    assert code == 0
    assert {p.name for p in out.iterdir()} - {".hdcad-manifest.json"} == {
        "comparison.svg", "residuals.svg", "residuals_in_order.svg", "report.html", "report.pdf"}
    html = (out / "report.html").read_text(encoding="utf-8")
    assert "te_2x" in html and "comparison.svg" in html and "residuals_in_order.svg" in html
    # the order plot's axis is the record's rows, the other's the WG angle
    assert "test order" in (out / "residuals_in_order.svg").read_text(encoding="utf-8")
    assert "test order" not in (out / "residuals.svg").read_text(encoding="utf-8")
    assert len(pypdf.PdfReader(str(out / "report.pdf")).pages) >= 1


# --------------------------------------------------------------------------- workflow sanity
def test_transmission_names_te_2x_and_recovers_its_amplitude():
    """3×10⁻⁵ rad 2× error (about a tenth of the CSF-GH accuracy 2.9×10⁻⁴ rad, table 059-1)
    with 2×10⁻⁶ rad noise: amplitude within 3 standard errors (σ·√(2/N) ≈ 1.2×10⁻⁷ rad)."""
    catalog = load_catalog()
    rows = np.array(transmission_rows(te2=3e-5), dtype=float)
    data = {"input_angle_rad": rows[:, 0], "output_angle_rad": rows[:, 1]}
    result = reconcile("transmission", data, resolve("CSF-32-100-GH", catalog), catalog)
    assert result.missing_effects == ["te_2x"]
    amplitude = result.steps[0].params["amplitude"]["value"]
    assert amplitude == pytest.approx(3e-5, abs=3 * 2e-6 * math.sqrt(2 / 600))
    assert result.rmse_after == pytest.approx(2e-6, rel=0.15)


def test_nothing_is_named_on_the_catalog_model_plus_noise():
    catalog = load_catalog()
    rows = np.array(transmission_rows(te2=0.0, seed=3), dtype=float)
    data = {"input_angle_rad": rows[:, 0], "output_angle_rad": rows[:, 1]}
    result = reconcile("transmission", data, resolve("CSF-32-100-GH", catalog), catalog)
    assert result.missing_effects == [] and result.steps == []
    assert result.rmse_after == result.rmse_before


def _torsion_triangle(T0, n, cycles=2):
    """Quasi-static torque 0 → +T0 → −T0 … → 0 [N·m] over ``cycles`` cycles, ``n`` rows."""
    knots = [0.0] + [T0 * (-1) ** k for k in range(2 * cycles)] + [0.0]
    return np.interp(np.linspace(0, len(knots) - 1, n), np.arange(len(knots)), knots)


def test_the_corner_width_is_found_when_the_noise_is_a_thousandth_of_the_twist():
    """CSF-45-120-GH (T1 76, T2 275 N·m) with corners spread over 12 N·m, 10 % stiffer than
    the catalog, ±450 N·m and noise 10⁻³ of the largest twist: the fit must walk from its grid
    point to the width (the shape fit once stopped where it started, its gradient tolerance
    absolute and the residual micro-radians, and named a backlash for what was left)."""
    from hdcad.reconcile.baseline import catalog_twist, stiffness_curve
    catalog = load_catalog()
    model = resolve("CSF-45-120-GH", catalog)
    torque = _torsion_triangle(450.0, 1200)
    twist = catalog_twist(stiffness_curve(model)[0], torque, 12.0) / 1.1
    sigma = 1e-3 * np.max(np.abs(twist))
    data = {"torque_Nm": torque,
            "twist_rad": twist + sigma * np.random.default_rng(5).standard_normal(len(torque))}
    result = reconcile("torsion", data, model, catalog)
    assert result.missing_effects == []
    width = {n["name"]: n["value"] for n in result.nuisances}["corner_width"]
    assert width == pytest.approx(12.0, rel=0.05)   # ±5 %: a few standard errors at this noise
    assert result.rmse_after == pytest.approx(sigma, rel=0.1)


def test_a_gear_softer_within_the_spread_is_also_read_as_a_series_spring():
    """CSF-32-100-GH 4 % softer than the catalog (within its ±10 %) over ±137 N·m: no
    effect is named, the stiffness scale takes it, and the report gives the other reading, a
    gear at its catalog stiffness with a series spring. The spring given adds at the test's
    largest torque the twist the softer gear adds there: T0 / (θ(T0)/0.96 − θ(T0)),
    within 2 % (the scale is fitted to a few tenths of a percent at this noise)."""
    from hdcad.reconcile.baseline import catalog_twist, stiffness_curve
    catalog = load_catalog()
    model = resolve("CSF-32-100-GH", catalog)
    curve = stiffness_curve(model)[0]
    torque = _torsion_triangle(137.0, 1500)
    sigma = 2e-6
    twist = (catalog_twist(curve, torque, 0.0) / 0.96
             + sigma * np.random.default_rng(4).standard_normal(len(torque)))
    result = reconcile("torsion", {"torque_Nm": torque, "twist_rad": twist}, model, catalog)
    assert result.missing_effects == []
    reading = next(r for r in result.equivalent_readings
                   if r.get("nuisance") == "stiffness_scale")
    assert reading["effects"] == ["housing_compliance"]
    theta0 = float(catalog_twist(curve, np.array([137.0]), 0.0)[0])
    given = float(reading["text"].split("about ")[1].split(" N")[0])
    assert given == pytest.approx(137.0 / (theta0 / 0.96 - theta0), rel=0.02)


def test_a_named_spring_beyond_the_spread_is_also_read_as_a_softer_gear():
    """CSF-32-100-GH with a series spring adding 30 % of the gear's twist at T0 (137 N·m):
    beyond the stiffness scale's ±10 % the spring is named, and the other reading, a gear
    softer than the catalog, gives back a spring that adds about the same twist at T0. The
    scale is fitted over the whole cycle and its compliance follows the curve's segments, so
    the stiffness it gives is 5.0–5.2 % below the true one for springs of 15, 30 and
    50 % of the gear's twist (bar 8 %); the estimate from K1 that this reading used before
    was 35 % below."""
    from hdcad.reconcile.baseline import catalog_twist, stiffness_curve
    catalog = load_catalog()
    model = resolve("CSF-32-100-GH", catalog)
    curve = stiffness_curve(model)[0]
    torque = _torsion_triangle(137.0, 1500)
    k_spring = 137.0 / (0.30 * float(catalog_twist(curve, np.array([137.0]), 0.0)[0]))
    sigma = 2e-6
    twist = (catalog_twist(curve, torque, 0.0) + torque / k_spring
             + sigma * np.random.default_rng(6).standard_normal(len(torque)))
    result = reconcile("torsion", {"torque_Nm": torque, "twist_rad": twist}, model, catalog)
    assert result.missing_effects == ["housing_compliance"]
    reading = next(r for r in result.equivalent_readings
                   if r.get("nuisance") == "stiffness_scale")
    given = float(reading["text"].split("about ")[1].split(" N")[0])
    assert given == pytest.approx(k_spring, rel=0.08)


@pytest.mark.parametrize("stiffness, outside", [(1.25, True), (1.04, False)])
def test_a_gear_stiffer_than_the_spread_is_kept_where_the_data_put_it(stiffness, outside):
    """CSF-32-100-GH 25 % stiffer than the catalog: no gear effect makes a gear stiffer, so
    nothing is named; the compliance scale, held within the ±10 % spread while effects are
    named, is let out of it for the reconciled model. The residual falls to the noise (it
    was the bound's: 1/1.1 − 1/1.25, 9 % of the twist) and the notes say where the gear
    was put. A gear 4 % stiffer is within the spread and needs no note."""
    from hdcad.reconcile.baseline import catalog_twist, stiffness_curve
    catalog = load_catalog()
    model = resolve("CSF-32-100-GH", catalog)
    curve = stiffness_curve(model)[0]
    torque = _torsion_triangle(137.0, 1500)
    sigma = 2e-6
    twist = (catalog_twist(curve, torque, 0.0) / stiffness
             + sigma * np.random.default_rng(5).standard_normal(len(torque)))
    result = reconcile("torsion", {"torque_Nm": torque, "twist_rad": twist}, model, catalog)
    assert result.missing_effects == []
    found = {n["name"]: n for n in result.nuisances}["stiffness_scale"]
    assert found["value"] == pytest.approx(stiffness, rel=0.01)
    assert found["within_spread"] is not outside
    assert result.rmse_after <= 1.1 * sigma
    kept = [n for n in result.notes if "where the data put it" in n]
    assert len(kept) == int(outside)
    if outside:
        share = float(kept[0].split("keeps the gear ")[1].split("%")[0]) / 100
        assert share == pytest.approx(stiffness - 1, abs=0.01)
        assert "stiffer than the catalog" in kept[0]


def test_suite_j_s_stiff_gear_is_kept_out_of_its_spread():
    """Suite J's gear 30 % stiffer than the catalog (written from the contract only; seed
    11): nothing named, and the reconciled model leaves the noise (it left 3.64× the noise
    with the scale at the spread's bound, the residual listed as unexplained in all eight
    torque bins; one bin near zero torque is left at 1.5× the noise, whose variance drifts
    in this suite)."""
    from truth_runs import case_run
    case, result = case_run("j", "j-torsion-decoy_separable-nuisance-stiffgear-000")
    assert result["missing_effects"] == []
    found = {n["name"]: n for n in result["nuisances"]}["stiffness_scale"]
    assert found["value"] == pytest.approx(case.nuisance["stiffness_scale"], rel=0.02)
    assert result["rmse_after"] <= 1.2 * case.noise_rms
    assert len(result["unexplained"]) <= 1


def test_a_warm_up_drift_of_the_twist_is_the_rig_not_the_gear():
    """A first-order warm-up (Newton's law of cooling) of the twist reading, 2×10⁻⁵ rad with a
    time constant of a tenth of the test, on CSF-32-100-GH: the drift is named as the rig's and
    follows the data to the noise; no gear effect."""
    catalog = load_catalog()
    model = resolve("CSF-32-100-GH", catalog)
    from hdcad.reconcile.baseline import catalog_twist, stiffness_curve
    torque = _torsion_triangle(137.0, 1500, cycles=3)
    t = np.linspace(0.0, 1.0, len(torque))
    sigma = 2e-6
    twist = (catalog_twist(stiffness_curve(model)[0], torque, 5.0)
             + 2e-5 * (1.0 - np.exp(-t / 0.1))
             + sigma * np.random.default_rng(8).standard_normal(len(torque)))
    result = reconcile("torsion", {"torque_Nm": torque, "twist_rad": twist}, model, catalog)
    assert result.missing_effects == []
    assert [m["effect"] for m in result.measurement_effects] == ["thermal_drift"]
    assert result.rmse_after == pytest.approx(sigma, rel=0.1)


def test_an_eccentric_input_encoder_reads_as_te_1x_not_as_the_record_s_time():
    """The input angle read by an eccentric encoder, φ_m = φ + e·sin φ, against an output
    that turns as φ/R (CSF-32-100-GH, 8 input revolutions at constant speed): the output's
    error is −(e/R)·sin φ, once per WG revolution. The output's slope must stay near 1/R
    (a gain error of the angle channel is small): with it free, the record's time stood in
    for the input angle and a drift of 0.2 rad took the whole error."""
    catalog = load_catalog()
    phi = np.linspace(0.0, 16 * math.pi, 3000)
    e, ratio, sigma = 3e-3, 100, 2e-6
    data = {"input_angle_rad": phi + e * np.sin(phi),
            "output_angle_rad": phi / ratio + sigma * np.random.default_rng(2).standard_normal(
                len(phi))}
    result = reconcile("transmission", data, resolve("CSF-32-100-GH", catalog), catalog)
    assert result.missing_effects == ["te_1x"]
    amplitude = result.steps[0].params["amplitude"]["value"]
    assert amplitude == pytest.approx(e / ratio, rel=0.05)
    assert any(r.get("measurement") == "encoder_eccentricity"
               for r in result.equivalent_readings)
    assert result.measurement_effects == []


def test_gross_outliers_are_left_out_of_the_regions_too():
    """CSF-32-100-GH at its catalog curve over ±137 N·m with noise 2×10⁻⁶ rad and every
    40th sample 100× the noise off (40 gross outliers): they are left out of the fit and
    the RMSE, and so out of the regions' RMS, which with them reads about 16× the noise in
    every torque region and calls it in disagreement before and after."""
    from hdcad.reconcile.baseline import catalog_twist, stiffness_curve
    catalog = load_catalog()
    model = resolve("CSF-32-100-GH", catalog)
    torque = _torsion_triangle(137.0, 1600)
    sigma = 2e-6
    twist = (catalog_twist(stiffness_curve(model)[0], torque, 0.0)
             + sigma * np.random.default_rng(6).standard_normal(len(torque)))
    twist[20::40] += 100 * sigma * np.where(np.arange(40) % 2, 1.0, -1.0)
    result = reconcile("torsion", {"torque_Nm": torque, "twist_rad": twist}, model, catalog)
    assert result.missing_effects == [] and result.outliers == 40
    assert result.rmse_after == pytest.approx(sigma, rel=0.1)
    assert result.regions and all(r["rms_after"] < 1.3 * sigma and not r["significant"]
                                  for r in result.regions)
    assert result.disagreements == [] and result.unexplained == []


def test_region_verdicts_read_before_and_after():
    from hdcad.reconcile.report import region_verdict
    assert region_verdict(True, False) == "disagreed → explained"
    assert region_verdict(True, True) == "disagreed → still disagrees"
    assert region_verdict(False, False) == ""


def scaled_example(tmp_path, column: str, factor: float):
    """The shipped torsion example with one column multiplied by ``factor``."""
    import csv
    from hdcad.resources import examples_dir
    rows = list(csv.DictReader(open(examples_dir() / "reconcile_torsion_synthetic.csv")))
    path = tmp_path / "scaled.csv"
    with open(path, "w", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=list(rows[0]))
        writer.writeheader()
        for r in rows:
            writer.writerow(dict(r, **{column: repr(float(r[column]) * factor)}))
    return path


@pytest.mark.parametrize("column, factor, words", [
    ("twist_rad", 180 / math.pi, "degrees instead of radians"),
    ("twist_rad", 60 * 180 / math.pi, "arc-minutes instead of radians"),
    ("twist_rad", 3600 * 180 / math.pi, "arc-seconds instead of radians"),
    ("torque_Nm", 1e-3, "kN·m"),
    ("torque_Nm", 1 / 9.80665, "kgf·m"),
])
def test_data_in_wrong_units_are_converted_and_named_as_the_rig(tmp_path, capsys, column,
                                                                factor, words):
    """A channel in the wrong unit is a measurement-chain finding, not a gear effect: the
    channel is converted and the shipped example's hysteresis is still the only gear effect."""
    path = scaled_example(tmp_path, column, factor)
    out = tmp_path / "r.json"
    code = main(["reconcile", "torsion", str(path), "--model", "CSF-32-100-GH", "--json",
                 str(out)])
    doc = json.loads(out.read_text(encoding="utf-8"))
    assert code == 0 and doc["missing_effects"] == ["hysteresis"]
    units = [m for m in doc["measurement_effects"] if m["effect"] == "wrong_units"]
    assert len(units) == 1 and words in units[0]["reading"]
    assert units[0]["factor"] == pytest.approx(1 / factor, rel=1e-12)


def test_implausible_scale_without_a_unit_reading_is_bad_input(tmp_path, capsys):
    """24× the catalog twist lies between the kgf·m reading's window (9.81 within a factor
    2) and the degrees' (57.3 within 2): no usual unit mistake explains it."""
    path = scaled_example(tmp_path, "twist_rad", 24.0)
    code = main(["reconcile", "torsion", str(path), "--model", "CSF-32-100-GH"])
    err = capsys.readouterr().err
    assert code == 2 and "twist_rad" in err and err.count("\n") == 1


def test_efficiency_as_a_fraction_is_converted():
    from hdcad.reconcile.units import find_fix
    data = {"efficiency_pct": np.full(50, 0.82), "load_torque_Nm": np.full(50, 100.0)}
    (fix,) = find_fix("efficiency", data, rated_torque=100.0)
    assert fix.column == "efficiency_pct" and fix.factor == 100.0 and "fraction" in fix.reading


def test_efficiency_in_per_mille_is_converted_and_named_as_the_rig():
    """A logger that counts 0.1 % steps reads 820 for 82 %: a median above 100 % is no
    efficiency in percent. The channel passes the reading check (in ‰), is converted and
    reported as the rig's unit; the level found is the one in percent. 1 200 ‰ stays bad
    input (120 %-points above the band a reading may stray to)."""
    from hdcad.catalog import load_catalog
    from hdcad.models import resolve
    from hdcad.reconcile import reconcile
    from hdcad.reconcile.data import validate_data
    catalog = load_catalog()
    rng = np.random.default_rng(3)
    speed, load = np.meshgrid([500.0, 1000.0, 2000.0], np.linspace(20.0, 180.0, 20))
    eta_pct = 82.0 + 0.3 * rng.standard_normal(speed.size)
    data = {"input_speed_rpm": speed.ravel(), "load_torque_Nm": load.ravel(),
            "temperature_C": np.full(speed.size, 25.0), "efficiency_pct": 10.0 * eta_pct}
    result = reconcile("efficiency", data, resolve("CSF-32-100-GH", catalog), catalog)
    (fix,) = [m for m in result.measurement_effects if m["effect"] == "wrong_units"]
    assert fix["factor"] == pytest.approx(0.1) and "per mille" in fix["reading"]
    assert result.missing_effects == []
    assert result.baseline_params["eta0"]["value"] == pytest.approx(82.0, abs=0.2)
    with pytest.raises(InputError, match="efficiency_pct"):
        validate_data("efficiency", dict(data, efficiency_pct=np.append(
            data["efficiency_pct"][:-1], 2100.0)))


@pytest.mark.parametrize("seed, name", [
    (7, "i-torsion-decoy-separable-torque-knm-torque-knm-000"),
    (13, "i-torsion-decoy-separable-torque-knm-torque-knm-001"),
])
def test_torque_in_kn_m_is_told_from_twist_in_mrad_by_the_curve_s_corners(seed, name):
    """Suite I's torque recorded in kN·m (``truths/truth_i.py``, written from the contract
    only). Against the catalog curve, dividing the twist by 1000 (mrad) gives a scale of
    0.96, nearer 1 than the right reading's 1.06–1.12 (the gear's own scatter), but it puts
    every torque on the curve's first segment: the shape misfit is 2.5–7× the kN·m
    reading's. With the twist divided, a backlash was named (ΔBIC 484)."""
    from truth_runs import bench, named_case
    case = named_case("i", name, seed)
    result = bench.reconcile_case(case)
    (fix,) = [m for m in result["measurement_effects"] if m["effect"] == "wrong_units"]
    assert fix["column"] == "torque_Nm" and fix["factor"] == 1000.0
    assert result["missing_effects"] == []
    assert result["rmse_after"] <= 1.2 * case.noise_rms


def test_an_output_angle_in_arc_seconds_is_converted():
    """Suite J's transmission record with the output angle in arc-seconds (the unit of the
    catalog's accuracy tables, seed 003 tables 051-1/059-1) was refused as bad input at its
    held-out score (the output turned 2.06e5 × input / ratio); it is converted and named as
    the rig, and no gear effect is named."""
    from truth_runs import bench, named_case
    case = named_case("j", "j-transmission-decoy_separable-wrong_units-arcsec-000", 11)
    result = bench.reconcile_case(case)
    (fix,) = result["measurement_effects"]
    assert fix["column"] == "output_angle_rad" and "arc-seconds" in fix["reading"]
    assert fix["factor"] == pytest.approx(math.pi / (180 * 3600), rel=1e-12)
    assert result["missing_effects"] == []


def test_a_transmission_record_under_one_revolution_is_bad_input(tmp_path, capsys):
    """Half a WG revolution in radians (the output at input / R): no unit reading explains
    it, and it is too short to name a 1× error: exit 2, the column named, nothing written."""
    rows = np.array(transmission_rows(), dtype=float)
    rows = rows[rows[:, 0] <= math.pi]
    csv = write_csv(tmp_path / "t.csv", COLUMNS["transmission"],
                    [(f"{a:.9g}", f"{b:.9g}") for a, b in rows])
    code, _, err = run(capsys, "reconcile", "transmission", csv, "--model", "CSF-32-100-GH",
                       "--out", tmp_path / "out")
    assert code == 2
    assert "input_angle_rad" in err and "WG revolutions" in err
    assert len(err.strip().splitlines()) == 1
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("seed", [11, 7])
def test_an_input_angle_in_revolutions_is_converted(seed):
    """Suite K's transmission record with the input angle in revolutions was refused as bad
    input at its held-out score (the output turned 6.28 × input / ratio). At seed 7 its
    4 WG revolutions, read as radians, span 0.64 of one: the least span is checked once the
    units are read, not before (it was refused as too short)."""
    from truth_runs import bench, named_case
    case = named_case("k", "k-transmission-decoy_separable-none-input-in-revolutions-000", seed)
    result = bench.reconcile_case(case)
    (fix,) = result["measurement_effects"]
    assert fix["column"] == "input_angle_rad" and "revolutions" in fix["reading"]
    assert fix["factor"] == pytest.approx(2 * math.pi, rel=1e-12)
    assert result["missing_effects"] == []


def test_an_input_angle_in_degrees_is_converted():
    """Suite L's transmission record with the input angle in degrees was refused as bad
    input at its held-out score (the output turned 0.0175 × input / ratio, 1/57.3)."""
    from truth_runs import bench, named_case
    case = named_case("l", "l-transmission-decoy-indeg-000", 11, per_cell=1)
    result = bench.reconcile_case(case)
    (fix,) = result["measurement_effects"]
    assert fix["column"] == "input_angle_rad" and "degrees" in fix["reading"]
    assert fix["factor"] == pytest.approx(math.pi / 180, rel=1e-12)
    assert result["missing_effects"] == []
    assert result["rmse_after"] <= 1.2 * case.noise_rms
