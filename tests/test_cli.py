"""The command line: exit codes, JSON shape, fixed check ids, no cadquery on the check path."""

import json
import subprocess
import sys

from hdcad.checks import CHECK_IDS
from hdcad.cli import main


def test_check_json_has_every_fixed_id(tmp_path, example_duty_path):
    out = tmp_path / "r.json"
    assert main(["check", "FD-25-80-2", "--duty", str(example_duty_path), "--json", str(out)]) == 1
    data = json.loads(out.read_text())
    assert [c["id"] for c in data["checks"]] == list(CHECK_IDS)
    assert set(data) >= {"model", "duty", "derived", "checks", "all_passed"}
    assert set(data["derived"]) >= {"avg_torque_Nm", "avg_output_speed_rpm",
                                    "avg_input_speed_rpm", "max_input_speed_rpm"}
    for check in data["checks"]:
        assert set(check) >= {"id", "title", "formula", "inputs", "value", "limit", "unit",
                              "margin", "status", "source", "note"}
        assert check["status"] in ("pass", "fail", "not_evaluated")
        if check["status"] == "not_evaluated":
            assert check["note"].startswith("not evaluated: ")
    assert data["all_passed"] is False


def test_check_does_not_import_cadquery(example_duty_path):
    code = ("import sys; from hdcad.cli import main; "
            f"main(['check', 'CSF-45-120-GH', '--duty', {str(example_duty_path)!r}]); "
            "print('cadquery' in sys.modules, 'OCP' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip().splitlines()[-1] == "False False"


def test_catalog_command_lists_series(capsys):
    assert main(["catalog", "--series", "CSG-GH"]) == 0
    text = capsys.readouterr().out
    assert "CSG-45-120-GH" in text and "CSF-45-120-GH" not in text


def test_select_lists_smallest_passing_first(tmp_path, example_duty_path, capsys):
    out = tmp_path / "sel.json"
    assert main(["select", "--duty", str(example_duty_path), "--series", "CSF-GH",
                 "--json", str(out)]) == 0
    data = json.loads(out.read_text())
    passing = [p["model"] for p in data["passing"]]
    assert passing[0] == "CSF-45-80-GH" and "CSF-45-120-GH" in passing
    sizes = [int(m.split("-")[1]) for m in passing]
    assert sizes == sorted(sizes)
    rejected = {r["model"]: r["check"]["id"] for r in data["rejected"]}
    assert rejected["CSF-32-100-GH"] == "avg_torque"  # Tav 319.7 > 216 N·m
    assert rejected["CSF-45-160-GH"] == "ratio_limit"  # 1800/14 = 128.6 < 160


def test_unknown_model_is_exit_2(example_duty_path, capsys):
    assert main(["check", "CSF-44-120-GH", "--duty", str(example_duty_path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "sizes in the catalog: 14, 20, 32, 45, 65" in err


def test_json_not_written_on_bad_input(tmp_path):
    out = tmp_path / "r.json"
    bad = tmp_path / "duty.yaml"
    bad.write_text("cycle: []\n")
    assert main(["check", "CSF-45-120-GH", "--duty", str(bad), "--json", str(out)]) == 2
    assert not out.exists()


def test_console_script_runs(example_duty_path):
    out = subprocess.run([sys.executable, "-m", "hdcad", "check", "CSF-45-120-GH", "--duty",
                          str(example_duty_path)], capture_output=True, text=True)
    assert out.returncode == 0 and "wg_life" in out.stdout
