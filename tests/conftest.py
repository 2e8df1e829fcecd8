import pytest

from exgen.load.bank import load_bank

#: The tests that hold the keys' numbers themselves (the golden draws, each answer and named mistake worked out
#: again from the printed givens, physics reached from the solvers, crashes reported): quick, and run first, so
#: that a wrong number in a key fails the suite in its first seconds rather than after the slow tests.
KEYS_FIRST = ("test_golden.py", "test_mistake_hand_worked.py", "test_physics_once.py", "test_solver_failures.py",
              "test_oracle_ch1.py", "test_oracle_ch2.py", "test_oracle_ch6.py", "test_flywheels_governors_oracle.py",
              "test_mistake_values_ch3_ch4.py", "test_mistake_values_ch5_ch7.py")


def pytest_collection_modifyitems(items):
    first = {name: k for k, name in enumerate(KEYS_FIRST)}
    items.sort(key=lambda item: first.get(item.path.name, len(first)))   # stable: each file's own order is kept


@pytest.fixture(scope="session")
def bank():
    return load_bank()
