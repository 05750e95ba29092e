"""Main (output) bearing of unit and gear-head types: moment, life, static safety.

References
----------
Seed 000 pp.030-034 and seed 002 lines 202-254 (formulas lost in 000):
- 030-1  Mmax = Frmax·(Lr + R) + Famax·La ≤ Mc
- 031-1/2  average loads (formula lost in both seeds; see ``average_load``)
- 031-3  Nav = Σ nᵢ·tᵢ / Σ tᵢ
- 031-4  Faav / (Frav + 2·(Frav·(Lr+R) + Faav·La)/dp) ≤ 1.5 → X = 1, Y = 0.45; else X = Y = 0.67
- 032-1  L10 = 10⁶/(60·Nav)·(C/(fw·Pc))^(10/3) (cross-roller; exponent 3 for 4-point contact)
- 032-2  Pc = X·(Frav + 2·(Frav·(Lr+R) + Faav·La)/dp) + Y·Faav
- 033-1  Loc = 10⁶/(60·n1)·(90/θ)·(C/(fw·Pc))^(10/3) for an oscillating output (n1
          oscillations per minute, θ = oscillating angle / 2 [deg]); at an oscillating angle
          of 5° or less fretting may occur: consult the maker (note under figure 033-1)
- 034-1/2  fs = Co/Po, Po = Frmax + 2·Mmax/dp + 0.44·Famax; fs ≥ 1.5 / 2 / 3 (table 034-3)
"""

from __future__ import annotations

from typing import Sequence

from ..duty import ExternalLoad, Segment
from .load_pattern import average_output_speed
from .record import CheckResult, Quantity, criterion, governed, not_evaluated
from .rules import label

FORMULA = ("Mmax = Frmax(Lr+R) + Famax·La ≤ Mc;  Pc = X(Frav + 2(Frav(Lr+R)+Faav·La)/dp) + "
           "Y·Faav;  L10 = 10⁶/(60·Nav)·(C/(fw·Pc))^(10/3);  fs = Co/Po ≥ fs,min")
SOURCE = "seed 000 pp.030-034; seed 002 (formulas 031-4, 032-1, 032-2, 034-2)"
ASSUMPTION_AVERAGE_LOAD = (
    "formula 031-1/031-2 (average loads) is lost in the seeds; the speed-time weighted "
    "p-power mean (p = 10/3 cross-roller, 3 four-point) consistent with 032-1 is used; with "
    "one external load for the whole cycle it equals that load")


FRETTING_ANGLE_DEG = 5.0  # oscillating angle at or below which fretting may occur (033-1)


def life_exponent(bearing_type: str) -> float:
    """10/3 for a cross-roller bearing, 3 for a four-point contact ball bearing (032-1)."""
    return 3.0 if bearing_type.startswith("four_point") else 10.0 / 3.0


def oscillating_life_hours(c_N: float, pc_N: float, fw: float, cycles_per_min: float,
                           angle_deg: float, exponent: float) -> float:
    """Loc [h] = 10⁶/(60·n1)·(90/θ)·(C/(fw·Pc))^p, θ = angle/2 [deg]; formula 033-1."""
    theta = angle_deg / 2.0
    return 1e6 / (60.0 * cycles_per_min) * (90.0 / theta) * (c_N / (fw * pc_N)) ** exponent


def max_moment(load: ExternalLoad, offset_R_m: float) -> float:
    """Mmax = Frmax·(Lr + R) + Famax·La [N·m]. Formula 030-1."""
    return load.radial_N * (load.Lr_m + offset_R_m) + load.axial_N * load.La_m


def average_load(loads_N: Sequence[float], cycle: Sequence[Segment], exponent: float) -> float:
    """Speed-time weighted p-power mean of per-segment loads [N] (see module note)."""
    weights = [abs(s.speed_rpm) * s.time_s for s in cycle]
    total = sum(weights)
    return (sum(w * abs(f) ** exponent for w, f in zip(weights, loads_N)) / total) ** (1 / exponent)


def radial_equivalent(fr_av: float, fa_av: float, load: ExternalLoad, offset_R_m: float,
                      dp_m: float) -> float:
    """Frav + 2·(Frav·(Lr+R) + Faav·La)/dp [N], the radial term of 031-4 and 032-2."""
    return fr_av + 2.0 * (fr_av * (load.Lr_m + offset_R_m) + fa_av * load.La_m) / dp_m


def load_factors(fr_av: float, fa_av: float, load: ExternalLoad, offset_R_m: float,
                 dp_m: float) -> tuple[float, float]:
    """(X, Y) from formula 031-4."""
    ratio = fa_av / radial_equivalent(fr_av, fa_av, load, offset_R_m, dp_m)
    return (1.0, 0.45) if ratio <= 1.5 else (0.67, 0.67)


def dynamic_equivalent_load(fr_av: float, fa_av: float, load: ExternalLoad, offset_R_m: float,
                            dp_m: float) -> float:
    """Pc [N], formula 032-2."""
    x, y = load_factors(fr_av, fa_av, load, offset_R_m, dp_m)
    return x * radial_equivalent(fr_av, fa_av, load, offset_R_m, dp_m) + y * fa_av


def bearing_life_hours(c_N: float, pc_N: float, fw: float, nav_rpm: float,
                       exponent: float) -> float:
    """L10 [h] = 10⁶/(60·Nav)·(C/(fw·Pc))^p, formula 032-1."""
    return 1e6 / (60.0 * nav_rpm) * (c_N / (fw * pc_N)) ** exponent


def static_equivalent_load(load: ExternalLoad, m_max_Nm: float, dp_m: float) -> float:
    """Po = Frmax + 2·Mmax/dp + 0.44·Famax [N], formula 034-2."""
    return load.radial_N + 2.0 * m_max_Nm / dp_m + 0.44 * load.axial_N


def required_static_safety(fw: float) -> float:
    """fs,min from table 034-3, chosen by the duty's load factor fw (table 032-3)."""
    return 2.0 if fw > 1.5 else 1.5


def main_bearing(cycle: Sequence[Segment], load: ExternalLoad | None, bearing: dict | None,
                 required_life_h: float, missing_reason: str = "",
                 oscillation=None, static_safety_min: float | None = None) -> CheckResult:
    """Full main-bearing procedure: moment, life (rotating 032-1 or oscillating 033-1) and
    static safety; the row shows the governing criterion, all three are in the details.

    ``oscillation``: an object with ``angle_deg`` (full oscillating angle) and
    ``cycles_per_min`` when the output oscillates instead of turning."""
    title = "Main bearing (moment, life, static safety)"
    if load is None:
        return not_evaluated("main_bearing", title, "bearing", FORMULA,
                             "external_load (radial_N, axial_N, Lr_m, La_m, fw) in the duty")
    if bearing is None:
        return not_evaluated("main_bearing", title, "bearing", FORMULA, missing_reason or
                             "main-bearing data dp, R, C, Co, Mc missing from the catalog "
                             "(supply them in an overlay table main_bearing)")
    dp, offset = bearing["dp_m"], bearing["R_m"]
    exponent = life_exponent(bearing.get("bearing_type") or "cross_roller")
    m_max = max_moment(load, offset)
    fr_av = average_load([load.radial_N] * len(cycle), cycle, exponent)
    fa_av = average_load([load.axial_N] * len(cycle), cycle, exponent)
    nav = average_output_speed(cycle)
    x, y = load_factors(fr_av, fa_av, load, offset, dp)
    pc = dynamic_equivalent_load(fr_av, fa_av, load, offset, dp)
    if pc <= 0:
        life = float("inf")
    elif oscillation is not None:
        life = oscillating_life_hours(bearing["C_N"], pc, load.fw, oscillation.cycles_per_min,
                                      oscillation.angle_deg, exponent)
    else:
        life = bearing_life_hours(bearing["C_N"], pc, load.fw, nav, exponent)
    po = static_equivalent_load(load, m_max, dp)
    fs = bearing["Co_N"] / po if po > 0 else float("inf")
    fs_min = static_safety_min or required_static_safety(load.fw)
    fs_rule = (label("static_safety_min", fs_min) if static_safety_min else
               "fs,min from the duty's fw (fw > 1.5 → 2, else 1.5): table 034-3 lists "
               "operating conditions, not fw; " + label("static_safety_min", "None"))
    life_rule = ("Loc, formula 033-1 (oscillating)" if oscillation is not None
                 else "L10, formula 032-1")
    criteria = {"life": criterion(life, required_life_h, "h", ">=", life_rule),
                "moment": criterion(m_max, bearing["Mc_Nm"], "N·m", "<=",
                                    "Mmax ≤ Mc, formula 030-1"),
                "static_safety": criterion(fs, fs_min, "", ">=",
                                           f"fs = Co/Po ≥ fs,min, formulas 034-1/2; {fs_rule}")}
    inputs = {"Frmax": Quantity(load.radial_N, "N"), "Famax": Quantity(load.axial_N, "N"),
              "Lr": Quantity(load.Lr_m, "m"), "La": Quantity(load.La_m, "m"),
              "fw": Quantity(load.fw, ""), "dp": Quantity(dp, "m", bearing.get("source", "")),
              "R": Quantity(offset, "m"), "C": Quantity(bearing["C_N"], "N"),
              "Co": Quantity(bearing["Co_N"], "N"), "Mc": Quantity(bearing["Mc_Nm"], "N·m"),
              "Nav": Quantity(nav, "r/min")}
    notes = [f"Mmax {m_max:.1f} N·m vs Mc {bearing['Mc_Nm']:g} N·m; fs {fs:.2f} vs "
             f"{fs_min:g}"]
    if oscillation is not None:
        inputs["n1"] = Quantity(oscillation.cycles_per_min, "cpm")
        inputs["oscillating angle"] = Quantity(oscillation.angle_deg, "deg")
        if oscillation.angle_deg <= FRETTING_ANGLE_DEG:
            notes.append(f"oscillating angle {oscillation.angle_deg:g}° ≤ "
                         f"{FRETTING_ANGLE_DEG:g}°: an oil film hardly forms and fretting may "
                         "occur; consult Harmonic Drive (seed 000 p.033)")
    details = {"Mmax_Nm": m_max, "Mc_Nm": bearing["Mc_Nm"], "Frav_N": fr_av, "Faav_N": fa_av,
               "X": x, "Y": y, "Pc_N": pc, "L10_h": life, "Po_N": po, "fs": fs,
               "fs_min": fs_min, "assumption": ASSUMPTION_AVERAGE_LOAD}
    return governed("main_bearing", title, "bearing", FORMULA, inputs, criteria, "life",
                    f"{SOURCE}; bearing data {bearing.get('source', '')}", "; ".join(notes),
                    details)
