"""Stages of a design in a side process give the same packet as the plain sequential run."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from hdcad.parallel import InlineExecutor, side_executor


def test_inline_executor_runs_at_once_and_keeps_the_error_for_result():
    ex = InlineExecutor()
    assert ex.submit(pow, 2, 10).result() == 1024
    failed = ex.submit(int, "not a number")
    assert failed.done()
    with pytest.raises(ValueError):
        failed.result()


def test_side_executor_is_inline_when_parallel_is_off():
    assert isinstance(side_executor(False), InlineExecutor)


@pytest.fixture(scope="module")
def packets(tmp_path_factory, catalog):
    pytest.importorskip("cadquery")
    from hdcad.design import run_design
    from hdcad.design_options import DesignOptions
    from hdcad.duty import load_duty
    from hdcad.models import resolve
    from hdcad.resources import examples_dir
    duty = load_duty(examples_dir() / "duty_seed_example.yaml")
    out = {}
    for parallel in (False, True):
        folder = tmp_path_factory.mktemp(f"parallel_{parallel}")
        out[parallel] = run_design(resolve("CSF-45-120-GH", catalog), duty, DesignOptions(),
                                   catalog, folder, parallel=parallel).folder
    return out


def test_side_process_writes_the_same_packet(packets):
    seq, par = packets[False], packets[True]
    files = sorted(p.relative_to(seq).as_posix() for p in seq.rglob("*") if p.is_file())
    assert files == sorted(p.relative_to(par).as_posix() for p in par.rglob("*") if p.is_file())
    # the plots carry no date: made in another process they are the same bytes
    for svg in (f for f in files if f.startswith("figures/")):
        assert (seq / svg).read_bytes() == (par / svg).read_bytes(), svg
    a, b = (json.loads((p / "results.json").read_text()) for p in (seq, par))
    assert a["checks"] == b["checks"] and a["calc_sheet"] == b["calc_sheet"]
    assert Path(par / "calc_sheet.pdf").stat().st_size > 50_000
