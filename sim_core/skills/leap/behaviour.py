"""The leap skill (Wooten ch. 4, 8): a vertical leap to a commanded height or a broad jump to a
commanded distance - balance crouch, proximal-to-distal thrust, landing, balance - with the
settings looked up in the calibrated leap table."""
from __future__ import annotations

import math

import numpy as np

from ...ballistics import GRAVITY
from ...control.balance import Balance, inside_a_skill, standing_hip_height
from ...control.behaviour import register
from ...control.commanded_thrust import CommandedThrust, FlightCommand, thrust_due
from ...control.measure import SupportGeometry
from ...control.recovery_step import RecoveryStep, StaggeredStance, StanceMeasure, StepAndHold
from ...control.leap import FLIGHT_TARGET_X, FLIGHT_TARGET_Y, LANDING_ARM_PITCH, LANDING_ARM_PITCH_GAIN, LANDING_RECOVERY_STEP, LANDING_STEP_MARGIN, LANDING_DELTA_FROM_DROP, LANDING_TOE_FIRST_AT_SPEED, LANDING_TUCK_KNEE_FLEXION, LANDING_TUCK_SHARE, LEAN_PUSH, RECOVERY_STEP_EVENT, LOW_LEVEL_SETTINGS, Landing, LeapThrust, balance_after_landing, foot_delta_lookup, broad_distances, broad_row, broad_rows, commandable_heights, leap_assess, leap_constants, load_mapping, vertical_key, vertical_row, vertical_table
from ...control.sequencer import Sequence, Step
from ...control.turn import jump_start, turn_steps
from ...errors import ParameterError
from ...schema import Parameter
from ...tuned import load, require_calibrated
from ...tuned.settings import SkillSchema


@register
class Leap(Sequence):
    name = "leap"
    summary = "Vertical leap or standing broad jump: crouch, extend, fly, land, balance (Wooten ch. 4, 6, 8)."
    default_duration = 5.0
    settings_schema = LOW_LEVEL_SETTINGS
    schema = SkillSchema(
        Parameter("height", "m", 0.3, 0.05, 1.2,
                  "commanded rise of the COM above standing (vertical leap): runs the calibrated leap nearest "
                  "it if that one's measured rise is within 10 % (3 cm below 0.3 m), else interpolates"),
        Parameter("distance", "m", 0.0, 0.0, 2.5,
                  "commanded horizontal COM travel (broad jump); 0 = vertical leap: runs the calibrated broad "
                  "jump nearest it if that one's measured travel is within 10 %, else interpolates"),
        Parameter("liftoff_hip", "rad", 0.0, -1.0, 1.0,
                  "hip flexion (-) or extension (+) at lift-off beyond the calibrated neutral (0 = no "
                  "somersault): sends the ground force past the COM and sets the somersault rate"),
        Parameter("low_level", "bool", 0.0, 0.0, 1.0,
                  "1 = run the low-level settings as set (--set crouch_height=...) instead of the calibrated leap"),
        Parameter("crouch_time", "s", 0.8, 0.3, 3.0, "time to sink into the crouch"),
        FLIGHT_TARGET_X,
        FLIGHT_TARGET_Y,
        Parameter("flight_target_z", "m", 0.0, -1.0, 1.0,
                  "commanded take-off: the feet land on a surface this high above the one stood on"),
        Parameter("flight_air_time", "s", 0.45, 0.05, 1.5, "commanded take-off: the feet are this long in the air"),
        Parameter("foot_delta", "m", 0.0, -0.3, 0.3, "landing: foot servo delta (see the land behaviour)"),
        Parameter("landing_knee_flexion", "rad", 0.9, 0.0, 1.5,
                  "landing: knee bend held in flight (less: the feet reach further forward)"),
        Parameter("landing_place_sideways", "bool", 0.0, 0.0, 1.0,
                  "landing: 1 = place the leading foot sideways by the COM's sideways speed (a sideways jump)"),
        Parameter("landing_swing_arms", "bool", 0.0, 0.0, 1.0,
                  "landing: 1 = swing the arms to landing_arm_flexion in flight (0 = hold them)"),
        Parameter("landing_arm_flexion", "rad", 0.6, -1.0, 3.0,
                  "landing: forward raise of the arms they swing to in flight (below 0: down and back, "
                  "which pitches the trunk back so the feet reach forward)"),
        LANDING_ARM_PITCH_GAIN,
        LANDING_ARM_PITCH,
        Parameter("landing_foot_lead_time", "s", 0.2, 0.0, 0.6,
                  "landing: the feet land this many seconds of horizontal COM travel ahead of the COM"),
        Parameter("landing_right_time", "s", 0.0, 0.0, 1.0,
                  "landing: after touchdown the hips right the trunk over this time (0 = at once)"),
        LANDING_RECOVERY_STEP,
        LANDING_STEP_MARGIN,
        LANDING_TUCK_KNEE_FLEXION,
        LANDING_TUCK_SHARE,
        LANDING_TOE_FIRST_AT_SPEED,
        LANDING_DELTA_FROM_DROP,
        LEAN_PUSH,
        settings=LOW_LEVEL_SETTINGS,
    )

    @classmethod
    def character_defaults(cls, character: str) -> dict:
        """A body whose calibrated leaps do not reach the schema's height (the child's 0.03-0.26 m
        against 0.3 m) leaps, unless told, to the middle of what it is offered."""
        rises = (load("leap", character) or {}).get(vertical_table("human"), {}).get("com_rise", [])
        if not rises:
            return {}
        low, high = commandable_heights(rises)
        height = cls.schema.by_name["height"].default
        return {} if low <= height <= high else {"height": round((low + high) / 2, 2)}

    def run_params(self) -> dict:
        """The parameters the leap runs with: the user's, or for a broad jump (distance > 0) the
        low-level leap of the calibrated broad jump within 10 % of the distance, else interpolated
        between the two whose measured COM travels bracket it (control.leap.broad_row; python -m
        sim_core calibrate leap plans the rows as jumps to a point straight ahead and fills the
        gaps between them), with the user's lift-off hip angle added."""
        p = self.params
        if p["low_level"] or p["distance"] <= 0:
            return p
        row = broad_row(load_mapping(self.ctx.character.name)["broad"], p["distance"])
        row["liftoff_hip"] = row.get("liftoff_hip", 0.0) + p["liftoff_hip"]
        return self.schema.validate(row)

    def settings(self, p: dict) -> dict:
        """The leap's low-level settings for the run parameters ``p``: the user's own (low_level) or
        the vertical-leap table's for the commanded height (vertical_row), with the user's lift-off
        hip angle added."""
        if p["low_level"]:
            settings = {k: p[k] for k in ("crouch_height", "crouch_pitch", "com_offset", "com_offset_y",
                                          "liftoff_roll", "arm_swing", "crouch_arms", "thrust_damping",
                                          "thrust_lean", "spin_hold", "turn_first", "turn_angle", "commanded_takeoff")}
            settings["liftoff_hip"] = p["liftoff_hip"]
            return settings
        row = vertical_row(load_mapping(self.ctx.character.name)[vertical_key(self.ctx)], p["height"])
        return {**row, "liftoff_hip": row["liftoff_hip"] + p["liftoff_hip"]}

    def check_feasible(self) -> None:
        p = self.params
        if p["low_level"]:
            return
        require_calibrated("leap", self.ctx.character.name, self.name)
        mapping = load_mapping(self.ctx.character.name)
        if p["distance"] > 0:
            travels, _ = broad_rows(mapping["broad"]) if mapping.get("broad") else ([], [])
            if not len(travels):
                raise ParameterError(f"the broad jump of {self.ctx.character.name} is not calibrated (distance "
                                     f"must be 0): run python -m sim_core calibrate leap --only broad (or use low_level=1)")
            low, high = broad_distances(travels)
            if not low <= p["distance"] <= high:
                raise ParameterError(
                    f"parameter distance={p['distance']:g} m is {'below' if p['distance'] < low else 'beyond'} the "
                    f"calibrated broad jumps of {self.ctx.character.name}; allowed range is [{low:.2f}, {high:.2f}] m "
                    f"(calibrated broad jumps travel {travels[0]:.2f} ... {travels[-1]:.2f} m; python -m sim_core "
                    f"calibrate leap --only broad)")
        else:
            key = vertical_key(self.ctx)
            strength = "unlimited strength" if key.endswith("unlimited") else "human torque limits"
            rises = mapping.get(key, {}).get("com_rise", [])
            if not rises:
                raise ParameterError(f"the vertical leap of {self.ctx.character.name} with {strength} is not "
                                     f"calibrated: run python -m sim_core calibrate leap (or use low_level=1)")
            low, high = commandable_heights(rises)
            allowed = (f"allowed range is [{low:.2f}, {high:.2f}] m (calibrated leaps rise "
                       f"{min(rises):.2f} ... {max(rises):.2f} m)")
            if p["height"] < low:
                raise ParameterError(f"parameter height={p['height']:g} m is below the calibrated leaps of "
                                     f"{self.ctx.character.name} with {strength}; {allowed}")
            if p["height"] > high:
                raise ParameterError(f"parameter height={p['height']:g} m is infeasible for "
                                     f"{self.ctx.character.name} with {strength}; {allowed}")

    def flight_target(self, p: dict) -> tuple[tuple, float]:
        """The commanded take-off's flight: the middle of the feet's landing point (x, y, z m from the
        middle of the feet at the start) and the air time (s)."""
        return (p["flight_target_x"], p["flight_target_y"], p["flight_target_z"]), p["flight_air_time"]

    def flight_command(self, p: dict, constants, delta: float, lead: float, push: float,
                       from_drop: bool = False) -> FlightCommand:
        """The commanded take-off's flight (control.commanded_thrust), landed by this leap's landing
        (its foot lead, its delta and the landing table's own delta); ``push`` its lean's push (LEAN_PUSH);
        ``from_drop``: the landing reads the table's delta for the touchdown speed on the surface landed on
        (LANDING_DELTA_FROM_DROP: the lift-off's vertical speed and the drop to it), else for the lift-off's."""
        target, air_time = self.flight_target(p)
        table_delta = foot_delta_lookup(self.ctx.character.name)
        drop = -float(target[2])
        touchdown = (lambda up: math.sqrt(max(up * up + 2.0 * GRAVITY * drop, 0.0))) if from_drop else abs   # ballistics
        hip = standing_hip_height(self.ctx.character)
        return FlightCommand(tuple(float(v) for v in target), float(air_time), float(lead), float(delta),
                             constants.commanded_touchdown_height * hip, constants.commanded_liftoff_height * hip,
                             push, constants.commanded_servo_time,
                             constants.commanded_correction_limit, constants.commanded_start_share,
                             constants.commanded_spin, constants.commanded_spin_gain,
                             lambda speed, up: table_delta(speed, touchdown(up)))

    def is_broad(self, p: dict) -> bool:
        """The broad jump's thrust (0.15/0.20/0.45 s extension, triggered by the leaning COM) for
        the run parameters ``p``."""
        return p["distance"] > 0

    def steps(self) -> list[Step]:
        p, ctx = self.run_params(), self.ctx
        cfg = self.settings(p)
        broad = self.is_broad(p)
        constants = leap_constants(ctx.character.name)

        def crouch(t):
            return Balance(inside_a_skill(pelvis_height=cfg["crouch_height"], torso_pitch=cfg["crouch_pitch"],
                                                com_offset_x=cfg["com_offset"],
                                                com_offset_y=cfg.get("com_offset_y", 0.0),
                                                arm_flexion=cfg.get("crouch_arms", 0.0), move_start=constants.crouch_move_start,
                                                heading_kp=constants.sideways_heading_kp if cfg.get("com_offset_y") else 0.0,
                                                spin_kp=cfg.get("spin_hold", 0.0),
                                                move_time=cfg["crouch_time"] if "crouch_time" in cfg
                                                else p["crouch_time"],
                                                hold_time=0.0, return_to_stand=0), ctx)

        def landing_settings():
            # the calibrated leap's own correction of the landing's foot servo delta, plus the user's
            knob = Leap.schema.by_name["foot_delta"]
            delta = min(max(p.get("foot_delta", 0.0) + cfg.get("foot_delta", 0.0), knob.minimum), knob.maximum)
            landing = {k: cfg.get("landing_" + k, p.get("landing_" + k, Landing.schema.defaults()[k]))
                       for k in ("swing_arms", "arm_flexion", "foot_lead_time", "place_sideways", "knee_flexion",
                                 "right_time", "arm_pitch_gain", "arm_pitch", "toe_first_at_speed", "delta_from_drop")}
            share = cfg.get("landing_tuck_share", p.get("landing_tuck_share", LANDING_TUCK_SHARE.default))
            if share > 0.0:     # the tuck, held for its share of the commanded flight's air time
                knee = cfg.get("landing_tuck_knee_flexion", p.get("landing_tuck_knee_flexion", LANDING_TUCK_KNEE_FLEXION.default))
                landing.update(tuck_knee_flexion=knee, tuck_time=share * float(self.flight_target(p)[1]))
            return delta, landing

        commanded = cfg.get("commanded_takeoff", 0.0) > 0.5
        if commanded:
            delta, landing = landing_settings()
            # the lean's push: the plan's own (a row measured with its own) over the run's, else the constant
            push = cfg.get("lean_push", p.get("lean_push", 0.0)) or constants.commanded_lean_push
            command = self.flight_command(p, constants, delta, landing["foot_lead_time"], push,
                                          bool(landing["delta_from_drop"]))
            support = SupportGeometry(ctx.model, prefix=ctx.actor.prefix)
            origin = support.points(ctx.data)
            origin = np.array([*origin[:, :2].mean(axis=0), float(origin[:, 2].min())])

        def lean(t):
            # the commanded take-off leans on from the crouch until the lean will give the flight's
            # horizontal speed (thrust_due), or the lean is at its furthest
            return Balance(inside_a_skill(pelvis_height=cfg["crouch_height"], torso_pitch=cfg["crouch_pitch"],
                                                com_offset_x=constants.commanded_lean_offset,
                                                arm_flexion=cfg.get("crouch_arms", 0.0), move_start=0.0,
                                                move_time=constants.commanded_lean_wait, hold_time=0.0,
                                                return_to_stand=0), ctx, from_height=cfg["crouch_height"])

        def leaned(b, t):
            return b.posture_reached(t) or thrust_due(command, ctx.data, b.pelvis, support, origin)

        def crouched(b, t):
            if commanded:
                return b.posture_reached(t)
            if broad:
                # broad jump: thrust once the COM, leaning forward, has left the middle of the
                # feet by the requested offset (Wooten §4.2: it would fall out of the support next)
                sideways = cfg.get("com_offset_y", 0.0)
                if sideways:        # a sideways jump: thrust once the COM has left the feet sideways
                    return b.posture_reached(t) or b.com_left_of_support() * math.copysign(1.0, sideways) > \
                        constants.broad_trigger * abs(sideways)
                return b.posture_reached(t) or b.com_ahead_of_support() > constants.broad_trigger * cfg["com_offset"]
            return b.posture_reached(t - constants.crouch_settle_time)

        def thrust(t):
            settings = dict(timing=constants.broad_timing if broad else constants.vertical_timing,
                            ankle_gain=constants.ankle_gain_broad if broad else constants.ankle_gain_vertical,
                            liftoff_hip=cfg["liftoff_hip"], arm_swing=cfg["arm_swing"],
                            stand_height=standing_hip_height(ctx.character), thrust_damping=cfg["thrust_damping"],
                            liftoff_roll=cfg.get("liftoff_roll", 0.0), thrust_lean=cfg.get("thrust_lean", 0.0),
                            spin_hold=cfg.get("spin_hold", 0.0))
            if commanded:
                settings["timing"] = tuple(t * constants.commanded_timing_scale for t in settings["timing"])
                # after a turn (turn_angle, or turn_first's quarter turn) the flight is aimed from the start's feet, the
                # spin about the new heading's side
                turned = dict(origin=origin, turned=True) if cfg.get("turn_angle", 0.0) or cfg.get("turn_first", 0.0) else {}
                return CommandedThrust({}, ctx, cfg["crouch_height"], command, **turned, **settings)
            return LeapThrust({}, ctx, cfg["crouch_height"], **settings)

        def land(t):
            delta, landing = landing_settings()
            landing["fast_knee_flexion"] = landing["knee_flexion"]     # calibrated with one knee bend
            return Landing(Landing.schema.validate(dict(foot_delta=delta, **landing)), ctx)

        # the recovery step's settings, like the landing's: the plan's (jump_to_target) over the run's (the leap)
        recovery = cfg.get("landing_recovery_step", p.get("landing_recovery_step", 0.0)) > 0.5
        margin = cfg.get("landing_step_margin", p.get("landing_step_margin", LANDING_STEP_MARGIN.default))
        if recovery:
            stance = StanceMeasure(ctx, StaggeredStance.schema.defaults()["min_height"])

        def landed(b, t):
            # with the recovery step the landing also ends, once the feet are down and the COM has stopped
            # falling (the impact taken), when the capture point leaves what the feet hold: the step
            return b.finished or (recovery and b.stage != "flight" and float(ctx.data.subtree_linvel[b.pelvis][2]) >= 0.0
                                  and bool(stance.outside(margin)))

        def stand(t):
            if recovery:
                return self.recovery(stance, margin)
            return balance_after_landing(ctx, self.previous)

        return turn_steps(ctx, cfg.get("turn_first", 0.0), self, cfg.get("turn_angle", 0.0)) + [
                Step("crouch", crouch, crouched)] + ([Step("lean", lean, leaned)] if commanded else []) + [
                Step("thrust", thrust, lambda b, t: b.lifted_off()),
                Step("land", land, landed),
                Step("balance", stand)]

    def recovery(self, measure: StanceMeasure, margin: float) -> StepAndHold:
        """The landing's recovery step (landing_recovery_step): the staggered stance from the feet as they
        landed, and a step wherever its capture point comes within ``margin`` of the support's edge - at once
        if it is there already (control/recovery_step.py StepAndHold, its parameters' defaults); the first
        step is a 'recovery_step' event; ``measure``: the landing's own StanceMeasure."""
        step, stance = RecoveryStep.schema.defaults(), StaggeredStance.schema.defaults()
        return RecoveryOnLanding(StepAndHold.schema.validate(dict(margin=margin)), self.ctx, step, stance,
                                 measure.outside(margin))

    @classmethod
    def assess(cls, trajectory):
        return leap_assess(trajectory, start=jump_start(trajectory))


class RecoveryOnLanding(StepAndHold):
    """StepAndHold whose first step is marked by the landing's RECOVERY_STEP_EVENT (leap_assess reads it)."""

    stepped = False

    def _begin(self, behaviour, t: float) -> None:
        if isinstance(behaviour, RecoveryStep) and not self.stepped:
            self.stepped = True
            self.event(t, RECOVERY_STEP_EVENT)
        super()._begin(behaviour, t)
