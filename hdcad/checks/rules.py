"""hdcad's own rules: where the catalog leaves a choice open, the value hdcad takes.

Each rule is printed with the check that uses it, labelled as hdcad's assumption, and a user
changes it in the design-options file under ``rules:`` (``hdcad check/design --design FILE``).

* ``resonance_band`` (0.20): steady input speeds must stay this fraction away from the
  resonant input speed. The catalog gives f = (1/2π)·√(K/J) (seed 000 p.021) and warns of
  resonance, but no margin; ±20 % in speed covers K/J from −36 % to +44 %.
* ``static_safety_min`` (None): the minimum static safety factor of the main bearing. Table
  034-3 lists operating conditions (1.5 normal, 2 with shocks or vibration, 3 for high
  rotation accuracy), not load factors; by default hdcad maps the duty's fw to it
  (fw > 1.5 → 2, else 1.5). Set it to the table's value for the application.
* ``adjustment_efficiency`` (0.6): efficiency of the FD phase-adjustment drive in the
  adjustment torque; the value of the seed's worked example (seed 001, FD-25-80).
* ``rotary_oring_speed_m_s`` (0.25): highest surface speed at which hdcad uses an O-ring as
  the slow rotary seal between the FD casing halves. O-ring makers class rotation below
  50 ft/min (0.25 m/s) as slow dynamic duty that a standard gland serves (Minnesota Rubber /
  Quadion design guide, "Defining factors in sealing applications"); faster needs a rotary
  gland or a lip seal.
"""

from __future__ import annotations

from dataclasses import dataclass, asdict


@dataclass(frozen=True)
class Rules:
    resonance_band: float = 0.20
    static_safety_min: float | None = None
    adjustment_efficiency: float = 0.6
    rotary_oring_speed_m_s: float = 0.25

    def as_dict(self) -> dict:
        return asdict(self)


def label(name: str, value) -> str:
    """How a record names a rule it used: hdcad's assumption, and where to change it."""
    return f"hdcad's own rule rules.{name} = {value} (change it in the design options)"
