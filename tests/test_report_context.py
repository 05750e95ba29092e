"""The sheet's design-options table says which values the design file set."""

from hdcad.design_options import DesignOptions, parse_options
from hdcad.report.context import option_rows


def test_a_value_the_user_set_is_marked_as_set_even_when_it_equals_the_default():
    options = parse_options({"motor_flange": "pa", "wall_mm": 8}).as_dict()
    rows = {r["key"]: r for r in option_rows(options)}
    assert rows["motor_flange"]["value"] == "PA" and not rows["motor_flange"]["default"]
    assert not rows["wall_mm"]["default"]  # 8 mm is also the default: the file set it
    assert rows["material"]["default"] and "given" not in rows


def test_an_unset_flange_says_how_it_is_chosen():
    rows = {r["key"]: r for r in option_rows(DesignOptions().as_dict())}
    assert rows["motor_flange"]["default"] and "first complete code" in rows["motor_flange"]["value"]
