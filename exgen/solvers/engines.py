"""Worked derivations for balancing reciprocating engines (course text §2.3, Examples 2.6-2.9).

In-line engines follow the text's table: each crank's m·r·ω² at θ (primary) and m·r·ω²/n at
2θ (secondary), with its signed distance x from the centre plane for the couples. Radial and V
engines use direct and reverse cranks. Many engines cancel some of these exactly, so a known
slip is recorded only where it changes the answer a student would give.
"""
from __future__ import annotations

import math

from ..mechanics import engines as me
from .polygons import ZERO, closing_angle, components, magnitude_formula

PI = math.pi
#: Forces and couples that are exactly zero are graded within this (N, or N·m).
ZERO_TOL = 0.5


def record(d, step: str, mistake: str, value: float) -> None:
    """Record a mistake, named only where it changes the answer beyond the grading tolerance."""
    d.mistake(step, mistake, value, if_apart=True)


def _speed_and_ratio(d, p, radius_name: str):
    return d.step("n", p.l / d.value_of(radius_name), "", symbol="n", formula=rf"\frac{{@l}}{{@{radius_name}}}",
                  note="connecting rod to crank ratio")


SYMBOLS_INLINE = {"Fp": r"F_{\mathrm{p}}", "Cp": r"C_{\mathrm{p}}", "Fs": r"F_{\mathrm{s}}", "Cs": r"C_{\mathrm{s}}"}


def _clean(value: float) -> float:
    """cos 90° is 6e-17 in floating point; a table shows 0."""
    return 0.0 if abs(value) < 1e-12 else value


def _crank_polygons(d, p, names, positions, with_angles: bool = False, fires=None):
    """Primary and secondary forces and couples of in-line cranks at angle steps/params `names`, x the signed
    distances from the centre plane. Every crank carries the same m r ω², so the text's table is worked in
    units of it: Σ cos θ and Σ x cos θ (and sines, and 2θ for the secondary). With `with_angles`, each
    result is followed by the angle of the vector that balances it; `fires` labels each crank's turn."""
    d.step("F1", p.m * p.r * p.N ** 2, "N", symbol=r"m r \omega^2", formula=r"@m\,@r\,@N^2",
           note="each crank's primary force")
    n = _speed_and_ratio(d, p, "r")
    d.step("F2", d.value_of("F1") / n, "N", symbol=r"\frac{m r \omega^2}{n}", formula=r"\frac{@F1}{@n}",
           note="each crank's secondary force")
    results = {}
    for harmonic, label in ((1, "p"), (2, "s")):
        k = "2" if harmonic == 2 else ""
        angles = [harmonic * d.value_of(a) for a in names]
        sums = {"c": [_clean(math.cos(a)) for a in angles], "s": [_clean(math.sin(a)) for a in angles]}
        sums["xc"] = [x * c for x, c in zip(positions, sums["c"])]
        sums["xs"] = [x * c for x, c in zip(positions, sums["s"])]
        scale = {"c": len(names), "s": len(names), "xc": sum(map(abs, positions)), "xs": sum(map(abs, positions))}
        for key, symbol, unit in (("c", rf"\Sigma\cos {k}\theta", ""), ("s", rf"\Sigma\sin {k}\theta", ""),
                                  ("xc", rf"\Sigma x\cos {k}\theta", "m"), ("xs", rf"\Sigma x\sin {k}\theta", "m")):
            total = sum(sums[key])
            d.step(f"S{label}_{key}", 0.0 if abs(total) <= ZERO * scale[key] else total, unit, symbol=symbol)
        head = [("Cylinder",)] + ([("Fires",)] if fires and harmonic == 1 else []) + \
            ([("$x$", "m"), (r"$\theta$", "rad")] if harmonic == 1 else [(r"$2\theta$", "rad")])
        rows = [[str(i)] + ([fires[i - 1]] if fires and harmonic == 1 else []) +
                ([x, f"@{a}"] if harmonic == 1 else [2 * d.value_of(a)]) +
                [sums["c"][i - 1], sums["s"][i - 1], sums["xc"][i - 1], sums["xs"][i - 1]]
                for i, (x, a) in enumerate(zip(positions, names), start=1)]
        head += [(rf"$\cos {k}\theta$",), (rf"$\sin {k}\theta$",), (rf"$x\cos {k}\theta$", "m"),
                 (rf"$x\sin {k}\theta$", "m")]
        title = ("Primary: cranks at θ" if harmonic == 1 else "Secondary: cranks at 2θ") + \
            ", distances x from the centre plane"
        d.table(title, head, rows, total=["Σ"] + [None] * (len(head) - 5) + [f"@S{label}_{key}" for key in
                                                                            ("c", "s", "xc", "xs")])
        size = "F1" if harmonic == 1 else "F2"
        what = "primary" if harmonic == 1 else "secondary"
        for tag, x_key, y_key, kind in ((f"F{label}", "c", "s", "force"), (f"C{label}", "xc", "xs", "couple")):
            x_name, y_name = f"S{label}_{x_key}", f"S{label}_{y_key}"
            results[tag] = d.step(tag, d.value_of(size) * math.hypot(d.value_of(x_name), d.value_of(y_name)),
                                  "N" if kind == "force" else "N*m", symbol=SYMBOLS_INLINE[tag],
                                  formula=rf"@{size}\sqrt{{@{x_name}^2 + @{y_name}^2}}",
                                  note=f"the largest unbalanced {what} {kind}")
            if with_angles and results[tag] > 0:   # a resultant that vanishes has no direction to balance
                closing_angle(d, f"theta_{tag}", rf"\theta_{{{tag[0]}_{{\mathrm{{{tag[1]}}}}}}}", x_name, y_name)
    return results


def _inline_slips(d, p, angles, positions, results, angle_steps: bool):
    """Known slips: rpm as rad/s, n inverted, the secondary angle not doubled, couples about an end."""
    omega, rpm = p.N, p.N * 60 / (2 * PI)
    n = p.l / p.r
    for tag in ("Fp", "Cp", "Fs", "Cs"):
        record(d, tag, "rpm_as_rad_s", results[tag] * (rpm / omega) ** 2)
    for tag in ("Fs", "Cs"):
        record(d, tag, "n_inverted", results[tag] * n ** 2)
    undoubled = me.inline_unbalance(p.m, p.r, n, omega, angles, positions, 1)
    for tag, (size, angle) in zip(("Fs", "Cs"), undoubled):
        wrong = size / n
        if angle_steps:
            record(d, tag, "secondary_not_doubled", wrong)
        else:
            d.mistake(tag, "secondary_not_doubled", wrong)
            d.mistake(f"theta_{tag}", "secondary_not_doubled", angle + PI)


def inline_engine_unbalance(p, d):
    """Example 2.6: four cranks at given angles; the unbalanced forces and couples, and the direction of
    the couple that balances the primary (a real four with cranks 90° apart balances its forces)."""
    names = [f"theta{i}" for i in range(1, 5)]
    angles = [getattr(p, name) for name in names]
    positions = me.centred_positions(4, p.a)
    results = _crank_polygons(d, p, names, positions, with_angles=True)
    unit, n = d.value_of("F1"), p.l / p.r
    d.require(results["Cp"] >= 0.15 * 4 * unit * p.a, "the engine nearly balances its primary couple: no direction")
    for tag in ("Fp", "Cp", "Fs", "Cs"):
        if f"theta_{tag}" in d:
            d.mistake(f"theta_{tag}", "resultant_not_balance", d.value_of(f"theta_{tag}") + PI)
    _inline_slips(d, p, angles, positions, results, angle_steps=True)
    record(d, "Fp", "scalar_sum", 4 * unit)
    record(d, "Fs", "scalar_sum", 4 * unit / n)
    for harmonic, tag in ((1, "Cp"), (2, "Cs")):
        # about cylinder 1's plane instead of the centre plane (the same while the forces balance);
        # every distance taken as positive
        for mistake, where in (("couple_about_end_plane", [x - positions[0] for x in positions]),
                               ("sign_lost", [abs(x) for x in positions])):
            _, (size, angle) = me.inline_unbalance(p.m, p.r, n, p.N, angles, where, harmonic)
            d.mistake(tag, mistake, size, if_apart=True)
            if f"theta_{tag}" in d:
                d.mistake(f"theta_{tag}", mistake, angle + PI, if_apart=True)


#: A crank drawn closer than this to another (at θ, or at 2θ unless they coincide) would share its label.
CRANK_GAP = math.radians(20)
#: A resultant below this share of its terms' sum has a direction a drawing hardly shows (Example 2.6: 0.09).
DIRECTION_SHARE = 0.08


def _apart(angles) -> bool:
    """Every two directions coincide (a shared spoke) or lie at least CRANK_GAP apart."""
    from .polygons import angle_gap_deg

    gaps = [angle_gap_deg(a, b) for i, a in enumerate(angles) for b in angles[i + 1:]]
    return all(g < 0.5 or g >= math.degrees(CRANK_GAP) for g in gaps)


def inline_engine_directions(p, d):
    """Example 2.6 itself: four cranks at any angles, so every polygon is left open; the size of each
    unbalanced force and couple and the direction of the force or couple that balances it."""
    _directions(p, d, [f"theta{i}" for i in range(1, 5)])


def inline_engine_angles_read(p, d):
    """Example 2.6 with the crank angles read off the end view's degree scale (Figure 2.8 gives them as a
    drawing): each angle read is a step (an answer, carried forward into the polygons), then the same work."""
    for i in range(2, 5):
        theta = getattr(p, f"theta{i}")
        d.step(f"read{i}", theta, "rad", symbol=rf"\theta_{i}",
               note=f"crank {i}, read off the end view's scale from crank 1 in the direction of rotation")
        d.mistake(f"read{i}", "against_rotation", 2 * PI - theta, if_apart=True)
        if i > 2:
            d.mistake(f"read{i}", "angle_between_cranks", (theta - getattr(p, f"theta{i - 1}")) % (2 * PI),
                      if_apart=True)
    _directions(p, d, ["theta1", "read2", "read3", "read4"])


def _directions(p, d, names):
    """The polygons of four cranks at the angle params or steps `names` (see inline_engine_directions)."""
    angles = [d.value_of(name) for name in names]
    d.require(_apart(angles) and _apart([2 * a for a in angles]), "two cranks too close to tell apart on a drawing")
    positions = me.centred_positions(4, p.a)
    results = _crank_polygons(d, p, names, positions, with_angles=True)
    unit, n = d.value_of("F1"), p.l / p.r
    couple_arm = sum(map(abs, positions))
    for tag, scale in (("Fp", 4 * unit), ("Cp", couple_arm * unit), ("Fs", 4 * unit / n), ("Cs", couple_arm * unit / n)):
        d.require(results[tag] >= DIRECTION_SHARE * scale, "a polygon nearly closes: its direction means little")
        d.mistake(f"theta_{tag}", "resultant_not_balance", d.value_of(f"theta_{tag}") + PI)
    _inline_slips(d, p, angles, positions, results, angle_steps=False)
    for tag, size in (("Fp", 4 * unit), ("Fs", 4 * unit / n)):
        d.mistake(tag, "scalar_sum", size)
    for harmonic, tag in ((1, "Cp"), (2, "Cs")):
        # about cylinder 1's plane: a different couple, as the forces do not balance; every distance positive
        for mistake, where in (("couple_about_end_plane", [x - positions[0] for x in positions]),
                               ("sign_lost", [abs(x) for x in positions])):
            _, (size, angle) = me.inline_unbalance(p.m, p.r, n, p.N, angles, where, harmonic)
            d.mistake(tag, mistake, size)
            d.mistake(f"theta_{tag}", mistake, angle + PI)


def inline_engine_firing(p, d):
    """Example 2.7, Problem 2.4(a): crank angles from the firing order; is the engine balanced?"""
    order = me.parse_firing_order(p.firing)
    count, strokes = len(order), int(p.strokes)
    interval = d.step("delta", strokes * PI / count, "rad", symbol=r"\Delta\theta",
                      formula=rf"\frac{{{strokes * 180}^\circ}}{{{count}}}",
                      note=f"cranks of a {strokes}-stroke engine are {strokes * 180}°/N apart, in firing order")
    angles = me.crank_angles(order, strokes)
    for k, cylinder in enumerate(order):
        d.step(f"theta{cylinder}", k * interval, "rad", symbol=f"\\theta_{cylinder}",
               formula=rf"{k}\,@delta" if k > 1 else ("@delta" if k == 1 else ""),
               note=f"cylinder {cylinder} fires {_ordinal(k + 1)}")
    names = [f"theta{i}" for i in range(1, count + 1)]
    ordered = [angles[i] for i in range(1, count + 1)]
    positions = me.centred_positions(count, p.a)
    turn = {cylinder: _ordinal(k + 1) for k, cylinder in enumerate(order)}
    results = _crank_polygons(d, p, names, positions, fires=[turn[i] for i in range(1, count + 1)])
    balanced = all(results[tag] <= ZERO_TOL for tag in ("Fp", "Cp", "Fs", "Cs"))
    d.step("verdict", "balanced" if balanced else "not balanced", "", symbol=r"\text{engine}",
           note="balanced only if all four polygons close")
    _inline_slips(d, p, ordered, positions, results, angle_steps=True)
    other = me.crank_angles(order, 6 - strokes)
    wrong = me.inline_unbalance(p.m, p.r, p.l / p.r, p.N, [other[i] for i in range(1, count + 1)], positions, 1) + \
        me.inline_unbalance(p.m, p.r, p.l / p.r, p.N, [other[i] for i in range(1, count + 1)], positions, 2)
    for tag, (size, _) in zip(("Fp", "Cp", "Fs", "Cs"), wrong):
        record(d, tag, "interval_wrong", size)
    primary_only = results["Fp"] <= ZERO_TOL and results["Cp"] <= ZERO_TOL
    if primary_only and not balanced:
        d.mistake("verdict", "secondary_ignored", "balanced")


def _ordinal(k: int) -> str:
    return f"{k}{'st' if k == 1 else 'nd' if k == 2 else 'rd' if k == 3 else 'th'}"


def inline_primary_balance(p, d):
    """Problem 2.1: outer cranks A and D given; the masses and angles of B and C for primary balance,
    then the largest secondary force."""
    from .balancing import FAR_SIDE, FORCE, PLANE, _forces, _plane, _planes

    for tag, value, formula, note in (("A", -p.lAB, r"-@lAB", FAR_SIDE), ("D", p.lBC + p.lCD, r"@lBC + @lCD", "")):
        _plane(d, tag, "m_out", "r", value, formula, note)
    mx, my = components(d, "M", "M", [("mrlA", None), ("mrlD", "phi")], "kg*m^2", "moments about B (angles from A)",
                        table=("Cranks A and D, with B as the reference: moments", PLANE,
                               _planes("AD", ("m_out", "m_out"), ("r", "r"), (None, "phi")), "m r l"))
    mrl_c = d.step("mrlC", math.hypot(mx, my), "kg*m^2", symbol=r"m_C r\,l_C", formula=magnitude_formula("M_0", "M_90"),
                   note="C closes the moment polygon about B")
    m_c = d.step("mC", mrl_c / (p.r * p.lBC), "kg", symbol=r"m_C", formula=r"\frac{@mrlC}{@r\,@lBC}")
    theta_c = closing_angle(d, "theta_C", r"\theta_C", "M_0", "M_90")
    d.step("mrC", m_c * p.r, "kg*m", symbol=r"m_C r", formula=r"@mC\,@r")
    fx, fy = components(d, "F", "F", [("mrA", None), ("mrC", "theta_C"), ("mrD", "phi")], "kg*m", "primary forces",
                        table=("Primary forces, with C", FORCE, _forces("ACD", (None, "theta_C", "phi")), "m r"))
    m_b = d.step("mB", math.hypot(fx, fy) / p.r, "kg", symbol=r"m_B",
                 formula=rf"\frac{{{magnitude_formula('F_0', 'F_90')}}}{{@r}}", note="B closes the force polygon")
    theta_b = closing_angle(d, "theta_B", r"\theta_B", "F_0", "F_90")

    n = _speed_and_ratio(d, p, "r")
    k = d.step("k2", p.r * p.N ** 2 / n, "m/s^2", symbol=r"\frac{r \omega^2}{n}", formula=r"\frac{@r\,@N^2}{@n}")
    for tag, mass in (("A", "m_out"), ("B", "mB"), ("C", "mC"), ("D", "m_out")):
        d.step(f"S{tag}", d.value_of(mass) * k, "N", symbol=rf"m_{tag} \frac{{r \omega^2}}{{n}}", formula=rf"@{mass}\,@k2")
    angles = {"A": 0.0, "B": d.value_of("theta_B"), "C": d.value_of("theta_C"), "D": p.phi}
    sx, sy = components(d, "Fs", r"F_{\mathrm{s}}", [("SA", None), ("SB", "theta_B"), ("SC", "theta_C"), ("SD", "phi")],
                        "N", "secondary forces (cranks at 2θ)", 2,
                        table=("Secondary forces: cranks at 2θ", [("Crank",), ("$m$", "kg"), (r"$2\theta$", "rad"),
                                                                  (r"$m\,r\omega^2/n$", "N")],
                               [[tag, f"@{mass}", 2 * angles[tag], f"@S{tag}"] for tag, mass in
                                (("A", "m_out"), ("B", "mB"), ("C", "mC"), ("D", "m_out"))], r"m\,r\omega^2/n"))
    secondary = d.step("Fs", math.hypot(sx, sy), "N", symbol=r"F_{\mathrm{s}}", formula=magnitude_formula("Fs_0", "Fs_90"),
                       note="the largest secondary unbalanced force")
    d.require(secondary >= 0.1 * (2 * p.m_out + m_b + m_c) * k, "secondary forces nearly balance: no direction to ask")
    theta_s = closing_angle(d, "theta_Fs", r"\theta_{F_{\mathrm{s}}}", "Fs_0", "Fs_90")
    _primary_balance_slips(p, d, (m_c, theta_c), (m_b, theta_b), (secondary, theta_s), n)
    _secondary_peak(d, theta_s)


def _secondary_peak(d, balancing_angle: float) -> None:
    """The crank angle at which the secondary force peaks: its resultant stands half a turn from the
    balancing direction, at ψ in the 2θ polygon, and the force along the stroke is F_s cos(2θ + ψ)."""
    resultant = balancing_angle - PI
    peak = me.peak_crank_angle(resultant)
    turns = round((2 * peak + balancing_angle - PI) / PI)     # the half turns 2θ + ψ makes: 0 or 1
    d.step("theta_peak", peak, "rad", symbol=r"\theta_{\max}",
           formula=rf"\frac{{{180 * (turns + 1)}^\circ - @theta_Fs}}{{2}}",
           note=r"crank A's angle from its inner dead centre: the force along the stroke is $F_{\mathrm{s}} \cos(2\theta + \psi)$, "
                r"largest when $2\theta + \psi$ is a whole number of half turns, $\psi$ the resultant's direction")
    d.mistake("theta_peak", "secondary_not_halved", 2 * peak, if_apart=True)


def _primary_balance_slips(p, d, right_c, right_b, right_s, n):
    from ..mechanics import balancing as mb

    lost = mb.balancing_vector([(p.m_out * p.lAB, 0.0), (p.m_out * (p.lBC + p.lCD), p.phi)])
    wrong_c = (lost[0] / p.lBC, lost[1])
    wrong_b = mb.balancing_vector([(p.m_out, 0.0), (p.m_out, p.phi), wrong_c])
    for tag, right, wrong in (("C", right_c, wrong_c), ("B", right_b, wrong_b)):
        d.mistake(f"m{tag}", "sign_lost", wrong[0])
        d.mistake(f"theta_{tag}", "sign_lost", wrong[1])
        d.mistake(f"theta_{tag}", "resultant_not_balance", right[1] + PI)
    rows = [(p.m_out, 0.0), (right_b[0], right_b[1]), (right_c[0], right_c[1]), (p.m_out, p.phi)]
    k = p.r * p.N ** 2 / n
    single = me.polygon([m * k for m, _ in rows], [a for _, a in rows])  # 0 while the primary balances
    single = (single[0], single[1] + PI)  # its balancing direction
    d.mistake("Fs", "secondary_not_doubled", single[0])
    d.mistake("theta_Fs", "secondary_not_doubled", single[1])
    d.mistake("Fs", "n_inverted", right_s[0] * n ** 2)
    d.mistake("Fs", "rpm_as_rad_s", right_s[0] * (60 / (2 * PI)) ** 2)
    d.mistake("theta_Fs", "resultant_direction", right_s[1] + PI)


CRANKS = (
    ("P_dir", "Fc", "primary direct cranks", "Direct, $\\theta$", lambda a: 0.0),
    ("P_rev", "Fc", "primary reverse cranks", "Reverse, $2\\alpha - \\theta$", lambda a: 2 * a),
    ("S_dir", "Fc2", "secondary direct cranks", "2nd direct, $2\\theta - \\alpha$", lambda a: -a),
    ("S_rev", "Fc2", "secondary reverse cranks", "2nd reverse, $3\\alpha - 2\\theta$", lambda a: 3 * a),
)
SYMBOLS = {"P_dir": r"F_{\mathrm{p,d}}", "P_rev": r"F_{\mathrm{p,r}}", "S_dir": r"F_{\mathrm{s,d}}",
           "S_rev": r"F_{\mathrm{s,r}}"}


def _direct_reverse(p, d, alphas, factor_formulas):
    """The four resultants of direct and reverse cranks for cylinders on lines `alphas` (crank at θ = 0)."""
    r = d.step("r", p.S / 2, "m", formula=r"\frac{@S}{2}", note="the crank radius is half the stroke")
    n = _speed_and_ratio(d, p, "r")
    d.step("Fc", me.crank_force(p.m, r, p.N), "N", symbol=r"F_1",
           formula=r"\frac{@m}{2}\,@r\,@N^2", note="the force of each primary crank, direct or reverse: it carries m/2")
    d.step("Fc2", me.crank_force(p.m, r, p.N, n), "N", symbol=r"F_2",
           formula=r"\frac{@m\,(2\,@N)^2\,@r}{8\,@n}",
           note="each secondary crank carries m/2 on a crank r/4n long turning at 2ω")
    found = me.radial_cranks(alphas)
    sums = {key: found[long] for key, long in zip(("P_dir", "P_rev", "S_dir", "S_rev"),
                                                   ("primary_direct", "primary_reverse", "secondary_direct",
                                                    "secondary_reverse"))}
    d.table(r"Crank positions with the crank on the reference line, $\theta = 0$; cylinder $i$'s line of stroke "
            r"is at $\alpha_i$", [("Cylinder",), (r"$\alpha_i$", "rad")] + [(head, "rad") for *_, head, _ in CRANKS],
            [[str(i), a] + [place(a) % (2 * math.pi) for *_, place in CRANKS] for i, a in enumerate(alphas, start=1)])
    out = {}
    for key, crank, where, _, place in CRANKS:
        d.step(f"k_{key}", sums[key][0], "", symbol=rf"k_{{\mathrm{{{key.replace('_', ',').lower()}}}}}",
               formula=factor_formulas.get(key, ""),
               note=f"the length of the resultant of the {where}, in cranks")
        out[key] = d.step(key, sums[key][0] * d.value_of(crank), "N", symbol=SYMBOLS[key],
                          formula=rf"@k_{key}\,@{crank}")
    return out, sums, r, n


def _crank_slips(p, d, out, sums, r, n, keys):
    rpm_factor = (60 / (2 * PI)) ** 2
    for key in keys:
        right = out[key]
        record(d, key, "rpm_as_rad_s", right * rpm_factor)
        record(d, key, "stroke_for_radius", right * (2 if key.startswith("P") else 4))
        if key.startswith("S"):
            record(d, key, "n_inverted", right * n ** 2)
            record(d, key, "secondary_speed_not_doubled", right / 4)


def radial_engine(p, d):
    """Example 2.8, Problems 2.3 and 2.4(b): a radial engine by direct and reverse cranks."""
    count = int(p.ncyl)
    alphas = me.radial_cylinder_angles(count)
    out, sums, r, n = _direct_reverse(p, d, alphas, {"P_dir": r"@ncyl"})
    d.step("Bb", count * p.m * r / 2, "kg*m", symbol=r"B\,b", formula=r"\frac{@ncyl\,@m\,@r}{2}",
           note="a rotating mass opposite the crank balances the direct cranks, which turn with it")
    secondary = d.step("S_max", out["S_dir"] + out["S_rev"], "N", symbol=r"F_{\mathrm{s,max}}",
                       formula=r"@S_dir + @S_rev", note="largest when the direct and reverse resultants line up")
    d.step("sec_verdict", "balanced" if secondary <= ZERO_TOL else "not balanced", "",
           symbol=r"\text{secondary}", note="balanced only if both secondary polygons close")
    rpm_factor = (60 / (2 * PI)) ** 2
    for key in ("P_dir", "S_max"):
        right = d.value_of(key)
        record(d, key, "rpm_as_rad_s", right * rpm_factor)
        record(d, key, "stroke_for_radius", right * (2 if key == "P_dir" else 4))
    d.mistake("Bb", "stroke_for_radius", 2 * d.value_of("Bb"))
    record(d, "S_max", "n_inverted", secondary * n ** 2)
    record(d, "S_max", "secondary_speed_not_doubled", secondary / 4)
    d.mistake("sec_verdict", "opposite", "not balanced" if secondary <= ZERO_TOL else "balanced")
    _primary_equation(d, count)


def _primary_equation(d, count: int) -> None:
    """Problem 2.3's proof as a formula: the N direct cranks, each m/2 at r turning with the crank, all
    stand at the crank and add to (N/2) m r ω²; the reverse cranks close (N ≥ 3)."""
    from ..answertypes.symbolic import Expression

    def force(per_cylinder: str) -> Expression:
        return Expression.parse(f"{count}*{per_cylinder}*r*omega^2", ("m", "r", "omega"))

    d.step("P_expr", force("m/2"), symbol=r"F_P(m, r, \omega)",
           note=rf"the {count} direct cranks, each $m/2$ at $r$, stand together at the crank: $F_P = \frac{{{count}}}{{2}} m r\omega^2$")
    d.mistake("P_expr", "full_mass_on_direct_crank", force("m"))


def v_engine(p, d):
    """Example 2.9: a two-cylinder V engine on one crank, by direct and reverse cranks."""
    d.step("beta", p.V / 2, "rad", symbol=r"\beta", formula=r"\frac{@V}{2}", symbolic=False,
           note="each line of stroke is β from the centre line")
    formulas = {"P_rev": r"2\left|\cos 2\,@beta\right|", "S_dir": r"2\left|\cos @beta\right|",
                "S_rev": r"2\left|\cos 3\,@beta\right|"}
    out, sums, r, n = _direct_reverse(p, d, me.v_cylinder_angles(p.V), formulas)
    _crank_slips(p, d, out, sums, r, n, tuple(out))
    half = p.V / 2
    record(d, "P_rev", "angle_not_doubled", 2 * abs(math.cos(half)) * d.value_of("Fc"))
    for a, b in (("P_dir", "P_rev"), ("S_dir", "S_rev")):
        record(d, a, "direct_reverse_swapped", out[b])
        record(d, b, "direct_reverse_swapped", out[a])
