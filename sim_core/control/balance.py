"""Balance (Wooten ch. 7): stand, bend the knees, pitch the torso, shift the COM.

The COM is servoed over the centre of the support polygon by offsets to the ankle and hip
targets (eqs. 7.1-7.2; hip offsets half the ankle's, opposite sign); the ankles keep the feet
flat (7.3-7.4); the knees set the pelvis height by the law of cosines (7.5) and the hips hold
the pelvis attitude (the role of 7.6). Everything is measured in the character's heading frame
with "up" opposite to gravity, so it also stands on a tilted ground.

A request is a timeline: stand until ``move_start``, move the posture (pelvis height, torso
pitch, COM offset) along a Hermite curve over ``move_time``, hold for ``hold_time``, and, if
``return_to_stand``, move back to standing over ``move_time``.
"""
from __future__ import annotations

import math

import mujoco
import numpy as np

from .behaviour import Behaviour, ControlContext
from .crouch import CrouchTable, arm_reach
from .measure import SupportGeometry, compliant_boxes, over_a_box
from .servo import hermite_scalar
from ..errors import ParameterError
from ..schema import Parameter, Schema
from ..tuned.constants import constant, own_constants, read_constants, register_constants

# the balance's hand-set constants: data, balance_any.json's "constants" (docs/tables.md)
BALANCE_CONSTANTS = Schema(
    constant("spine_share", "1", 0.0, 1.0, "share of the torso pitch taken by the spine (the rest by the hips)"),
    constant("standing_knee_flex", "rad", 0.0, 0.5, "knees are never locked straight (the law of cosines is singular there)"),
    constant("hip_strategy_max", "rad", 0.0, 2.0, "largest hip offset of the fast hip strategy"),
    constant("lean_rate", "1/s", 0.0, 5.0, "rad/s of trunk lean per radian of COM error beyond the ankles' reach"),
    constant("lean_leak", "1/s", 0.0, 5.0, "the lean returns to zero at this rate when the error is gone"),
    constant("lean_max", "rad", 0.0, 2.0, "largest trunk lean"),
    constant("crouch_com_tolerance", "m", 0.0, 0.2, "a crouch whose COM misses the centre of the feet by more is refused"),
    constant("com_forward_share", "1", 0.0, 1.0,
             "a COM offset is held up to this share of the feet's half length ahead of their centre (measured: 0.49-0.64)"),
    constant("com_back_share", "1", 0.0, 1.0,
             "... and this share behind it (measured: 0.85-0.89)"),
    constant("com_side_share", "1", 0.0, 1.0,
             "... and this share of the feet's half width to either side, the three the axes of an ellipse (measured: "
             "0.62-0.93)"),
    constant("hip_share", "1", 0.0, 2.0, "hip offset per unit of ankle offset of the COM servo (eq. 7.2, opposite sign)"),
    constant("ankle_authority", "1", 0.0, 2.0, "share of the torque the foot can take (COP at its edge) used by the ankles"),
    constant("toe_share", "1", 0.0, 1.0, "where between ball (0) and toe tip (1) the front edge of the foot is taken"),
    constant("excess_to_hip", "1", 0.0, 20.0, "hip flexion per radian of COM demand the ankles cannot deliver"),
    constant("crouch_rate", "1/s", 0.0, 5.0,
             "a crouch may be asked no faster than this many standing hip heights of descent per second of "
             "move_time (the mean rate of the Hermite move; faster ones fell or stepped)"),
    constant("free_pitch", "rad", 0.0, 2.0, "a torso pitch up to this is moved at any move_time the panel offers"),
    constant("pitch_rate", "rad/s", 0.0, 5.0,
             "... the pitch beyond it no faster than this many radians per second of move_time"),
    constant("pitched_side_share", "1", 0.0, 1.0,
             "... narrowed to this share of the half width when the torso is pitched forward (measured: 0.2 held "
             "by all four at every pitch, 0.3-0.4 stepped or fell with the arms raised)"),
    constant("side_pitch", "rad", 0.01, 2.0, "... linearly from no pitch to this torso pitch"),
    constant("back_pitch_free_depth", "1", 0.0, 1.0,
             "a backward torso pitch is held over the panel's whole range in a crouch down to this share of the "
             "standing hip height (measured: the man, the child and the imaginary runner held -0.35 rad at 0.15)"),
    constant("back_pitch_depth", "1", 0.0, 1.0,
             "... and narrows linearly to back_pitch_deep at this crouch depth and deeper (the child fell at "
             "-0.3 / -0.25 / -0.15 / -0.1 rad at depths 0.2 / 0.25 / 0.3 / 0.4)"),
    constant("back_pitch_deep", "rad", 0.0, 0.35, "... the backward pitch a crouch that deep holds (the child: -0.05)"),
    constant("hand_clearance", "1", 0.0, 1.0,
             "a posture whose hands come nearer the ground than this share of the standing hip height is "
             "refused (posed kinematically: the hands touched the ground below it)"),
    constant("pelvis_held_share", "1", 0.0, 1.0,
             "a posture whose pelvis, posed kinematically, stands lower than this share of its standing height is "
             "refused (below 0.5 counts as a fall; the held crouch sags 0-0.017 of it below the posed one upright)"),
    constant("pelvis_pitch_sag", "1", 0.0, 1.0,
             "... and this share more with the torso pitched forward (the sag measured 0.034-0.049 from 0.3 rad on)"),
    constant("pelvis_sag_pitch", "rad", 0.01, 2.0, "... reached linearly from no pitch at this torso pitch"),
    constant("settle_time", "s", 0.0, 10.0,
             "a run lasts at least this long after the request's timeline (move, hold, return) ends, so it is "
             "judged still (TARGETS.md) once the posture has settled, not in mid-move"),
)
register_constants("balance", BALANCE_CONSTANTS)
CONSTANTS = read_constants("balance", BALANCE_CONSTANTS)
GAINS_SET_FOR = "man"                            # definition: the body the schema's servo gains were set for
SCALED_GAINS = ("com_kp", "com_kv", "height_kp")  # definition: the gains per metre a body's size changes (Fig. 6)

SPINE_Y = ("spine_l3_y", "spine_l1_y", "spine_t7_y", "spine_t4_y")
CROUCH_TABLE_ROWS = 6      # balanced crouch poses solved between standing and the requested height


def hip_servo_stiffness(character) -> float:
    """The hip pitch servo's stiffness per kg of body and metre of leg (N m/rad / (kg m)): a hip offset's
    push on the whole body through the legs and the ground (the fast hip strategy's authority per tick).
    Fig. 6's scaling keeps it for a body shaped like the man; Fig. 3's bodies differ (the imaginary
    cyclist's heavy trunk, whose inertia about the hip sets its hip servo, gives 2.8 times his)."""
    from ..character.dimensions import fig3_measures
    kp = character.dofs[character.dof_index["hip_r_y"]].kp
    return kp / (character.total_mass * fig3_measures(character)["leg length"])


def standing_hip_height(character) -> float:
    """Height of the hip joints above the ground standing (m), the mean of both legs."""
    return 0.5 * sum(LegGeometry(character, side).standing_hip_height() for side in "RL")


class LegGeometry:
    """Planar leg lengths and the rest-pose knee flexion of one side (for eq. 7.5)."""

    def __init__(self, character, side: str):
        hip = character.joint_position("ULEG" + side)
        knee = character.joint_position("LLEG" + side)
        ankle = character.joint_position("FOOT" + side)
        thigh, shank = knee - hip, ankle - knee
        self.upper = float(np.linalg.norm(thigh[[0, 2]]))
        self.lower = float(np.linalg.norm(shank[[0, 2]]))
        # geometric flexion already present at zero joint angle (shank leaning back of the thigh)
        self.rest_flex = math.atan2(-shank[0], -shank[2]) - math.atan2(-thigh[0], -thigh[2])
        self.ankle_height = float(ankle[2])
        self.hip_height = float(hip[2])

    def knee_angle_for(self, hip_to_ankle: float) -> float:
        """Eq. 7.5: knee joint angle that puts hip and ankle ``hip_to_ankle`` apart."""
        u, l = self.upper, self.lower
        c = (u * u + l * l - hip_to_ankle * hip_to_ankle) / (2 * u * l)
        flex = math.pi - math.acos(max(-1.0, min(1.0, c)))
        return flex - self.rest_flex

    def thigh_pitch_for(self, foot_ahead: float, knee_flexion: float) -> float:
        """Thigh pitch from vertical (+ = foot behind the hip) that puts the ankle ``foot_ahead``
        metres ahead of the hip with this knee flexion (planar two-link leg)."""
        u, l = self.upper, self.lower
        k = knee_flexion + self.rest_flex
        a, b = u + l * math.cos(k), l * math.sin(k)
        r = math.hypot(a, b)
        return math.asin(max(-1.0, min(1.0, -foot_ahead / r))) - math.atan2(b, a)

    def standing_hip_height(self) -> float:
        u, l = self.upper, self.lower
        flex = CONSTANTS.standing_knee_flex + self.rest_flex
        return self.ankle_height + math.sqrt(u * u + l * l + 2 * u * l * math.cos(flex))

    def lowest_hip_height(self, knee_limit: float) -> float:
        u, l = self.upper, self.lower
        flex = knee_limit + self.rest_flex
        return self.ankle_height + math.sqrt(max(u * u + l * l + 2 * u * l * math.cos(flex), 0.0))


def _geom_bottom(model, data, geom: int) -> float:
    """Lowest world height of a box, capsule or sphere geom as posed in ``data``."""
    z, size = float(data.geom_xpos[geom][2]), model.geom_size[geom]
    axes_z = np.abs(data.geom_xmat[geom].reshape(3, 3)[2])       # each local axis's share of world z
    kind = model.geom_type[geom]
    if kind == mujoco.mjtGeom.mjGEOM_BOX:
        return z - float(axes_z @ size)
    if kind == mujoco.mjtGeom.mjGEOM_CAPSULE:
        return z - float(axes_z[2] * size[1]) - float(size[0])
    return z - float(size[0])


class Balance(Behaviour):
    name = "balance"
    summary = "Stand balanced; bend the knees, pitch the torso or shift the COM, and come back (Wooten ch. 7)."
    default_duration = 5.0
    control_rate = 100.0       # a 10 ms balance loop (human postural reflexes take 50-100 ms)
    schema = Schema(
        Parameter("pelvis_height", "m", 0.0, 0.20, 1.20,
                  "height of the mid-hip point above the ground to move to; 0 = standing height", special=0.0),
        Parameter("torso_pitch", "rad", 0.0, -0.35, 1.75,
                  "forward pitch of the upper body from vertical (hips take 75 %, the spine 25 %)"),
        Parameter("com_offset_x", "m", 0.0, -0.25, 0.25,
                  "desired COM offset forward of the centre of the support polygon (heading frame)"),
        Parameter("com_offset_y", "m", 0.0, -0.20, 0.20,
                  "desired COM offset to the left of the centre of the support polygon"),
        Parameter("move_start", "s", 0.5, 0.0, 600.0, "time to start moving to the requested posture"),
        Parameter("move_time", "s", 1.5, 0.2, 20.0, "duration of the Hermite move there (and back)"),
        Parameter("hold_time", "s", 1.0, 0.0, 600.0, "time to hold the posture before returning"),
        Parameter("return_to_stand", "bool", 1.0, 0.0, 1.0, "1 = return to standing after the hold"),
        Parameter("arm_abduction", "rad", 0.0, -0.5, 1.5, "extra sideways raise of both arms"),
        Parameter("arm_flexion", "rad", 0.0, -0.8, 2.5,
                  "forward raise of both arms from hanging (they follow the torso pitch)"),
        Parameter("elbow_flexion", "rad", 0.2, 0.0, 2.4, "elbow bend of both arms"),
        Parameter("head_pitch", "rad", 0.0, -0.8, 0.8, "head nod forward (+) or back (-)"),
        Parameter("com_kp", "rad/m", 4.0, 0.0, 20.0, "COM servo stiffness: ankle offset per metre of COM error (eq. 7.1)"),
        Parameter("com_kv", "rad s/m", 2.0, 0.0, 5.0, "COM servo damping: ankle offset per m/s of COM speed (eq. 7.1)"),
        Parameter("heading_kp", "rad/rad", 0.0, 0.0, 10.0,
                  "hip rotation offset per radian of the pelvis's heading away from the feet's (0 = the hips' "
                  "rotation is not servoed): in a deep crouch the hips' abduction acts partly about the "
                  "vertical and turns the pelvis - a sideways lean holds the heading"),
        Parameter("spin_kp", "rad/(kg m²/s)", 0.0, 0.0, 0.5,
                  "hip rotation offset per kg m²/s of the whole body's angular momentum about the vertical "
                  "(0 = not servoed): a sideways lean pushes at the forefeet, ahead of the COM, which "
                  "twists the body; the hips turn the trunk against it while the feet are down"),
        Parameter("stagger_kp", "rad/rad", 1.0, 0.0, 10.0,
                  "hip pitch offset, opposite on the two legs, per radian that the line between the feet has "
                  "turned in the feet's heading frame since the balance started, while the feet stand on ground "
                  "that gives (the landing mat; 0 = not servoed): the hips hold the pelvis square to the feet; on "
                  "the soft mat the feet twist and, without it, the body slowly turns over them and falls (on a "
                  "rigid floor the feet's grip holds them)"),
        Parameter("stagger_on_floor", "bool", 1.0, 0.0, 1.0,
                  "1 = stagger_kp acts on a rigid floor too: with the COM offset over one foot the other is "
                  "nearly unloaded and its grip no longer holds the legs' scissor - the child's feet twisted "
                  "apart and she fell in slow moves (docs/skills/balance.md); 0 for the balances inside other "
                  "skills, whose tables were measured without it"),
        Parameter("height_kp", "rad/m", 10.0, 0.0, 40.0,
                  "pelvis height servo: knee offset per metre of height error (corrects servo sag)"),
        Parameter("hip_strategy_scale", "1", 1.0, 0.0, 2.0,
                  "the fast hip strategy's hip offsets (hip_share and excess_to_hip per unit of the COM servo's "
                  "speed term) times this; 1 = as set for the man. A body whose hip servo is stiffer per kg of "
                  "body and metre of leg than his gets his stiffness over its own (character_defaults): the "
                  "imaginary cyclist's, 2.8 times his, drove the hips tick against tick and it fell standing"),
    )

    def __init__(self, params, ctx: ControlContext, from_height: float | None = None,
                 from_pitch: float | None = None):
        """``from_height``, ``from_pitch``: start from this pelvis height and pelvis pitch instead
        of standing (after a landing), so the hand-over does not jerk."""
        super().__init__(params, ctx)
        self.from_height = from_height
        self.from_pitch = from_pitch
        self.t0 = 0.0
        self._held = None           # the held posture's hands and pelvis, posed once (_pose_held)
        ch = ctx.character
        m = ctx.model
        self.legs = {s: LegGeometry(ch, s) for s in "RL"}
        self.support = SupportGeometry(m, prefix=ctx.actor.prefix)
        s = ctx.servos
        self.i = s.index
        body = ctx.actor.body_id
        self.pelvis = body("PELVIS")
        self.total_mass = float(m.body_subtreemass[self.pelvis])
        self.feet = [body("FOOTR"), body("FOOTL")]
        self.hips = [body("ULEGR"), body("ULEGL")]
        self.spine_idx = s.indices(SPINE_Y)
        self.base = ch.standing_pose.copy()
        self.damping_ratio = s.default_kv / s.default_kp
        self.side_index = [{f"{n}_{a}": s.index[f"{n}_{side}_{a}"] for n, a in
                            (("knee", "y"), ("ankle", "y"), ("ankle", "x"), ("hip", "y"), ("hip", "x"),
                             ("hip", "z"))}
                           for side in "rl"]
        self._targets_key, self._targets = None, None
        self._lean = 0.0
        self._stagger = 0.0
        self.soft_ground = compliant_boxes(m)
        # ankle offset that puts the centre of pressure at the front (toe) / back (heel) edge
        weight_per_foot = 0.5 * self.total_mass * float(np.linalg.norm(m.opt.gravity))
        ankle = ch.joint_position("FOOTR")
        sites = [c["pos"] for c in ch.body("FOOTR")["contacts"] + ch.body("TOER")["contacts"]]
        front = CONSTANTS.toe_share * max(p[0] for p in sites) + (1 - CONSTANTS.toe_share) * ch.joint_position("TOER")[0] - ankle[0]
        back = ankle[0] - min(p[0] for p in sites)
        kp_ankle = ch.dofs[ch.dof_index["ankle_r_y"]].kp
        self.ankle_limit_front = CONSTANTS.ankle_authority * weight_per_foot * front / kp_ankle
        self.ankle_limit_back = CONSTANTS.ankle_authority * weight_per_foot * back / kp_ankle
        self.ankle_height = self.legs["R"].ankle_height
        self.stand_height = standing_hip_height(ch)

    @classmethod
    def character_defaults(cls, character: str) -> dict:
        """The COM and height servos' gains (SCALED_GAINS, set for the man: Wooten's) scaled to
        ``character`` by Fig. 6 (geometric: they carry no mass; L its leg length over his): with the
        man's per-metre gains the child's COM crept toward her toes and she fell in slow pitched moves
        (docs/skills/balance.md). And ``hip_strategy_scale``: the man's hip servo stiffness over the body's
        (``hip_servo_stiffness``), at most 1 - the imaginary cyclist's stiff hip drove the hip strategy tick
        against tick and it fell standing. The balances inside other skills keep the schema's."""
        from ..adapt.scaling import ScaleFactors, Units, scale
        from ..character.dimensions import leg_length_ratio
        from ..character.spec import available_characters, load_character
        if character == GAINS_SET_FOR or character not in available_characters():
            return {}               # a body made into a file of its own is known here by name only: the schema's
        man, body = load_character(GAINS_SET_FOR), load_character(character)
        factors = ScaleFactors(leg_length_ratio(man, body))
        gains = {name: round(scale(cls.schema.by_name[name].default, Units.parse(cls.schema.by_name[name].unit), factors), 4)
                 for name in SCALED_GAINS}
        hip_scale = min(1.0, hip_servo_stiffness(man) / hip_servo_stiffness(body))
        return {**gains, "hip_strategy_scale": round(hip_scale, 4)}

    @classmethod
    def duration_for(cls, params: dict, character: str, strength) -> float:
        """The default run, or longer: until ``settle_time`` after the timeline (move, hold and the
        return) ends."""
        end = params["move_start"] + params["move_time"] * (1 + bool(params["return_to_stand"])) + params["hold_time"]
        return max(cls.default_duration, end + CONSTANTS.settle_time)

    # ----------------------------------------------------------------- requests
    def target_posture(self) -> np.ndarray:
        p = self.params
        height = p["pelvis_height"] or self.stand_height
        return np.array([height, p["torso_pitch"], p["com_offset_x"], p["com_offset_y"]])

    def standing_posture(self) -> np.ndarray:
        return np.array([self.stand_height, 0.0, 0.0, 0.0])

    def check_feasible(self) -> None:
        """Refuse a COM offset outside what the feet hold (com_reach), a pelvis height with no
        balanced crouch pose (COM not over the feet within the joint ranges) or above standing
        height, and a crouch or torso pitch asked faster than measured to hold (move_time_needed),
        before simulating."""
        self._check_com_offset()
        self._check_height()
        self._check_move_time()
        self._check_back_pitch()
        self._check_hands()
        self._check_pelvis_held()

    @property
    def body_constants(self):
        """The balance's constants for this body: balance_any.json's, each one its own
        ``balance_<character>.json`` holds replaced (the imaginary cyclist's)."""
        return own_constants("balance", self.ctx.character.name, CONSTANTS)

    def _pose_held(self) -> tuple[float, float]:
        """The held posture posed kinematically (the nominal joint targets, the pelvis at the requested
        height and at the pitch the hips hold; the feet and the balance feedback left out), once per request:
        (the hands' lowest point above the ground, m; the pelvis's height as a share of its standing height)."""
        if self._held is None:
            m, actor = self.ctx.model, self.ctx.actor
            posture = self.target_posture()
            self.crouch = CrouchTable(m, self.ctx.character, [posture[0]], self.stand_height, actor=actor)  # start() builds the run's
            q = self.joint_targets(posture)
            pitch = posture[1] * (1.0 - CONSTANTS.spine_share) + self._crouch_pitch
            d = self.crouch.data
            d.qpos[:] = self.crouch.base_qpos
            d.qpos[self.ctx.servos.qpos_adr] = q
            root = actor.root_qpos
            d.qpos[root + 3:root + 7] = (math.cos(0.5 * pitch), 0.0, math.sin(0.5 * pitch), 0.0)   # about +y: forward
            mujoco.mj_kinematics(m, d)
            hips = 0.5 * (d.xpos[self.hips[0]] + d.xpos[self.hips[1]])
            above = hips[2] - posture[0]            # the posed hips over the requested pelvis height
            hands = min(_geom_bottom(m, d, g) for side in "RL"
                        for g in np.nonzero(m.geom_bodyid == actor.body_id("HAND" + side))[0])
            self._held = (hands - above, (d.xpos[self.pelvis][2] - above) / self.ctx.character.bodies[0]["com"][2])
        return self._held

    def hands_clearance(self) -> float:
        """Height (m) of the hands' lowest point above the ground in the held posture, posed
        kinematically (``_pose_held``)."""
        return self._pose_held()[0]

    def held_pelvis_share(self) -> float:
        """The pelvis's height in the held posture, posed kinematically (``_pose_held``), as a share of
        its standing height: below 0.5 the run counts as a fall (TARGETS.md's "stable",
        analysis.standard_metrics), whatever the hips' height."""
        return self._pose_held()[1]

    def pelvis_held_needed(self) -> float:
        """The least posed pelvis share (``held_pelvis_share``) this request's torso pitch holds above a fall
        (the body's own sag where its ``balance_<character>.json`` holds one: the imaginary cyclist's)."""
        own = self.body_constants
        forward = min(1.0, max(0.0, self.params["torso_pitch"]) / own.pelvis_sag_pitch)
        return own.pelvis_held_share + own.pelvis_pitch_sag * forward

    def _check_pelvis_held(self) -> None:
        share, needed = self.held_pelvis_share(), self.pelvis_held_needed()
        if share < needed:
            p = self.params
            raise ParameterError(
                f"parameters pelvis_height={p['pelvis_height']:g} m, torso_pitch={p['torso_pitch']:g} rad hold the "
                f"{self.ctx.character.name}'s pelvis at {share:.3f} of its standing height; allowed: at least "
                f"{needed:.3f} with this torso pitch (below 0.5 is a fall): a higher pelvis_height or a smaller torso_pitch")

    def _check_hands(self) -> None:
        clearance = self.hands_clearance()
        own = self.body_constants
        least = own.hand_clearance * self.stand_height
        if clearance < least:
            p = self.params
            raise ParameterError(
                f"parameters torso_pitch={p['torso_pitch']:g} rad, arm_flexion={p['arm_flexion']:g} rad, "
                f"elbow_flexion={p['elbow_flexion']:g} rad at pelvis_height={p['pelvis_height']:g} m bring the "
                f"{self.ctx.character.name}'s hands to {clearance:.3f} m above the ground; allowed: at least "
                f"{least:.3f} m ({own.hand_clearance:g} of the standing hip height)")

    def crouch_depth(self) -> float:
        """How far the request lowers the pelvis, as a share of the standing hip height (0: standing)."""
        h = self.params["pelvis_height"]
        return max(0.0, 1.0 - h / self.stand_height) if h else 0.0

    def move_time_needed(self) -> float:
        """The shortest move_time (s) that holds this request's crouch depth and torso pitch: the
        crouch at ``crouch_rate`` standing hip heights per second, the pitch beyond ``free_pitch`` at
        ``pitch_rate`` (measured on the four bodies, the imaginary cyclist's its own where its
        ``balance_<character>.json`` holds them: docs/skills/balance.md)."""
        own = self.body_constants
        pitch_beyond = max(0.0, self.params["torso_pitch"] - own.free_pitch)
        return max(self.crouch_depth() / own.crouch_rate, pitch_beyond / own.pitch_rate)

    def back_pitch_allowed(self) -> float:
        """The largest backward torso pitch (rad, as a positive number) this request's crouch holds: the
        panel's whole range down to ``back_pitch_free_depth`` of the standing hip height, narrowing
        linearly to ``back_pitch_deep`` at ``back_pitch_depth`` and deeper (measured on the four bodies,
        the imaginary cyclist's its own where its ``balance_<character>.json`` holds them: docs/skills/balance.md)."""
        own = self.body_constants
        widest = -self.schema.by_name["torso_pitch"].minimum
        beyond = (self.crouch_depth() - own.back_pitch_free_depth) / (own.back_pitch_depth - own.back_pitch_free_depth)
        return widest - (widest - own.back_pitch_deep) * min(1.0, max(0.0, beyond))

    def _check_back_pitch(self) -> None:
        pitch, allowed = self.params["torso_pitch"], self.back_pitch_allowed()
        shown = math.floor(allowed * 1000) / 1000        # definition: the message's mrad, rounded inward
        if pitch < -allowed:
            raise ParameterError(
                f"parameter torso_pitch={pitch:g} rad leans the torso back further than the {self.ctx.character.name} "
                f"holds in a crouch of {self.crouch_depth():.2f} of the standing hip height; allowed range is "
                f"[{-shown:g}, {self.schema.by_name['torso_pitch'].maximum:g}] rad")

    def _check_move_time(self) -> None:
        needed, asked = self.move_time_needed(), self.params["move_time"]
        if asked < needed:
            raise ParameterError(
                f"parameter move_time={asked:g} s is too fast for {self.ctx.character.name} to hold a crouch of "
                f"{self.crouch_depth():.2f} of the standing hip height with torso_pitch={self.params['torso_pitch']:g} "
                f"rad; allowed range is [{math.ceil(needed * 100) / 100:.2f}, 20] s")

    def _check_height(self) -> None:
        h = self.params["pelvis_height"]
        if not h:
            return
        # "stable" (TARGETS.md) keeps the pelvis above half its standing height
        pelvis = self.ctx.character.bodies[0]
        lowest_stable = 0.5 * pelvis["com"][2] - (pelvis["com"][2] - self.legs["R"].hip_height) + 0.01  # criterion: 1 cm inside it

        def balanced(height):
            return (lowest_stable <= height <= self.stand_height
                    and self._crouch_residual(height) < CONSTANTS.crouch_com_tolerance)
        if balanced(h):
            return
        lo, hi = 0.3, self.stand_height     # definition: bisection (from 0.3 m) for the refusal's lowest height
        for _ in range(12):                 # definition: 12 halvings, the message's mm
            mid = 0.5 * (lo + hi)
            lo, hi = (lo, mid) if balanced(mid) else (mid, hi)
        raise ParameterError(
            f"parameter pelvis_height={h:g} m is out of reach for {self.ctx.character.name} (no balanced "
            f"crouch with feet flat); allowed range is [{hi:.3f}, {self.stand_height:.3f}] m (or 0 for standing)")

    def com_reach(self) -> tuple[float, float, float]:
        """How far (m) the COM may be asked ahead of, behind and to either side of the centre of the
        feet: the constants' shares of the feet's half length and half width in the heading frame, the
        side narrower with the torso pitched (measured on the man, the woman, the child and the
        imaginary runner: docs/skills/balance.md)."""
        spans = [self._support_span(self._heading_axis(axis)) for axis in (0, 1)]
        half_length, half_width = ((hi - lo) / 2.0 for lo, hi in spans)
        # a forward-pitched torso narrows the sideways reach, down to pitched_side_share at side_pitch
        bent = min(1.0, max(0.0, self.params["torso_pitch"]) / CONSTANTS.side_pitch)
        side = CONSTANTS.com_side_share - (CONSTANTS.com_side_share - CONSTANTS.pitched_side_share) * bent
        return (CONSTANTS.com_forward_share * half_length, CONSTANTS.com_back_share * half_length,
                side * half_width)

    def _check_com_offset(self) -> None:
        x, y = self.params["com_offset_x"], self.params["com_offset_y"]
        if not (x or y):
            return
        ahead, behind, side = self.com_reach()
        if (x / (ahead if x > 0 else behind)) ** 2 + (y / side) ** 2 > 1.0:
            raise ParameterError(
                f"parameter com_offset_x={x:g} m, com_offset_y={y:g} m puts the COM beyond what the "
                f"{self.ctx.character.name}'s feet hold; allowed: within the ellipse of {ahead:.3f} m ahead, "
                f"{behind:.3f} m behind and {side:.3f} m to either side of the feet's centre")

    def _crouch_residual(self, height: float) -> float:
        """How far the COM of the best crouch pose at this height misses the centre of the feet."""
        table = CrouchTable(self.ctx.model, self.ctx.character, [height], self.stand_height, actor=self.ctx.actor)
        knee, hip, ankle = table.table[0, :3]
        return abs(table.measure(knee, hip, ankle)[1])

    def initial_posture(self) -> np.ndarray:
        height = self.from_height if self.from_height is not None else self.stand_height
        torso = 0.0
        if self.from_pitch is not None:         # the torso pitch that gives the current pelvis pitch
            torso = (self.from_pitch - self._crouch_pitch_at(height)) / (1.0 - CONSTANTS.spine_share)
        return np.array([height, torso, 0.0, 0.0])

    def _crouch_pitch_at(self, height: float) -> float:
        if not hasattr(self, "crouch"):
            return 0.0
        return float(self.crouch.at(height)[3])

    def posture(self, t: float) -> np.ndarray:
        """Posture (pelvis height, torso pitch, COM offset x, y) at time t of this behaviour's
        timeline, which starts when the behaviour starts."""
        p = self.params
        t = t - self.t0
        initial, goal, stand = self._postures
        t1 = p["move_start"]
        t2 = t1 + p["move_time"]
        t3 = t2 + p["hold_time"]
        if t < t1:
            return initial
        if t < t2 or not p["return_to_stand"]:
            return initial + (goal - initial) * hermite_scalar((t - t1) / p["move_time"])
        if t < t3:
            return goal
        return goal + (stand - goal) * hermite_scalar((t - t3) / p["move_time"])

    def com_ahead_of_support(self) -> float:
        """How far the COM (projected along gravity) is ahead of the centre of the feet, in the
        pelvis heading frame (m)."""
        return self._com_from_support(0)

    def com_left_of_support(self) -> float:
        """How far the COM is to the left of the centre of the feet, in the heading frame (m)."""
        return self._com_from_support(1)

    def _com_from_support(self, axis: int) -> float:
        along = self._heading_axis(axis)
        lo, hi = self._support_span(along)
        com = self.ctx.data.subtree_com[self.pelvis]
        return float(along[0] * com[0] + along[1] * com[1] - 0.5 * (lo + hi))

    def _heading_axis(self, axis: int) -> tuple[float, float]:
        """The pelvis heading frame's forward (0) or left (1) axis in the ground plane."""
        m = self.ctx.data.xmat[self.pelvis]
        yaw = math.atan2(m[3], m[0])
        c, s = math.cos(yaw), math.sin(yaw)
        return (c, s) if axis == 0 else (-s, c)

    def _support_span(self, along: tuple[float, float]) -> tuple[float, float]:
        """The supporting points' extent along the ground-plane direction ``along`` (m, world origin)."""
        pts = self.support.supporting_points(self.ctx.data)
        p = along[0] * pts[:, 0] + along[1] * pts[:, 1]
        return float(p.min()), float(p.max())

    def feet_stagger(self) -> float:
        """The angle of the line from the right ankle to the left one in the feet's heading frame
        (their mean yaw; 0: side by side, + the left foot ahead): it changes when the feet twist in
        place (on a soft mat), not when the pelvis turns over still feet (the heading servo's)."""
        d = self.ctx.data
        right, left = d.xmat[self.feet[0]], d.xmat[self.feet[1]]
        yaw = math.atan2(right[3] + left[3], right[0] + left[0])
        dx, dy = (d.xpos[self.feet[1]] - d.xpos[self.feet[0]])[:2].tolist()
        c, s = math.cos(yaw), math.sin(yaw)
        return math.atan2(c * dx + s * dy, -s * dx + c * dy)

    def posture_reached(self, t: float) -> bool:
        return t - self.t0 >= self.params["move_start"] + self.params["move_time"]

    def start(self, t: float) -> None:
        self.t0 = t
        self._stagger = self.feet_stagger()
        goal = self.params["pelvis_height"] or self.stand_height
        low = min(goal, self.initial_posture()[0])
        heights = np.linspace(low, self.stand_height, CROUCH_TABLE_ROWS) if low < self.stand_height else [goal]
        self.crouch = CrouchTable(self.ctx.model, self.ctx.character, heights, self.stand_height,
                                  actor=self.ctx.actor)
        self._postures = (self.initial_posture(), self.target_posture(), self.standing_posture())
        self.ctx.servos.hold(self.joint_targets(self.initial_posture()), t)
        self.event(t, "stand" if self.from_height is None else "balance")
        p = self.params
        self.event(t + p["move_start"], "move")
        self.event(t + p["move_start"] + p["move_time"], "hold")
        if p["return_to_stand"]:
            self.event(t + p["move_start"] + p["move_time"] + p["hold_time"], "return")

    # ----------------------------------------------------------------- control law
    def joint_targets(self, posture: np.ndarray) -> np.ndarray:
        """Nominal joint targets for a posture (before the balance feedback)."""
        height, torso_pitch = posture[0], posture[1]
        q = self.base.copy()
        i, p = self.i, self.params
        knee, _, _, self._crouch_pitch, self._leg_length = self.crouch.at(height)
        q[i["knee_r_y"]] = q[i["knee_l_y"]] = knee
        reach = arm_reach(height, self.stand_height)
        q[self.spine_idx] = torso_pitch * CONSTANTS.spine_share / len(SPINE_Y)
        mirror = {"r": 1.0, "l": -1.0}
        for s, sign in mirror.items():
            q[i[f"shoulder_{s}_x"]] = self.base[i[f"shoulder_{s}_x"]] - sign * p["arm_abduction"]
            q[i[f"shoulder_{s}_z"]] = sign * (p["arm_flexion"] + torso_pitch + reach)   # arms keep hanging
            q[i[f"elbow_{s}_z"]] = sign * p["elbow_flexion"]
        q[i["neck_c2_y"]] = p["head_pitch"]
        return q

    def update(self, t: float) -> None:
        d, servos, idx = self.ctx.data, self.ctx.servos, self.side_index
        posture = self.posture(t)
        key = tuple(posture)
        if key != self._targets_key:                 # nominal targets change only while moving
            self._targets_key, self._targets = key, self.joint_targets(posture)
        targets = self._targets.copy()
        gravity = self.ctx.model.opt.gravity
        norm = math.sqrt(gravity[0] ** 2 + gravity[1] ** 2 + gravity[2] ** 2)
        ux, uy, uz = -gravity[0] / norm, -gravity[1] / norm, -gravity[2] / norm

        # heading frame of the pelvis; COM projected along gravity onto the ground plane
        pelvis_m = d.xmat[self.pelvis].tolist()
        yaw = math.atan2(pelvis_m[3], pelvis_m[0])
        c, s = math.cos(yaw), math.sin(yaw)
        cx, cy, cz = d.subtree_com[self.pelvis].tolist()
        vx, vy, _ = d.subtree_linvel[self.pelvis].tolist()
        gx, gy = cx - cz * ux / uz, cy - cz * uy / uz
        pts = self.support.supporting_points(d)
        px = c * pts[:, 0] + s * pts[:, 1]
        py = -s * pts[:, 0] + c * pts[:, 1]
        centre_x = 0.5 * (px.min() + px.max())
        centre_y = 0.5 * (py.min() + py.max())
        kp, kv = self.params["com_kp"], self.params["com_kv"]
        position_x = kp * (c * gx + s * gy - centre_x - posture[2])
        velocity_x = kv * (c * vx + s * vy)
        delta_x = position_x + velocity_x                                                # eq. 7.1
        # the fast hip strategy answers the COM speed the ankles cannot stop (trunk against legs)
        # (forward only: bending at the hips stops a forward fall; leaning the trunk back to stop
        # a backward one tips a character that is already behind its heels)
        velocity_excess = max(velocity_x - self.ankle_limit_front, 0.0)
        hip_x = self.params["hip_strategy_scale"] * (-CONSTANTS.hip_share * velocity_x
                                                     - CONSTANTS.excess_to_hip * velocity_excess)
        hip_x = min(max(hip_x, -CONSTANTS.hip_strategy_max), CONSTANTS.hip_strategy_max)
        delta_y = kp * (-s * gx + c * gy - centre_y - posture[3]) + kv * (-s * vx + c * vy)  # eq. 7.2

        # the ankles can only push as hard as the foot can take with its centre of pressure at the
        # toe (or heel) - beyond that the foot tips over; the rest goes to the hips (hip strategy)

        offset = servos.offset
        angles = servos.angles()
        velocities = servos.velocities()
        # a COM error the ankles cannot hold for long (a slope, a load) slowly leans the trunk
        # towards it - the quasi-static complement of the fast hip strategy below
        clipped = min(max(position_x, -self.ankle_limit_back), self.ankle_limit_front)
        self._lean += (CONSTANTS.lean_rate * (clipped - position_x) - CONSTANTS.lean_leak * self._lean) * self.ctx.control_dt
        self._lean = min(max(self._lean, -CONSTANTS.lean_max), CONSTANTS.lean_max)
        pelvis_pitch_goal = posture[1] * (1.0 - CONSTANTS.spine_share) + self._crouch_pitch + self._lean
        pelvis_pitch = math.atan2(-(pelvis_m[0] * ux + pelvis_m[3] * uy + pelvis_m[6] * uz),
                                  pelvis_m[2] * ux + pelvis_m[5] * uy + pelvis_m[8] * uz)
        # the knees servo the hip-to-ankle distance of the crouch pose (not the height, which
        # also changes when the whole body leans, on a slope or under a push)
        hx_, hy_, hz_ = (0.5 * (d.xpos[self.hips[0]] + d.xpos[self.hips[1]]) -
                         0.5 * (d.xpos[self.feet[0]] + d.xpos[self.feet[1]])).tolist()
        leg_length = math.sqrt(hx_ * hx_ + hy_ * hy_ + hz_ * hz_)
        knee_offset = self.params["height_kp"] * (leg_length - self._leg_length)
        ratio = self.damping_ratio
        heading_kp, spin_kp = self.params["heading_kp"], self.params["spin_kp"]
        spin = spin_kp * float(d.subtree_angmom[self.pelvis][2]) if spin_kp else 0.0
        # the hips hold the pelvis square to the feet where the ground gives: with the hips' and
        # ankles' pitch servos both following the measured angles, nothing else holds the legs'
        # scissor - on a rigid floor the feet's grip does; on a soft mat the feet twist in it and
        # the body turns over them
        square = (self.params["stagger_kp"] * (self.feet_stagger() - self._stagger)
                  if self.params["stagger_on_floor"] or (self.soft_ground and over_a_box(pts, self.soft_ground))
                  else 0.0)
        for k in (0, 1):
            j = idx[k]
            f = d.xmat[self.feet[k]].tolist()          # row-major 3x3: columns are the foot axes
            wx, wy, wz = d.cvel[self.feet[k], :3].tolist()
            # flat on the ground: pitch and roll against the ground's normal (world Z), not gravity
            foot_pitch = math.atan2(-f[6], f[8])
            foot_roll = math.atan2(f[7], f[8])
            pitch_rate = wx * f[1] + wy * f[4] + wz * f[7]
            roll_rate = wx * f[0] + wy * f[3] + wz * f[6]
            ay, ax, hy, hx = j["ankle_y"], j["ankle_x"], j["hip_y"], j["hip_x"]
            offset[j["knee_y"]] = knee_offset
            # ankles keep the feet flat (7.3-7.4) plus the COM servo offset; the servo's damping
            # is moved from the ankle rate onto the foot's own rate, so that it does not drag the
            # foot along when the shank rotates over it
            # the ankle command (foot-flat term + COM offset) is limited to what the foot can take
            # with its centre of pressure at the toe tip or the heel; the rest goes to the hips
            command = min(max(delta_x - foot_pitch, -self.ankle_limit_back), self.ankle_limit_front)
            targets[ay] = angles[ay]
            targets[ax] = angles[ax] - foot_roll
            offset[ay] = command + ratio[ay] * (velocities[ay] - pitch_rate)
            offset[ax] = -delta_y + ratio[ax] * (velocities[ax] - roll_rate)
            # hips hold the pelvis attitude, plus half the ankle offset (eqs. 7.1-7.2)
            targets[hy] = angles[hy] + (pelvis_pitch - pelvis_pitch_goal)
            offset[hy] = hip_x - square if k == 0 else hip_x + square
            offset[hx] = CONSTANTS.hip_share * delta_y
            if heading_kp or spin_kp:
                heading_error = math.remainder(yaw - math.atan2(f[3], f[0]), math.tau) if heading_kp else 0.0
                offset[j["hip_z"]] = heading_kp * heading_error + spin          # pelvis vs this foot, and the spin
        servos.hold(targets, t)


def inside_a_skill(**params) -> dict:
    """Validated Balance parameters for a balance inside another skill (a take-off's crouch, a
    landing's stand): ``params`` over the schema's, with ``stagger_on_floor`` off - those skills'
    tables were measured without it."""
    return Balance.schema.validate({**params, "stagger_on_floor": 0.0})
