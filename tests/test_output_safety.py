"""Output that never loses a user's files and is never half-written: targets checked before
any work, one run per folder, killed runs cleaned up, the umask honoured, --json written
through devices, pipes and symlinks."""

from __future__ import annotations

import json
import os
import stat
import subprocess
import sys
import threading
from pathlib import Path

import numpy as np
import pytest

from hdcad.cli import main
from hdcad.errors import InputError
from hdcad.output import MANIFEST, _locked, staged_dir, write_text_atomic
from hdcad.resources import examples_dir

DUTY = str(examples_dir() / "duty_seed_example.yaml")


def _reconcile(out, *extra):
    """A transmission record of the catalog model with noise only: the output folder's rules
    are the same for every kind, and this one reconciles in a fraction of a second."""
    csv = Path(str(out).rstrip("/") + ".csv") if str(out) else Path("transmission.csv")
    if str(out) and not csv.exists():
        wg = np.linspace(0.0, 8 * np.pi, 800).tolist()
        noise = np.random.default_rng(0).normal(0.0, 1e-6, len(wg)).tolist()
        rows = "\n".join(f"{a!r},{a / 100 + e!r}" for a, e in zip(wg, noise))
        csv.write_text("input_angle_rad,output_angle_rad\n" + rows + "\n")
    return main(["reconcile", "transmission", str(csv), "--model", "CSF-32-100-GH",
                 "--out", str(out), *extra])


def test_a_users_file_in_the_output_folder_is_kept_unless_forced(tmp_path, capsys):
    out = tmp_path / "rep"
    assert _reconcile(out) == 0
    assert json.loads((out / MANIFEST).read_text())  # what hdcad wrote is recorded
    assert _reconcile(out) == 0  # its own files it may replace
    (out / "my notes.txt").write_text("keep me")
    assert _reconcile(out) == 2
    assert "my notes.txt" in capsys.readouterr().err and (out / "my notes.txt").exists()
    assert _reconcile(out, "--force") == 0 and not (out / "my notes.txt").exists()


def test_a_symlinked_or_empty_output_is_refused_before_any_work(tmp_path, capsys):
    (tmp_path / "real").mkdir()
    (tmp_path / "link").symlink_to(tmp_path / "real")
    assert _reconcile(tmp_path / "link") == 2
    assert "symbolic link" in capsys.readouterr().err
    assert _reconcile("") == 2


def test_one_run_at_a_time_per_folder(tmp_path):
    target = tmp_path / "MODEL"
    with _locked(tmp_path / ".MODEL.lock") as held:
        assert held
        with pytest.raises(InputError, match="another hdcad run"):
            with staged_dir(target):
                pass
    assert not target.exists()


def test_staging_folders_of_killed_runs_are_removed(tmp_path):
    dead = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"],
                          capture_output=True, text=True).stdout.strip()
    stale = tmp_path / f".MODEL.staging-{dead}-abc123"
    stale.mkdir()
    (stale / "part.step").write_text("half")
    mine = tmp_path / f".MODEL.staging-{os.getpid()}-zzz"
    mine.mkdir()  # a live run's staging folder is left alone
    with staged_dir(tmp_path / "MODEL") as stage:
        (stage / "x.txt").write_text("x")
    assert not stale.exists() and mine.exists() and (tmp_path / "MODEL" / "x.txt").exists()


def test_files_and_folders_follow_the_umask(tmp_path):
    old = os.umask(0o027)
    try:
        with staged_dir(tmp_path / "MODEL") as stage:
            (stage / "sub").mkdir()
            (stage / "sub" / "a.txt").write_text("a")
        write_text_atomic(tmp_path / "r.json", "{}")
    finally:
        os.umask(old)
    mode = lambda p: stat.S_IMODE(p.stat().st_mode)  # noqa: E731
    assert mode(tmp_path / "MODEL") == 0o750 and mode(tmp_path / "MODEL" / "sub") == 0o750
    assert mode(tmp_path / "MODEL" / "sub" / "a.txt") == 0o640
    assert mode(tmp_path / "r.json") == 0o640


def test_json_goes_through_a_symlink_and_a_fifo_and_refuses_a_folder(tmp_path):
    real = tmp_path / "real.json"
    real.write_text("old")
    link = tmp_path / "link.json"
    link.symlink_to(real)
    write_text_atomic(link, '{"a": 1}')
    assert link.is_symlink() and real.read_text() == '{"a": 1}'
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    got = []
    reader = threading.Thread(target=lambda: got.append(fifo.read_text()))
    reader.start()
    write_text_atomic(fifo, '{"b": 2}')
    reader.join(timeout=10)
    assert got == ['{"b": 2}'] and stat.S_ISFIFO(fifo.stat().st_mode)
    with pytest.raises(InputError, match="folder"):
        write_text_atomic(tmp_path, "{}")


def test_json_to_dev_stdout_is_written_through():
    done = subprocess.run([sys.executable, "-m", "hdcad.cli", "check", "CSF-45-120-GH",
                           "--duty", DUTY, "--json", "/dev/stdout"], capture_output=True,
                          text=True)
    assert done.returncode == 0 and '"catalog_revision"' in done.stdout
    assert Path("/dev/stdout").exists()


@pytest.mark.parametrize("row, field", [
    ("{model: CSF-45-120-GH, bearing_type: cross_roller, dp_m: 0, R_m: 0.02, C_N: 40000, "
     "Co_N: 60000, Mc_Nm: 800}", "dp_m"),
    ("{model: CSF-45-120-GH, bearing_type: ball, dp_m: 0.1, R_m: 0.02, C_N: 40000, "
     "Co_N: 60000, Mc_Nm: 800}", "bearing_type"),
])
def test_overlay_rows_are_validated_like_shipped_tables(tmp_path, capsys, row, field):
    overlay = tmp_path / "overlay.yaml"
    overlay.write_text(f"source: test\ntables:\n  main_bearing:\n    - {row}\n")
    assert main(["check", "CSF-45-120-GH", "--duty", DUTY, "--catalog-overlay",
                 str(overlay)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and field in err and "overlay.yaml" in err


@pytest.mark.parametrize("text, words", [
    ("a: 1\na: 2\n", "duplicate key"),
    ("a: &a [1]\n" + "".join(f"b{i}: *a\n" for i in range(30)), "aliases"),
    ("a: " + "[" * 100 + "]" * 100 + "\n", "nesting"),
    ("a: 1" + "0" * 400 + "\n", "digits"),
])
def test_yaml_traps_are_bad_input(tmp_path, capsys, text, words):
    path = tmp_path / "duty.yaml"
    path.write_text(text)
    assert main(["check", "CSF-45-120-GH", "--duty", str(path)]) == 2
    err = capsys.readouterr().err
    assert words in err and err.count("\n") == 1 and len(err) < 320


@pytest.mark.parametrize("special", ["/dev/zero", "/dev/null", "/tmp"])
def test_special_files_are_refused_as_inputs(capsys, special):
    assert main(["check", "CSF-45-120-GH", "--duty", special]) == 2
    assert special in capsys.readouterr().err


def test_a_non_utf8_file_is_bad_input(tmp_path, capsys):
    path = tmp_path / "duty.yaml"
    path.write_bytes("cycle: é\n".encode("latin-1"))
    assert main(["check", "CSF-45-120-GH", "--duty", str(path)]) == 2
    assert "UTF-8" in capsys.readouterr().err


def test_a_killed_design_leaves_only_a_staging_folder_that_the_next_run_removes(tmp_path):
    pytest.importorskip("cadquery")
    import signal
    import time
    cmd = [sys.executable, "-m", "hdcad.cli", "design", "CSF-45-120-GH", "--duty", DUTY,
           "--out", str(tmp_path), "--quiet"]
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    deadline = time.time() + 30
    while not list(tmp_path.glob(".CSF-45-120-GH.staging-*")) and time.time() < deadline:
        time.sleep(0.05)
    time.sleep(0.5)
    proc.send_signal(signal.SIGKILL)  # no chance to clean up
    proc.wait()
    assert not (tmp_path / "CSF-45-120-GH").exists()
    assert subprocess.run(cmd, capture_output=True).returncode == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["CSF-45-120-GH"]
