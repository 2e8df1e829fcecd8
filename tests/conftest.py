import pytest

from exgen.bank import load_bank


@pytest.fixture(scope="session")
def bank():
    return load_bank()
