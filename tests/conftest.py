import os
import shutil
import uuid

# One BLAS thread per process: the suite's process pools already fill the cores, and the
# fits' matrices are small (threads oversubscribe the CPU and slow them down).
for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

from pathlib import Path  # noqa: E402

import pytest  # noqa: E402
import yaml  # noqa: E402

from hdcad.catalog import load_catalog  # noqa: E402
from hdcad.resources import examples_dir  # noqa: E402

DATA = Path(__file__).parent / "data"


@pytest.fixture(scope="session")
def catalog():
    return load_catalog()


@pytest.fixture(scope="session")
def references():
    return yaml.safe_load((DATA / "reference_examples.yaml").read_text(encoding="utf-8"))


@pytest.fixture
def example_duty_path():
    return examples_dir() / "duty_seed_example.yaml"


def duty_dict():
    return yaml.safe_load((examples_dir() / "duty_seed_example.yaml").read_text(encoding="utf-8"))


def pytest_configure(config):
    """Under ``pytest -n``, a run id known to the controller, so that it can remove the
    folder in which the workers share the truth suites' sample (``truth_runs``)."""
    if not hasattr(config, "workerinput") and getattr(config.option, "numprocesses", None):
        config.option.testrunuid = config.option.testrunuid or uuid.uuid4().hex


def pytest_sessionfinish(session):
    run = getattr(session.config.option, "testrunuid", None)
    if run and not hasattr(session.config, "workerinput"):
        from truth_runs import shared_folder
        shutil.rmtree(shared_folder(run), ignore_errors=True)
