"""Input shaft bore of the wave generator: hub bore, direct plug mounting and parallel key.

The requested input shaft diameter d is checked against the wave-generator hub bores
(standard H7 bore, pilot bore, maximum bore; table 027-1). Above the maximum hub bore the
seed allows the Oldham coupling to be dropped and the plug mounted directly on the input
shaft, up to the plug bore φV' (table 027-2); above that the bore is not allowed. The
parallel key for the bore is taken from JIS B 1301 and checked for shear and side pressure.

Rules and interpretations
-------------------------
* Hub (027-1): pilot bore ≤ d ≤ maximum bore. The standard bore may be changed up to the
  maximum (seed lines 2679-2682); a bore cannot be smaller than the pilot bore it is
  machined from. Sizes 8 and 11 print "—" for pilot and maximum: only the standard bore.
* Plug (027-2): the seed says the φV' values "include the keyway depth etc." (line 2690).
  Read literally, the bore *with* its hub keyway must stay inside φV', so the allowed bore is
  φV' − t2 (t2 = hub keyway depth of the JIS key for d). ``plug_limit_includes_keyway=False``
  selects the looser reading d ≤ φV'.
* Key: JIS B 1301 parallel key selected by shaft diameter (shaft_min < d ≤ shaft_max). With
  T the input torque and l the effective (bearing) key length [mm] (l = L − b for a
  round-ended key)::

      τ = 2·T / (d·b·l)            key shear in the plane between shaft and hub
      p = 2·T / (d·(h − t1)·l)     side pressure on the hub side of the key

  The tangential force is taken at the shaft surface, F = 2T/d; the hub-side bearing height
  h − t1 is smaller than the shaft-side height t1 for every JIS B 1301 key, so it governs
  (R. L. Mott, *Machine Elements in Mechanical Design*, 4th ed., §11-4, with the bearing
  height of the hub side instead of h/2; DIN 6892 method C uses the same force and heights).
* Default key length l = 1.5·d (a common upper bound for parallel keys: longer keys do not
  carry load uniformly because of shaft torsion). With the plug mounted directly, the
  default is min(1.5·d, minimum plug thickness): the plug thickness of 027-2 is read as the
  axial width of the plug, which bounds the key's bearing length.
* Allowables (design defaults, not standard values; both are parameters and are printed in
  the note): Mott §11-4 design stresses τa = 0.5·Re/N and pa = Re/N with N = 2 and
  Re = 345 MPa (yield point of normalized S45C, JIS G 4051 reference values), i.e.
  τa = 86.25 MPa, pa = 172.5 MPa. pa applies to the weakest of key, shaft and hub: lower it
  for cast-iron or aluminium hubs. Use the largest input torque (peak or momentary) for T.

References
----------
Seed 000 p.027: WG hub bore table 027-1, plug bore table 027-2 and the text above them
(JIS keyways recommended; key length "sufficient for the transmitted torque").
JIS B 1301:1996, Keys and their corresponding keyways (parallel keys, applicable shaft
diameters); ISO/R 773 and DIN 6885-1 have the same b, h, t1, t2.
R. L. Mott, Machine Elements in Mechanical Design, 4th ed., Prentice Hall, §11-4.
JIS G 4051, Carbon steels for machine structural use (S45C, normalized: Re ≥ 345 MPa).
"""

from __future__ import annotations

from typing import Iterable

from .record import FAIL, PASS, CheckResult, Quantity, compared, margin_of, not_evaluated

FAMILY = "geometry"
ID = "input_bore"
TITLE = "Input shaft bore and key"
FORMULA = ("pilot ≤ d ≤ d_max,hub (027-1); above: d ≤ φV' − t2 (027-2, Oldham coupling "
           "dropped); τ = 2T/(d·b·l) ≤ τa; p = 2T/(d·(h − t1)·l) ≤ pa")
HUB_TABLE, PLUG_TABLE, KEY_TABLE = "wg_hub_bore", "wg_plug_bore", "parallel_key_jisb1301"
HUB_SOURCE = "seed 000 table 027-1 (p.027)"
PLUG_SOURCE = "seed 000 table 027-2 (p.027)"
KEY_SOURCE = "JIS B 1301:1996"

KEY_YIELD_MPa = 345.0          # S45C normalized, JIS G 4051 (reference values)
KEY_SAFETY = 2.0               # Mott §11-4, typical industrial design factor N
TAU_ALLOW_MPa = 0.5 * KEY_YIELD_MPa / KEY_SAFETY   # 86.25 MPa
P_ALLOW_MPa = KEY_YIELD_MPa / KEY_SAFETY           # 172.5 MPa
KEY_LENGTH_FACTOR = 1.5        # default effective key length l = 1.5·d
ALLOWABLE_RULE = (f"allowables τa = 0.5·Re/N = {TAU_ALLOW_MPa:g} MPa, pa = Re/N = "
                  f"{P_ALLOW_MPa:g} MPa (Mott §11-4, N = {KEY_SAFETY:g}, Re = "
                  f"{KEY_YIELD_MPa:g} MPa for S45C per JIS G 4051; design defaults, not "
                  "standard values)")


def select_key(shaft_mm: float, rows: Iterable[dict]) -> dict | None:
    """The JIS B 1301 key row for a shaft of diameter ``shaft_mm`` [mm].

    A row applies for shaft_min < d ≤ shaft_max; the smallest row also includes its minimum.
    """
    rows = sorted(rows, key=lambda r: r["shaft_min_mm"])
    for i, row in enumerate(rows):
        low, high = row["shaft_min_mm"], row["shaft_max_mm"]
        if (low < shaft_mm or (i == 0 and low == shaft_mm)) and shaft_mm <= high:
            return row
    return None


def key_stresses(torque_Nm: float, shaft_mm: float, b_mm: float, h_mm: float, t1_mm: float,
                 length_mm: float) -> tuple[float, float]:
    """Key shear stress τ and hub-side pressure p [MPa] of a parallel key.

    τ = 2T/(d·b·l), p = 2T/(d·(h − t1)·l); T [N·m], d, b, h, t1, l [mm].
    """
    force_N = 2.0 * abs(torque_Nm) * 1000.0 / shaft_mm
    return force_N / (b_mm * length_mm), force_N / ((h_mm - t1_mm) * length_mm)


def _shipped_key_rows() -> list[dict]:
    from ..catalog import load_catalog
    return load_catalog().rows(KEY_TABLE)


def input_bore(shaft_mm: float, size: int, input_torque_Nm: float, hub_row: dict | None,
               plug_row: dict | None, key_length_mm: float | None = None, *,
               key_rows: Iterable[dict] | None = None,
               tau_allow_MPa: float = TAU_ALLOW_MPa, p_allow_MPa: float = P_ALLOW_MPa,
               plug_limit_includes_keyway: bool = True) -> CheckResult:
    """Input shaft diameter [mm] against the WG hub / plug bores, and its parallel key.

    Parameters
    ----------
    shaft_mm : input shaft diameter d [mm]
    size : gear size (for the messages)
    input_torque_Nm : largest torque the key carries T [N·m]
    hub_row : table 027-1 row (``standard_H7_mm``, ``pilot_mm``, ``max_mm``) or None
    plug_row : table 027-2 row (``max_bore_V_mm``, ``min_plug_thickness_mm``) or None
    key_length_mm : effective key length l [mm]; default 1.5·d (plug: min(1.5·d, plug
        thickness))
    key_rows : JIS B 1301 rows; default the shipped ``parallel_key_jisb1301`` table
    tau_allow_MPa, p_allow_MPa : allowable key shear stress and side pressure [MPa]
    plug_limit_includes_keyway : direct plug mounting allowed for d + t2 ≤ φV' (True) or
        d ≤ φV' (False)

    Returns
    -------
    CheckResult with value = d [mm], limit = the governing allowed bore [mm] (sense ``<=``;
    ``>=`` with the pilot bore when d is below it). The status also fails when the key is
    overstressed; the margin is then the smallest of the bore and key margins.
    """
    d = float(shaft_mm)
    torque = abs(float(input_torque_Nm))
    inputs = {"d": Quantity(d, "mm"), "size": Quantity(size, ""),
              "T": Quantity(torque, "N·m")}
    if hub_row is None:
        return not_evaluated(ID, TITLE, FAMILY, FORMULA,
                             f"size {size} missing from table {HUB_TABLE} (seed 000 table "
                             "027-1)", inputs, d, "mm", HUB_SOURCE)
    standard, pilot, hub_max = (hub_row.get("standard_H7_mm"), hub_row.get("pilot_mm"),
                                hub_row.get("max_mm"))
    rebore_max = hub_max if hub_max is not None else standard
    min_bore = pilot if pilot is not None else standard
    inputs["standard H7 bore"] = Quantity(standard, "mm", HUB_SOURCE)
    inputs["pilot bore"] = Quantity(pilot, "mm", HUB_SOURCE)
    inputs["max hub bore"] = Quantity(hub_max, "mm", HUB_SOURCE)

    rows = list(key_rows) if key_rows is not None else _shipped_key_rows()
    key = select_key(d, rows) if rows else None
    details: dict = {"standard_H7_mm": standard, "pilot_mm": pilot, "hub_max_mm": hub_max}
    notes: list[str] = []
    sources = [HUB_SOURCE]

    if d < min_bore:
        regime, limit, sense = "below_pilot", float(min_bore), ">="
        notes.append(f"d = {d:g} mm is below the {'pilot' if pilot is not None else 'standard'}"
                     f" bore {min_bore:g} mm of the WG hub: the hub cannot be bored smaller "
                     "(use a bushing or a larger input shaft)")
    elif d <= rebore_max:
        regime, limit, sense = "hub", float(rebore_max), "<="
        if d == standard:
            notes.append(f"standard H7 hub bore {standard:g} mm")
        else:
            notes.append(f"hub rebored to {d:g} H7 (standard {standard:g} mm; allowed up to the "
                         f"maximum {rebore_max:g} mm, p.027); JIS keyway recommended (p.027)")
        if hub_max is None:
            notes.append("table 027-1 prints no maximum bore for this size: only the standard "
                         "bore is available")
    else:
        if plug_row is None:
            return not_evaluated(ID, TITLE, FAMILY, FORMULA,
                                 f"size {size} missing from table {PLUG_TABLE} (seed 000 table "
                                 f"027-2); d = {d:g} mm is above the max hub bore "
                                 f"{rebore_max:g} mm", inputs, d, "mm", HUB_SOURCE,
                                 details=details)
        regime, sense = "plug", "<="
        sources.append(PLUG_SOURCE)
        v_max = float(plug_row["max_bore_V_mm"])
        thickness = plug_row.get("min_plug_thickness_mm")
        inputs["φV'"] = Quantity(v_max, "mm", PLUG_SOURCE)
        inputs["min plug thickness"] = Quantity(thickness, "mm", PLUG_SOURCE)
        details.update(plug_max_bore_V_mm=v_max, min_plug_thickness_mm=thickness)
        if plug_limit_includes_keyway and key is not None:
            limit = v_max - float(key["t2_mm"])
            rule = (f"φV' includes the keyway depth (p.027): d ≤ φV' − t2 = {v_max:g} − "
                    f"{key['t2_mm']:g} = {limit:g} mm")
        else:
            limit = v_max
            rule = f"d ≤ φV' = {v_max:g} mm"
            if plug_limit_includes_keyway:
                rule += " (no JIS key for this d, keyway depth not deducted)"
        notes.append(f"d above the max hub bore {rebore_max:g} mm: the WG plug is mounted "
                     "directly on the input shaft and the Oldham coupling is lost (no "
                     "compensation of input-shaft misalignment: the input shaft must be "
                     f"concentric with the circular spline, guideline 1 p.024); {rule}")
        details["plug_rule"] = rule
    details.update(regime=regime, allowed_bore_mm=limit)

    # -- parallel key ------------------------------------------------------------------
    key_margins: list[float] = []
    key_failed = False
    if key is not None:
        sources.append(KEY_SOURCE)
        b, h, t1, t2 = (float(key[c]) for c in ("b_mm", "h_mm", "t1_mm", "t2_mm"))
        if key_length_mm is not None:
            length, length_rule = float(key_length_mm), "given"
            if regime == "plug" and details.get("min_plug_thickness_mm") and \
                    length > details["min_plug_thickness_mm"]:
                notes.append(f"key length {length:g} mm exceeds the minimum plug thickness "
                             f"{details['min_plug_thickness_mm']:g} mm: check the plug width")
        elif regime == "plug" and details.get("min_plug_thickness_mm"):
            length = min(KEY_LENGTH_FACTOR * d, float(details["min_plug_thickness_mm"]))
            length_rule = "min(1.5·d, minimum plug thickness) (default)"
        else:
            length, length_rule = KEY_LENGTH_FACTOR * d, "1.5·d (default)"
        tau, pressure = key_stresses(torque, d, b, h, t1, length)
        key_margins = [margin_of(tau, tau_allow_MPa, "<="),
                       margin_of(pressure, p_allow_MPa, "<=")]
        key_failed = tau > tau_allow_MPa or pressure > p_allow_MPa
        details["key"] = {
            "designation": f"{b:g} × {h:g} (JIS B 1301)", "b_mm": b, "h_mm": h,
            "t1_mm": t1, "t2_mm": t2, "length_mm": length, "length_rule": length_rule,
            "tau_MPa": tau, "tau_allow_MPa": tau_allow_MPa,
            "p_MPa": pressure, "p_allow_MPa": p_allow_MPa,
            "tau_formula": "τ = 2T/(d·b·l)", "p_formula": "p = 2T/(d·(h − t1)·l)",
            "status": FAIL if key_failed else PASS,
        }
        inputs["key b × h"] = Quantity(f"{b:g} × {h:g}", "mm", KEY_SOURCE)
        inputs["l"] = Quantity(length, "mm", length_rule)
        notes.append(f"key {b:g} × {h:g}, t1 = {t1:g}, t2 = {t2:g}, l = {length:g} mm "
                     f"({length_rule}): τ = {tau:.1f} MPa (τa {tau_allow_MPa:g}), p = "
                     f"{pressure:.1f} MPa (pa {p_allow_MPa:g})")
        if (tau_allow_MPa, p_allow_MPa) == (TAU_ALLOW_MPa, P_ALLOW_MPa):
            notes.append(ALLOWABLE_RULE)
        if key_failed:
            notes.append("key overstressed: use a longer key, two keys or a larger shaft")
    note = "; ".join(notes)
    source = "; ".join(sources)

    result = compared(ID, TITLE, FAMILY, FORMULA, inputs, d, limit, "mm", sense, source,
                      note, details)
    if result.status == FAIL:
        return result
    if key is None:
        missing = (f"table {KEY_TABLE} missing from the catalog" if not rows else
                   f"no JIS B 1301 parallel key for a {d:g} mm shaft in table {KEY_TABLE} "
                   f"(rows cover {min(r['shaft_min_mm'] for r in rows):g}-"
                   f"{max(r['shaft_max_mm'] for r in rows):g} mm)")
        return not_evaluated(ID, TITLE, FAMILY, FORMULA, missing, inputs, d, "mm", source,
                             note=f"bore within the allowed range ({note})", details=details)
    if key_failed:
        result.status = FAIL
    margins = [m for m in [result.margin, *key_margins] if m is not None]
    result.margin = min(margins) if margins else None
    return result
