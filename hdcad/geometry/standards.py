"""Standard part dimensions the geometry needs (screws, holes, counterbores).

Values are the standards' published ones; ``tests/test_geometry_standards.py`` checks those
that also stand in the catalog's standard tables (catalog/*iso*.csv) against them.
"""

ISO_261_PITCH_MM = {"M3": 0.5, "M4": 0.7, "M5": 0.8, "M6": 1.0, "M8": 1.25, "M10": 1.5,
                    "M12": 1.75, "M14": 2.0, "M16": 2.0, "M20": 2.5, "M24": 3.0}
"""ISO 261 (ISO general-purpose metric screw threads): coarse pitch P by nominal size."""

ISO_273_MEDIUM_MM = {"M3": 3.4, "M4": 4.5, "M5": 5.5, "M6": 6.6, "M8": 9.0, "M10": 11.0,
                     "M12": 13.5, "M14": 15.5, "M16": 17.5, "M20": 22.0, "M24": 26.0}
"""ISO 273 (clearance holes for bolts and screws), series "medium"."""

TAP_DRILL_MM = {"M3": 2.5, "M4": 3.3, "M5": 4.2, "M6": 5.0, "M8": 6.8, "M10": 8.5,
                "M12": 10.2, "M14": 12.0, "M16": 14.0, "M20": 17.5, "M24": 21.0}
"""Tap-drill diameter for ISO 261 coarse threads, class 6H: about d − P (ISO 2306, DIN 336)."""

ISO_4762_HEAD_MM = {"M3": (5.5, 3.0), "M4": (7.0, 4.0), "M5": (8.5, 5.0), "M6": (10.0, 6.0),
                    "M8": (13.0, 8.0), "M10": (16.0, 10.0), "M12": (18.0, 12.0),
                    "M14": (21.0, 14.0), "M16": (24.0, 16.0), "M20": (30.0, 20.0),
                    "M24": (36.0, 24.0)}
"""ISO 4762 hexagon socket head cap screws: (head diameter dk max, head height k max)."""

DIN_974_1_CBORE_MM = {"M3": 6.5, "M4": 8.0, "M5": 10.0, "M6": 11.0, "M8": 15.0, "M10": 18.0,
                      "M12": 20.0, "M14": 24.0, "M16": 26.0, "M20": 33.0, "M24": 40.0}
"""DIN 974-1 counterbore diameter for ISO 4762 heads without washer (row 1, ISO 273 medium)."""

ISO_4762_LENGTHS_MM = (6, 8, 10, 12, 16, 20, 25, 30, 35, 40, 45, 50, 55, 60, 65, 70, 80, 90,
                       100, 110, 120, 130, 140, 150, 160, 180, 200)
"""ISO 4762 preferred nominal lengths l [mm] (the range M3-M24 covers; not every length exists
for every size, e.g. M3 stops at 30 and M24 starts at 40: ask the supplier)."""


ISO_4762_LENGTH_RANGE_MM = {"M3": (5, 30), "M4": (6, 40), "M5": (8, 50), "M6": (10, 60),
                            "M8": (12, 80), "M10": (16, 100), "M12": (20, 120),
                            "M14": (25, 140), "M16": (25, 160), "M20": (30, 200),
                            "M24": (40, 200)}
"""ISO 4762 Table 1: range of nominal lengths l per thread (commercial lengths in between)."""


def preferred_lengths(thread: str) -> tuple[int, ...]:
    """ISO 4762 preferred lengths [mm] that exist for ``thread``."""
    lo, hi = ISO_4762_LENGTH_RANGE_MM[thread]
    return tuple(l for l in ISO_4762_LENGTHS_MM if lo <= l <= hi)


def thread_diameter(thread: str) -> float:
    """Nominal diameter [mm] of an ISO metric coarse thread ("M5" → 5.0); ValueError naming
    the known threads if it is not in the ISO 261 table above."""
    if thread not in ISO_261_PITCH_MM:
        raise ValueError(f"thread {thread!r} is not in the ISO 261 table of "
                         f"hdcad.geometry.standards; known: {', '.join(ISO_261_PITCH_MM)}")
    return float(thread[1:])


def review_minor_diameter(thread: str) -> float:
    """d − P [mm]: the Ø at which the review assembly models a screw's shank and its tapped
    hole, so that a screw in its thread does not count as interference."""
    return thread_diameter(thread) - ISO_261_PITCH_MM[thread]
