"""Gait metrics read off a trajectory: when each foot touches and leaves the ground, and from
that the step frequency, step length, stance/step fraction and mean speed that Hodgins &
Pollard 1997 (Fig. 12) compare with human runners.

Everything is measured on the recorded frames, not on the controller's own bookkeeping: a foot
is on the ground while any of its contact sites (heel, ball, toe spheres) is within
CONTACT_HEIGHT of it. Short flickers (a heel bouncing for one frame) are merged.
"""
from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np

from .analysis import true_runs
from .trajectory import Trajectory

STEADY_RUN = 30.0            # s: a run from a stand whose last 10 s are at steady speed, where TARGETS.md's
                             # speed is measured (the fast speeds accelerate for ~14 s: 90 % of 4.5 m/s at 13.7 s)
CONTACT_HEIGHT = 0.005       # m: a contact sphere this close to the ground supports the foot
MIN_PHASE = 0.02             # s: contact or air phases shorter than this are merged into their neighbours
FEET = (("R", ("FOOTR", "TOER")), ("L", ("FOOTL", "TOEL")))


@dataclass
class Contact:
    foot: str
    start: float             # s: touchdown
    end: float               # s: lift-off
    position: np.ndarray     # ground position (x, y) of the foot's sites at touchdown (mean)

    @property
    def duration(self) -> float:
        return self.end - self.start


def foot_site_columns(traj: Trajectory) -> dict[str, np.ndarray]:
    """Columns of ``support_points`` that belong to each foot (read off the model in the run)."""
    model = mujoco.MjModel.from_xml_string(traj.meta["model_xml"])
    prefix = traj.meta.get("actor_prefix", "")              # one actor of a scene: its own feet
    feet = {model.body(prefix + n).id for n in ("FOOTR", "FOOTL", "TOER", "TOEL")}
    sites = [i for i in range(model.nsite) if model.site_bodyid[i] in feet]   # the recorder's order
    columns = {}
    for foot, bodies in FEET:
        ids = {model.body(prefix + b).id for b in bodies}
        columns[foot] = np.array([k for k, s in enumerate(sites) if model.site_bodyid[s] in ids])
    return columns


def contacts(traj: Trajectory, t_from: float = 0.0) -> list[Contact]:
    """Every ground contact of each foot (touchdown, lift-off), sorted by touchdown time."""
    a = traj.arrays
    time, points = a["time"], a["support_points"]
    dt = float(np.median(np.diff(time))) if len(time) > 1 else 1.0
    gap = max(1, int(round(MIN_PHASE / dt)))
    found = []
    for foot, cols in foot_site_columns(traj).items():
        on = (points[:, cols, 2] < CONTACT_HEIGHT).any(axis=1)
        runs = true_runs(on)
        merged = []
        for start, end in runs:                      # merge contacts separated by a flicker of air
            if merged and start - merged[-1][1] < gap:
                merged[-1] = (merged[-1][0], end)
            else:
                merged.append((start, end))
        for start, end in merged:
            if end - start < gap or start == 0 or end >= len(time):
                continue                             # a flicker, or cut by the start/end of the run
            if time[start] < t_from:
                continue
            position = points[start, cols, :2].mean(axis=0)
            found.append(Contact(foot, float(time[start]), float(time[end]), position))
    return sorted(found, key=lambda c: c.start)


def gait_metrics(traj: Trajectory, window: float = 10.0, until: float | None = None) -> dict:
    """Gait over the last ``window`` seconds before ``until`` (a fall; default the end of the run):
    mean speed (m/s, mean horizontal COM speed), step frequency (steps/s: touchdowns of either
    foot per second), step length (m: mean speed / step frequency, as in Fig. 12), stance/step
    (%: contact time of a foot over the time between successive touchdowns), flight time,
    and the alternation of feet."""
    a = traj.arrays
    time = a["time"]
    t_end = float(time[-1]) if until is None else min(float(until), float(time[-1]))
    t_from = max(0.0, t_end - window)
    sel = (time >= t_from) & (time <= t_end)
    speed = np.linalg.norm(a["com_vel"][sel, :2], axis=1)
    xy = a["com"][sel, :2]
    travelled = float(np.sum(np.linalg.norm(np.diff(xy, axis=0), axis=1)))
    mean_speed = travelled / max(float(time[sel][-1] - time[sel][0]), 1e-9)
    steps = [c for c in contacts(traj) if t_from <= c.start and c.end <= t_end]
    result = {
        "window_s": float(t_end - t_from),
        "mean_speed": mean_speed,
        "mean_com_speed": float(speed.mean()),
        "steps": len(steps),
    }
    if len(steps) < 3:
        result.update(step_frequency=None, step_length=None, stance_fraction=None, stance_time=None,
                      flight_time=None, step_time=None, alternating=None, foot_step_length=None)
        return result
    starts = np.array([c.start for c in steps])
    step_times = np.diff(starts)
    step_time = float(step_times.mean())
    stance_time = float(np.mean([c.duration for c in steps]))
    alternating = float(np.mean([s1.foot != s2.foot for s1, s2 in zip(steps, steps[1:])]))
    # distance between successive footprints, as the foot lands (the other measure of step length)
    prints = np.array([c.position for c in steps])
    foot_step = float(np.mean(np.linalg.norm(np.diff(prints, axis=0), axis=1)))
    frequency = 1.0 / step_time
    result.update(
        step_frequency=frequency,
        step_length=mean_speed / frequency,
        foot_step_length=foot_step,
        step_time=step_time,
        stance_time=stance_time,
        stance_fraction=100.0 * stance_time / step_time,
        flight_time=float(np.mean(np.maximum(step_times - stance_time, 0.0))),
        step_time_cv=float(step_times.std() / step_time),
        alternating=alternating,
    )
    return result


# Hodgins & Pollard 1997, Fig. 12: human data (and the 1997 simulation) for comparison
HUMAN_FIG12 = {
    "man": {"speed": 4.83, "step_frequency": 2.92, "step_length": 1.66, "stance_fraction": 57.9},
    "woman": {"speed": 4.83, "step_frequency": 3.05, "step_length": 1.60, "stance_fraction": 55.2},
    "child": {"speed": 2.13, "step_frequency": 3.8, "step_length": 0.56, "stance_fraction": 68.5},
}
SIMULATED_1997 = {
    "man": {"speed": 4.41, "step_frequency": 3.18, "step_length": 1.39, "stance_fraction": 59.6},
    "woman": {"speed": 4.45, "step_frequency": 3.33, "step_length": 1.33, "stance_fraction": 54.3},
    "child": {"speed": 2.52, "step_frequency": 4.3, "step_length": 0.58, "stance_fraction": 63.3},
}


def compare_with_human(metrics: dict, character: str = "man") -> dict:
    """Relative error of each Fig. 12 quantity against the human figure."""
    human = HUMAN_FIG12[character]
    out = {}
    for key in ("step_frequency", "step_length", "stance_fraction"):
        value = metrics.get(key)
        out[key] = {"simulated": value, "human": human[key],
                    "relative_error": None if value is None else (value - human[key]) / human[key]}
    return out


def heading_series(traj: Trajectory) -> np.ndarray:
    """Heading (rad) of the horizontal COM velocity per frame."""
    v = traj.arrays["com_vel"]
    return np.arctan2(v[:, 1], v[:, 0])


def head_acceleration(traj: Trajectory) -> np.ndarray:
    """Acceleration (m/s^2) of the head's centre per frame, by finite differences of its position
    (one of the penalties of the tuning evaluation, Hodgins & Pollard §4.3.1)."""
    a = traj.arrays
    head = a["body_pos"][:, traj.body_index("HEAD")]
    t = a["time"]
    v = np.gradient(head, t, axis=0)
    return np.linalg.norm(np.gradient(v, t, axis=0), axis=1)


def attitude_series(traj: Trajectory, body: str = "PELVIS") -> np.ndarray:
    """Roll, pitch, yaw (rad) of a body per frame (ZYX Euler angles from its quaternion)."""
    q = traj.arrays["body_quat"][:, traj.body_index(body)]
    w, x, y, z = q.T
    roll = np.arctan2(2 * (w * x + y * z), 1 - 2 * (x * x + y * y))
    pitch = np.arcsin(np.clip(2 * (w * y - z * x), -1, 1))
    yaw = np.arctan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))
    return np.stack([roll, pitch, yaw], axis=1)


def stride_attitude_variation(traj: Trajectory, t_from: float = 0.0) -> float:
    """Mean absolute change of the pelvis roll, pitch and yaw (rad) from one stride to the next,
    sampled at the touchdowns of the right foot (the evaluation's "deviations in roll, pitch and
    yaw from one stride to the next"). Yaw is taken relative to the direction of travel."""
    touchdowns = [c.start for c in contacts(traj, t_from) if c.foot == "R"]
    if len(touchdowns) < 3:
        return float("nan")
    t = traj.arrays["time"]
    frames = np.searchsorted(t, touchdowns)
    att = attitude_series(traj)[frames]
    att[:, 2] = np.angle(np.exp(1j * (att[:, 2] - heading_series(traj)[frames])))
    return float(np.mean(np.abs(np.diff(att, axis=0))))
