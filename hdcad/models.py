"""Model codes and the catalog data that belongs to one model.

Model codes (seed 001 p.304, seed 003 p.043, seed 000 p.015):
``FD-<size>-<ratio>-0`` unit, ``FD-<size>-<ratio>-2`` component set,
``CSF|CSG-<size>-<ratio>-GH`` gear head, ``CSF|CSG-<size>-<ratio>-2A-GR`` component set.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from .catalog import Catalog, Datum
from .errors import InputError

FAMILIES = {
    "FD-0": "FD unit (cased harmonic differential gear)",
    "FD-2": "FD component set (circular splines S and D, flexspline, wave generator)",
    "GH": "gear head for servo motors",
    "2A-GR": "cup-type component set",
}
SERIES = ("FD", "CSF-GH", "CSG-GH", "CSF", "CSG")

_CODE = re.compile(
    r"^(?:(?P<fd>FD)-(?P<fd_size>\d+)-(?P<fd_ratio>\d+)-(?P<fd_type>[02])"
    r"|(?P<cup>CSF|CSG)-(?P<size>\d+)-(?P<ratio>\d+)-(?P<suffix>GH|2A-GR))$"
)

# Ratings every model may carry; names are the catalog column names.
RATING_COLUMNS = (
    "rated_torque_Nm", "avg_torque_max_Nm", "peak_torque_Nm", "momentary_torque_Nm",
    "avg_input_speed_max_rpm", "max_input_speed_rpm", "efficiency_rated_pct",
)
STIFFNESS_COLUMNS = ("T1_Nm", "T2_Nm", "K1_Nm_per_rad", "K2_Nm_per_rad", "K3_Nm_per_rad",
                     "theta1_rad", "theta2_rad")
RATED_INPUT_SPEED_RPM = 2000.0  # seed 000 p.012: rated torque is at 2000 r/min input


@dataclass
class GearModel:
    """A catalog model and every value the catalog holds for it."""

    code: str
    series: str  # FD, CSF-GH, CSG-GH, CSF, CSG
    family: str  # FD-0, FD-2, GH, 2A-GR
    size: int
    ratio: int
    data: dict[str, Datum] = field(default_factory=dict)
    fd_torque_by_speed: list[tuple[float, Datum]] = field(default_factory=list)

    @property
    def description(self) -> str:
        return f"{self.series} size {self.size}, ratio {self.ratio}: {FAMILIES[self.family]}"

    @property
    def is_fd(self) -> bool:
        return self.series == "FD"

    def get(self, name: str) -> Datum | None:
        return self.data.get(name)

    def _put(self, name: str, datum: Datum | None) -> None:
        if datum is not None:
            self.data[name] = datum


def parse_code(code: str) -> tuple[str, str, int, int]:
    """(series, family, size, ratio) from a model code; InputError if malformed."""
    text = code.strip().upper()
    match = _CODE.match(text)
    if not match:
        raise InputError("model", f"{code!r} is not a model code; expected FD-<size>-<ratio>-0|2, "
                                  "CSF|CSG-<size>-<ratio>-GH or CSF|CSG-<size>-<ratio>-2A-GR")
    if match["fd"]:
        return "FD", f"FD-{match['fd_type']}", int(match["fd_size"]), int(match["fd_ratio"])
    suffix = match["suffix"]
    series = match["cup"] + ("-GH" if suffix == "GH" else "")
    return series, ("GH" if suffix == "GH" else "2A-GR"), int(match["size"]), int(match["ratio"])


def _offered(catalog: Catalog, series: str, family: str) -> dict[int, list[int]]:
    """size → ratios the catalog offers for a series and family."""
    if series == "FD":
        pairs = [(r["size"], r["ratio"]) for r in catalog.rows("fd_ratios")]
    elif family == "GH":
        pairs = [(r["size"], r["ratio"]) for r in catalog.rows("gh_ratings", series=series)]
    else:
        pairs = [(r["size"], r["ratio"])
                 for t in ("component_examples", "component_ratings")
                 for r in catalog.rows(t, series=series)]
    offered: dict[int, list[int]] = {}
    for size, ratio in pairs:
        offered.setdefault(size, [])
        if ratio not in offered[size]:
            offered[size].append(ratio)
    return {s: sorted(r) for s, r in sorted(offered.items())}


def _check_offered(catalog: Catalog, series: str, family: str, size: int, ratio: int) -> None:
    offered = _offered(catalog, series, family)
    label = f"{series}" if family != "2A-GR" else f"{series}-2A-GR"
    if size not in offered:
        sizes = ", ".join(str(s) for s in offered) or "none"
        raise InputError("model", f"{label} has no size {size}; sizes in the catalog: {sizes}")
    if ratio not in offered[size]:
        ratios = ", ".join(str(r) for r in offered[size])
        raise InputError("model", f"{label}-{size} has no ratio {ratio}; ratios: {ratios}")


def resolve(code: str, catalog: Catalog) -> GearModel:
    """The GearModel for ``code`` with its catalog data; InputError lists what exists."""
    series, family, size, ratio = parse_code(code)
    _check_offered(catalog, series, family, size, ratio)
    canonical = (f"FD-{size}-{ratio}-{family[-1]}" if series == "FD"
                 else f"{series.split('-')[0]}-{size}-{ratio}-{family}")
    model = GearModel(canonical, series, family, size, ratio)
    if series == "FD":
        _load_fd(model, catalog)
    elif family == "GH":
        _load_gear_head(model, catalog)
    else:
        _load_component(model, catalog)
    _load_life(model, catalog)
    return model


_FD_GEAR = re.compile(r"^FD-\d+-\d+$")


def resolve_gear(code: str, catalog: Catalog) -> tuple[GearModel, str | None]:
    """(model, note) for a command that needs only the gear (reconcile): an FD code without
    its type is read as the unit (-0), whose gear data (ratio, rated torque, efficiency,
    lost motion, spring constant) are the component set's (-2), and the note says so."""
    text = code.strip().upper()
    if not _FD_GEAR.match(text):
        return resolve(code, catalog), None
    model = resolve(f"{text}-0", catalog)
    return model, (f"{text} read as {model.code}: the unit (-0) and the component set (-2) "
                   "share the gear's data (tables 304-1, 310-1, 313, 314-1)")


def _load_fd(model: GearModel, catalog: Catalog) -> None:
    rows = catalog.rows("fd_rated_torque", size=model.size, ratio=model.ratio)
    model.fd_torque_by_speed = sorted(
        (r["speed_rpm"], catalog.datum("fd_rated_torque", r, "rated_torque_Nm")) for r in rows
    )
    speeds = catalog.find("fd_max_input_speed", size=model.size)
    model._put("max_input_speed_oil_rpm", catalog.datum("fd_max_input_speed", speeds,
                                                        "oil_max_rpm"))
    model._put("max_input_speed_grease_rpm", catalog.datum("fd_max_input_speed", speeds,
                                                           "grease_max_rpm"))
    spring = catalog.find("fd_lost_motion_spring", size=model.size)
    model._put("spring_constant_Nm_per_rad",
               catalog.datum("fd_lost_motion_spring", spring, "spring_constant_Nm_per_rad"))
    model._put("lost_motion_rad", catalog.datum("fd_lost_motion_spring", spring,
                                                "lost_motion_rad"))
    model._put("oil_level_A_mm", catalog.datum("fd_oil_level", catalog.find(
        "fd_oil_level", size=model.size), "A_mm"))


def _load_gear_head(model: GearModel, catalog: Catalog) -> None:
    row = catalog.find("gh_ratings", series=model.series, size=model.size, ratio=model.ratio)
    model._put("rated_torque_Nm", catalog.datum("gh_ratings", row, "rated_torque_2000_Nm"))
    for column in RATING_COLUMNS[1:]:
        model._put(column, catalog.datum("gh_ratings", row, column))
    ratchet = catalog.find("gh_ratcheting", series=model.series, size=model.size,
                           ratio=model.ratio)
    model._put("ratcheting_torque_Nm", catalog.datum("gh_ratcheting", ratchet,
                                                     "ratcheting_torque_Nm"))
    buckling = catalog.find("gh_buckling", series=model.series, size=model.size)
    model._put("buckling_torque_Nm", catalog.datum("gh_buckling", buckling,
                                                   "buckling_torque_Nm"))
    stiff = _ratio_group_row(catalog, "gh_stiffness", model, size=model.size)
    for column in STIFFNESS_COLUMNS:
        model._put(column, catalog.datum("gh_stiffness", stiff, column))
    model._put("rated_input_speed_rpm", Datum(RATED_INPUT_SPEED_RPM, "rpm",
                                              "seed 000 p.012 (rating terms)"))


def _ratio_group_row(catalog: Catalog, table: str, model: GearModel, **match) -> dict | None:
    """Row of a table split by ratio groups (ratio_min … ratio_max, empty max = open)."""
    for row in reversed(catalog.rows(table, series=model.series, **match)):
        low, high = row["ratio_min"], row.get("ratio_max")
        if low <= model.ratio and (high is None or model.ratio <= high):
            return row
    return None


def _load_component(model: GearModel, catalog: Catalog) -> None:
    for table in ("component_examples", "component_ratings"):
        row = catalog.find(table, series=model.series, size=model.size, ratio=model.ratio)
        for column in RATING_COLUMNS + STIFFNESS_COLUMNS:
            model._put(column, catalog.datum(table, row, column) if row else None)
    model._put("rated_input_speed_rpm", Datum(RATED_INPUT_SPEED_RPM, "rpm",
                                              "seed 000 p.012 (rating terms)"))


def _load_life(model: GearModel, catalog: Catalog) -> None:
    row = catalog.find("wg_life", series=model.series)
    model._put("L10_h", catalog.datum("wg_life", row, "L10_h"))
    model._put("L50_h", catalog.datum("wg_life", row, "L50_h"))


def list_models(catalog: Catalog, series: str | None = None) -> list[str]:
    """Every model code the catalog offers, smallest size first."""
    wanted = [series] if series else list(SERIES)
    unknown = [s for s in wanted if s not in SERIES]
    if unknown:
        raise InputError("--series", f"{unknown[0]!r} is not a series; allowed: "
                                     f"{', '.join(SERIES)}")
    codes: list[tuple[int, int, str]] = []
    for name in wanted:
        if name == "FD":
            for size, ratios in _offered(catalog, "FD", "FD-2").items():
                codes += [(size, r, f"FD-{size}-{r}-{t}") for r in ratios for t in (2, 0)]
        elif name.endswith("-GH"):
            for size, ratios in _offered(catalog, name, "GH").items():
                codes += [(size, r, f"{name.split('-')[0]}-{size}-{r}-GH") for r in ratios]
        else:
            for size, ratios in _offered(catalog, name, "2A-GR").items():
                codes += [(size, r, f"{name}-{size}-{r}-2A-GR") for r in ratios]
    return [c for _, _, c in sorted(codes, key=lambda t: (t[0], t[1]))]
