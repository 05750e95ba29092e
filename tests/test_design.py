"""`hdcad design`: complete output folders, re-importable STEP, nothing left on bad input."""

import json

import pytest

cq = pytest.importorskip("cadquery")

from hdcad.cli import main  # noqa: E402


def _design(tmp_path, model, duty, *extra):
    out = tmp_path / "out"
    code = main(["design", model, "--duty", str(duty), "--out", str(out), *extra])
    return code, out / model


@pytest.fixture(scope="module")
def fd2_design(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("fd2")
    duty = tmp / "light.yaml"
    duty.write_text("""
cycle:
  - {phase: start, torque_Nm: 30, time_s: 0.5, speed_rpm: 5}
  - {phase: steady, torque_Nm: 20, time_s: 2, speed_rpm: 10}
  - {phase: stop, torque_Nm: 30, time_s: 0.5, speed_rpm: 5}
  - {phase: rest, torque_Nm: 0, time_s: 20, speed_rpm: 0}
max_output_speed_rpm: 10
max_input_speed_rpm: 1500
required_life_h: 7000
lubrication: oil
""")
    code, folder = _design(tmp, "FD-25-80-2", duty)
    return code, folder


def test_fd2_design_writes_every_file(fd2_design):
    code, folder = fd2_design
    assert code in (0, 1)
    names = {p.name for p in folder.iterdir()}
    assert {"casing_half_S.step", "casing_half_D.step", "assembly.step", "results.json",
            "casing_half_S.stl", "casing_half_S.svg"} <= names
    result = json.loads((folder / "results.json").read_text())
    ids = [c["id"] for c in result["checks"]]
    assert "interference" in ids and ids.count("bolt_pattern") >= 2 and "input_bore" in ids
    inter = next(c for c in result["checks"] if c["id"] == "interference")
    assert inter["status"] == "pass" and inter["value"] == pytest.approx(0.0, abs=1e-3)
    assert all(p["mass_kg"] > 0 for p in result["parts"])


def test_step_reimports_as_valid_solids(fd2_design):
    _, folder = fd2_design
    for name in ("casing_half_S", "casing_half_D", "sleeve_S", "sleeve_D"):
        shape = cq.importers.importStep(str(folder / f"{name}.step")).val()
        assert shape.isValid() and len(shape.Solids()) == 1
    assembly = cq.importers.importStep(str(folder / "assembly.step"))
    assert len(assembly.solids().vals()) == 4  # two casing halves and their sleeves


def test_step_opens_in_gmsh(fd2_design):
    """A second, independent STEP reader (gmsh's OCC build) sees the same solids."""
    gmsh = pytest.importorskip("gmsh")
    _, folder = fd2_design
    gmsh.initialize(["-noenv"])
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("check")
        entities = gmsh.model.occ.importShapes(str(folder / "assembly.step"))
        gmsh.model.occ.synchronize()
        volumes = [tag for dim, tag in entities if dim == 3]
        assert len(volumes) == 4
        masses = [gmsh.model.occ.getMass(3, tag) for tag in volumes]
        assert all(m > 1000 for m in masses)  # mm³: each part is a real solid
    finally:
        gmsh.finalize()


def test_bad_flange_code_exit_2_and_nothing_written(tmp_path, example_duty_path):
    options = tmp_path / "design.yaml"
    options.write_text("motor_flange: ZZ\n")
    code, folder = _design(tmp_path, "CSF-45-120-GH", example_duty_path, "--design", str(options))
    assert code == 2 and not folder.exists()
    assert not any((tmp_path / "out").glob("*")) if (tmp_path / "out").exists() else True


def test_bad_option_exit_2(tmp_path, example_duty_path, capsys):
    options = tmp_path / "design.yaml"
    options.write_text("wall_mm: -4\n")
    code, folder = _design(tmp_path, "CSF-45-120-GH", example_duty_path, "--design", str(options))
    assert code == 2 and not folder.exists()
    assert "wall_mm" in capsys.readouterr().err


def test_component_housing_without_tables_says_what_is_missing(tmp_path, example_duty_path,
                                                              capsys):
    code, folder = _design(tmp_path, "CSF-40-120-2A-GR", example_duty_path)
    assert code == 2 and not folder.exists()
    assert "component_outline" in capsys.readouterr().err


def test_failing_design_is_still_written(tmp_path, example_duty_path):
    code, folder = _design(tmp_path, "FD-25-80-0", example_duty_path)  # Tav 320 N·m ≫ 57 N·m
    assert code == 1
    result = json.loads((folder / "results.json").read_text())
    assert not result["all_passed"] and (folder / "assembly.step").exists()


def test_interference_with_a_single_part_is_not_evaluated():
    from hdcad.design import interference_check
    single = interference_check([], {"motor_flange": 0.9})
    assert single.status == "not_evaluated" and "no pair" in single.note
    pair = interference_check([("a", "b", 0.0)], {"a": 1.0, "b": 2.0})
    assert pair.status == "pass"


def test_fits_travel_to_results_and_fits_csv(fd2_design):
    """Every ISO 286 fit of the parts is in results.json and fits.csv (STEP AP214 carries no
    PMI); the 6006 seat is M7 (ISO 286-2 on Ø55: 0/−30 µm)."""
    import csv
    _, folder = fd2_design
    result = json.loads((folder / "results.json").read_text())
    casing = next(p for p in result["parts"] if p["name"] == "casing_half_S")
    seat = next(f for f in casing["fits"] if f["code"] == "M7")
    assert seat["nominal_mm"] == 55 and seat["deviations_um"] == [0, -30]
    rows = list(csv.DictReader((folder / "fits.csv").open(encoding="utf-8")))
    assert len(rows) == sum(len(p["fits"]) for p in result["parts"])
    assert {"part": "casing_half_S", "code": "M7", "upper_um": "0", "lower_um": "-30"}.items() \
        <= next(r for r in rows if r["code"] == "M7" and r["part"] == "casing_half_S").items()
    review = next(c for c in result["checks"] if c["id"] == "review_assembly")
    assert review["status"] == "pass" and (folder / "review_assembly.step").is_file()
