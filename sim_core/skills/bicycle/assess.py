"""Judging a ride from its trajectory: did anything but the tyres touch the ground, the
bicycle's speed, roll and heading, and how far the attachments stretched."""
from __future__ import annotations

import math

import mujoco
import numpy as np

from ...world.bicycle import NAMES, WHEEL_BODIES, frame_state


def ride_metrics(trajectory) -> dict:
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
    last10 = (t >= t[end - 1] - 10.0) & (np.arange(len(t)) < end)
    return {
        "fell": fall_frame is not None,
        "fall_time": None if fall_frame is None else float(t[fall_frame]),
        "mean_speed_last_10s": float(speed[last10].mean()),
        "max_abs_roll_deg": float(np.degrees(np.abs(roll[:end]).max())),
        "final_heading_deg": float(np.degrees(yaw[end - 1])),
        "distance": float(np.linalg.norm(a["qpos"][end - 1, q:q + 2] - a["qpos"][0, q:q + 2])),
    }
