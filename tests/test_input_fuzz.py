"""Fuzzing the input schemas: any YAML-shaped value gives a Duty / DesignOptions or one
InputError line, never another exception (hypothesis, bounded so that it stays fast)."""

from __future__ import annotations

import math

from hypothesis import given, settings, strategies as st

from hdcad.design_options import DesignOptions, parse_options
from hdcad.duty import Duty, parse_duty
from hdcad.errors import InputError

SCALARS = (st.none() | st.booleans() | st.integers(min_value=-10**400, max_value=10**400)
           | st.floats(allow_nan=True, allow_infinity=True) | st.text(max_size=20))
VALUES = st.recursive(SCALARS, lambda inner: st.lists(inner, max_size=4)
                      | st.dictionaries(st.text(max_size=12), inner, max_size=4), max_leaves=12)
NUMBER = st.integers(min_value=-10**30, max_value=10**30) | st.floats(allow_nan=True,
                                                                      allow_infinity=True)
SEGMENT = st.fixed_dictionaries({"phase": st.sampled_from(["start", "steady", "stop", "rest",
                                                          "x"]),
                                 "torque_Nm": NUMBER, "time_s": NUMBER, "speed_rpm": NUMBER})
DUTY = st.fixed_dictionaries(
    {"cycle": st.lists(SEGMENT, max_size=4), "max_output_speed_rpm": NUMBER,
     "max_input_speed_rpm": NUMBER, "required_life_h": NUMBER},
    optional={"shock": st.fixed_dictionaries({"torque_Nm": NUMBER, "time_s": NUMBER,
                                              "speed_rpm": NUMBER}), "lubrication": VALUES,
              "ambient_C": NUMBER, "extra": VALUES})


def _one_line_error_or(kind, parse, raw):
    try:
        result = parse(raw)
    except InputError as error:
        assert "\n" not in str(error) and len(str(error)) < 400
        return
    assert isinstance(result, kind)
    return result


@settings(max_examples=300, deadline=None)
@given(DUTY)
def test_duty_shaped_values(raw):
    duty = _one_line_error_or(Duty, parse_duty, raw)
    if duty is not None:  # what passes is finite and within the physical bounds
        for s in duty.cycle:
            assert math.isfinite(s.torque_Nm) and 0 < s.time_s <= 1e9 and s.speed_rpm <= 1e5


@settings(max_examples=200, deadline=None)
@given(VALUES)
def test_any_value_as_a_duty(raw):
    _one_line_error_or(Duty, parse_duty, raw)


@settings(max_examples=200, deadline=None)
@given(st.dictionaries(st.sampled_from(["motor_flange", "wall_mm", "material", "bolt_class",
                                        "friction_coefficient", "typo"]), VALUES, max_size=4))
def test_design_options(raw):
    _one_line_error_or(DesignOptions, parse_options, raw)
