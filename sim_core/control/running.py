"""Running (Hodgins et al. 1995, "Running"; Hodgins & Pollard 1997 §3.2).

A per-leg state machine (Fig. 3): the *active* leg is the one on the ground or being placed for
touchdown, the *idle* leg the other; they swap roles at lift-off. The active leg goes

    flight -> loading -> heel -> heel+toe -> toe -> unloading -> (lift-off: swap)

with transitions on contact (heel, ball of the foot) and, for the thrust, on the time since
touchdown reaching a fraction of the expected stance duration (30-50 %).

Control laws, each from the paper:
  * foot placement at touchdown, eqs. 1-2: hip-to-heel distance on the ground
    x_hh = 1/2 (t_s xdot - cos(theta) l_f) + k (xdot - xdot_d), likewise y; the leg length at
    touchdown is fixed, which gives z_hh; leg inverse kinematics gives hip and knee targets;
  * ground-speed matching: during flight the hip swings the leg further forward and brings it
    back just before touchdown, so that the foot meets the ground moving backwards;
  * stance: the knee is a spring (low gain, target = its touchdown angle); the ankle gives the
    thrust (ankle and knee extend in the toe state); the stance hip servos the body's roll,
    pitch (slightly forward) and yaw;
  * the idle leg is shortened and its hip mirrors the active hip (eqs. 3-4);
  * the shoulders swing against the opposite hip (eq. 5), elbows cycling with them;
  * every joint is a PD servo (eq. 6) whose target moves smoothly (the laws are continuous in
    the measured state, and targets that change at a state switch are blended along Hermite
    curves).

Steering: a facing direction, or a path followed by pure pursuit (running_path); the body leans
into the turn (desired roll from the turn rate). The run starts from the standing pose: the
body leans forward over the feet, the left leg pushes off and the state machine takes over
while the commanded speed ramps up.

Tuned values (the five parameters of Hodgins & Pollard §4.3.1) are data:
``rigs/tuned/running_<character>.json``, written by ``scripts/tune_running.py``; the schema
takes its defaults from it.
"""
from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

from sim_core.control.behaviour import Behaviour, ControlContext, register
from sim_core.control.running_leg import RunnerLeg
from sim_core.control.running_path import (PathFollower, circle_path, figure_eight_path, parse_points,
                                           turn_path, validate_path)
from sim_core.control.servo import hermite_scalar
from sim_core.errors import ParameterError
from sim_core.schema import Parameter, Schema

TUNED_DIR = Path(__file__).resolve().parents[2] / "rigs" / "tuned"
TUNED_NAMES = ("ground_speed_matching", "stance_pitch", "thrust_time", "ankle_extension", "knee_extension")

# states of the active leg (Hodgins 1995 Fig. 3)
FLIGHT, LOADING, HEEL, HEEL_TOE, TOE, UNLOADING, START = range(7)
STATE_NAMES = ("flight", "loading", "heel", "heel_toe", "toe", "unloading", "start")

CONTACT_HEIGHT = 0.004      # m: a foot contact sphere this close to the ground touches it
LOADING_TIME = 0.010        # s: contact held this long before the stance laws take over
SWAP_BLEND = 0.06           # s: Hermite blend of the new active leg's targets after lift-off
GRAVITY = 9.80665


def tuned_defaults(character: str = "man") -> dict[str, float]:
    """Tuned values for a character (rigs/tuned/running_<name>.json), or {} if none."""
    path = TUNED_DIR / f"running_{character}.json"
    try:
        data = json.loads(path.read_text())
    except (FileNotFoundError, json.JSONDecodeError):
        return {}
    return {k: float(v) for k, v in data.get("parameters", {}).items()}


_TUNED = tuned_defaults("man")


def _tuned(name: str, fallback: float) -> float:
    return _TUNED.get(name, fallback)


class RunningSchema(Schema):
    """The numeric parameters, plus ``path``: a list of [x, y] points in metres (on the CLI
    ``--set path="x,y; x,y; ..."``), validated into a clean polyline or refused as degenerate."""

    def validate(self, values: dict) -> dict:
        values = dict(values)
        path = values.pop("path", None)
        result = super().validate(values)
        if path is not None and not (isinstance(path, (list, tuple)) and len(path) == 0):
            result["path"] = validate_path(parse_points(path)).tolist()
        return result


@register
class Running(Behaviour):
    name = "running"
    summary = "Run at 2.5-5 m/s from a stand, facing a direction or along a path (Hodgins et al. 1995)."
    default_duration = 20.0
    control_rate = 200.0
    schema = RunningSchema(
        Parameter("speed", "m/s", 3.5, 2.5, 5.0, "desired running speed on the ground plane"),
        Parameter("facing", "rad", 0.0, -math.pi, math.pi,
                  "facing direction to run in (0 = +X, counter-clockwise), used when no path is given"),
        Parameter("course", "1", 0.0, 0.0, 3.0,
                  "built-in path: 0 = straight along facing, 1 = turn by turn_angle, 2 = figure eight, 3 = circle"),
        Parameter("turn_angle", "rad", math.pi / 2, -math.pi, math.pi, "course 1: angle of the turn (left positive)"),
        Parameter("turn_radius", "m", 5.0, 1.5, 50.0, "course 1-3: radius of the turn, of each loop of the eight, of the circle"),
        Parameter("turn_after", "m", 15.0, 2.0, 200.0, "course 1-3: distance run straight before the turn or the loops"),
        Parameter("lean", "1", 1.0, 0.0, 1.5, "share of the lean into a turn that balances the centripetal force (atan(v^2 / (g r)))"),
        Parameter("lookahead", "m", 2.5, 0.5, 10.0, "path following: distance along the path of the point the runner heads for"),
        Parameter("ground_speed_matching", "m", _tuned("ground_speed_matching", 0.10), 0.0, 0.3,
                  "tuned: how much further forward the foot swings during flight before it is brought back to touchdown"),
        Parameter("stance_pitch", "rad", _tuned("stance_pitch", 0.08), -0.1, 0.4,
                  "tuned: forward pitch of the pelvis the stance hip holds"),
        Parameter("thrust_time", "1", _tuned("thrust_time", 0.40), 0.2, 0.7,
                  "tuned: share of the expected stance time after which the ankle thrusts (toe state)"),
        Parameter("ankle_extension", "rad", _tuned("ankle_extension", 0.45), 0.0, 0.87,
                  "tuned: ankle plantarflexion the stance ankle extends to in thrust"),
        Parameter("knee_extension", "rad", _tuned("knee_extension", 0.10), 0.0, 0.8,
                  "tuned: knee angle the stance knee extends to in thrust"),
        Parameter("speed_gain", "s", _tuned("speed_gain", 0.08), 0.0, 0.3,
                  "k of eqs. 1-2: extra forward placement of the foot per m/s of speed error"),
        Parameter("touchdown_leg", "m", _tuned("touchdown_leg", 0.90), 0.75, 0.95,
                  "hip-to-heel distance at touchdown (fixes z_hh of eqs. 1-2)"),
        Parameter("idle_knee", "rad", _tuned("idle_knee", 1.6), 0.5, 2.4, "knee flexion of the idle (shortened) leg"),
        Parameter("arm_swing", "1", _tuned("arm_swing", 0.8), 0.0, 2.0,
                  "k of eq. 5: shoulder swing per radian of the opposite hip's swing"),
        Parameter("start_lean", "s", 0.35, 0.1, 1.0, "time the standing body leans forward before the first push-off"),
    )

    # --------------------------------------------------------------------- setup
    def __init__(self, params, ctx: ControlContext):
        super().__init__(params, ctx)
        m, s, ch = ctx.model, ctx.servos, ctx.character
        self.pelvis = m.body("PELVIS").id
        self.hip_body = [m.body("ULEGR").id, m.body("ULEGL").id]
        self.legs = [RunnerLeg(ch, "R"), RunnerLeg(ch, "L")]
        site = lambda n: m.site(n).id
        self.heel_sites = [[site(f"FOOT{c}_heel_a"), site(f"FOOT{c}_heel_b")] for c in "RL"]
        self.ball_sites = [[site(f"FOOT{c}_ball_a"), site(f"FOOT{c}_ball_b"), site(f"TOE{c}_toe_a"),
                            site(f"TOE{c}_toe_b")] for c in "RL"]
        self.foot_sites = np.array([i for k in range(2) for i in self.heel_sites[k] + self.ball_sites[k]])
        ix = s.index
        self.j = [dict(hy=ix[f"hip_{c}_y"], hx=ix[f"hip_{c}_x"], hz=ix[f"hip_{c}_z"], knee=ix[f"knee_{c}_y"],
                       ay=ix[f"ankle_{c}_y"], ax=ix[f"ankle_{c}_x"], mt=ix[f"mt_{c}_y"],
                       sx=ix[f"shoulder_{c}_x"], sy=ix[f"shoulder_{c}_y"], sz=ix[f"shoulder_{c}_z"],
                       ez=ix[f"elbow_{c}_z"]) for c in "rl"]
        self.leg_idx = [s.indices([f"hip_{c}_y", f"hip_{c}_x", f"hip_{c}_z", f"knee_{c}_y", f"ankle_{c}_y",
                                   f"ankle_{c}_x", f"mt_{c}_y"]) for c in "rl"]
        self.neck_y = ix["neck_c2_y"]
        self.spine_y = [ix[n] for n in ("spine_l3_y", "spine_l1_y", "spine_t7_y", "spine_t4_y")]
        self.base = ch.standing_pose.copy()
        self.kp0 = s.default_kp.copy()
        self.kv0 = s.default_kv.copy()
        self.ratio = (s.default_kv / s.default_kp).tolist()
        self.path = self._path()
        self.follower = PathFollower(self.path, params["lookahead"]) if self.path is not None else None

    def _path(self):
        p = self.params
        if "path" in p:
            return np.asarray(p["path"], dtype=float)
        course = int(round(p["course"]))
        if course == 1:
            return turn_path(p["turn_angle"], p["turn_after"], p["turn_radius"])
        if course == 2:
            return figure_eight_path(p["turn_radius"], p["turn_after"])
        if course == 3:
            return circle_path(p["turn_radius"], p["turn_after"])
        return None

    def check_feasible(self) -> None:
        p = self.params
        if abs(p["course"] - round(p["course"])) > 1e-9:
            raise ParameterError(f"parameter course={p['course']:g} must be a whole number 0, 1, 2 or 3")

    # --------------------------------------------------------------------- start
    def start(self, t: float) -> None:
        d = self.ctx.data
        self.targets = self.base.tolist()
        self.active = 1                      # the left leg pushes off first
        self.state = START
        self.t_state = t
        self.t_touchdown = t
        self.t_liftoff = t
        self.stance_time = 0.30              # expected stance duration t_s (from the last stance)
        self.flight_time = 0.10
        self.contact_since = None
        self.idle_lo = [0.0, 0.0]            # idle hip (y, x) at the last lift-off
        self.active_lo = [0.0, 0.0]          # active hip (y, x) at the last lift-off
        self.active_goal = [0.0, 0.0, 0.0]   # desired active hip (y, x, z)
        self.blend_from = None
        self.knee_touchdown = 0.2
        self.ankle_flat = 0.0
        self.heading_goal = self.params["facing"]
        self.roll_goal = 0.0
        self.speed_goal = 0.0
        self.step_count = 0
        self.event(t, "start")

    # --------------------------------------------------------------------- helpers
    def _set_leg_gains(self, leg: int, kp: dict, kv_ratio: float | None = None) -> None:
        """Gains of one leg's servos by joint key (hip, knee, ankle, mt); logged for replay."""
        j = self.j[leg]
        names = {"hip": ("hy", "hx", "hz"), "knee": ("knee",), "ankle": ("ay", "ax"), "mt": ("mt",)}
        idx, kps, kvs = [], [], []
        for key, value in kp.items():
            for n in names[key]:
                i = j[n]
                idx.append(i)
                kps.append(self.kp0[i] * value)
                kvs.append(self.kv0[i] * value if kv_ratio is None else self.kp0[i] * value * kv_ratio)
        self.ctx.servos.set_gains(np.array(idx), np.array(kps), np.array(kvs))

    def _enter(self, t: float, state: int) -> None:
        if state == TOE:
            self.t_thrust = t
        self.state = state
        self.t_state = t
        side = "R" if self.active == 0 else "L"
        self.event(t, f"{STATE_NAMES[state]}_{side}")
        a = self.active
        if state == FLIGHT:
            self._set_leg_gains(a, {"hip": 1.0, "knee": 1.0, "ankle": 1.0, "mt": 0.5})
            self._set_leg_gains(1 - a, {"hip": 1.0, "knee": 0.6, "ankle": 0.5, "mt": 0.3})
        elif state == HEEL:
            self._set_leg_gains(a, {"knee": STANCE_KNEE_GAIN, "ankle": 0.3})
        elif state == HEEL_TOE:
            self._set_leg_gains(a, {"knee": STANCE_KNEE_GAIN, "ankle": 1.0})
        elif state == TOE:
            self._set_leg_gains(a, {"knee": 1.0, "ankle": 1.0})

    # --------------------------------------------------------------------- control
    def update(self, t: float) -> None:
        d = self.ctx.data
        p = self.params
        servos = self.ctx.servos
        q = servos.angles().tolist()
        qd = servos.velocities().tolist()
        m = d.xmat[self.pelvis].tolist()
        wx, wy, wz = d.cvel[self.pelvis, :3].tolist()
        cx, cy, cz = d.subtree_com[self.pelvis].tolist()
        vx, vy, vz = d.subtree_linvel[self.pelvis].tolist()
        z = d.site_xpos[self.foot_sites, 2].tolist()
        heel = [min(z[0], z[1]) < CONTACT_HEIGHT, min(z[6], z[7]) < CONTACT_HEIGHT]
        ball = [min(z[2], z[3], z[4], z[5]) < CONTACT_HEIGHT, min(z[8], z[9], z[10], z[11]) < CONTACT_HEIGHT]
        touch = [heel[0] or ball[0], heel[1] or ball[1]]

        yaw = math.atan2(m[3], m[0])
        pitch = math.atan2(-m[6], m[8])
        roll = math.atan2(m[7], m[8])
        pitch_rate = wx * m[1] + wy * m[4] + wz * m[7]
        roll_rate = wx * m[0] + wy * m[3] + wz * m[6]

        # ---- steering: facing direction (or pure pursuit on the path) and lean into the turn
        if self.follower is not None:
            goal = self.follower.heading(cx, cy)
        else:
            goal = p["facing"]
        speed_now = math.hypot(vx, vy)
        turn = _wrap(goal - self.heading_goal)
        max_turn = 2.0 * max(speed_now, 1.0) / max(p["turn_radius"], 1.5) / self.control_rate
        self.heading_goal = _wrap(self.heading_goal + max(-max_turn, min(max_turn, turn)))
        turn_rate = max(-max_turn, min(max_turn, turn)) * self.control_rate
        roll_target = -p["lean"] * math.atan(speed_now * turn_rate / GRAVITY)
        self.roll_goal += 0.05 * (roll_target - self.roll_goal)
        heading = self.heading_goal
        ch, sh = math.cos(heading), math.sin(heading)
        # commanded speed ramps up from the stand (the foot is placed to accelerate by <= 1 m/s per step)
        speed_cmd = min(p["speed"], speed_now + ACCEL_MARGIN)
        vxd, vyd = speed_cmd * ch, speed_cmd * sh

        a = self.active
        i = 1 - a
        ja, ji = self.j[a], self.j[i]
        targets = self.targets

        # ---- state transitions of the active leg
        state = self.state
        if state == START:
            lean_done = t - self.t_state >= p["start_lean"]
            if lean_done:
                # the left leg pushes off (toe state), the right becomes the idle leg
                self.idle_lo = [q[ji["hy"]], q[ji["hx"]]]
                self.active_lo = [q[ja["hy"]], q[ja["hx"]]]
                self.t_touchdown = t - 0.5 * self.stance_time
                self._enter(t, TOE)
        elif state == FLIGHT:
            if touch[a]:
                self.flight_time = 0.5 * self.flight_time + 0.5 * (t - self.t_liftoff)
                self.t_touchdown = t
                self.knee_touchdown = q[ja["knee"]]
                self._enter(t, LOADING)
        elif state == LOADING:
            if not touch[a]:
                self._enter(t, FLIGHT)
            elif t - self.t_state >= LOADING_TIME:
                self.ankle_flat = q[ja["ay"]]
                self._enter(t, HEEL_TOE if ball[a] else HEEL)
        elif state == HEEL:
            if ball[a]:
                self.ankle_flat = q[ja["ay"]]
                self._enter(t, HEEL_TOE)
            elif t - self.t_touchdown >= p["thrust_time"] * self.stance_time:
                self._enter(t, TOE)
        elif state == HEEL_TOE:
            if t - self.t_touchdown >= p["thrust_time"] * self.stance_time:
                self._enter(t, TOE)
        elif state in (TOE, UNLOADING):
            if state == TOE and (not heel[a]) and t - self.t_touchdown >= self.stance_time * 0.85:
                self._enter(t, UNLOADING)
            if not touch[a]:
                # lift-off: the legs swap roles
                self.stance_time = min(0.45, max(0.12, 0.5 * self.stance_time + 0.5 * (t - self.t_touchdown)))
                self.t_liftoff = t
                self.step_count += 1
                self.active_lo = [q[ji["hy"]], q[ji["hx"]]]      # the new active leg's hip now
                self.idle_lo = [q[ja["hy"]], q[ja["hx"]]]        # the new idle leg's hip now
                self.blend_from = [targets[ji["hy"]], targets[ji["hx"]], targets[ji["hz"]],
                                   targets[ji["knee"]], targets[ji["ay"]]]
                self.active = a = i
                i = 1 - a
                ja, ji = self.j[a], self.j[i]
                self.event(t, "liftoff")
                self._enter(t, FLIGHT)
            elif touch[i] and state == UNLOADING:
                pass
        state = self.state

        # ---- active leg
        r = self.ratio
        if state == START:
            s = hermite_scalar((t - self.t_state) / p["start_lean"])
            for leg in (0, 1):
                jj = self.j[leg]
                targets[jj["ay"]] = -START_ANKLE_LEAN * s
                targets[jj["knee"]] = 0.15 * s
                targets[jj["hy"]] = q[jj["hy"]] + (pitch - p["stance_pitch"] * s) + r[jj["hy"]] * (qd[jj["hy"]] + pitch_rate)
            hy_goal = targets[ja["hy"]]
            hx_goal = 0.0
        elif state == FLIGHT:
            leg = self.legs[a]
            hip = d.xpos[self.hip_body[a]].tolist()
            ts = self.stance_time
            lf = leg.foot_length
            x_hh = 0.5 * (ts * vx - ch * lf) + p["speed_gain"] * (vx - vxd)
            y_hh = 0.5 * (ts * vy - sh * lf) + p["speed_gain"] * (vy - vyd)
            # lateral: toward the centre line (feet land nearly under the body)
            side = -1.0 if a == 0 else 1.0
            x_hh += -side * sh * FOOT_INWARD
            y_hh += side * -ch * FOOT_INWARD
            # ground speed matching: further forward early in flight, brought back before touchdown
            phase = (t - self.t_liftoff) / max(self.flight_time, 0.03)
            gsm = p["ground_speed_matching"] * (1.0 - hermite_scalar((phase - 0.3) / 0.7))
            x_hh += gsm * ch
            y_hh += gsm * sh
            reach = math.hypot(x_hh, y_hh)
            limit = 0.6 * p["touchdown_leg"]
            if reach > limit:
                x_hh *= limit / reach
                y_hh *= limit / reach
            z_hh = math.sqrt(max(p["touchdown_leg"] ** 2 - x_hh * x_hh - y_hh * y_hh, 0.01))
            fx, fz = leg.ankle_from_heel(TOUCHDOWN_TOE_UP)
            ax_w, ay_w, az_w = x_hh + fx * ch, y_hh + fx * sh, -z_hh + fz
            # world -> pelvis frame (R^T v); m is row-major world-from-pelvis
            px = m[0] * ax_w + m[3] * ay_w + m[6] * az_w
            py = m[1] * ax_w + m[4] * ay_w + m[7] * az_w
            pz = m[2] * ax_w + m[5] * ay_w + m[8] * az_w
            hy_goal, hx_goal, knee_goal = leg.hip_knee_for(px, py, pz)
            hz_goal = max(-0.4, min(0.4, _wrap(heading - yaw))) * (1.0 if a == 0 else 1.0)
            # ankle: foot pitched toe-up at touchdown (pitch of the foot = pelvis pitch + hip + knee + ankle)
            ankle_goal = -TOUCHDOWN_TOE_UP - pitch - hy_goal - knee_goal
            blend = hermite_scalar((t - self.t_liftoff) / SWAP_BLEND) if self.blend_from else 1.0
            goals = (hy_goal, hx_goal, hz_goal, knee_goal, ankle_goal)
            keys = ("hy", "hx", "hz", "knee", "ay")
            for k_, key in enumerate(keys):
                start = self.blend_from[k_] if self.blend_from else goals[k_]
                targets[ja[key]] = start + (goals[k_] - start) * blend
            targets[ja["ax"]] = 0.0
            targets[ja["mt"]] = 0.0
            hy_goal, hx_goal = targets[ja["hy"]], targets[ja["hx"]]
        else:
            # stance: the hip servos the body attitude (roll, pitch, yaw); damping acts on the
            # body's rates (the servo's own damping on the joint rate is cancelled)
            pitch_goal = p["stance_pitch"]
            e_pitch = pitch - pitch_goal
            e_roll = roll - self.roll_goal
            e_yaw = _wrap(yaw - heading)
            targets[ja["hy"]] = q[ja["hy"]] + ATT_GAIN * e_pitch + r[ja["hy"]] * (qd[ja["hy"]] + ATT_DAMP * pitch_rate)
            targets[ja["hx"]] = q[ja["hx"]] + ATT_GAIN * e_roll + r[ja["hx"]] * (qd[ja["hx"]] + ATT_DAMP * roll_rate)
            targets[ja["hz"]] = q[ja["hz"]] + ATT_GAIN * e_yaw + r[ja["hz"]] * (qd[ja["hz"]] + ATT_DAMP * wz)
            if state in (LOADING, HEEL, HEEL_TOE):
                targets[ja["knee"]] = self.knee_touchdown
                if state == HEEL:
                    # let the foot come down flat
                    targets[ja["ay"]] = -(pitch + q[ja["hy"]] + q[ja["knee"]])
                elif state == HEEL_TOE:
                    targets[ja["ay"]] = self.ankle_flat
            else:
                s = hermite_scalar((t - self.t_state) / THRUST_RAMP)
                targets[ja["knee"]] = self.knee_touchdown + (p["knee_extension"] - self.knee_touchdown) * s
                targets[ja["ay"]] = p["ankle_extension"]
            targets[ja["ax"]] = 0.0
            targets[ja["mt"]] = 0.0
            hy_goal, hx_goal = targets[ja["hy"]], targets[ja["hx"]]
        self.active_goal = [hy_goal, hx_goal]

        # ---- idle leg: shortened, hip mirroring the active hip (eqs. 3-4)
        if state != START:
            hy_idle = self.idle_lo[0] - (hy_goal - self.active_lo[0])
            hx_idle = self.idle_lo[1] - (hx_goal - self.active_lo[1])
            side = 1.0 if i == 0 else -1.0           # +x adducts the right hip, abducts the left
            hx_idle = side * max(-0.15, min(0.05, side * hx_idle))
            hy_idle = max(-1.2, min(0.5, hy_idle))
            targets[ji["hy"]] = hy_idle
            targets[ji["hx"]] = hx_idle
            targets[ji["hz"]] = 0.0
            if state in (TOE, UNLOADING):
                # the idle leg prepares for its touchdown while the active leg thrusts: the knee
                # unfolds so that the short flight can swing it out to the placement
                s_ = hermite_scalar((t - self.t_thrust) / max(IDLE_UNFOLD * self.stance_time, 0.02))
                targets[ji["knee"]] = p["idle_knee"] + (IDLE_UNFOLD_KNEE - p["idle_knee"]) * s_
            else:
                targets[ji["knee"]] = p["idle_knee"]
            targets[ji["ay"]] = -0.2
            targets[ji["ax"]] = 0.0
            targets[ji["mt"]] = 0.0

        # ---- arms (eq. 5): each shoulder swings against the opposite hip; elbows cycle with it
        k_arm = p["arm_swing"]
        for leg in (0, 1):
            jj, opposite = self.j[leg], self.j[1 - leg]
            sign = 1.0 if leg == 0 else -1.0
            swing = -k_arm * q[opposite["hy"]] + ARM_OFFSET
            targets[jj["sz"]] = sign * swing
            targets[jj["ez"]] = sign * (ELBOW_BASE + ELBOW_SWING * swing)
        targets[self.neck_y] = -p["stance_pitch"]
        servos.hold(np.array(targets), t)


def _wrap(angle: float) -> float:
    return (angle + math.pi) % (2.0 * math.pi) - math.pi


STANCE_KNEE_GAIN = 1.0   # share of the knee's default kp in stance (the knee is a spring)
ATT_GAIN = 1.0                # stance hip: joint-target radians per radian of attitude error
ATT_DAMP = 1.0
THRUST_RAMP = 0.05            # s: the thrust targets move in over this time
TOUCHDOWN_TOE_UP = 0.20       # rad: foot pitched toe-up at touchdown, heel first
FOOT_INWARD = 0.05            # m: the foot lands this far inside the hip, toward the centre line
ACCEL_MARGIN = 1.0            # m/s: the speed command is at most this above the current speed
START_ANKLE_LEAN = 0.25       # rad of ankle dorsiflexion target while leaning into the start
IDLE_UNFOLD = 0.6            # share of the expected stance over which the idle knee unfolds after thrust
IDLE_UNFOLD_KNEE = 0.6       # rad: idle knee flexion at the end of the unfolding
ARM_OFFSET = 0.1              # gamma_0 of eq. 5 (rad, forward)
ELBOW_BASE = 1.3              # rad: running elbow flexion
ELBOW_SWING = 0.3             # extra elbow flexion per radian of forward arm swing
