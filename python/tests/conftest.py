import pathlib

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
ASSETS = REPO / "assets"


@pytest.fixture
def repo():
    return REPO


@pytest.fixture
def assets():
    return ASSETS
