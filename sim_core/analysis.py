"""Metrics read off a trajectory, and the outcome they imply (TARGETS.md: "stable" means no body
but the feet (and hands where the skill calls for it) touches the ground, the pelvis stays above
half its standing height, and the COM is still (< 0.1 m/s) at the end)."""
from __future__ import annotations

import numpy as np
from scipy.spatial import ConvexHull, QhullError

from .ballistics import GRAVITY
from .control.measure import surface_under
from .trajectory import Trajectory

FOOT_BODIES = ("FOOTR", "FOOTL", "TOER", "TOEL")
STILL_SPEED = 0.1            # m/s
STEP_DISTANCE = 0.03         # m: a foot that slides or steps further than this has stepped
LIFT_HEIGHT = 0.02           # m: a foot whose every contact site is this high is off the ground
CONTACT_HEIGHT = 0.005       # m: a contact site this close to the ground supports the body


def true_runs(mask: np.ndarray) -> list[tuple[int, int]]:
    """(first, last + 1) frame index of each run of True (a phase: a flight, a contact)."""
    padded = np.concatenate([[False], mask, [False]]).astype(np.int8)
    edges = np.diff(padded)
    return [(int(i), int(j)) for i, j in zip(np.nonzero(edges == 1)[0], np.nonzero(edges == -1)[0])]


def surface_under_points(trajectory, points: np.ndarray) -> np.ndarray:
    """Height of what is under each point (..., 2 or 3) in the trajectory's world: a box's top, or
    the ground (World.floor)."""
    world = trajectory.meta.get("world", {})
    floor = world.get("floor", 0.0)
    standing = []                 # the fixed apparatus one stands on, as boxes (x, y, top, length, width)
    if world.get("vault_table"):
        x, y, height, length, width = world["vault_table"]
        standing.append((x, y, floor + height, length, width))
    if world.get("landing_mat"):
        x, y, length, width, thickness = world["landing_mat"]
        standing.append((x, y, floor + thickness, length, width))
    return surface_under(points, tuple(world.get("boxes", ())) + tuple(standing), floor)


def feet_above_surface(trajectory) -> np.ndarray:
    """Per frame and foot site: height above the ground or the box under it."""
    points = trajectory.arrays["support_points"]
    return points[:, :, 2] - surface_under_points(trajectory, points)


def com_support_margins(traj: Trajectory, up: np.ndarray | None = None) -> np.ndarray:
    """Per frame: how far the COM (projected along gravity) lies outside the support polygon
    (inf when fewer than three foot sites touch). A hull is reused while the same sites touch
    and none has moved more than 1 mm."""
    com = traj.arrays["com"]
    up = np.tile([0.0, 0.0, 1.0], (len(com), 1)) if up is None else np.atleast_2d(up)
    ground = com[:, :2] - com[:, 2:3] * up[:, :2] / up[:, 2:3]
    pts = traj.arrays["support_points"]
    touching_all = feet_above_surface(traj) < CONTACT_HEIGHT
    out = np.full(len(com), np.inf)
    cached_mask, cached_pts, equations = None, None, None
    for k in range(len(com)):
        touching = touching_all[k]
        if touching.sum() < 3:
            continue
        p = pts[k, touching, :2]
        if (cached_mask is None or not np.array_equal(touching, cached_mask)
                or np.abs(p - cached_pts).max() > 1e-3):
            try:
                equations = ConvexHull(p).equations
            except (QhullError, ValueError):
                continue
            cached_mask, cached_pts = touching, p
        out[k] = float(np.max(equations[:, :2] @ ground[k] + equations[:, 2]))
    return out


def gravity_up(traj: Trajectory) -> np.ndarray:
    """Up (against gravity) at every frame, from the logged gravity edits."""
    a = traj.arrays
    g = np.tile([0.0, 0.0, -GRAVITY], (len(a["time"]), 1))
    field = traj.meta.get("edit_fields", []).index("opt.gravity") if "edit_fields" in traj.meta else None
    if field is not None and len(a["edit_tick"]):
        for tick, f, index, value in zip(a["edit_tick"], a["edit_field"], a["edit_index"], a["edit_value"]):
            if f == field:
                frame = int(round(tick))            # frame k is recorded at tick k
                g[frame:, index] = value
    return -g / np.linalg.norm(g, axis=1, keepdims=True)


def standard_metrics(traj: Trajectory, allowed_contacts=FOOT_BODIES, squat: tuple[int, float] | None = None) -> dict:
    """Metrics every behaviour reports: falls, steps, COM against the support polygon, pelvis
    heights, final COM speed, peak ground reaction force.

    ``squat`` = (frame, floor): before that frame the skill crouches deliberately (the deep squat
    of a take-off), and there the pelvis counts as fallen only below ``floor`` m, not below half
    its standing height."""
    a = traj.arrays
    names = traj.body_names
    pelvis = names.index("PELVIS")
    allowed = np.array([n in allowed_contacts for n in names])
    bad_contact = (a["ground_contact"] & ~allowed).any(axis=1)
    hip_height = 0.5 * (a["body_pos"][:, names.index("ULEGR"), 2] + a["body_pos"][:, names.index("ULEGL"), 2])
    stand_pelvis = a["body_pos"][0, pelvis, 2] - traj.meta.get("start_state", {}).get("height", 0.0)
    # above what is under the pelvis: the ground, a box landed on, or the ground below the box started on
    under = surface_under_points(traj, a["body_pos"][:, pelvis])
    hip_height = hip_height - under
    lowest = np.full(len(a["time"]), 0.5 * stand_pelvis)
    if squat is not None:
        lowest[:squat[0]] = min(squat[1], 0.5 * stand_pelvis)
    too_low = a["body_pos"][:, pelvis, 2] - under < lowest
    fell_frames = np.nonzero(bad_contact | too_low)[0]
    fell = len(fell_frames) > 0
    feet = a["support_points"]
    slide = np.linalg.norm(feet[:, :, :2] - feet[0:1, :, :2], axis=2).max()
    # a foot has stepped when all of it leaves the ground (a heel rising while the toes stay down
    # is part of balancing, not a step)
    sides = np.array(traj.meta.get("support_site_side", ["R"] * feet.shape[1]))
    heights = feet_above_surface(traj)
    lifted = any(bool((heights[:, sides == side] > LIFT_HEIGHT).all(axis=1).any()) for side in set(sides))
    margins = com_support_margins(traj, gravity_up(traj))
    final_speed = float(np.linalg.norm(a["com_vel"][-1]))
    weight = GRAVITY * float(traj.meta.get("total_mass") or 1.0)
    hands = [names.index("HANDR"), names.index("HANDL")]
    knees = [names.index("LLEGR"), names.index("LLEGL")]
    hand_below_knee = float(np.max(a["body_pos"][:, knees, 2].mean(axis=1) - a["body_pos"][:, hands, 2].mean(axis=1)))
    metrics = {
        "fell": bool(fell),
        "fall_time": float(a["time"][fell_frames[0]]) if fell else None,
        "stepped": bool(slide > STEP_DISTANCE or lifted),
        "max_foot_slide": float(slide),
        "com_outside_support_max": float(np.max(margins)),
        "com_inside_support_throughout": bool(np.all(margins <= 0.0)),
        "min_pelvis_height": float(np.min(hip_height)),
        "final_pelvis_height": float(hip_height[-1]),
        "final_com_speed": final_speed,
        "max_hand_below_knee": hand_below_knee,
        "peak_grf": float(np.max(np.linalg.norm(a["grf"], axis=1))),
        "peak_vertical_grf_body_weights": float(np.max(a["grf"][:, 2]) / weight),
        "duration": float(a["time"][-1]),
    }
    return metrics


def standing_outcome(metrics: dict) -> str:
    """'success' for a skill that ends standing still where it started, else the named failure."""
    if metrics["fell"]:
        return "fell"
    if metrics["stepped"]:
        return "stepped"
    if metrics["final_com_speed"] >= STILL_SPEED:
        return "not_still"
    return "success"
