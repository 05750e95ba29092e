"""Every result row reads true: ``value op limit`` as printed holds exactly as the check says.

A passing check prints its sense (≤, ≥), a failing one the relation that failed (>, <); a
multi-criterion check must show its governing criterion in the row, so the printed numbers
always agree with the status. Swept over the whole catalog for a light and a heavy duty.
"""

from __future__ import annotations

import math
import operator

import pytest

from hdcad.checks.run import run_checks
from hdcad.duty import parse_duty
from hdcad.models import list_models, resolve
from hdcad.report.format import relation_text

OPS = {"≤": operator.le, "≥": operator.ge, "<": operator.lt, ">": operator.gt}
HEAVY = {"cycle": [{"phase": "start", "torque_Nm": 900, "time_s": 0.3, "speed_rpm": 7},
                   {"phase": "steady", "torque_Nm": 800, "time_s": 3.0, "speed_rpm": 14},
                   {"phase": "stop", "torque_Nm": 900, "time_s": 0.4, "speed_rpm": 7}],
         "max_output_speed_rpm": 14, "max_input_speed_rpm": 1800, "required_life_h": 7000,
         "lubrication": "grease"}
FAST = dict(HEAVY, cycle=[{"phase": "steady", "torque_Nm": 10, "time_s": 3, "speed_rpm": 30},
                          {"phase": "rest", "torque_Nm": 0, "time_s": 3, "speed_rpm": 0}],
            max_output_speed_rpm=31, max_input_speed_rpm=3800)
LIGHT = dict(HEAVY, cycle=[dict(s, torque_Nm=s["torque_Nm"] / 100) for s in HEAVY["cycle"]])


@pytest.mark.parametrize("raw", [HEAVY, LIGHT, FAST], ids=["heavy", "light", "fast"])
def test_printed_relation_holds_for_every_check_of_every_model(catalog, raw):
    duty = parse_duty(raw, "duty")
    wrong, counted = [], {"pass": 0, "fail": 0, "warn": 0}
    for code in list_models(catalog):
        for c in run_checks(resolve(code, catalog), duty, catalog).checks:
            op = relation_text(c.sense, c.status)
            if c.status not in counted or not op or c.value is None or c.limit is None:
                continue
            counted[c.status] += 1
            if not OPS[op](c.value, c.limit):
                wrong.append(f"{code} {c.id}: {c.value:g} {op} {c.limit:g} ({c.status})")
    assert counted["pass"] > 100 and (raw is not HEAVY or counted["fail"] > 50)
    assert raw is not FAST or counted["warn"] > 0  # gear heads above the 3000 r/min guide
    assert not wrong, "\n".join(wrong[:20])


def _geometric(catalog, code: str, **options):
    pytest.importorskip("cadquery")
    from hdcad.checks.geometric import geometric_checks
    from hdcad.design_options import DesignOptions
    from hdcad.geometry.build import build_parts
    model = resolve(code, catalog)
    opts = DesignOptions(**options)
    return geometric_checks(model, build_parts(model, catalog, opts), opts, catalog)


# seed 003 table 064-1, CSF-GH size 45: PP = M12 on φ200 in a □180 flange, PG and PQ square too;
# holes at 45° + k·90° sit in the corners: 180/2 − 100·sin 45° = 19.3 mm to the sides
@pytest.mark.parametrize("flange", ["PP", "PG", "PQ"])
def test_square_motor_flanges_measure_edge_distance_to_the_square(catalog, flange):
    record = next(c for c in _geometric(catalog, "CSF-45-120-GH", motor_flange=flange)
                  if c.id == "bolt_pattern")
    edge = record.details["criteria"]["edge_outer"]
    row = catalog.find("gh_motor_flange", series="CSF-GH", size=45, flange_code=flange)
    r, half = row["bolt_circle_mm"] / 2, row["square_mm"] / 2
    assert edge["value"] == pytest.approx(half - r * math.sin(math.pi / 4))
    assert edge["status"] == "pass" and record.status == "pass"
    if flange == "PP":
        assert edge["value"] == pytest.approx(19.29, abs=0.01)


@pytest.mark.parametrize("code", ["CSF-45-120-GH", "FD-25-80-2", "FD-25-80-0"])
def test_geometric_rows_read_true(catalog, code):
    checks = [c for c in _geometric(catalog, code) if c.value is not None and c.limit is not None]
    assert checks
    for c in checks:
        op = relation_text(c.sense, c.status)
        assert OPS[op](c.value, c.limit), f"{c.id} {c.details.get('name')}: {c.value} {op} {c.limit}"
