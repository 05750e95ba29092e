"""The duty parser: valid files load, bad values give one line naming the field, exit 2."""

import copy
import math

import pytest
import yaml
from hypothesis import HealthCheck, given, settings, strategies as st

from hdcad.cli import main
from hdcad.duty import parse_duty
from hdcad.errors import InputError
from conftest import duty_dict

GOOD = duty_dict()


def test_example_duty_parses():
    duty = parse_duty(copy.deepcopy(GOOD))
    assert len(duty.cycle) == 4 and duty.shock.count == 1000 and duty.required_life_h == 7000


def _with(path, value):
    raw = copy.deepcopy(GOOD)
    node = raw
    for key in path[:-1]:
        node = node[key]
    if value is _DELETE:
        del node[path[-1]]
    else:
        node[path[-1]] = value
    return raw


_DELETE = object()
BAD = [
    (("cycle", 0, "time_s"), -0.3, "cycle[0].time_s"),
    (("cycle", 0, "time_s"), 0, "cycle[0].time_s"),
    (("cycle", 1, "torque_Nm"), float("nan"), "cycle[1].torque_Nm"),
    (("cycle", 1, "speed_rpm"), float("inf"), "cycle[1].speed_rpm"),
    (("cycle", 2, "phase"), "braking", "cycle[2].phase"),
    (("cycle", 3, "speed_rpm"), 5, "cycle[3].speed_rpm"),
    (("cycle", 1, "speed_rpm"), 20, "cycle[1].speed_rpm"),
    (("cycle",), [], "cycle"),
    (("cycle",), [{"phase": "rest", "torque_Nm": 0, "time_s": 1, "speed_rpm": 0}], "cycle"),
    (("shock", "speed_rpm"), 15, "shock.speed_rpm"),
    (("shock", "count"), -1, "shock.count"),
    (("shock", "count"), 2.5, "shock.count"),
    (("max_input_speed_rpm",), "fast", "max_input_speed_rpm"),
    (("required_life_h",), _DELETE, "required_life_h"),
    (("lubrication",), "water", "lubrication"),
    (("grease",), "butter", "grease"),
    (("ambient_C",), 500, "ambient_C"),
    (("load_inertia_kgm2",), 0, "load_inertia_kgm2"),
    (("external_load",), {"radial_N": 1, "axial_N": 1, "Lr_m": 0.1, "La_m": 0.1, "fw": 9},
     "external_load.fw"),
    (("typo_key",), 1, "typo_key"),
]


@pytest.mark.parametrize("path, value, field", BAD, ids=[b[2] for b in BAD])
def test_bad_values_name_the_field(path, value, field):
    with pytest.raises(InputError) as info:
        parse_duty(_with(path, value))
    assert str(info.value).startswith(field + ":"), str(info.value)
    assert "\n" not in str(info.value)


def _run(tmp_path, raw, capsys):
    path = tmp_path / "duty.yaml"
    path.write_text(raw if isinstance(raw, str) else yaml.safe_dump(raw), encoding="utf-8")
    code = main(["check", "CSF-45-120-GH", "--duty", str(path)])
    return code, capsys.readouterr()


@pytest.mark.parametrize("path, value, field", BAD, ids=[b[2] for b in BAD])
def test_command_line_exit_2_one_line(tmp_path, capsys, path, value, field):
    code, out = _run(tmp_path, _with(path, value), capsys)
    assert code == 2
    assert out.err.count("\n") == 1 and field in out.err and "Traceback" not in out.err
    assert out.out == ""


NUMERIC_FIELDS = [("cycle", i, k) for i in range(4) for k in ("torque_Nm", "time_s", "speed_rpm")] \
    + [("shock", k) for k in ("torque_Nm", "time_s", "speed_rpm", "count")] \
    + [("max_output_speed_rpm",), ("max_input_speed_rpm",), ("required_life_h",),
       ("ambient_C",), ("load_inertia_kgm2",)]
JUNK = st.one_of(st.text(max_size=5), st.lists(st.integers(), max_size=2), st.none(),
                 st.booleans(), st.just(float("nan")), st.just(float("-inf")),
                 st.floats(max_value=-1e-9, allow_nan=False), st.dictionaries(st.text(max_size=2),
                                                                              st.integers(),
                                                                              max_size=1))


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(field=st.sampled_from(NUMERIC_FIELDS), junk=JUNK)
def test_property_bad_values_always_exit_2(tmp_path, capsys, field, junk):
    if junk is None and field[0] in ("ambient_C", "load_inertia_kgm2", "shock"):
        junk = "none"  # None means 'not given' for optional fields; use a string instead
    if field[-1] == "torque_Nm" and isinstance(junk, float) and math.isfinite(junk):
        junk = "x"  # a negative torque is a valid (reversing) load
    if field == ("ambient_C",) and isinstance(junk, float) and math.isfinite(junk):
        junk = junk - 1000.0  # sub-zero ambients are valid; push below the -60 °C bound
    code, out = _run(tmp_path, _with(field, junk), capsys)
    assert code == 2, (field, junk, out)
    assert out.err.startswith("hdcad: error: ") and out.err.count("\n") == 1
    assert "Traceback" not in out.err


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(text=st.text(max_size=60))
def test_property_arbitrary_text_never_tracebacks(tmp_path, capsys, text):
    code, out = _run(tmp_path, text, capsys)
    assert code in (0, 1, 2)
    assert "Traceback" not in out.err
    if code == 2:
        assert out.err.count("\n") == 1
