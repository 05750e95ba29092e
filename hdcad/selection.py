"""Model selection: run the checks over the whole catalog, smallest model first.

A model is proposed only when no check fails and its core ratings could be checked
(``CORE_CHECKS``); a model that fails nothing but lacks a core rating is "incomplete".
"""

from __future__ import annotations

from dataclasses import dataclass

from .catalog import Catalog
from .checks.record import NOT_EVALUATED
from .checks.run import Evaluation, run_checks
from .duty import Duty
from .models import list_models, resolve

CORE_CHECKS = ("avg_torque", "max_input_speed")


@dataclass
class Candidate:
    model: str
    evaluation: Evaluation

    @property
    def missing_core(self) -> list[str]:
        return [c.id for c in self.evaluation.checks
                if c.id in CORE_CHECKS and c.status == NOT_EVALUATED]

    @property
    def status(self) -> str:
        if self.evaluation.failures:
            return "fail"
        return "incomplete" if self.missing_core else "pass"

    @property
    def passes(self) -> bool:
        return self.status == "pass"

    @property
    def first_failure(self):
        failures = self.evaluation.failures
        return failures[0] if failures else None


def select(duty: Duty, catalog: Catalog, series: str | None = None) -> list[Candidate]:
    """Every catalog model (of ``series``) evaluated against ``duty``, smallest first."""
    return [Candidate(code, run_checks(resolve(code, catalog), duty, catalog))
            for code in list_models(catalog, series)]
