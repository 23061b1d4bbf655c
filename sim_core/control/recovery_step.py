"""A recovery step and the staggered stance held after it (a landing's missing basin: docs/vault.md).

When a landing's capture point (the COM's place plus its speed times sqrt(h / g), ahead of the middle of
the supporting feet) leaves what the ankles can hold, one foot steps to where it goes, forward or back
(``RecoveryStep``): the swing leg lifts (knee flexed) and reaches (the thigh aimed in the world frame, as
the leap's landing aims it, at the capture point), while the stance leg's ankle servos the capture point
and its hip holds the pelvis's lean. Once the swing foot is down, ``StaggeredStance`` holds the stance as
it is - the feet fore and aft apart, not side by side: the ankles servo the capture point over the
middle of the whole polygon (its length is the step's), the knees rise to a set bend, the hips hold the
pelvis's lean (plus a timeline of it: the bow) and sideways the ankles' roll with the hips' abduction keep
the COM between the feet. Neither knows the skill that uses it: the vault's landing uses them (issue 31),
and any landing whose impact leaves the capture point outside the feet can.
"""
from __future__ import annotations

import math

import numpy as np

from ..ballistics import GRAVITY
from .balance import CROUCH_TABLE_ROWS as CROUCH_ROWS, LegGeometry, standing_hip_height
from .behaviour import Behaviour, ControlContext
from .crouch import CrouchTable
from .leap import UP
from .measure import SupportGeometry, pitch_of, roll_of
from .servo import hermite_scalar
from ..schema import Parameter, Schema

SIDES = "rl"


class StanceMeasure:
    """What both behaviours read: the heading frame (the feet's yaw), the supporting points, and the
    capture point ahead of and the COM left of the middle of the support."""

    def __init__(self, ctx: ControlContext, min_height: float):
        body = ctx.actor.body_id
        self.ctx = ctx
        self.pelvis = body("PELVIS")
        self.feet = [body("FOOTR"), body("FOOTL")]
        self.hips = [body("ULEGR"), body("ULEGL")]
        self.support = SupportGeometry(ctx.model, prefix=ctx.actor.prefix)
        self.min_height = min_height
        s = ctx.servos
        self.joints = [{k: s.index[f"{j}_{side}_{a}"] for k, (j, a) in
                        {"hip": ("hip", "y"), "hip_x": ("hip", "x"), "hip_z": ("hip", "z"), "knee": ("knee", "y"),
                         "ankle": ("ankle", "y"), "ankle_x": ("ankle", "x")}.items()} for side in SIDES]

    def heading(self) -> tuple[float, float]:
        """The feet's mean heading (the pelvis's, pitched and rolled by a landing, is not a heading)."""
        d = self.ctx.data
        right, left = d.xmat[self.feet[0]], d.xmat[self.feet[1]]
        yaw = math.atan2(float(right[3] + left[3]), float(right[0] + left[0]))
        return math.cos(yaw), math.sin(yaw)

    def along(self, v) -> tuple[float, float]:
        """A world vector's components ahead and to the left in the heading frame."""
        c, s = self.heading()
        return c * float(v[0]) + s * float(v[1]), -s * float(v[0]) + c * float(v[1])

    def capture(self, points: np.ndarray | None = None) -> tuple[float, float, float, float]:
        """The capture point ahead of the support's middle, the COM left of it, the COM's sideways speed,
        and the COM's height above the lowest supporting point (at least ``min_height``)."""
        d = self.ctx.data
        points = self.support.supporting_points(d) if points is None else points
        com, v = d.subtree_com[self.pelvis], d.subtree_linvel[self.pelvis]
        c, s = self.heading()
        px, py = c * points[:, 0] + s * points[:, 1], -s * points[:, 0] + c * points[:, 1]
        cx, cy = self.along(com)
        vx, vy = self.along(v)
        height = max(float(com[2]) - float(points[:, 2].min()), self.min_height)
        ahead = cx - 0.5 * float(px.min() + px.max()) + vx * math.sqrt(height / GRAVITY)
        return ahead, cy - 0.5 * float(py.min() + py.max()), vy, height

    def foot_touching(self, k: int) -> bool:
        """Foot k (0 right, 1 left) has a site on (or in) what is under it."""
        heights = self.support.heights(self.ctx.data)
        mask = self.support.right if k == 0 else self.support.left
        return bool((heights[mask] < self.support.contact_height).any())

    def foot_height(self, k: int) -> float:
        heights = self.support.heights(self.ctx.data)
        return float(heights[self.support.right if k == 0 else self.support.left].min())

    def outside(self, margin: float) -> float:
        """+1 (-1) when the capture point is within ``margin`` of the support's front (back) edge or past it,
        else 0: where a step is due."""
        points = self.support.supporting_points(self.ctx.data)
        ahead, _, _, _ = self.capture(points)
        c, s = self.heading()
        px = c * points[:, 0] + s * points[:, 1]
        half = 0.5 * float(px.max() - px.min())
        return 1.0 if ahead > half - margin else -1.0 if ahead < margin - half else 0.0

    def pelvis_lean(self) -> float:
        return pitch_of(self.ctx.data.xmat[self.pelvis], UP)

    def aim(self, k: int, ankle_x: float, knee: float, leg: LegGeometry) -> float:
        """Hip k's pitch target that puts its ankle at ``ankle_x`` (along the heading, world) with this knee
        bend: the thigh aimed in the world frame (as the leap's landing aims it), less the pelvis's lean."""
        hip_x = self.along(self.ctx.data.xpos[self.hips[k]])[0]
        return leg.thigh_pitch_for(ankle_x - hip_x, knee) - self.pelvis_lean()

    def flat_foot(self, targets: np.ndarray, angles: np.ndarray, k: int, ankle: float, roll: float) -> None:
        """Foot k's ankle targets: flat on the ground, offset by ``ankle`` (pitch) and ``roll``."""
        f = self.ctx.data.xmat[self.feet[k]]
        j = self.joints[k]
        targets[j["ankle"]] = angles[j["ankle"]] - pitch_of(f, UP) + ankle
        targets[j["ankle_x"]] = angles[j["ankle_x"]] - roll_of(f, UP) - roll


class RecoveryStep(Behaviour):
    """One step of one foot to where the capture point goes (forward or back): the foot that carries less
    (``unloaded``), else the foot behind for a forward step, the one ahead for a backward one. The swing leg lifts (``lift_knee`` for ``lift_time``),
    then reaches (``reach_knee``), its thigh aimed every tick so that the sole lands past the capture point
    by ``spread`` of its distance from the stance foot and ``beyond`` (from ``min_step`` to ``max_step`` ahead
    of the stance foot) (at most ``max_step`` from the stance foot); the stance ankle servos the capture point
    (``stance_kp``, within ``ankle_max``), the hips hold the pelvis's lean as the step began; the arms go to ``arm`` (out of the way of the ground). Finished when
    the swing foot is down after ``min_swing`` (or at ``max_swing``)."""

    schema = Schema(
        Parameter("unloaded", "m", 0.01, 0.0, 0.2,
                  "the foot whose lowest point stands this much higher than the other's swings (it carries less; else "
                  "the foot behind for a forward step, the one ahead for a backward one)"),
        Parameter("wait_vz", "m/s", 5.0, 0.0, 5.0,
                  "the lift waits while the COM rises faster than this (a rebound off a soft ground: the stance foot "
                  "would leave it too), the legs held, the hips holding the lean"),
        Parameter("lift_knee", "rad", 1.6, 0.3, 2.4, "the swing knee's flexion that lifts the foot out of the ground"),
        Parameter("lift_time", "s", 0.12, 0.02, 0.5, "the lift lasts this long, then the reach"),
        Parameter("reach_knee", "rad", 0.7, 0.0, 1.6, "the swing knee's flexion while the foot reaches for its goal"),
        Parameter("swing_gain", "1", 2.0, 1.0, 10.0, "gain factor of the swing leg's hip and knee servos"),
        Parameter("spread", "1", 0.0, 0.0, 1.0,
                  "the sole's centre lands past the capture point by this share of the capture point's distance from "
                  "the stance sole's centre (1: the capture point in the middle of the new stance) ..."),
        Parameter("beyond", "m", 0.0, -0.3, 0.3, "... and this far further"),
        Parameter("min_step", "m", 0.0, 0.0, 0.6, "... at least this far from the stance foot along the heading ..."),
        Parameter("max_step", "m", 0.45, 0.05, 0.9, "... and at most this far"),
        Parameter("width", "m", 0.16, 0.0, 0.5,
                  "sideways the swing foot lands half this beyond the COM's sideways capture point, on its own side"),
        Parameter("side_kp", "rad/m", 4.0, -20.0, 20.0,
                  "the stance ankle's roll per metre of the COM left of the stance foot's middle ..."),
        Parameter("side_kv", "rad s/m", 4.0, -10.0, 10.0, "... and per m/s of its leftward speed"),
        Parameter("side_hip", "1", 1.0, 0.0, 2.0, "the stance hip's abduction per radian of that roll command"),
        Parameter("arm", "rad", 1.5, -1.0, 3.14, "both arms' shoulder flexion goes to this in the step ..."),
        Parameter("arm_time", "s", 0.2, 0.02, 1.0, "... in this time (Hermite)"),
        Parameter("stance_kp", "rad/m", 8.0, 0.0, 20.0, "the stance ankle's offset per metre of the capture point ahead of the foot"),
        Parameter("ankle_max", "rad", 0.3, 0.0, 0.6, "the stance ankle's offset at most this either way"),
        Parameter("min_swing", "s", 0.15, 0.0, 1.0, "the swing foot counts as down only after this"),
        Parameter("max_swing", "s", 0.6, 0.1, 2.0, "the step ends after this, the foot down or not"),
        Parameter("min_height", "m", 0.1, 0.05, 1.0, "the capture point's COM height is at least this (a guard)"),
    )

    def __init__(self, params, ctx: ControlContext, direction: float):
        """``direction``: +1 a forward step, -1 a backward one (the sign of the capture point's error)."""
        super().__init__(params, ctx)
        self.direction = 1.0 if direction >= 0.0 else -1.0
        self.measure = StanceMeasure(ctx, self.params["min_height"])
        self.leg = LegGeometry(ctx.character, "R")
        sites = [c["pos"] for c in ctx.character.body("FOOTR")["contacts"] + ctx.character.body("TOER")["contacts"]]
        self.sole_centre = 0.5 * (max(q[0] for q in sites) + min(q[0] for q in sites)) - ctx.character.joint_position("FOOTR")[0]
        self.down_at = self.lift_at = None
        self.hip_x_range = [tuple(ctx.model.jnt_range[ctx.actor.joint_id(f"hip_{side}_x")]) for side in SIDES]

    def start(self, t: float) -> None:
        m, s, d = self.measure, self.ctx.servos, self.ctx.data
        self.t0 = t
        s.offset[:] = 0.0
        feet_x = [m.along(d.xpos[f])[0] for f in m.feet]
        # forward: the foot behind swings; back: the foot ahead - unless one foot stands less deep in the
        # ground by ``unloaded`` (it carries less): that one
        sunk = [m.foot_height(k) for k in (0, 1)]
        if abs(sunk[0] - sunk[1]) >= self.params["unloaded"]:
            self.swing = int(np.argmax(sunk))
        else:
            self.swing = int(np.argmin(feet_x)) if self.direction > 0 else int(np.argmax(feet_x))
        self.stance = 1 - self.swing
        self.base = s.angles().copy()
        self.lean = m.pelvis_lean()
        self.stance_x = m.along(d.xpos[m.feet[self.stance]])[0]
        j = m.joints[self.swing]
        legs = np.array([j["hip"], j["knee"]])
        s.set_gains(legs, s.default_kp[legs] * self.params["swing_gain"], s.default_kv[legs] * self.params["swing_gain"])
        self.shoulders = s.indices(["shoulder_r_z", "shoulder_l_z"])
        self.arms_from = self.base[self.shoulders].copy()
        self.event(t, "step_forward" if self.direction > 0 else "step_back")

    def goal(self) -> float:
        """Where the swing sole's centre goes, ahead of the stance foot's ankle (heading frame)."""
        m, d, p = self.measure, self.ctx.data, self.params
        stance_points = m.support.points(d)[m.support.right if self.stance == 0 else m.support.left]
        ahead, _, _, _ = m.capture(stance_points)
        c, s = m.heading()
        px = c * stance_points[:, 0] + s * stance_points[:, 1]
        middle = 0.5 * float(px.min() + px.max())
        stance_x = m.along(d.xpos[m.feet[self.stance]])[0]
        goal = middle + ahead * (1.0 + p["spread"]) + self.direction * p["beyond"] - stance_x
        if goal * self.direction < p["min_step"]:
            goal = self.direction * p["min_step"]
        return min(max(goal, -p["max_step"]), p["max_step"]), ahead

    def sideways(self, height: float) -> float:
        """The swing hip's abduction that puts its foot half ``width`` beyond the COM's sideways capture point
        on its own side (as the leap's landing aims the feet sideways: the leg's angle from the measured hip,
        less the pelvis's roll); + swings the foot to the left."""
        m, d = self.measure, self.ctx.data
        _, com_left = m.along(d.subtree_com[m.pelvis])
        _, speed_left = m.along(d.subtree_linvel[m.pelvis])
        side = 1.0 if self.swing == 1 else -1.0
        wanted = com_left + speed_left * math.sqrt(height / GRAVITY) + side * 0.5 * self.params["width"]
        hip, foot = d.xpos[m.hips[self.swing]], d.xpos[m.feet[self.swing]]
        length = float(np.linalg.norm(hip - foot))
        reach = math.asin(max(-1.0, min(1.0, (wanted - m.along(hip)[1]) / length)))
        low, high = self.hip_x_range[self.swing]
        return min(max(reach - roll_of(d.xmat[m.pelvis], UP), low), high)

    def update(self, t: float) -> None:
        m, s, d, p = self.measure, self.ctx.servos, self.ctx.data, self.params
        angles = s.angles()
        targets = self.base.copy()
        goal, ahead = self.goal()
        height = m.capture()[3]
        pelvis_lean = m.pelvis_lean()
        # the stance leg: foot flat, the ankle on the capture point; its hip holds the lean
        ankle = min(max(p["stance_kp"] * ahead, -p["ankle_max"]), p["ankle_max"])
        stance_points = m.support.points(d)[m.support.right if self.stance == 0 else m.support.left]
        _, left, left_speed, _ = m.capture(stance_points)
        sideways = p["side_kp"] * left + p["side_kv"] * left_speed
        m.flat_foot(targets, angles, self.stance, ankle, sideways)
        js, jw = m.joints[self.stance], m.joints[self.swing]
        targets[js["hip_x"]] = self.base[js["hip_x"]] + p["side_hip"] * sideways
        if m.foot_touching(self.stance):        # the stance hip turns the pelvis only through a foot on the ground
            targets[js["hip"]] = angles[js["hip"]] + (pelvis_lean - self.lean)
            self.stance_x = m.along(d.xpos[m.feet[self.stance]])[0]
        else:                                   # off it (the mat's rebound) the foot is aimed back where it stood
            targets[js["hip"]] = m.aim(self.stance, self.stance_x, angles[js["knee"]], self.leg)
        # the swing leg: lift, then reach; the thigh aimed in the world frame (as the leap's landing)
        if self.lift_at is None:
            if float(d.subtree_linvel[m.pelvis][2]) < p["wait_vz"]:
                self.lift_at = t
                self.event(t, "step_lift")
            else:                               # waiting: both feet as they stand, the swing leg held
                m.flat_foot(targets, angles, self.swing, ankle, sideways)
                s.hold(targets, t)
                return
        lifting = t - self.lift_at < p["lift_time"]
        knee = p["lift_knee"] if lifting else p["reach_knee"]
        stance_x = m.along(d.xpos[m.feet[self.stance]])[0]
        targets[jw["knee"]] = knee
        targets[jw["hip"]] = m.aim(self.swing, stance_x + goal - self.sole_centre, knee, self.leg)
        targets[jw["hip_x"]] = self.sideways(height)
        swing = hermite_scalar((t - self.t0) / p["arm_time"])
        targets[self.shoulders] = self.arms_from + (np.array([1.0, -1.0]) * p["arm"] - self.arms_from) * swing
        m.flat_foot(targets, angles, self.swing, 0.0, 0.0)
        s.hold(targets, t)
        if self.down_at is None and t - self.lift_at >= p["min_swing"] and m.foot_touching(self.swing):
            self.down_at = t
            self.event(t, "step_down")

    @property
    def finished(self) -> bool:
        return self.down_at is not None or (self.lift_at is not None
                                            and self.ctx.data.time - self.lift_at >= self.params["max_swing"])


class StaggeredStance(Behaviour):
    """Standing on the feet as they are - side by side or fore and aft apart after a step: the ankles servo
    the capture point to ``target`` ahead of the middle of the whole support polygon (``kp``, within
    ``ankle_max``: the polygon of a staggered stance is long, so the same ankles hold a capture point over a
    much longer reach); over ``rise_time`` the knees straighten from where they are to the standing crouch's
    and the hips take the pelvis's lean from where it is to the lean of the balanced crouch (crouch.py) of the
    height she is at, plus ``lean``; less ``lean_kp`` per metre of the capture point's error throughout,
    plus ``bow`` (a timeline: pitch, time, hold, forward and back), the arms to ``arm`` flexion; sideways
    the ankles roll and the hips abduct (``side_kp``, ``side_kv``, ``side_hip``) to keep the COM between
    the feet, and the hips' rotation is held; the hips hold the feet where they stood, fore and aft (``stagger_kp``)
    and sideways (``splay_kp``). ``still(t)``: risen and the COM slower than ``still_speed``."""

    schema = Schema(
        Parameter("rise_time", "s", 1.0, 0.1, 5.0,
                  "the knees straighten to standing and the lean goes to the balanced crouch's over this time (and "
                  "the arms likewise)"),
        Parameter("rise_after", "s", 0.0, 0.0, 3.0, "the rise starts this long after the stance began (held till then)"),
        Parameter("kp", "rad/m", 6.0, 0.0, 20.0, "ankle offset per metre of the capture point ahead of target"),
        Parameter("target", "m", 0.0, -0.2, 0.2, "the capture point is servoed this far ahead of the support's middle"),
        Parameter("ankle_max", "rad", 0.3, 0.0, 0.6, "the ankles' offset at most this either way"),
        Parameter("lean", "rad", 0.0, -0.5, 1.0,
                  "the hips lean the pelvis this much further forward than the crouch of the height she is at"),
        Parameter("lean_kp", "rad/m", 0.0, -10.0, 10.0, "... less this per metre of the capture point ahead of target"),
        Parameter("arm", "rad", 0.0, -1.0, 3.14, "both arms' shoulder flexion goes to this"),
        Parameter("side_kp", "rad/m", 4.0, -20.0, 20.0, "ankle roll per metre of the COM left of the support's middle"),
        Parameter("side_kv", "rad s/m", 4.0, -10.0, 10.0, "ankle roll per m/s of the COM's leftward speed"),
        Parameter("side_hip", "1", 1.0, 0.0, 2.0, "hip abduction per radian of the ankles' roll command"),
        Parameter("stagger_kp", "rad/m", 0.0, 0.0, 20.0,
                  "hip pitch, opposite on the two legs, per metre that the feet have moved apart fore and aft since "
                  "the stance began (each hip pulls its foot back toward where it stood: on a soft mat the feet creep "
                  "apart under the hips' torques, nothing else holds them)"),
        Parameter("splay_kp", "rad/m", 0.0, 0.0, 20.0,
                  "hip abduction, opposite on the two legs, per metre that the feet have moved apart sideways since "
                  "the stance began"),
        Parameter("level_kp", "rad/m", 0.0, 0.0, 40.0,
                  "each knee straightens by this per metre its foot stands higher in the ground than the feet's mean "
                  "(the lighter foot is pressed down, so both carry her)"),
        Parameter("flat_off", "bool", 0.0, 0.0, 1.0,
                  "1 = a foot off the ground is held flat (no capture-point offset), so it comes down flat"),
        Parameter("still_speed", "m/s", 0.05, 0.0, 1.0, "still: the COM slower than this"),
        Parameter("min_height", "m", 0.1, 0.05, 1.0, "the capture point's COM height is at least this (a guard)"),
    )

    def __init__(self, params, ctx: ControlContext, bow: tuple[float, float, float] | None = None):
        """``bow``: (pitch, time, hold): the lean goes that much further forward over time, is held, and
        comes back in the same time, from the start of this behaviour (after the rise: the bow stands
        from a stance already risen)."""
        super().__init__(params, ctx)
        self.measure = StanceMeasure(ctx, self.params["min_height"])
        self.leg = LegGeometry(ctx.character, "R")
        self.bow = bow

    def start(self, t: float) -> None:
        m, s = self.measure, self.ctx.servos
        self.t0 = t
        s.offset[:] = 0.0
        s.set_gains(np.arange(len(s.names)), s.default_kp, s.default_kv)
        self.base = s.angles().copy()
        self.knees = np.array([j["knee"] for j in m.joints])
        stand = standing_hip_height(self.ctx.character)
        # definition: balanced crouches from half the standing hip height up, as the leap's landing's table
        self.crouch = CrouchTable(self.ctx.model, self.ctx.character, np.linspace(0.5 * stand, stand, CROUCH_ROWS),
                                  stand, actor=self.ctx.actor)
        self.knees_from = self.base[self.knees].copy()
        self.lean_from = m.pelvis_lean()
        self.shoulders = s.indices(["shoulder_r_z", "shoulder_l_z"])
        self.arms_from = self.base[self.shoulders].copy()
        self.apart_from = self.feet_apart()
        self.stood = [m.along(self.ctx.data.xpos[f])[0] for f in m.feet]
        self.event(t, "staggered_stance")

    def feet_apart(self) -> tuple[float, float]:
        """How far the left foot is ahead of and left of the right one (heading frame)."""
        d, m = self.ctx.data, self.measure
        return m.along(d.xpos[m.feet[1]] - d.xpos[m.feet[0]])

    def share(self, t: float) -> float:
        return hermite_scalar((t - self.t0 - self.params["rise_after"]) / self.params["rise_time"])

    def pelvis_height(self) -> float:
        """The mid-hip point's height above the feet with the ankles' own height (the crouch table's measure)."""
        d, m = self.ctx.data, self.measure
        hips = 0.5 * (d.xpos[m.hips[0]] + d.xpos[m.hips[1]])
        feet = 0.5 * (d.xpos[m.feet[0]] + d.xpos[m.feet[1]])
        return float(hips[2] - feet[2]) + self.leg.ankle_height

    def bow_pitch(self, t: float) -> float:
        if self.bow is None:
            return 0.0
        pitch, time, hold = self.bow
        u = t - self.t0
        if u < time + hold:
            return pitch * hermite_scalar(u / time)
        return pitch * (1.0 - hermite_scalar((u - time - hold) / time))

    def update(self, t: float) -> None:
        m, s, p = self.measure, self.ctx.servos, self.params
        angles = s.angles()
        targets = self.base.copy()
        share = self.share(t)
        ahead, left, left_speed, _ = m.capture()
        error = ahead - p["target"]
        ankle = min(max(p["kp"] * error, -p["ankle_max"]), p["ankle_max"])
        sideways = p["side_kp"] * left + p["side_kv"] * left_speed
        standing_knee = self.crouch.at(float(self.crouch.heights[-1]))[0]
        targets[self.knees] = self.knees_from + (standing_knee - self.knees_from) * share
        if p["level_kp"]:
            sunk = np.array([m.foot_height(0), m.foot_height(1)])
            targets[self.knees] -= p["level_kp"] * (sunk - sunk.mean())
        crouch_lean = float(self.crouch.at(self.pelvis_height())[3]) + p["lean"]
        lean = self.lean_from + (crouch_lean - self.lean_from) * share - p["lean_kp"] * error + self.bow_pitch(t)
        trunk_error = m.pelvis_lean() - lean
        sign = np.array([1.0, -1.0])                  # the left arm's axis is mirrored
        targets[self.shoulders] = self.arms_from + (sign * p["arm"] - self.arms_from) * share
        ahead, left = self.feet_apart()
        # the left foot further ahead: its hip pulls it back (hip_y +: extension), the right one's forward; further
        # left: its abduction swings it right (hip_x +: the foot to the left), the right one's left
        stagger = 0.5 * p["stagger_kp"] * (ahead - self.apart_from[0]) * np.array([-1.0, 1.0])
        splay = 0.5 * p["splay_kp"] * (left - self.apart_from[1]) * np.array([1.0, -1.0])
        for k in (0, 1):
            j = m.joints[k]
            touching = m.foot_touching(k)
            # the capture point's ankle offset on a foot off the ground only tips it: that foot is held flat
            m.flat_foot(targets, angles, k, ankle if touching or not p["flat_off"] else 0.0, sideways)
            if touching:                    # a hip turns the pelvis only through a leg on the ground ...
                targets[j["hip"]] = angles[j["hip"]] + trunk_error + stagger[k]
                self.stood[k] = m.along(self.ctx.data.xpos[m.feet[k]])[0]
            else:                           # ... off it the foot is aimed back where it stood
                targets[j["hip"]] = m.aim(k, self.stood[k], angles[j["knee"]], self.leg)
            targets[j["hip_x"]] = self.base[j["hip_x"]] + p["side_hip"] * sideways + splay[k]
        s.hold(targets, t)

    def risen(self, t: float) -> bool:
        return self.share(t) >= 1.0

    def still(self, t: float) -> bool:
        speed = float(np.linalg.norm(self.ctx.data.subtree_linvel[self.measure.pelvis]))
        return self.risen(t) and speed < self.params["still_speed"]

    def posture_back(self, t: float) -> bool:
        """The bow is over (forward, held, back)."""
        if self.bow is None:
            return True
        _, time, hold = self.bow
        return t - self.t0 >= 2 * time + hold

    def outside(self, margin: float) -> float:
        """+1 (-1) when the capture point is within ``margin`` of the support's front (back) edge or past it,
        else 0: where a further step is due (StanceMeasure.outside)."""
        return self.measure.outside(margin)


class StepAndHold(Behaviour):
    """The staggered stance, and a further recovery step whenever its capture point comes within ``margin``
    of the support's edge (or past it) - at most ``max_steps`` of them, each ``min_hold`` after the last
    stance began - then the stance again from the new feet. ``risen(t)``: the current stance has risen."""

    schema = Schema(
        Parameter("max_steps", "1", 1.0, 0.0, 5.0, "at most this many further steps"),
        Parameter("margin", "m", 0.03, -0.2, 0.3, "a step once the capture point is this close to the support's edge"),
        Parameter("min_hold", "s", 0.2, 0.0, 2.0, "... and the stance has held this long"),
    )

    def __init__(self, params, ctx: ControlContext, step: dict, stance: dict, first: float = 0.0):
        """``step``, ``stance``: RecoveryStep's and StaggeredStance's validated parameters; ``first``: +1 (-1)
        begins with a step forward (back), not counted in ``max_steps`` (0: with the stance)."""
        super().__init__(params, ctx)
        self.step_params, self.stance_params = step, stance
        self.steps = 0
        self.first = first

    def _begin(self, behaviour: Behaviour, t: float) -> None:
        self.current = behaviour
        behaviour.phase_events = self.phase_events
        behaviour.start(t)

    def start(self, t: float) -> None:
        self._begin(RecoveryStep(self.step_params, self.ctx, self.first) if self.first
                    else StaggeredStance(self.stance_params, self.ctx), t)

    def update(self, t: float) -> None:
        current, p = self.current, self.params
        if isinstance(current, RecoveryStep) and current.finished:
            self._begin(StaggeredStance(self.stance_params, self.ctx), t)
        elif isinstance(current, StaggeredStance) and self.steps < p["max_steps"] and t - current.t0 >= p["min_hold"]:
            direction = current.outside(p["margin"])
            if direction:
                self.steps += 1
                self._begin(RecoveryStep(self.step_params, self.ctx, direction), t)
        self.current.update(t)

    def risen(self, t: float) -> bool:
        return isinstance(self.current, StaggeredStance) and self.current.risen(t)

    @property
    def t_stance(self) -> float:
        """When the current stance began (the step's start while stepping)."""
        return self.current.t0
