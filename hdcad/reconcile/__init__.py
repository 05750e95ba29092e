"""``hdcad reconcile``: where simulation and measured data disagree, and why.

The catalog model of a gear (stiffness, ratio, rated torque) predicts what a test rig should
measure; this package finds where the measurement disagrees, names the physical effect the
model is missing from a library of candidates, adds it, refits and reports how much of the gap
it closes.
"""

from .data import COLUMNS, KINDS, MIN_ROWS, read_data, validate_data
from .effects import EFFECT_NAMES, EFFECTS, Effect, Parameter
from .workflow import Reconciliation, reconcile

__all__ = ["KINDS", "COLUMNS", "EFFECT_NAMES", "EFFECTS", "MIN_ROWS", "Effect", "Parameter",
           "Reconciliation", "read_data", "reconcile", "validate_data"]
