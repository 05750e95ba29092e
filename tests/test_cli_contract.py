"""The command line's contract: exit codes 0/1/2/3/130, one-line messages, no tracebacks,
help for every option, a quiet broken pipe, `hdcad catalog MODEL`, stage lines."""

from __future__ import annotations

import argparse
import os
import signal
import subprocess
import sys
import time

import pytest

from hdcad import cli
from hdcad.resources import examples_dir

DUTY = str(examples_dir() / "duty_seed_example.yaml")
HDCAD = [sys.executable, "-m", "hdcad.cli"]


def _boom(args):
    raise ZeroDivisionError("division by zero in a check")


def test_an_internal_error_is_one_line_and_exit_3(monkeypatch, capsys):
    monkeypatch.setattr(cli, "cmd_check", _boom)
    assert cli.main(["check", "CSF-45-120-GH", "--duty", DUTY]) == 3
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "Traceback" not in err
    assert "ZeroDivisionError" in err and "--debug" in err


def test_debug_prints_the_traceback(monkeypatch, capsys):
    monkeypatch.setattr(cli, "cmd_check", _boom)
    assert cli.main(["--debug", "check", "CSF-45-120-GH", "--duty", DUTY]) == 3
    assert "Traceback" in capsys.readouterr().err


def test_ctrl_c_is_exit_130(monkeypatch, capsys):
    def interrupted(args):
        raise KeyboardInterrupt
    monkeypatch.setattr(cli, "cmd_select", interrupted)
    assert cli.main(["select", "--duty", DUTY]) == 130
    assert "interrupted" in capsys.readouterr().err


def test_ctrl_c_while_the_command_line_loads_is_exit_130(monkeypatch, capsys):
    """The console command remembers Ctrl-C from its first line (``hdcad._entry``): an
    interrupt while the command line's modules load ends the run with one line and 130."""
    from hdcad import _entry
    monkeypatch.setattr(_entry, "caught", [signal.SIGINT])
    assert cli.main(["catalog"]) == 130
    assert capsys.readouterr().err.strip() == "hdcad: interrupted"
    from importlib.metadata import entry_points
    command = next(e for e in entry_points(group="console_scripts") if e.name == "hdcad")
    assert command.value == "hdcad._entry:run"


def test_bad_arguments_are_exit_2(capsys):
    assert cli.main(["check"]) == 2
    assert cli.main(["reconcile", "vibration", "x.csv", "--model", "CSF-32-100-GH",
                     "--load-inertia", "inf"]) == 2
    assert "--load-inertia" in capsys.readouterr().err


def test_long_values_are_shortened_in_error_lines():
    line = cli.shorten("x" * 5000 + "\nsecond line")
    assert len(line) <= cli.MESSAGE_LIMIT and "\n" not in line and "…" in line


def test_every_option_has_help():
    parser = cli._parser()
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    missing = [f"{name} {opt.dest}" for name, p in sub.choices.items() for opt in p._actions
               if not isinstance(opt, argparse._HelpAction) and not opt.help]
    assert not missing


def test_a_closed_pipe_ends_quietly():
    done = subprocess.run(" ".join(HDCAD) + " catalog | head -n 1", shell=True,
                          capture_output=True, text=True, executable="/bin/bash")
    assert done.stdout.startswith("hdcad catalog") and done.stderr == ""


def test_catalog_model_lists_the_motor_flange_codes(capsys):
    assert cli.main(["catalog", "CSF-45-120-GH"]) == 0
    out = capsys.readouterr().out
    # seed 003 table 064-1: PP = pilot 114.3 H7, M12 × 25 on φ200, □180
    pp = next(line for line in out.splitlines() if line.startswith("PP "))
    assert "114.3" in pp and "200" in pp and "M12 × 25" in pp and "180" in pp
    assert "momentary_torque_Nm" in out and "table 050-1/058-1" in out


def test_design_prints_a_line_per_stage(tmp_path):
    pytest.importorskip("cadquery")
    done = subprocess.run(HDCAD + ["design", "CSF-45-120-GH", "--duty", DUTY, "--out",
                                   str(tmp_path), "--progress"], capture_output=True, text=True)
    assert done.returncode == 0
    stages = [line for line in done.stderr.splitlines() if line.strip().endswith(" s)")]
    assert [s.split()[0] for s in stages][:2] == ["checks", "build"] and len(stages) >= 5


def _own_group_with_default_sigint():
    # a job started in the background inherits SIGINT ignored: give the child the default,
    # and its own process group so that Ctrl-C can be sent to all of it as a terminal does
    signal.signal(signal.SIGINT, signal.SIG_DFL)
    os.setsid()


# 0.3 s: inside the imports (an interrupt there can surface as an ImportError);
# 2.5 s: CAD built, the side process drawing the plots and the PDF
@pytest.mark.parametrize("delay_s", [0.3, 2.5])
def test_ctrl_c_during_a_design_leaves_nothing_behind(tmp_path, delay_s):
    pytest.importorskip("cadquery")
    proc = subprocess.Popen(HDCAD + ["design", "CSF-45-120-GH", "--duty", DUTY, "--out",
                                     str(tmp_path)], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True,
                            preexec_fn=_own_group_with_default_sigint)
    time.sleep(delay_s)
    os.killpg(proc.pid, signal.SIGINT)
    out, err = proc.communicate(timeout=60)
    if proc.returncode == 0:
        pytest.skip("the design finished before the interrupt (a very fast machine)")
    assert proc.returncode == 130, err
    assert err.strip() == "hdcad: interrupted" and os.listdir(tmp_path) == []


def test_an_interrupted_module_run_leaves_with_130_and_its_output(tmp_path):
    """``python -m`` ends the process by SIGINT, whatever the exit code, once a
    KeyboardInterrupt escaped an embedded ``PyRun_*`` call that Python code later caught (as
    an import interrupted inside a C extension does): ``_entry.leave`` keeps 130 and flushes
    what was printed."""
    (tmp_path / "interrupted_once.py").write_text(
        "import ctypes\n"
        "ctypes.pythonapi.PyRun_SimpleString(b'raise KeyboardInterrupt')\n"
        "print('the answer')\n"
        "from hdcad._entry import leave\n"
        "leave(130)\n")
    done = subprocess.run([sys.executable, "-m", "interrupted_once"], cwd=tmp_path,
                          capture_output=True, text=True,
                          env=dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path)))
    assert (done.returncode, done.stdout) == (130, "the answer\n")


def test_a_ctrl_c_after_the_answer_is_given_keeps_exit_130(monkeypatch, capsys):
    """A Ctrl-C whose handler runs only after the command line answered (the interpreter runs
    a pending signal's handler at its next chance) must not end in a death by SIGINT or a
    second message: the console entry returns 130 with one line, and ignores SIGINT from
    then on."""
    from hdcad import _entry, cli

    def answered_then_interrupted(argv=None):
        print("hdcad: interrupted", file=sys.stderr)
        _entry.reported.append(True)
        raise KeyboardInterrupt

    saved = signal.getsignal(signal.SIGINT)
    monkeypatch.setattr(_entry, "reported", [])
    monkeypatch.setattr(cli, "main", answered_then_interrupted)
    try:
        assert _entry.run() == 130
        assert signal.getsignal(signal.SIGINT) is signal.SIG_IGN
    finally:
        signal.signal(signal.SIGINT, saved)
    assert capsys.readouterr().err == "hdcad: interrupted\n"
    _entry.reported.clear()  # interrupted before the command line could answer
    monkeypatch.setattr(cli, "main", lambda argv=None: (_ for _ in ()).throw(KeyboardInterrupt))
    try:
        assert _entry.run() == 130
    finally:
        signal.signal(signal.SIGINT, saved)
    assert capsys.readouterr().err == "hdcad: interrupted\n"
