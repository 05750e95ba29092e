"""Which parts a model gets, where they sit in the assembly, and what they weigh.

FD-…-2: the two casing halves of the FD-0 unit (seed 001 p.315: casings and bearings of an
FD-2 follow the FD-0 unit), placed back to back with the running gap between them.
FD-…-0: a drive flange on each turning casing half, for the user's gears or pulleys.
CSF/CSG-…-GH: the motor adapter flange for the chosen flange code.
CSF/CSG-…-2A-GR: housing, input cover and output flange from the overlay tables
component_outline and component_housing (the seeds have neither).
"""

from __future__ import annotations

import itertools

from ..catalog import Catalog
from ..design_options import DesignOptions
from ..errors import InputError
from ..models import GearModel
from .part import Part

MISSING_COMPONENT_TABLES = (
    "component_outline", "component_housing")


def build_parts(model: GearModel, catalog: Catalog, options: DesignOptions) -> list[Part]:
    """The parts of ``model``, placed for the assembly. InputError for impossible requests."""
    missing = [t for t in MISSING_COMPONENT_TABLES
               if catalog.find(t, series=model.series, size=model.size) is None]
    try:
        if model.family == "FD-2":
            return _fd_casing(model, catalog, options)
        if model.family == "FD-0":
            return _fd_flanges(model, catalog, options)
        if model.family == "GH":
            parts = (_gh_motor(model, catalog, options) if options.motor
                     else [_gh_flange(model, catalog, options)])
            return parts + _gh_mounting(model, catalog)
        if model.family == "2A-GR" and not missing:
            return _component_set(model, catalog, options)
    except ValueError as exc:
        raise InputError("design", str(exc).splitlines()[0]) from None
    raise InputError("model", f"{model.code}: the housing needs a {model.series} size "
                              f"{model.size} row in the tables {', '.join(missing)} (outline "
                              "and recommended housing dimensions), which the seeds do not "
                              "contain; supply them with --catalog-overlay")


def _fd_casing(model, catalog, options) -> list[Part]:
    """Both casing halves and their journal sleeves, back to back across the running gap
    (each sleeve is built in its half's frame and placed with it)."""
    from .fd_casing import FDCasingHalf
    from .fd_sleeve import FDSleeve
    gap = options.running_gap_mm
    parts = []
    for side, flip, z in (("S", True, -gap / 2), ("D", False, gap / 2)):
        for maker in (FDCasingHalf, FDSleeve):
            part = maker(model.size, catalog, options, side=side).build()
            part.flip, part.offset_z_mm = flip, z
            parts.append(part)
    return parts


def _fd_flanges(model, catalog, options) -> list[Part]:
    from .flanges import FDDriveFlange
    width = catalog.find("fd0_dimensions", size=model.size)["D_mm"]  # unit width (311-1)
    from .fd0_review import flange_neighbours
    parts = []
    for side, flip, z in (("S", True, -width / 2), ("D", False, width / 2)):
        maker = FDDriveFlange(model.size, catalog, options)
        part = maker.build()
        part.name, part.flip, part.offset_z_mm = f"drive_flange_{side}", flip, z
        part.neighbours = flange_neighbours(maker, with_unit=side == "D")
        parts.append(part)
    return parts


def _gh_flange(model, catalog, options) -> Part:
    from .flanges import GHMotorFlange
    codes = GHMotorFlange.codes(catalog, model.series, model.size)
    if not codes:
        raise ValueError(f"{model.series}-{model.size} has no motor-flange table in the catalog")
    code = options.motor_flange or codes[0]
    if code not in codes:
        raise ValueError(f"motor_flange {code!r} is not available for {model.series}-"
                         f"{model.size}; complete codes: {', '.join(codes)}")
    return GHMotorFlange(model.series, model.size, code, catalog, options).build()


# the mounting plate sits apart from the input parts in assembly.step: the gear head's
# length between its input and output faces is not in the seeds
MOUNTING_PLATE_OFFSET_MM = -300.0


def _gh_mounting(model, catalog) -> list[Part]:
    """The mounting plate on the machine, when the overlay gives the gear head's face."""
    from .gh_mounting_plate import mounting_plate
    maker = mounting_plate(catalog, model.series, model.size)
    if maker is None:
        return []
    part = maker.build()
    part.offset_z_mm = MOUNTING_PLATE_OFFSET_MM
    part.flip = True   # its gear-head face towards the gear head, between the two plates
    return [part]


def motor_choice(model, catalog, options) -> tuple[dict, list[str]]:
    """The flange code for the user's motor and what keeps it from fitting directly."""
    from .motor_adapter import Motor, choose_code
    if options.motor_flange:
        from .motor_adapter import mismatches
        row = catalog.find("gh_motor_flange", series=model.series, size=model.size,
                           flange_code=options.motor_flange)
        if row is None:
            raise ValueError(f"motor_flange {options.motor_flange!r} is not available for "
                             f"{model.series}-{model.size}")
        return row, mismatches(row, Motor.from_options(options))
    return choose_code(catalog, model.series, model.size, Motor.from_options(options))


def _gh_motor(model, catalog, options) -> list[Part]:
    """The motor adapter plate when the user's motor does not fit a flange code directly;
    the chosen code's own flange (seed motor side) when it does."""
    from dataclasses import replace

    from .motor_adapter import Motor, MotorAdapter
    row, mismatch = motor_choice(model, catalog, options)
    if not mismatch:
        return [_gh_flange(model, catalog, replace(options, motor_flange=row["flange_code"]))]
    return [MotorAdapter(row, Motor.from_options(options), catalog, options, mismatch).build()]


def _component_set(model, catalog, options) -> list[Part]:
    from .component_housing import ComponentSetHousing
    return ComponentSetHousing(model.series, model.size, catalog, options).build_all()


def part_mass_kg(part: Part, density_kg_m3: float) -> float:
    """Mass [kg] from the solid's volume [mm³]."""
    return part.solid().Volume() * 1e-9 * density_kg_m3


def interference_mm3(parts: list[Part]) -> list[tuple[str, str, float]]:
    """Intersection volume [mm³] of every pair of placed parts."""
    placed = [(p.name, p.placed()) for p in parts]
    out = []
    for (name_a, a), (name_b, b) in itertools.combinations(placed, 2):
        common = a.intersect(b)
        out.append((name_a, name_b, common.Volume() if common.Solids() else 0.0))
    return out


def review_plan(model: GearModel, parts: list[Part]) -> dict | None:
    """Seed point and section angles of the family's review assembly; None when its parts
    carry no neighbour bodies yet (the review is then not evaluated)."""
    if model.family == "FD-2":
        from .fd_review import review_plan as fd_plan
        return fd_plan(parts)
    if model.family == "2A-GR":
        from .component_review import review_plan as set_plan
        return set_plan(parts)
    if model.family == "FD-0":
        return {"seed_zr": None, "angles": [0.0],
                "title": "FD-0 unit (catalog outline) with both drive flanges and screws"}
    if any(p.name == "motor_adapter" for p in parts):
        return {"seed_zr": None, "angles": [45.0],
                "title": "motor adapter between the flange code's motor side and the motor"}
    if any(n.body is not None for p in parts for n in p.neighbours):
        return {"seed_zr": None, "angles": [45.0],
                "title": "gear-head plates with the gear-head housing (overlay face) and screws"}
    return None
