"""Solvers for the validate tests: each breaks one rule a template author cannot see from the YAML."""

from exgen.errors import InvalidDraw


def step_named_like_a_parameter(p, d):
    d.step("x", 2 * p.x, "m")


def later_part_ignores_the_earlier(p, d):
    d.step("double", 2 * p.x, "m")
    d.step("triple", 3 * p.x, "m")  # worked from the given x, not from `double`


def later_part_follows_the_earlier(p, d):
    double = d.step("double", 2 * p.x, "m")
    d.step("triple", 1.5 * double, "m")


def mistakes(p, d):
    double = d.step("double", 2 * p.x, "m")
    d.mistake("double", "no_words_for_this", 3 * p.x)
    d.mistake("double", "always_close", double * 1.001)
    d.mistake("double", "sometimes_close", double * (1.001 if p.x < 3 else 1.5), if_apart=True)


def crashes_below_two(p, d):
    """A defect: a division that fails for a third of the draws (x from 1 to 5)."""
    d.step("double", 2 * p.x, "m")
    return 1 / max(0.0, p.x - 2)


def rejects_below_two(p, d):
    """The same data turned down by name: those draws are retried."""
    if p.x < 2:
        raise InvalidDraw("x below 2 gives no problem")
    d.step("double", 2 * p.x, "m")
