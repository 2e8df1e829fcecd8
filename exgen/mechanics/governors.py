"""Centrifugal governors (course text chapter 4): plain functions over SI floats.

Lengths in m, angles in radians from the vertical, speeds in rad/s, masses in kg, forces in N;
g = 9.81 m/s² as in the text.

Watt, Porter and Proell governors are worked as the text does, by moments about I, the
instantaneous centre of the lower arm (eqs 4.1-4.3): I lies where the upper arm's line meets
the horizontal through the sleeve pivot Y, Z is the point of that horizontal below the ball
X, and for each ball

    F · XZ = m g · IZ + (M g ± f)/2 · IY,     F = m ω² r,

with the friction f adding to the sleeve load when the sleeve rises and relieving it when it
falls (eq 4.6). The same moments hold for unequal arms, pivots off the axis, and the Proell
governor's ball on an extension of the lower arm.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

G = 9.81


@dataclass(frozen=True)
class Linkage:
    """A Porter-type linkage: upper arms from pivots `upper_offset` off the axis, lower arms to
    sleeve pivots `lower_offset` off it; the arms meet at the joint (the ball of a Porter governor)."""

    upper: float
    lower: float
    upper_offset: float = 0.0
    lower_offset: float = 0.0

    @property
    def radius_range(self) -> tuple[float, float]:
        """Joint radii the arms can take, with both arms hanging below their pivots."""
        return (max(self.upper_offset, self.lower_offset),
                min(self.upper_offset + self.upper, self.lower_offset + self.lower))


@dataclass(frozen=True)
class Pose:
    """The linkage with its joint at radius `r`."""

    r: float
    alpha: float     # upper arm to the vertical
    beta: float      # lower arm to the vertical
    h_upper: float   # joint below the upper pivots
    h_lower: float   # joint above the sleeve pivots

    @property
    def depth(self) -> float:
        """Sleeve pivots below the upper pivots: the sleeve rises as this shrinks."""
        return self.h_upper + self.h_lower


def pose(linkage: Linkage, r: float) -> Pose:
    """The linkage with its joint at radius r; ValueError if the arms cannot reach it."""
    low, high = linkage.radius_range
    if not low < r < high:
        raise ValueError(f"the arms cannot put the joint at a radius of {r:g} m "
                         f"(between {low:g} m and {high:g} m they can)")
    s_up = (r - linkage.upper_offset) / linkage.upper
    s_low = (r - linkage.lower_offset) / linkage.lower
    return Pose(r, math.asin(s_up), math.asin(s_low),
                linkage.upper * math.sqrt(1.0 - s_up ** 2), linkage.lower * math.sqrt(1.0 - s_low ** 2))


def pose_at_angle(linkage: Linkage, alpha: float) -> Pose:
    """The linkage with its upper arms at α to the vertical."""
    return pose(linkage, linkage.upper_offset + linkage.upper * math.sin(alpha))


def pose_at_depth(linkage: Linkage, depth: float) -> Pose:
    """The linkage with its sleeve pivots `depth` below the upper pivots (found by bisection:
    the depth falls steadily as the joint moves out)."""
    low, high = linkage.radius_range
    if not pose(linkage, high - 1e-12 * high).depth < depth < pose(linkage, low + 1e-12 * max(high, 1.0)).depth:
        raise ValueError(f"the sleeve cannot sit {depth:g} m below the upper pivots")
    for _ in range(200):
        mid = 0.5 * (low + high)
        if mid in (low, high):
            break
        if pose(linkage, mid).depth > depth:
            low = mid
        else:
            high = mid
    return pose(linkage, 0.5 * (low + high))


def joint_radius_for_ball(linkage: Linkage, extension: float, upright_radius: float, ball_radius: float) -> float:
    """The joint radius r at which a Proell ball, on an extension fixed to the lower arm and upright
    when the joint was at `upright_radius`, turns at `ball_radius`: r + e sin(β(r) − β(r₀)) = r_b,
    found by bisection (the ball's radius grows steadily with the joint's)."""
    upright = pose(linkage, upright_radius).beta

    def ball(r: float) -> float:
        return r + extension * math.sin(pose(linkage, r).beta - upright)

    low, high = upright_radius, min(ball_radius, linkage.radius_range[1] * (1 - 1e-12))
    if not ball(low) <= ball_radius <= ball(high):
        raise ValueError(f"no joint radius puts the ball at {ball_radius:g} m")
    for _ in range(200):
        mid = 0.5 * (low + high)
        if mid in (low, high):
            break
        if ball(mid) < ball_radius:
            low = mid
        else:
            high = mid
    return 0.5 * (low + high)


@dataclass(frozen=True)
class LeverArms:
    """Distances for moments about I: ball X, point Z below it on the sleeve-pivot line, sleeve pivot Y."""

    ball_radius: float
    XZ: float
    IZ: float
    IY: float
    I_radius: float


def lever_arms(linkage: Linkage, at: Pose, extension: float = 0.0, extension_tilt: float = 0.0) -> LeverArms:
    """Moment arms about the lower arm's instantaneous centre I.

    A Porter ball sits at the joint; a Proell ball on an extension of length `extension`
    fixed to the lower arm, turned `extension_tilt` outward from the vertical (zero where the
    extension was set parallel to the axis).
    """
    if at.h_upper <= 0:
        raise ValueError("an upper arm lying flat has no instantaneous centre below it")
    i_radius = linkage.upper_offset + (at.r - linkage.upper_offset) * at.depth / at.h_upper
    ball_radius = at.r + extension * math.sin(extension_tilt)
    height = at.h_lower + extension * math.cos(extension_tilt)
    return LeverArms(ball_radius, height, i_radius - ball_radius, i_radius - linkage.lower_offset, i_radius)


def centrifugal_force(ball_mass: float, sleeve_force: float, arms: LeverArms) -> float:
    """F from F·XZ = m g·IZ + (sleeve force/2)·IY; the sleeve force is M g, M g + f or M g − f."""
    return (ball_mass * G * arms.IZ + sleeve_force / 2.0 * arms.IY) / arms.XZ


def equilibrium_speed(ball_mass: float, sleeve_force: float, arms: LeverArms) -> float:
    """ω at which the balls hold this pose: m ω² r = F."""
    force = centrifugal_force(ball_mass, sleeve_force, arms)
    if force <= 0:
        raise ValueError("no speed holds this pose: the sleeve force pulls the balls out by itself")
    return math.sqrt(force / (ball_mass * arms.ball_radius))


def sleeve_mass(force: float, ball_mass: float, arms: LeverArms) -> float:
    """The central load M that a centrifugal force F holds in this pose (friction neglected)."""
    return 2.0 * (force * arms.XZ - ball_mass * G * arms.IZ) / (G * arms.IY)


def sleeve_friction(force: float, ball_mass: float, sleeve_load: float, arms: LeverArms) -> float:
    """The friction f that makes F the force at which the sleeve starts to rise: F·XZ = m g·IZ + (M g + f)/2·IY."""
    return 2.0 * (force * arms.XZ - ball_mass * G * arms.IZ) / arms.IY - sleeve_load * G


def upper_arm_tension(ball_mass: float, sleeve_force: float, alpha: float) -> float:
    """Tension in an upper arm at α to the vertical: its vertical part carries the ball's weight
    and half the sleeve force, T cos α = m g + (M g)/2 (Example 4.2)."""
    return (ball_mass * G + sleeve_force / 2.0) / math.cos(alpha)


def watt_height(omega: float) -> float:
    """Height of a Watt governor (arms pivoted on the axis): h = g / ω² (eq 4.1)."""
    return G / omega ** 2


def sensitivity(mean_speed: float, highest: float, lowest: float) -> float:
    """ω / (ω₁ − ω₂) (eq 4.5): the larger, the smaller the speed change that moves the sleeve."""
    return mean_speed / (highest - lowest)


# ---- spring-loaded governors ---------------------------------------------------------------


def hartnell_sleeve_force(force: float, ball_arm: float, sleeve_arm: float) -> float:
    """Total sleeve force (M g + spring ± friction) two balls hold through bell cranks: 2 F a / b (eq 4.4)."""
    return 2.0 * force * ball_arm / sleeve_arm


def bell_crank_angle(r: float, r_vertical: float, ball_arm: float) -> float:
    """Turn of the bell crank from the ball arm's vertical position, at ball radius r."""
    return math.asin((r - r_vertical) / ball_arm)


def sleeve_lift(r1: float, r2: float, ball_arm: float, sleeve_arm: float) -> float:
    """Sleeve travel while the balls move from r₁ to r₂ (small angles): (r₂ − r₁) b / a."""
    return (r2 - r1) * sleeve_arm / ball_arm


def controlling_line(f1: float, r1: float, f2: float, r2: float) -> tuple[float, float]:
    """(slope, intercept) of a controlling force F = slope·r + intercept through two points (eq 4.7)."""
    slope = (f2 - f1) / (r2 - r1)
    return slope, f1 - slope * r1


def radius_at_speed(ball_mass: float, omega: float, slope: float, intercept: float) -> float:
    """Where m ω² r meets the controlling force line slope·r + intercept."""
    return intercept / (ball_mass * omega ** 2 - slope)


def isochronous_speed(ball_mass: float, slope: float) -> float:
    """The one speed of a governor whose controlling force passes through the origin: ω² = slope/m."""
    return math.sqrt(slope / ball_mass)


STABLE, ISOCHRONOUS, UNSTABLE = "stable", "isochronous", "unstable"


def stability(intercept: float, scale: float = 1.0) -> str:
    """Stable if the controlling-force line cuts the force axis below the origin (F/r rises with r),
    isochronous through it, unstable above it (§4.8)."""
    if abs(intercept) <= 1e-9 * max(abs(scale), 1.0):
        return ISOCHRONOUS
    return STABLE if intercept < 0 else UNSTABLE
