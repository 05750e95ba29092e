"""`hdcad design`: checks, parts, STEP/STL/SVG export and results.json in one folder.

Everything is written to a staging folder that replaces ``OUT/<MODEL>`` only when complete:
bad input (exit 2) leaves nothing behind; a design whose checks fail is written in full.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from pathlib import Path

from .catalog import Catalog
from .checks.record import CheckResult, Quantity, compared, not_evaluated
from .checks.run import Evaluation, run_checks
from .design_options import DesignOptions
from .duty import Duty
from .models import GearModel


@dataclass
class DesignResult:
    evaluation: Evaluation
    options: DesignOptions
    folder: Path
    files: list[str]
    masses_kg: dict[str, float]
    timings_s: dict[str, float] = field(default_factory=dict)  # per stage, for benchmarks


def interference_check(pairs: list[tuple[str, str, float]], masses: dict[str, float]
                       ) -> CheckResult:
    """No two parts overlap: largest pairwise intersection volume [mm³] must be 0."""
    worst = max((v for _, _, v in pairs), default=0.0)
    inputs = {f"{a} ∩ {b}": Quantity(v, "mm³") for a, b, v in pairs}
    inputs.update({f"mass {name}": Quantity(m, "kg") for name, m in masses.items()})
    if not pairs:
        return not_evaluated("interference", "Interference between parts", "geometry",
                             "max over part pairs of V(A ∩ B) ≤ 0",
                             f"a second part: the design has {len(masses)} part(s), so no pair "
                             "to check", inputs, unit="mm³",
                             source="OCCT boolean common of the placed solids",
                             details={"pairs": [], "masses_kg": masses})
    # 1e-3 mm³ is far below any real overlap and above OCCT's boolean noise on touching faces
    return compared("interference", "Interference between parts", "geometry",
                    "max over part pairs of V(A ∩ B) ≤ 0", inputs, worst, 1e-3, "mm³", "<=",
                    "OCCT boolean common of the placed solids",
                    f"{len(pairs)} pair(s) checked; masses " +
                    ", ".join(f"{n} {m:.3f} kg" for n, m in masses.items()),
                    {"pairs": [{"a": a, "b": b, "volume_mm3": v} for a, b, v in pairs],
                     "masses_kg": masses})


def oil_level_check(model: GearModel, parts: list, duty: Duty, options: DesignOptions,
                    catalog: Catalog) -> CheckResult:
    """`oil_level` on the generated parts: the FD-2 casings and the 2A-GR housing hold oil."""
    from .checks.oil_level import oil_level
    from .geometry import oil
    level, source = _oil_level(model, catalog)
    args = dict(lubrication=duty.lubrication, level_mm=level, level_source=source,
                axis=options.axis, cavity_depth_mm=None, seal_shaft_mm=None,
                oil_volume_mL=None)
    cavity = {"FD-2": oil.fd_casing_cavity, "2A-GR": oil.component_set_cavity}.get(model.family)
    if cavity is not None and level is not None:
        space = cavity(parts)
        args.update(cavity_depth_mm=space.depth_mm, seal_shaft_mm=space.seal_shaft_mm,
                    oil_volume_mL=oil.volume_below_mL(space.solid, level),
                    volume_note=space.note,
                    plug_radius_mm=parts[0].dimensions.get("oil_plug_radius_mm"),
                    support_bearing_od_mm=parts[0].dimensions.get("bearing_seat_mm"),
                    openings=space.openings)
    return oil_level(**args)


def _geometry_options(model, catalog, options, checks: list, parts: list):
    """With a ``motor:`` the chosen flange code and the motor shaft stand in for
    motor_flange and input_shaft_mm; the motor checks are added to ``checks``."""
    if model.family != "GH" or not options.motor:
        return options
    from dataclasses import replace

    from .checks.motor import motor_fit, motor_shaft_reach
    from .geometry.build import motor_choice
    row, mismatch = motor_choice(model, catalog, options)
    checks.append(motor_fit(row, mismatch, options.motor))
    plate = next((p for p in parts if p.name == "motor_adapter"), None)
    if plate is not None:
        checks.append(motor_shaft_reach(row, options.motor, plate.dimensions["motor_shift_mm"]))
    return replace(options, motor_flange=row["flange_code"],
                   input_shaft_mm=options.motor["shaft_diameter_mm"])


@dataclass
class _Review:
    check: CheckResult
    files: list[str]

    @property
    def step_files(self) -> list[str]:
        return [f for f in self.files if f.endswith(".step")]

    @property
    def figures(self) -> list:
        from .report.context import Figure
        return [Figure("review assembly", f, "the generated parts with their neighbours as "
                       "true-size bodies (bearings ISO 15, seals, O-rings, rings, screws, "
                       "plugs, gear outline), cut through the axis; the review_assembly "
                       "check reports what its probes measured")
                for f in self.files if f.endswith(".png")]


def _review(model: GearModel, parts: list, stage: Path) -> _Review:
    """The review assembly's probes as a check, with its STEP and section render."""
    from .checks.review import review_check
    from .geometry.build import review_plan
    from .geometry.review import run_review
    plan = review_plan(model, parts)
    if plan is None:
        return _Review(review_check(None, f"neighbour bodies for the {model.family} parts "
                                          "(bearings, seals, screws, gear outline) are not "
                                          "built yet"), [])
    result = run_review(parts, plan, stage)
    return _Review(review_check(result), result["files"])


def _oil_level(model: GearModel, catalog: Catalog) -> tuple[float | None, str]:
    """Oil level A [mm below the axis] and its source: FD table 315-1 or the overlay."""
    if model.is_fd:
        datum = catalog.datum("fd_oil_level", catalog.find("fd_oil_level", size=model.size),
                              "A_mm")
    elif catalog.has("component_housing"):
        datum = catalog.datum("component_housing", catalog.find(
            "component_housing", series=model.series, size=model.size), "oil_level_from_axis_mm")
    else:
        datum = None
    return (None, "") if datum is None else (float(datum), datum.source)


class _Clock:
    """Wall time of each stage of a design run (reported by benchmarks/bench_design.py)."""

    def __init__(self, progress=None):
        self.laps: dict[str, float] = {}
        self._last = time.perf_counter()
        self._progress = progress

    def lap(self, name: str, value=None):
        """Close the stage ``name`` (evaluated just before this call); passes ``value`` on."""
        now = time.perf_counter()
        self.laps[name] = now - self._last
        self._last = now
        if self._progress:
            self._progress(name, self.laps[name])
        return value


def _export_parts(parts: list, stage: Path) -> list[str]:
    """STEP, STL and SVG of every part, and the assembly STEP; returns the file names."""
    from .geometry.part import export_assembly, export_step, export_stl, export_svg
    files = []
    for part in parts:
        for suffix, export in ((".step", export_step), (".stl", export_stl),
                               (".svg", export_svg)):
            export(part, stage / f"{part.name}{suffix}")
            files.append(f"{part.name}{suffix}")
    export_assembly(parts, stage / "assembly.step")
    return files + ["assembly.step"]


def _draw_parts(parts: list, stage: Path, masses: dict[str, float] | None = None,
                material: str = "") -> list:
    """A dimensioned drawing (SVG for the sheet, PNG beside the part) from each STEP file."""
    from .geometry.drawing import part_drawing
    from .report.context import Figure
    (stage / "drawings").mkdir()
    figures = []
    for part in parts:
        part_drawing(stage / f"{part.name}.step", part, stage / "drawings" / f"{part.name}.svg",
                     stage / "drawings" / f"{part.name}.png", (masses or {}).get(part.name),
                     material)
        figures.append(Figure(part.name, f"drawings/{part.name}.svg",
                              f"front view and half section of {part.name}.step"))
    return figures


def _part_record(part, mass_kg: float) -> dict:
    volume = part.solid().Volume()
    before = mass_kg * (volume + part.pockets_mm3) / volume if part.pockets_mm3 else None
    return {"name": part.name, "mass_kg": mass_kg, "mass_before_pockets_kg": before,
            "dimensions": part.dimensions,
            "notes": part.notes, "purchased": part.purchased, "material": part.material,
            "bolt_circles": [b.__dict__ for b in part.bolt_circles],
            "fits": [dict(f.__dict__, deviations_um=list(f.deviations_um)) for f in part.fits],
            "tolerances": [t.__dict__ for t in part.tolerances]}


FITS_COLUMNS = ("part", "feature", "nominal_mm", "code", "kind", "upper_um", "lower_um",
                "mate", "reason", "source")


def _signed(value: float) -> str:
    return "0" if value == 0 else f"{value:+g}"


def _write_fits_csv(records: list[dict], path: Path) -> None:
    """Every ISO 286 fit of every part, one row each (STEP AP214 carries no PMI)."""
    import csv
    with open(path, "w", newline="", encoding="utf-8") as f:
        out = csv.writer(f, lineterminator="\n")
        out.writerow(FITS_COLUMNS)
        for rec in records:
            for fit in rec["fits"]:
                up, low = fit["deviations_um"]
                out.writerow([rec["name"], fit["feature"], f"{fit['nominal_mm']:g}",
                              fit["code"], fit["kind"], _signed(up), _signed(low), fit["mate"],
                              fit["reason"], fit["source"]])


def run_design(model: GearModel, duty: Duty, options: DesignOptions, catalog: Catalog,
               out_dir: Path, parallel: bool = False, progress=None,
               force: bool = False) -> DesignResult:
    """Build, check and export ``model``; returns what was written.

    ``parallel``: plots and the PDF in a side process while the CAD chain runs (False inside
    a batch whose designs already run in parallel). ``progress(stage, seconds)`` is called
    as each stage ends. ``force``: replace ``out_dir/MODEL`` even when it holds files hdcad
    did not write (otherwise an InputError before any work).
    """
    from .output import json_text, staged_dir
    from .parallel import interrupts_deferred, running, side_executor
    from .report.sheet import make_bolt_figures, make_figures, warm_up, write_calc_sheet

    from .output import check_target
    check_target(Path(out_dir) / model.code, force)
    clock = _Clock(progress)
    evaluation = run_checks(model, duty, catalog, options.input_thrust_capacity_N,
                            options.check_rules)
    clock.lap("checks")
    target = Path(out_dir) / model.code
    # the side process stops before the staging folder is removed on an error or Ctrl-C
    with staged_dir(target, force) as stage, running(side_executor(parallel)) as side:
        # the report chain (matplotlib, WeasyPrint) runs beside the CAD chain until the PDF
        plots = side.submit(make_figures, evaluation, stage)
        side.submit(warm_up)
        # cadquery is imported here, after the side process has started
        with interrupts_deferred():
            from .checks.geometric import geometric_checks
            from .geometry.build import build_parts, interference_mm3, part_mass_kg
            from .geometry.clearance import inner_wall_clearance
        parts = clock.lap("build", build_parts(model, catalog, options))
        masses = {p.name: part_mass_kg(p, options.density_kg_m3) for p in parts}
        evaluation.checks += geometric_checks(model, parts, _geometry_options(
            model, catalog, options, evaluation.checks, parts), catalog)
        evaluation.checks.append(inner_wall_clearance(model, parts, catalog, options))
        evaluation.checks.append(oil_level_check(model, parts, evaluation.duty, options,
                                                 catalog))
        evaluation.checks.append(interference_check(interference_mm3(parts), masses))
        if model.family == "FD-2":
            from .checks.seals import gap_seal_speed
            journal = next((p.dimensions.get("gap_seal_journal_mm") for p in parts
                            if "gap_seal_journal_mm" in p.dimensions), None)
            evaluation.checks.append(gap_seal_speed(journal, evaluation.duty, model.ratio,
                                                    options.check_rules.rotary_oring_speed_m_s))
        review = _review(model, parts, stage)
        evaluation.checks.append(review.check)
        clock.lap("geometric checks")
        result = evaluation.as_dict()
        result.update({"design_options": options.as_dict(),
                       "parts": [_part_record(p, masses[p.name]) for p in parts]})
        bolts = side.submit(make_bolt_figures, result["parts"], stage)
        _write_fits_csv(result["parts"], stage / "fits.csv")
        files = clock.lap("export", _export_parts(parts, stage))
        drawings = clock.lap("drawings", _draw_parts(parts, stage, masses, options.material))
        drawings += review.figures
        sheet = side.submit(write_calc_sheet, stage, result, evaluation, catalog, drawings,
                            plots.result() + bolts.result()).result()
        clock.lap("calc sheet")
        files += ([f"drawings/{p.name}.png" for p in parts] + review.step_files
                  + sheet["files"] + ["fits.csv", "results.json"])
        result.update({"files": files, "bill_of_materials": sheet["bom"],
                       "calc_sheet": {"pages": sheet["pages"], "images": sheet["images"]}})
        (stage / "results.json").write_text(json_text(result), encoding="utf-8")
    return DesignResult(evaluation, options, target, files, masses, clock.laps)
