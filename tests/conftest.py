from pathlib import Path

import pytest
import yaml

from hdcad.catalog import load_catalog
from hdcad.resources import examples_dir

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
