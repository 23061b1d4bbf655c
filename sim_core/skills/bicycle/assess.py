"""Judging a ride from its trajectory: did anything but the tyres touch the ground, the
bicycle's speed, roll and heading, and how far the attachments stretched."""
from __future__ import annotations

import math

import mujoco
import numpy as np

from ...world.bicycle import NAMES, WHEEL_BODIES, WHEEL_RADIUS, frame_state


HEADING_TOLERANCE_DEG = 5.0
FIRST_FORK_MOTION = math.radians(1.0)   # rad: the fork's first move counts from this far


def attachment_gaps(model: mujoco.MjModel, qpos: np.ndarray) -> np.ndarray:
    """Frames x attachments (seat r, l, hands r, l, feet r, l): the distance (m) between each
    rider site and its bicycle site, from the recorded joint angles."""
    from .mount import SitePairs
    data = mujoco.MjData(model)
    pairs = SitePairs(model)
    out = np.zeros((len(qpos), len(pairs.names)))
    for k, q in enumerate(qpos):
        data.qpos[:] = q
        mujoco.mj_kinematics(model, data)
        out[k] = pairs.gaps(data)
    return out


def ride_metrics(trajectory) -> dict:
    """Fall (anything but a tyre on the ground), speed, roll, heading (the time from which it
    stays within 5 deg of the commanded one, the fork's first move: -1 right, +1 left) and the
    attachments' largest stretch."""
    a, meta = trajectory.arrays, trajectory.meta
    model = mujoco.MjModel.from_xml_string(meta["model_xml"])
    body_names = [model.body(b).name for b in range(1, model.nbody)]
    wheels = [body_names.index(n) for n in WHEEL_BODIES]
    others = np.ones(len(body_names), dtype=bool)
    others[wheels] = False
    touching = a["ground_contact"][:, others].any(axis=1)
    fall_frame = int(np.argmax(touching)) if touching.any() else None
    free = model.joint(NAMES["free"])
    q, dof = int(free.qposadr[0]), int(free.dofadr[0])
    steer = model.jnt_qposadr[model.joint(NAMES["steer"]).id]
    crank = model.jnt_qposadr[model.joint(NAMES["crank_spin"]).id]
    states = [frame_state(a["qpos"][k, q + 3:q + 7], a["qvel"][k, dof:dof + 6], a["qpos"][k, steer],
                          a["qpos"][k, crank]) for k in range(len(a["time"]))]
    speed = np.array([s["speed"] for s in states])
    roll = np.array([s["roll"] for s in states])
    yaw = np.unwrap([s["yaw"] for s in states])
    t = a["time"]
    end = len(t) if fall_frame is None else fall_frame
    last10 = (t >= t[end - 1] - 10.0) & (np.arange(len(t)) < end)     # criterion: TARGETS.md's mean speed of the last 10 s
    gaps = attachment_gaps(model, a["qpos"][:end])
    desired = yaw[0] + meta["params"]["heading"]
    error = np.degrees(np.abs(yaw[:end] - desired))
    outside = np.nonzero(error > HEADING_TOLERANCE_DEG)[0]
    settled = 0.0 if len(outside) == 0 else (float(t[outside[-1] + 1]) if outside[-1] + 1 < end else None)
    steer_path = np.array([s["steer"] for s in states[:end]])
    moved = np.nonzero(np.abs(steer_path - steer_path[0]) > FIRST_FORK_MOTION)[0]
    last5 = (t >= t[end - 1] - 5.0) & (np.arange(len(t)) < end)     # criterion: the mean speed and cadence reported over the last 5 s
    gear = float(model.wrap_prm[model.tendon_adr[model.tendon(NAMES["chain"]).id]])
    rear = model.jnt_qposadr[model.joint(NAMES["rear_spin"]).id]
    stretch = gear * a["qpos"][:end, crank] - a["qpos"][:end, rear]
    crank_rate = a["qvel"][:end, model.jnt_dofadr[model.joint(NAMES["crank_spin"]).id]]
    return {
        "fell": fall_frame is not None,
        "mean_speed_last_5s": float(speed[last5].mean()),
        "heading_within_5deg_from": settled,
        "first_fork_motion": 0.0 if len(moved) == 0 else float(np.sign(steer_path[moved[0]] - steer_path[0])),
        "max_hand_gap": float(gaps[:, 2:4].max()), "max_foot_gap": float(gaps[:, 4:6].max()),
        "max_seat_gap": float(gaps[:, 0:2].max()),
        "max_chain_stretch": float(np.abs(stretch - stretch[0]).max()),
        "cadence_last_5s_hz": float(crank_rate[last5[:end]].mean() / (2 * math.pi)),
        "cadence_expected_hz": float(speed[last5].mean() / (2 * math.pi * WHEEL_RADIUS * gear)),
        "fall_time": None if fall_frame is None else float(t[fall_frame]),
        "mean_speed_last_10s": float(speed[last10].mean()),
        "max_abs_roll_deg": float(np.degrees(np.abs(roll[:end]).max())),
        "final_heading_deg": float(np.degrees(yaw[end - 1])),
        "distance": float(np.linalg.norm(a["qpos"][end - 1, q:q + 2] - a["qpos"][0, q:q + 2])),
    }
