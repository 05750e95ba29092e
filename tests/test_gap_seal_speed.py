"""gap_seal_speed: surface speed of the running-gap O-ring between the FD casing halves."""

import math

import pytest

from hdcad.checks.seals import gap_seal_speed, relative_casing_rpm, surface_speed_m_s
from hdcad.duty import parse_duty

REDUCER = {"cycle": [{"phase": "steady", "torque_Nm": 10, "time_s": 5, "speed_rpm": 20}],
           "max_output_speed_rpm": 30, "max_input_speed_rpm": 3000, "required_life_h": 7000,
           "lubrication": "oil"}


def test_surface_speed_by_hand():
    # Ø96.2 spigot at 30 r/min: π × 0.0962 m × 0.5 1/s = 0.1511 m/s
    assert surface_speed_m_s(96.2, 30) == pytest.approx(math.pi * 0.0962 * 0.5)


def test_reducer_use_runs_at_the_output_speed():
    duty = parse_duty(REDUCER)
    n, how = relative_casing_rpm(duty, 80)
    assert n == 30 and "output speed" in how
    check = gap_seal_speed(96.2, duty, 80, 0.25)
    assert check.status == "pass" and check.value == pytest.approx(0.1511, abs=1e-4)


def test_differential_use_runs_at_line_speed_over_r_plus_one():
    raw = dict(REDUCER, use="differential", max_output_speed_rpm=1500,
               cycle=[{"phase": "steady", "torque_Nm": 10, "time_s": 5, "speed_rpm": 810,
                       "wave_generator_rpm": 40}])
    n, _ = relative_casing_rpm(parse_duty(raw), 80)
    assert n == pytest.approx(810 / 81 + 40 / 80)  # 10 + 0.5 r/min


def test_too_fast_fails_and_says_what_to_use():
    duty = parse_duty(dict(REDUCER, max_output_speed_rpm=100))
    check = gap_seal_speed(96.2, duty, 80, 0.25)  # 0.50 m/s
    assert check.status == "fail" and "lip seal" in check.note
    assert gap_seal_speed(96.2, duty, 80, 0.6).status == "pass"  # the rule is the user's


def test_without_a_seal_it_is_not_evaluated():
    assert gap_seal_speed(None, parse_duty(REDUCER), 80, 0.25).status == "not_evaluated"
