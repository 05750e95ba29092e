"""Selection checks: pure functions, one module per check family.

Every check returns a :class:`hdcad.checks.record.CheckResult`. :func:`run_checks` runs the
whole set for one model and duty.
"""

from .record import CheckResult, FAIL, NOT_EVALUATED, PASS

__all__ = ["CheckResult", "FAIL", "NOT_EVALUATED", "PASS", "CHECK_IDS"]

CHECK_IDS = (
    "ratio_limit", "avg_torque", "avg_input_speed", "max_input_speed", "peak_torque",
    "momentary_torque", "shock_count", "wg_life", "thrust_force", "torsional_resonance",
    "lubrication", "main_bearing",
)
