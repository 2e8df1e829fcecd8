"""Worked derivation for the mobility of a drawn mechanism (course text §7.3-7.4, eq 7.1).

The student counts from the kinematic diagram: L links with the ground (link 1), J1 lower pairs
(a pin where k links meet is k - 1 joints; a slider is one more) and J2 higher pairs (a pin in a
slot, a gear mesh), then M = 3(L - 1) - 2 J1 - J2.
"""
from __future__ import annotations

from ..mechanics.mechanism_catalogue import build, misleading, parallel_cranks
from ..mechanics.mobility import instantaneous_mobility, mobility as kutzbach


def mechanism_of(p):
    return build(str(p.base), (str(p.add1), str(p.add2), str(p.add3)), str(p.mirror) == "yes")


def _plural(count: int, word: str) -> str:
    return f"{count} {word}" + ("" if count == 1 else "s")


def mobility(p, d):
    """Count links and joints from the diagram; M by Kutzbach's form of Gruebler's equation."""
    mech = mechanism_of(p)
    d.require(-1 <= mech.mobility <= 3, "a mobility the course never asks about")
    d.require(not misleading(mech), "loose links on a locked part: Gruebler's count would mislead")
    d.require(mech.link_count <= 11, "too many links to count comfortably")
    pins = mech.pins()
    shared = {point: k for point, k in pins.items() if k >= 2}
    links = d.step("L", mech.link_count, "", symbol="L",
                   note=f"the ground (link 1) and {_plural(len(mech.links), 'moving link')}")
    pin_note = f"{_plural(len(pins), 'pin')}"
    if shared:
        pin_note += (f", {len(shared)} of them joining three or more links: "
                     + ", ".join(f"{k} joints where {k + 1} links meet" for k in shared.values()))
    if mech.sliders:
        pin_note += f"; {_plural(len(mech.sliders), 'sliding pair')}"
    j1 = d.step("J1", mech.lower_pairs, "", symbol="J_1", note=pin_note)
    higher = []
    if mech.slots:
        higher.append(_plural(len(mech.slots), "pin in a slot"))
    if mech.meshes:
        higher.append(_plural(len(mech.meshes), "gear mesh"))
    j2 = d.step("J2", mech.higher_pairs, "", symbol="J_2", note=" and ".join(higher) or "no higher pairs")
    m = d.step("M", kutzbach(links, j1, j2), "", symbol="M", formula=r"3(@L - 1) - 2\,@J1 - @J2",
               note="eq 7.1")
    kind = "mechanism" if m >= 1 else "structure"
    d.step("kind", kind, "", symbol=r"\text{verdict}",
           note=(f"it moves, and needs {_plural(int(m), 'input')} to control it" if m >= 1
                 else "it cannot move: M = 0 is a structure, M < 0 one with more members than it needs"))
    _mistakes(d, mech, links, j1, j2)


def _mistakes(d, mech, links, j1, j2) -> None:
    d.mistake("L", "ground_not_counted", links - 1)
    d.mistake("M", "ground_not_counted", kutzbach(links - 1, j1, j2))
    d.mistake("M", "without_minus_one", 3 * links - 2 * j1 - j2)
    if mech.shared_extra:
        d.mistake("J1", "shared_joint_counted_once", j1 - mech.shared_extra)
        d.mistake("M", "shared_joint_counted_once", kutzbach(links, j1 - mech.shared_extra, j2))
    if mech.higher_pairs:
        d.mistake("J1", "higher_pair_as_lower", j1 + j2)
        d.mistake("J2", "higher_pair_as_lower", 0)
        d.mistake("M", "higher_pair_as_lower", kutzbach(links, j1 + j2, 0))
    if mech.sliders:
        d.mistake("J1", "slider_not_counted", j1 - len(mech.sliders))
        d.mistake("M", "slider_not_counted", kutzbach(links, j1 - len(mech.sliders), j2))


TRUE_REASON = {
    "four-bar": "a parallelogram four-bar: the count is right, one input drives it",
    "three cranks": "crank 4 is parallel and equal to the others, so it moves exactly as the coupler "
                    "already carries it: its two joints take away no freedom, and the linkage still moves",
    "four cranks": "the extra cranks are parallel and equal to the others, so each moves exactly as the coupler "
                   "already carries it: their joints take away no freedom, and the linkage still moves",
    "three cranks, one askew": "crank 4 is not parallel to the others: its pin on the coupler must go round a "
                               "circle about a point other than crank 4's pivot, so nothing can move at all",
}


def mobility_exceptions(p, d):
    """§7.4: Gruebler's count of a parallelogram linkage with extra cranks, then the mobility its geometry gives
    (seize-and-fix), which the count cannot see."""
    case = str(p.case)
    mech = parallel_cranks(case, p.theta, str(p.mirror) == "yes")
    links = d.step("L", mech.link_count, "", symbol="L",
                   note=f"the ground (link 1), the coupler and {_plural(len(mech.links) - 1, 'crank')}")
    j1 = d.step("J1", mech.lower_pairs, "", symbol="J_1", note=f"{_plural(len(mech.pins()), 'pin')}, no sliders")
    m = d.step("M", kutzbach(links, j1, 0), "", symbol="M", formula=r"3(@L - 1) - 2\,@J1 - 0",
               note="eq 7.1, with no higher pairs")
    true = d.step("M_true", instantaneous_mobility(mech), "", symbol=r"M_{\mathrm{true}}", note=TRUE_REASON[case])
    kind = "mechanism" if true >= 1 else "structure"
    d.step("kind", kind, "", symbol=r"\text{verdict}",
           note="it moves: one input drives it" if true >= 1 else "nothing can move: a structure")
    d.mistake("L", "ground_not_counted", links - 1)
    d.mistake("M", "ground_not_counted", kutzbach(links - 1, j1, 0))
    d.mistake("M", "without_minus_one", 3 * links - 2 * j1)
    if true != m:
        d.mistake("M_true", "gruebler_trusted", m)
    gruebler_kind = "mechanism" if m >= 1 else "structure"
    if gruebler_kind != kind:
        d.mistake("kind", "gruebler_trusted", gruebler_kind)
