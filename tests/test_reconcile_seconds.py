"""A second effect beside a loop, weighed again once the loop has its final form: one left
undecided between two (:func:`hdcad.reconcile.seconds.decided_after_refining`), and one
named that gives way to its rival (:func:`hdcad.reconcile.seconds.swapped_after_refining`),
and a loop named beside a play that the play in its final form leaves nothing to
(:func:`hdcad.reconcile.seconds.dropped_after_refining`); a play added beside a loop named
alone (:func:`hdcad.reconcile.seconds.added_after_refining`); and a play that friction
holds, named as a loop, given as the loop's other reading
(:func:`hdcad.reconcile.seconds.held_play_for_loop`).

Beside a Bouc–Wen loop a play and a housing spring can fit about equally (pairs within 5 %
in ΔBIC) when both patch what the loop's formula misses of the truth's loop; the second is
then left undecided. With the loop refined to the form that follows the data (a Preisach or
friction-element sum, drawn about the catalog curve), a play that is there still adds and a
spring that is not adds nothing. The cases come from suites H, M, G and I
(``truths/truth_h.py``, ``truth_m.py``, ``truth_g.py``, ``truth_i.py``, each written by a helper
from the contract only) and B (``truth_b.py``).
"""

from __future__ import annotations

import pytest
from truth_runs import bench, named_case

DECIDED = "named once the loop took its final form"


@pytest.mark.parametrize("suite, name, before", [
    # seed 11, 2 per cell: a Zener loop with an elastic-ramp Oldham play left 3.39σ with the
    # second undecided, a Davidenkov loop with an arctan take-up 1.82σ
    ("h", "h-torsion-pair-hysteresis-backlash-zener+ramp-001", 3.39),
    ("m", "m-torsion-pair-hysteresis+backlash-davidenkov+cauchy-000", 1.82),
])
def test_a_play_beside_a_loop_is_named_once_the_loop_has_its_final_form(suite, name, before):
    """Both of the pair are named, the note says why, and the fit is within 1.2σ of the
    true noise (the issue's bar; before: ``before`` σ)."""
    case = named_case(suite, name, 11)
    result = bench.reconcile_case(case)
    assert set(result["missing_effects"]) == {"hysteresis", "backlash"}
    assert any(DECIDED in note for note in result["notes"])
    assert not any("undecided" in r for r in result["equivalent_readings"])
    assert result["rmse_after"] <= 1.2 * case.noise_rms < before * case.noise_rms


def test_a_play_that_explains_less_than_the_noise_stays_undecided():
    """Suite B's Bouc–Wen n = 3 single (seed 11, 2 per cell): beside the loop in its final
    form a play passes the other gates for a second (ΔBIC 171) but explains 0.19 noise
    variances, under the noise variance any second try must explain; the second stays
    undecided and only the loop is named."""
    case = named_case("b", "b-torsion-single-hysteresis-boucwen3-001", 11)
    result = bench.reconcile_case(case)
    assert result["missing_effects"] == ["hysteresis"]
    assert not any(DECIDED in note for note in result["notes"])
    assert any(r.get("undecided") for r in result["equivalent_readings"])


SWAPPED = "backlash in place of housing_compliance"


@pytest.mark.parametrize("suite, seed, name, before", [
    # seed 7, 2 per cell: a Krasnosel'skii–Pokrovskii loop with an erf dead zone; the play,
    # taken up over a wide band, was read as a stiffening spring beside the Bouc–Wen loop
    ("g", 7, "g-torsion-pair-hysteresis-backlash-kp-erf-deadzone-triangular-001", 1.67),
    # seed 11, 2 per cell: a Mindlin–Deresiewicz loop with a play that back-driving friction
    # holds; a linear spring was named by its shape beside the loop
    ("i", 11, "i-torsion-pair-hysteresis-backlash-mindlin-deresiewicz-backdrive-held-play-001",
     1.98),
])
def test_a_spring_beside_a_loop_gives_way_to_the_play_once_the_loop_has_its_final_form(
        suite, seed, name, before):
    """The play is named in the spring's place, the note says why, no stiffening-spring
    reading is left, and the fit is within 1.2σ of the true noise (before: ``before`` σ).
    Over suites B–N at seeds 7 and 11 (2 per cell) the wrong swaps a play would make beside
    a loop gain ΔBIC −0.1 at most: below the margin of 10."""
    case = named_case(suite, name, seed)
    result = bench.reconcile_case(case)
    assert set(result["missing_effects"]) == {"hysteresis", "backlash"}
    assert any(note.startswith(SWAPPED) for note in result["notes"])
    assert not any(r.get("reading") == "progressive_spring"
                   for r in result["equivalent_readings"])
    assert result["rmse_after"] <= 1.2 * case.noise_rms < before * case.noise_rms


def test_a_loop_beside_a_held_play_is_dropped_once_the_play_has_its_final_form():
    """Suite I's play held by back-driving friction, alone (seed 11, 2 per cell): while
    effects are named the play crosses at zero torque and a loop is named beside it to take
    the held play's own loop; beside the play held and started freely the loop adds ΔBIC
    −6.1 and is dropped (true loops beside plays, seeds 7 and 11 at 2 per cell, add 155 or
    more). Only the play is named, with the fit at the noise."""
    case = named_case("i", "i-torsion-single-backlash-backdrive-held-play-001", 11)
    result = bench.reconcile_case(case)
    assert result["missing_effects"] == ["backlash"]
    assert any(note.startswith("hysteresis, named beside the play") for note in result["notes"])
    assert any("held by friction" in note for note in result["notes"])
    assert result["rmse_after"] <= 1.2 * case.noise_rms


def _held_play_readings(result: dict) -> list[dict]:
    return [r for r in result["equivalent_readings"] if r.get("reading") == "held_play"]


def test_a_play_held_by_friction_named_as_a_loop_is_given_as_its_other_reading():
    """Suite I's play that back-driving friction holds, alone (seed 13, 2 per cell): while
    effects are named a play crosses at zero torque, so the held play's own loop (b wide,
    2·T_h long) is named as hysteresis. The play in its final form (held, its start free)
    in the loop's place reads as well (ΔBIC +3.7, a tie): the report gives it as the other
    reading, with its lost motion and holding torque."""
    case = named_case("i", "i-torsion-single-backlash-backdrive-held-play-000", 13)
    result = bench.reconcile_case(case)
    assert result["missing_effects"] == ["hysteresis"]
    (other,) = _held_play_readings(result)
    assert other["alternative"] == ["backlash"] and "ΔBIC +3.7" in other["text"]
    assert result["rmse_after"] <= 1.2 * case.noise_rms


def test_a_loop_that_narrows_to_its_turning_points_gets_no_held_play_reading():
    """Suite I's Armstrong–Frederick loop (seed 13, 2 per cell): a play held by friction in
    its place fits worse by ΔBIC 30.5, beyond the margin of 10: no such reading."""
    case = named_case("i", "i-torsion-single-hysteresis-armstrong-frederick-001", 13)
    result = bench.reconcile_case(case)
    assert "hysteresis" in result["missing_effects"]
    assert not _held_play_readings(result)


def test_a_play_beside_a_loop_named_alone_is_added_once_the_loop_has_its_final_form():
    """Suite M's Hilbert loop with a lost motion (seed 13, 2 per cell): while effects were
    named, a spring beside the Bouc–Wen loop was read as the loop's own narrowing and the
    loop was named alone, at 1.75σ. Beside the loop in its final form the play adds ΔBIC
    470 and explains more than the noise variance, the spring nothing: the play is named
    and the fit is at the noise. Suites B–N at seeds 7 and 11 (2 per cell) did not change."""
    case = named_case("m", "m-torsion-pair-hysteresis+backlash-hilbert+lostmotion-001", 13)
    result = bench.reconcile_case(case)
    assert set(result["missing_effects"]) == {"hysteresis", "backlash"}
    assert any(note.startswith("backlash named once the loop took its final form: beside it")
               for note in result["notes"])
    assert result["rmse_after"] <= 1.2 * case.noise_rms < 1.75 * case.noise_rms
