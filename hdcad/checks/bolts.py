"""Bolt circles: hole placement, head room, thread engagement and friction torque capacity.

One record per bolt circle (``n`` socket head cap screws ISO 4762 on a circle of diameter D).
Sub-criteria, all listed in ``details['criteria']`` with their numbers:

* ``edge_inner`` / ``edge_outer`` – every hole lies inside the flange annulus with an edge
  distance (hole centre to edge) e ≥ 1.2·d_h, the minimum edge distance e2 of
  EN 1993-1-8:2005 Table 3.3, used here as a design rule for machined flanges
  (``edge_factor``). d_h is the ISO 273 medium clearance hole for ``hole_kind='clearance'``
  and the thread major diameter d for ``hole_kind='tapped'`` (the cut thread reaches d).
* ``head_room`` – neighbouring heads must not overlap: chord c = D·sin(π/n) ≥ dk
  (ISO 4762 dk max, plain head). Skipped for n = 1.
* ``engagement`` – available engagement (tapped depth) m ≥ k_m·d with k_m = 1.0 (steel),
  1.25 (cast iron), 2.0 (aluminium alloy): common machine-design minimum engagement lengths
  for property class 8.8 (design defaults, not values printed in a standard; VDI 2230
  Part 1:2015 §5.5.5 gives the exact calculation m_eff ≥ m_eff,min, not done here). Raise
  them for 10.9 / 12.9 screws in soft materials (``min_engagement``). Not evaluated when no
  tapped depth is given (the screw engages a part this record does not describe).
* ``assembly_stress`` – only when a tightening torque M_A is given: the preload it
  produces must not exceed F_M,zul (90 % of the ISO 898-1 proof stress, below).
* ``torque_capacity`` – friction torque of the bolt circle T_cap ≥ S·T (value and limit of
  the record).

Preload and torques (VDI 2230 Part 1:2015)::

    F_M,zul = ν·Rp0.2,min·As / √(1 + 3·[3/2·(d2/d0)·(P/(π·d2) + 1.155·µG)]²)   (R7, ν = 0.9,
              d0 = (d2 + d3)/2, A0 = As)
    M_A     = F_M·(0.16·P + 0.58·d2·µG + µK·D_Km/2)                           (R13)
    F_M     = M_A / (0.16·P + 0.58·d2·µG + µK·D_Km/2)      (M_A given)
    D_Km    = (dw + d_h,medium)/2   (head bearing face ISO 4762 dw min, hole ISO 273 medium)
    T_cap   = n·(F_M/αA)·µT·D/2     (slip of the joint faces: clamp load times interface
                                     friction at the bolt-circle radius)

With no M_A given, M_A is the torque that gives F_M,zul (90 % utilisation) and F_M = F_M,zul.
µG = µK = 0.12 (VDI 2230 friction class B, lightly oiled black-oxide or phosphated screws) are
defaults. αA (tightening factor, default 1 = nominal preload) and embedding losses are not
deducted unless given: the safety factor S must cover them (VDI 2230 gives αA ≈ 1.4-1.6 for
torque-wrench tightening).

References
----------
VDI 2230 Part 1:2015, Systematic calculation of highly stressed bolted joints (R7, R13;
clamp load for slip resistance).
ISO 261 / ISO 724 (threads), ISO 898-1:2013 (As, Rp0.2), ISO 4762:2004 (dk, dw),
ISO 273:1979 (clearance holes): catalog tables, see ``catalog/SOURCES.checks_standards.yaml``.
EN 1993-1-8:2005 Table 3.3 (minimum edge distance 1.2·d0).
Seed 000 p.024 design guideline 3: bolt the flexspline to the output with adequate
tightening torque.
"""

from __future__ import annotations

import math

from .record import FAIL, NOT_EVALUATED, CheckResult, Quantity, criterion, governed, \
    not_evaluated

FAMILY = "geometry"
ID = "bolt_pattern"
THREAD_TABLE = "iso_metric_thread_iso261_iso724"
HEAD_TABLE = "socket_head_iso4762"
HOLE_TABLE = "clearance_hole_iso273"
CLASS_TABLE = "bolt_property_iso898-1"
FORMULA = "T_cap = n·F_M·µT·D/2 ≥ S·T,  F_M = M_A / (0.16·P + 0.58·d2·µG + µK·D_Km/2)"
SOURCE = ("VDI 2230 Part 1:2015 (R7, R13); ISO 261/724, ISO 898-1:2013, ISO 4762:2004, "
          "ISO 273:1979; EN 1993-1-8:2005 Table 3.3")

MU_THREAD = 0.12          # µG, VDI 2230 friction class B
MU_HEAD = 0.12            # µK
UTILISATION = 0.9         # ν: 90 % of Rp0.2,min at assembly
EDGE_FACTOR = 1.2         # e ≥ 1.2·d_h, EN 1993-1-8 Table 3.3
MIN_ENGAGEMENT = {"steel": 1.0, "cast_iron": 1.25, "aluminium": 2.0}  # × d, for 8.8
HOLE_KINDS = ("clearance", "tapped")


def permissible_preload_N(As_mm2: float, d2_mm: float, d3_mm: float, pitch_mm: float,
                          Rp02_MPa: float, mu_thread: float = MU_THREAD,
                          utilisation: float = UTILISATION) -> float:
    """Assembly preload F_M,zul [N] at ν·Rp0.2 equivalent stress (VDI 2230 R7, A0 = As)."""
    d0 = (d2_mm + d3_mm) / 2.0
    bracket = 1.5 * (d2_mm / d0) * (pitch_mm / (math.pi * d2_mm) + 1.155 * mu_thread)
    return utilisation * Rp02_MPa * As_mm2 / math.sqrt(1.0 + 3.0 * bracket ** 2)


def torque_factor_mm(pitch_mm: float, d2_mm: float, D_Km_mm: float,
                     mu_thread: float = MU_THREAD, mu_head: float = MU_HEAD) -> float:
    """K = 0.16·P + 0.58·d2·µG + µK·D_Km/2 [mm], so that M_A [N·mm] = F_M [N]·K."""
    return 0.16 * pitch_mm + 0.58 * d2_mm * mu_thread + mu_head * D_Km_mm / 2.0


def preload_from_torque_N(M_A_Nm: float, pitch_mm: float, d2_mm: float, D_Km_mm: float,
                          mu_thread: float = MU_THREAD, mu_head: float = MU_HEAD) -> float:
    """F_M [N] = M_A / (0.16·P + 0.58·d2·µG + µK·D_Km/2), M_A in N·m (VDI 2230 R13)."""
    return M_A_Nm * 1000.0 / torque_factor_mm(pitch_mm, d2_mm, D_Km_mm, mu_thread, mu_head)


def friction_torque_Nm(count: int, preload_N: float, mu_joint: float,
                       circle_diameter_mm: float) -> float:
    """T_cap [N·m] = n·F·µT·D/2: torque the clamped faces carry before slipping."""
    return count * preload_N * mu_joint * circle_diameter_mm / 2.0 / 1000.0


def _class_row(catalog, bolt_class: str, d: float) -> dict | None:
    for row in catalog.rows(CLASS_TABLE, kind=str(bolt_class)):
        if row["d_over_mm"] < d <= row["d_upto_mm"]:
            return row
    return None


def bolt_pattern(name: str, circle_diameter_mm: float, count: int, thread: str, hole_kind: str,
                 annulus_inner_mm: float | None, annulus_outer_mm: float | None,
                 engagement_mm: float | None, bolt_class: str, friction: float,
                 torque_to_carry_Nm: float, safety_factor: float,
                 tightening: float | None = None, *, tapped_material: str = "steel",
                 catalog=None, mu_thread: float = MU_THREAD, mu_head: float = MU_HEAD,
                 edge_factor: float = EDGE_FACTOR, min_engagement: dict | None = None,
                 tightening_factor: float = 1.0, outline_square_mm: float | None = None,
                 start_angle_deg: float = 0.0) -> CheckResult:
    """Check one bolt circle of ISO 4762 socket head cap screws.

    Parameters
    ----------
    name : bolt-circle name (title and details)
    circle_diameter_mm : bolt-circle diameter D [mm]
    count : number of screws n
    thread : ISO metric coarse thread, e.g. "M6"
    hole_kind : "clearance" (ISO 273 medium holes in this annulus) or "tapped"
    annulus_inner_mm, annulus_outer_mm : diameters of the material ring holding the holes
        [mm]; None = that edge is not checked
    engagement_mm : usable thread engagement (tapped depth) m [mm]; None = not evaluated
    bolt_class : ISO 898-1 property class "8.8", "10.9" or "12.9"
    friction : friction coefficient of the clamped joint faces µT [-]
    torque_to_carry_Nm : torque T the joint must transmit by friction [N·m]
    safety_factor : S on T [-]
    tightening : tightening torque M_A [N·m]; None = torque for 90 % of Rp0.2
    tapped_material : "steel", "cast_iron" or "aluminium" (material of the tapped part)
    catalog : Catalog with the standard tables; default the shipped catalog
    mu_thread, mu_head : µG, µK [-]
    edge_factor : minimum edge distance / hole diameter [-]
    min_engagement : {material: minimum engagement / d}
    tightening_factor : αA ≥ 1; the capacity uses F_M/αA
    outline_square_mm : side of a square outline centred on the bolt circle [mm] (instead
        of ``annulus_outer_mm``): the outer edge distance is measured to the square's sides
    start_angle_deg : angle of the first hole from +X [deg] (others evenly spaced), for the
        square outline

    Returns
    -------
    CheckResult whose value, limit, unit and sense are those of the governing criterion:
    the failing one, or with all passing the one with the smallest margin (named in
    ``details['governing']``; all criteria in ``details['criteria']``).
    """
    if hole_kind not in HOLE_KINDS:
        raise ValueError(f"hole_kind must be one of {', '.join(HOLE_KINDS)} (got {hole_kind!r})")
    ratios = dict(MIN_ENGAGEMENT if min_engagement is None else min_engagement)
    if tapped_material not in ratios:
        raise ValueError(f"tapped_material must be one of {', '.join(ratios)} "
                         f"(got {tapped_material!r})")
    if catalog is None:
        from ..catalog import load_catalog
        catalog = load_catalog()
    title = f"Bolt circle {name}"
    D, n = float(circle_diameter_mm), int(count)
    required = float(torque_to_carry_Nm) * float(safety_factor)
    inputs = {"bolt circle": Quantity(name, ""), "D": Quantity(D, "mm"), "n": Quantity(n, ""),
              "thread": Quantity(thread, ""), "property class": Quantity(bolt_class, ""),
              "µT": Quantity(friction, ""), "T": Quantity(torque_to_carry_Nm, "N·m"),
              "S": Quantity(safety_factor, "")}
    details: dict = {"name": name, "thread": thread, "count": n, "hole_kind": hole_kind,
                     "circle_diameter_mm": D}

    looked_up = {}
    for table, label, match in ((THREAD_TABLE, "thread", {"thread": thread}),
                                (HEAD_TABLE, "ISO 4762 head", {"thread": thread}),
                                (HOLE_TABLE, "ISO 273 clearance hole", {"thread": thread})):
        row = catalog.find(table, **match)
        if row is None:
            return not_evaluated(ID, title, FAMILY, FORMULA,
                                 f"{label} {thread} missing from table {table}", inputs,
                                 unit="N·m", source=SOURCE, details=details)
        looked_up[table] = row
    th, head, hole = looked_up[THREAD_TABLE], looked_up[HEAD_TABLE], looked_up[HOLE_TABLE]
    d, P, d2, d3, As = (float(th[c]) for c in ("d_mm", "pitch_mm", "d2_mm", "d3_mm", "As_mm2"))
    prop = _class_row(catalog, bolt_class, d)
    if prop is None:
        return not_evaluated(ID, title, FAMILY, FORMULA,
                             f"property class {bolt_class} for {thread} missing from table "
                             f"{CLASS_TABLE}", inputs, unit="N·m", source=SOURCE,
                             details=details)
    dk, dw, d_medium = float(head["dk_mm"]), float(head["dw_mm"]), float(hole["medium_mm"])
    d_hole = d_medium if hole_kind == "clearance" else d
    criteria: dict[str, dict] = {}

    # -- holes inside the annulus ---------------------------------------------------------
    e_min = edge_factor * d_hole
    edge_rule = (f"hole centre to edge ≥ {edge_factor:g}·d_h = {e_min:.2f} mm, d_h = "
                 f"{d_hole:g} mm ({'ISO 273 medium' if hole_kind == 'clearance' else 'thread d'}"
                 "; EN 1993-1-8 Table 3.3 e2)")
    outer = (square_edge_distance_mm(D, n, float(outline_square_mm), start_angle_deg)
             if outline_square_mm else None if annulus_outer_mm is None
             else (float(annulus_outer_mm) - D) / 2.0)
    for label, distance in (("edge_inner", None if annulus_inner_mm is None
                             else (D - float(annulus_inner_mm)) / 2.0),
                            ("edge_outer", outer)):
        if distance is None:
            criteria[label] = criterion(None, e_min, "mm", ">=", edge_rule + "; annulus "
                                         "diameter not given", NOT_EVALUATED)
        else:
            criteria[label] = criterion(distance, e_min, "mm", ">=", edge_rule)

    # -- head room between neighbours ----------------------------------------------------
    if n >= 2:
        chord = D * math.sin(math.pi / n)
        criteria["head_room"] = criterion(chord, dk, "mm", ">=",
                                           f"chord D·sin(π/n) ≥ dk = {dk:g} mm (ISO 4762 "
                                           "dk max, plain head)")
    # -- thread engagement ------------------------------------------------------------------
    k_m = ratios[tapped_material]
    m_min = k_m * d
    eng_rule = f"m ≥ {k_m:g}·d = {m_min:g} mm in {tapped_material} (design default)"
    if engagement_mm is None:
        criteria["engagement"] = criterion(None, m_min, "mm", ">=",
                                            eng_rule + "; no tapped depth given",
                                            NOT_EVALUATED)
    else:
        criteria["engagement"] = criterion(float(engagement_mm), m_min, "mm", ">=", eng_rule)

    # -- preload (VDI 2230) -------------------------------------------------------------------
    Rp02 = float(prop["Rp02_MPa"])
    D_Km = (dw + d_medium) / 2.0
    F_zul = permissible_preload_N(As, d2, d3, P, Rp02, mu_thread)
    K = torque_factor_mm(P, d2, D_Km, mu_thread, mu_head)
    if tightening is None:
        M_A = F_zul * K / 1000.0
        F_M = F_zul
        torque_rule = (f"M_A for {UTILISATION:.0%} of Rp0.2 = {Rp02:g} MPa (ISO 898-1), "
                       "VDI 2230 R7/R13")
    else:
        M_A = float(tightening)
        F_M = preload_from_torque_N(M_A, P, d2, D_Km, mu_thread, mu_head)
        torque_rule = "M_A given"
        criteria["assembly_stress"] = criterion(
            F_M, F_zul, "N", "<=", f"F_M ≤ F_M,zul ({UTILISATION:.0%} of Rp0.2 = {Rp02:g} MPa, "
                                   "VDI 2230 R7)")
    F_cap = F_M / float(tightening_factor)
    capacity = friction_torque_Nm(n, F_cap, float(friction), D)
    criteria["torque_capacity"] = criterion(capacity, required, "N·m", ">=",
                                             "T_cap = n·(F_M/αA)·µT·D/2 ≥ S·T")
    details.update({
        "hole_diameter_mm": d_hole, "clearance_hole_medium_mm": d_medium,
        "dk_mm": dk, "dw_mm": dw, "pitch_mm": P, "d2_mm": d2, "d3_mm": d3, "As_mm2": As,
        "Rp02_MPa": Rp02, "mu_G": mu_thread, "mu_K": mu_head, "mu_T": float(friction),
        "D_Km_mm": D_Km, "torque_factor_mm": K, "F_Mzul_N": F_zul, "M_A_Nm": M_A,
        "M_A_rule": torque_rule, "F_M_N": F_M, "alpha_A": float(tightening_factor),
        "T_cap_Nm": capacity, "T_required_Nm": required, "tapped_material": tapped_material,
    })
    inputs.update({"M_A": Quantity(M_A, "N·m", torque_rule), "F_M": Quantity(F_M, "N"),
                   "µG = µK": Quantity(f"{mu_thread:g} / {mu_head:g}", "")})

    failed = [k for k, c in criteria.items() if c["status"] == FAIL]
    skipped = [k for k, c in criteria.items() if c["status"] == NOT_EVALUATED]
    notes = [f"{n} × {thread} {bolt_class} on φ{D:g}, M_A = {M_A:.3g} N·m ({torque_rule}), "
             f"F_M = {F_M / 1000:.3g} kN"]
    if failed:
        notes.append("fails: " + ", ".join(
            f"{k} ({_fmt(criteria[k]['value'])} vs {_fmt(criteria[k]['limit'])} "
            f"{criteria[k]['unit']})" for k in failed))
    if skipped:
        notes.append("not evaluated: " + ", ".join(
            f"{k} ({criteria[k]['rule'].split('; ')[-1]})" for k in skipped))
    if tightening_factor == 1.0:
        notes.append("nominal preload: tightening scatter αA and embedding are left to the "
                     "safety factor")
    return governed(ID, title, FAMILY, FORMULA, inputs, criteria, "torque_capacity", SOURCE,
                    "; ".join(notes), details)


def square_edge_distance_mm(circle_diameter_mm: float, count: int, side_mm: float,
                            start_angle_deg: float = 0.0) -> float:
    """Smallest distance [mm] from a hole centre to the sides of a centred square outline."""
    r, half = circle_diameter_mm / 2.0, side_mm / 2.0
    angles = (math.radians(start_angle_deg) + 2 * math.pi * i / count for i in range(count))
    return min(half - max(abs(r * math.cos(a)), abs(r * math.sin(a))) for a in angles)


def _fmt(x) -> str:
    return "—" if x is None else f"{x:.3g}"
