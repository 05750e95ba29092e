"""`review_assembly`: what the probes of the review assembly measured, read as a design
review's verdict (no interference, every bearing ring stopped on both sides, every lip seal on
a journal of its own diameter over its width, every screw engaged and not bottoming, the oil
cavity closed at every section probed).

The numbers come from hdcad.geometry.review (solids and sections); this module only judges.
"""

from __future__ import annotations

from .lubrication import Criterion
from .record import FAIL, PASS, CheckResult, Quantity, not_evaluated

TITLE = "Review assembly (parts with bearings, seals, screws, gear outline)"
FORMULA = "failed probes = 0"
SOURCE = "hdcad review assembly: OCCT solids and axial sections (HOUSING_RULES §1-§4)"
COVERED_MIN = 0.999   # a seal counts as on its journal when 99.9 % of its width is


def review_check(result: dict | None, missing: str = "") -> CheckResult:
    if result is None:
        return not_evaluated("review_assembly", TITLE, "geometry", FORMULA, missing,
                             source=SOURCE)
    criteria = [_interference(result), _bearings(result), _seals(result), _screws(result),
                _oil(result)]
    failed = [c for c in criteria if c.status == FAIL]
    inputs = {"bodies": Quantity(result["bodies"], ""),
              "bearings": Quantity(len(result["bearings"]), ""),
              "seals": Quantity(len(result["seals"]), ""),
              "screws": Quantity(len(result["screws"]), ""),
              "sections probed": Quantity(len(result["oil_escapes"]), "")}
    return CheckResult("review_assembly", TITLE, "geometry", FORMULA, inputs,
                       float(len(failed)), 0.0, "", "<=", FAIL if failed else PASS, SOURCE,
                       "; ".join(c.text for c in criteria), None,
                       {"criteria": [c.__dict__ for c in criteria], "probes": result})


def _interference(r: dict) -> Criterion:
    pairs = r["interferences"]
    if pairs:
        worst = max(pairs, key=lambda p: p["volume_mm3"])
        return Criterion("interference", FAIL, f"{len(pairs)} overlapping pair(s), worst "
                         f"{worst['a']} ∩ {worst['b']} = {worst['volume_mm3']:.2f} mm³")
    return Criterion("interference", PASS, f"no overlap among {r['bodies']} bodies")


def _bearings(r: dict) -> Criterion:
    loose = [f"{b['bearing']} {face}" for b in r["bearings"] for face in
             ("inner_low", "inner_high", "outer_low", "outer_high") if not b[face]]
    if loose:
        return Criterion("bearing location", FAIL, "nothing stops " + ", ".join(loose[:4]))
    return Criterion("bearing location", PASS, f"{len(r['bearings'])} bearing(s): both rings "
                     "stopped on both faces (shoulder, ring, collar or the neighbour bearing)")


def _seals(r: dict) -> Criterion:
    short = [s for s in r["seals"] if s["covered"] < COVERED_MIN]
    if short:
        return Criterion("seal journals", FAIL, "; ".join(
            f"{s['seal']} runs on a journal over {100 * s['covered']:.0f} % of its width"
            for s in short))
    return Criterion("seal journals", PASS, f"{len(r['seals'])} lip seal(s) on journals of "
                     "their own diameter over their full width")


def _screws(r: dict) -> Criterion:
    bad = [s for s in r["screws"] if s["engaged"] < s["engaged_min"] - 1e-6
           or s["engaged"] > s["thread_depth"] + 1e-6]
    if bad:
        s = bad[0]
        return Criterion("screw engagement", FAIL, f"{len(bad)} screw(s) engage "
                         f"{s['engaged']:.1f} mm (need {s['engaged_min']:g}…"
                         f"{s['thread_depth']:g})")
    if not r["screws"]:
        return Criterion("screw engagement", PASS, "no screws in the review assembly")
    least = min(s["engaged"] for s in r["screws"])
    return Criterion("screw engagement", PASS, f"{len(r['screws'])} screws engage ≥ "
                     f"{least:.1f} mm and stop short of the thread end")


def _oil(r: dict) -> Criterion:
    if not r["oil_escapes"]:
        return Criterion("oil tightness", PASS, "no oil in these parts")
    open_at = [a for a, escaped in r["oil_escapes"].items() if escaped]
    if open_at:
        return Criterion("oil tightness", FAIL, "oil reaches the outside in the section(s) at "
                         + ", ".join(f"{a}°" for a in open_at))
    return Criterion("oil tightness", PASS, "the oil cavity is closed by seals, O-rings and "
                     f"plugs in every section probed ({', '.join(r['oil_escapes'])}°)")
