"""The vault's phases, Table 1 and its outcome, read off a trajectory's contact forces
(``contact_force``: the force of each named world geom on each body), so that anyone can recompute
them from the file; the behaviour's ``assess`` (behaviour.py) and the report (report.py) both read
them here."""
from __future__ import annotations

import math

import numpy as np

from ...analysis import FOOT_BODIES, true_runs
from ..handspring.behaviour import HAND_BODIES
from ...ballistics import GRAVITY
from ..somersault.behaviour import pelvis_pitch


STILL_SPEED = 0.1                 # m/s: TARGETS.md "still"
ROTATION_TOLERANCE = 0.5          # rad: one somersault is 2 pi within this (issue 31)
PEAK_LANDING_LIMIT = 11.6         # body weights: the dismount band's top ([T] 481, Ozguven & Berme)
CONTACT_GAP = 0.015               # s: a contact broken for at most this long is one contact (a bounce)
SHIN_BODIES = ("LLEGR", "LLEGL")  # the lower legs (their body origin is the knee)
KNEELING_HEIGHT = 0.15            # m: a knee this low above the mat is a kneel
FALLEN_PELVIS = 0.35              # m: the pelvis this low above the mat after the landing is a fall
BALANCED_TIME = 2.0               # s: standing balanced at least this long at the end (TARGETS.md V7, ours)
NO_STEP = 0.02                    # m: in the bow no foot moves more than this (issue 31: the bow without a step)
BOW_BODIES = ("FOOTR", "FOOTL", "TOER", "TOEL")
HORSE_BODIES = ("HANDR", "HANDL", "LARMR", "LARML")   # a handspring touches the horse with these only
# the servos with no torque on the horse: the seed's state 4, "no shoulder or wrist torque"
LIMP_ON_HORSE = ("shoulder_r_z", "shoulder_l_z", "shoulder_r_x", "shoulder_l_x", "shoulder_r_y", "shoulder_l_y",
                 "wrist_r_x", "wrist_l_x", "wrist_r_y", "wrist_l_y")

# Table 1 of Hodgins et al. 1995 ([A] 208-230): (row, unit, Takei mean, min, max, the 1995 simulation)
TABLE_1 = (
    ("board contact", "s", 0.137, 0.11, 0.15, 0.105),
    ("first flight", "s", 0.235, 0.14, 0.30, 0.156),
    ("horse contact", "s", 0.245, 0.19, 0.30, 0.265),
    ("second flight", "s", 0.639, 0.50, 0.78, 0.632),
    ("vx board touchdown", "m/s", 6.75, 5.92, 7.25, 6.75),
    ("vx board liftoff", "m/s", 4.61, 3.97, 5.26, 4.01),
    ("vx horse touchdown", "m/s", 4.61, 3.97, 5.26, 4.01),
    ("vx horse liftoff", "m/s", 3.11, 2.48, 3.83, 2.83),
    ("vz board touchdown", "m/s", -1.15, -1.54, -0.71, -1.13),
    ("vz board liftoff", "m/s", 3.34, 2.98, 3.87, 3.81),
    ("vz horse touchdown", "m/s", 1.26, 0.74, 2.39, 2.13),
    ("vz horse liftoff", "m/s", 1.46, 0.56, 2.47, 1.10),
    ("mean vertical force board", "N", 2175, 1396, 2792, 5075),
    ("mean vertical force horse", "N", 521, 309, 752, 957),
)
TAKEI_MASS = (47.96, 35.5, 64.0, 64.3)     # kg: mean, min, max, the 1995 simulation's gymnast
TAKEI_HEIGHT = (1.55, 1.39, 1.66, 1.64)    # m


def _column(trajectory, geom: str) -> np.ndarray:
    """Per frame: the world-frame force (N) of the named world geom on the whole character."""
    geoms = trajectory.meta["world_geoms"]
    return trajectory.arrays["contact_force"][:, :, geoms.index(geom)].sum(axis=1)


def contact_runs(force_z: np.ndarray, gap: int) -> list[tuple[int, int]]:
    """The runs of frames with a pushing contact, a gap of at most ``gap`` frames closed: the first
    impact on the springboard throws its light deck ahead of the feet for a few ms, and that is
    not a flight."""
    runs = true_runs(force_z > 0.0)
    merged: list[tuple[int, int]] = []
    for run in runs:
        if merged and run[0] - merged[-1][1] <= gap:
            merged[-1] = (merged[-1][0], run[1])
        else:
            merged.append(run)
    return merged


def vault_phases(trajectory) -> dict:
    """The contact phases as frame ranges [first, last + 1): the first board contact; the horse
    contact from the first touch after it to the last release before the mat; the first mat
    contact after that (to the end). The flights are between them."""
    gap = int(round(CONTACT_GAP * float(trajectory.meta["control_rate"])))
    board, horse, mat = (contact_runs(_column(trajectory, g)[:, 2], gap) for g in ("springboard", "vault_table", "landing_mat"))
    phases = {}
    if board:
        phases["board"] = board[0]
        horse = [h for h in horse if h[0] >= board[0][1]]
        mat = [r for r in mat if horse and r[0] >= horse[0][1]]
        if horse:
            # the horse contact: from the first touch to the last release before the mat (the hands
            # bounce and land again: one support phase, as Takei's contact time counts it)
            end = mat[0][0] if mat else len(trajectory.arrays["time"])
            phases["horse"] = (horse[0][0], max(h[1] for h in horse if h[0] < end))
            if mat:
                phases["mat"] = (mat[0][0], len(trajectory.arrays["time"]))
    return phases


def table_1(trajectory) -> dict:
    """Table 1's rows measured off the run (a row is None where its phase did not happen), and
    per contact the impulse-momentum check: the mean vertical force m (dv_z / T + g). A touchdown
    velocity is the COM's at the last frame before the contact (the first contact frame already
    holds up to a frame of the impact: the board took 0.063 m/s off vx in it, the horse 0.063); a
    liftoff velocity the COM's at the first frame after it."""
    a, meta = trajectory.arrays, trajectory.meta
    t, v = a["time"], a["com_vel"]
    mass = float(meta["total_mass"])
    dt = 1.0 / float(meta["control_rate"])
    ph = vault_phases(trajectory)
    rows = {name: None for name, *_ in TABLE_1}
    checks = {}
    if "board" in ph:
        i, j = ph["board"]
        rows["board contact"] = float(t[j] - t[i]) if j < len(t) else None
        rows["vx board touchdown"], rows["vz board touchdown"] = float(v[i - 1, 0]), float(v[i - 1, 2])
        if j < len(t):
            rows["vx board liftoff"], rows["vz board liftoff"] = float(v[j, 0]), float(v[j, 2])
    for name, key, geom in (("board", "board", "springboard"), ("horse", "horse", "vault_table")):
        if key not in ph or ph[key][1] >= len(t):
            continue
        i, j = ph[key]
        duration = float(t[j] - t[i])
        force = _column(trajectory, geom)[:, 2]
        # a frame's force is the one of the physics step before it: frames i+1 .. j cover the contact
        mean = float(force[i + 1:j + 1].sum() * dt / duration)
        momentum = mass * ((float(v[j, 2]) - float(v[i, 2])) / duration + GRAVITY)
        rows[f"mean vertical force {name}"] = mean
        checks[name] = {"mean_force": mean, "momentum_force": momentum,
                        "relative_difference": abs(mean - momentum) / max(abs(mean), 1e-9)}
    if "horse" in ph:
        i, j = ph["horse"]
        rows["first flight"] = float(t[i] - t[ph["board"][1]])
        rows["vx horse touchdown"], rows["vz horse touchdown"] = float(v[i - 1, 0]), float(v[i - 1, 2])
        if j < len(t):
            rows["horse contact"] = float(t[j] - t[i])
            rows["vx horse liftoff"], rows["vz horse liftoff"] = float(v[j, 0]), float(v[j, 2])
    if "mat" in ph:
        rows["second flight"] = float(t[ph["mat"][0]] - t[ph["horse"][1]])
    return {"rows": rows, "impulse_momentum": checks, "mass": mass}


def trunk_pitch(trajectory) -> np.ndarray:
    """Per frame: the trunk's forward pitch from vertical (rad), the line from the pelvis to the
    upper chest (CHEST1)."""
    names = list(trajectory.arrays["body_names"])
    pos = trajectory.arrays["body_pos"]
    axis = pos[:, names.index("CHEST1")] - pos[:, names.index("PELVIS")]
    return np.arctan2(axis[:, 0], axis[:, 2])


def bow_measured(trajectory) -> dict:
    """The bow, from its start (the "bow" event) to the end of the run: the trunk's pitch at the
    start, deepest and at the end, and how far the feet (the foot and toe bodies) moved at most;
    {} when the run has no bow."""
    a = trajectory.arrays
    t = a["time"]
    when = [time for time, name in trajectory.meta.get("phase_events", []) if name == "bow"]
    if not when:
        return {}
    first = int(np.searchsorted(t, when[0] - 1e-9))
    pitch = trunk_pitch(trajectory)[first:]
    names = list(a["body_names"])
    feet = a["body_pos"][first:, [names.index(n) for n in BOW_BODIES]]
    return {"bow_start": float(t[first]), "bow_trunk_pitch_start": float(pitch[0]),
            "bow_trunk_pitch": float(pitch.max()), "bow_deepest_time": float(t[first + int(np.argmax(pitch))]),
            "bow_trunk_pitch_end": float(pitch[-1]),
            "bow_feet_moved": float(np.linalg.norm(feet - feet[0], axis=2).max())}


def horse_contact_bodies(trajectory, frames: tuple[int, int]) -> dict:
    """Which bodies touch the horse over its contact, each with its share of the vertical impulse
    the horse gives (a body pulled down over the edge has a negative share), and the fault: any
    body but the hands and forearms (HORSE_BODIES) touching the horse - a head, trunk or upper arm."""
    i, j = frames
    force = trajectory.arrays["contact_force"][i:j + 1, :, trajectory.meta["world_geoms"].index("vault_table")]
    names = list(trajectory.arrays["body_names"])
    touched = np.flatnonzero(np.abs(force).sum(axis=(0, 2)) > 0)
    impulse = force[:, :, 2].sum(axis=0)
    total = float(impulse.sum()) or 1.0
    share = {names[b]: float(impulse[b] / total) for b in touched}
    return {"horse_bodies": share, "horse_fault": [n for n in share if n not in HORSE_BODIES]}


def servos_on_horse(trajectory, joints: tuple[str, ...] = LIMP_ON_HORSE) -> dict:
    """TARGETS.md V5 (the seed's state 4: no shoulder or wrist torque on the horse), read off the file:
    for every frame in which some body pushes on the horse, whether any servo of ``joints`` had a
    non-zero gain (kp or kv) during the physics step that produced the frame - the model's gains with
    the logged edits up to the tick before it. Returns the frames touching the horse, those with such a
    servo acting, their times and the servos that acted; a frame in which a touch begins is counted
    apart (``onsets_active``: the step it began in ran before the controller could see it). (Reads the
    model from the file: the report and the tests call it, not the per-run assess.)"""
    import mujoco
    a, meta = trajectory.arrays, trajectory.meta
    model = mujoco.MjModel.from_xml_string(meta["model_xml"])
    names = list(meta["dof_names"])
    watched = [k for k, n in enumerate(names) if n in joints]
    kp = model.actuator_gainprm[:, 0].copy()
    kv = -model.actuator_biasprm[:, 2].copy()
    gain_field, bias_field = meta["edit_fields"].index("actuator_gainprm"), meta["edit_fields"].index("actuator_biasprm")
    gain_cols, bias_cols = model.actuator_gainprm.shape[1], model.actuator_biasprm.shape[1]
    edits = sorted(zip(a["edit_tick"], range(len(a["edit_tick"]))))
    force = a["contact_force"][:, :, meta["world_geoms"].index("vault_table")]
    touching = np.flatnonzero(np.abs(force).sum(axis=(1, 2)) > 0)
    active, acting, e, onsets = [], set(), 0, 0
    touched = set(touching.tolist())
    for frame in touching:
        while e < len(edits) and edits[e][0] <= frame - 1:       # the gains of the step before the frame
            k = edits[e][1]
            field, index, value = int(a["edit_field"][k]), int(a["edit_index"][k]), float(a["edit_value"][k])
            if field == gain_field and index % gain_cols == 0:
                kp[index // gain_cols] = value
            elif field == bias_field and index % bias_cols == 2:
                kv[index // bias_cols] = -value
            e += 1
        on = [names[k] for k in watched if kp[k] != 0.0 or kv[k] != 0.0]
        if not on:
            continue
        if frame - 1 not in touched:
            onsets += 1                  # the step a touch begins in: the controller sees it a tick later
            continue
        active.append(int(frame))
        acting.update(on)
    dt = 1.0 / float(meta["control_rate"])
    return {"frames": len(touching), "active_frames": len(active), "touching_time": len(touching) * dt,
            "active_time": len(active) * dt, "first_active": float(a["time"][active[0]]) if active else None,
            "acting": sorted(acting), "onsets_active": onsets}


def vault_assess(trajectory) -> tuple[str, dict]:
    """The vault's outcome: the phases in order (board, horse, mat), one forward somersault from
    the upright (2 pi within ROTATION_TOLERANCE, the pelvis's pitch at the end), the feet first on
    the mat, no body but the feet on the mat or the floor after the landing, the peak landing
    force within PEAK_LANDING_LIMIT body weights, and at the end still, standing (COM over the
    feet's polygon) for BALANCED_TIME; plus Table 1's rows."""
    a, meta = trajectory.arrays, trajectory.meta
    names = list(a["body_names"])
    t = a["time"]
    measured = table_1(trajectory)
    metrics = {"table_1": measured["rows"], "impulse_momentum": measured["impulse_momentum"]}
    ph = vault_phases(trajectory)
    metrics["phases"] = {k: [float(t[i]), float(t[min(j, len(t) - 1)])] for k, (i, j) in ph.items()}
    pitch = pelvis_pitch(trajectory)
    metrics["rotation"] = float(pitch[-1])
    metrics["somersaults"] = metrics["rotation"] / (2 * math.pi)
    if "horse" in ph:
        # the palms at the horse touchdown: the angle (deg) between each palm's normal (the hand
        # box's thin axis, inward: medial in the standing pose) and straight down (palm down flat)
        w, x, y, _ = a["body_quat"][ph["horse"][0], [names.index(n) for n in HAND_BODIES]].T
        metrics["palm_angle_at_horse_deg"] = np.degrees(np.arccos(np.clip(1 - 2 * (x * x + y * y), -1, 1))).tolist()
        # the elbows on the horse: the largest angle (deg) between upper arm and forearm, each side
        i, j = ph["horse"]
        bends = []
        for side in "RL":
            shoulder, elbow, wrist = (a["body_pos"][i:j, names.index(n + side)] for n in ("UARM", "LARM", "HAND"))
            upper, fore = elbow - shoulder, wrist - elbow
            cos = (upper * fore).sum(axis=1) / np.linalg.norm(upper, axis=1) / np.linalg.norm(fore, axis=1)
            bends.append(float(np.degrees(np.arccos(np.clip(cos, -1, 1))).max()))
        metrics["elbow_bend_on_horse_deg"] = bends
        metrics.update(horse_contact_bodies(trajectory, ph["horse"]))
    weight = GRAVITY * float(meta["total_mass"])
    if "mat" not in ph:
        return ("no_board" if "board" not in ph else "no_horse" if "horse" not in ph else "no_landing"), metrics
    first = ph["mat"][0]
    metrics["rotation_at_touchdown"] = float(pitch[first])
    mat_force = a["contact_force"][:, :, meta["world_geoms"].index("landing_mat")]
    touching = np.flatnonzero(np.linalg.norm(mat_force[first], axis=1) > 0)
    metrics["first_on_mat"] = [names[b] for b in touching]
    metrics["feet_first"] = bool(len(touching)) and all(names[b] in FOOT_BODIES for b in touching)
    metrics["peak_landing_body_weights"] = float(mat_force[first:, :, 2].sum(axis=1).max() / weight)
    # a fall after the landing: a body but the feet on the mat or the floor - except the shins while
    # the knees are well above the mat (the feet sink into the mat and its top closes round the
    # ankles, where the shin's capsule ends; a shin on the mat with the knee low is a kneel) - or
    # the pelvis low
    mat_top = meta["world"]["landing_mat"][4]
    shins = [names.index(n) for n in SHIN_BODIES]
    knee_low = a["body_pos"][first:, shins, 2] - mat_top < KNEELING_HEIGHT
    after = a["ground_contact"][first:].copy()
    after[:, shins] &= knee_low
    allowed = np.array([n in FOOT_BODIES for n in names])
    bad = np.flatnonzero((after & ~allowed).any(axis=1))
    pelvis_z = a["body_pos"][first:, names.index("PELVIS"), 2]
    low = np.flatnonzero(pelvis_z - mat_top < FALLEN_PELVIS)
    metrics["fell"] = bool(len(bad) or len(low))
    metrics["fall_time"] = float(t[first + min([*bad[:1], *low[:1]])]) if metrics["fell"] else None
    # the feet through the mat onto the floor under it (until a fall, after which she may roll off
    # the mat): what she then stands on is not the mat
    feet = [names.index(n) for n in FOOT_BODIES]
    until = first + min([*bad[:1], *low[:1]]) if metrics["fell"] else len(t)
    floor = a["contact_force"][first:until + 1, feet, meta["world_geoms"].index("ground"), 2].sum(axis=1)
    metrics["floor_under_mat_peak"] = float(floor.max())
    metrics["landing_sink"] = float(mat_top - a["support_points"][first:until + 1, :, 2].min())
    metrics["through_the_mat"] = bool(floor.max() > 0.0)
    metrics["final_com_speed"] = float(np.linalg.norm(a["com_vel"][-1]))
    feet = a["support_points"]
    com = a["com"]
    # standing balanced: the COM's ground projection inside the feet's box (x, y) at the end
    lo, hi = feet[:, :, :2].min(axis=1), feet[:, :, :2].max(axis=1)
    inside = ((com[:, :2] >= lo) & (com[:, :2] <= hi)).all(axis=1) & (t > t[first])
    runs = true_runs(inside)
    metrics["balanced_time_at_end"] = float(t[-1] - t[runs[-1][0]]) if runs and runs[-1][1] == len(t) else 0.0
    middle = feet[first:, :, :2].mean(axis=1)
    settled = int(np.searchsorted(t[first:], t[first] + 0.5))
    metrics["landing_slide_after_settle"] = float(np.linalg.norm(middle[settled:] - middle[min(settled, len(middle) - 1)],
                                                                 axis=1).max()) if settled < len(middle) else 0.0
    metrics.update(bow_measured(trajectory))
    if metrics["fell"]:
        return "fell", metrics
    if not metrics["feet_first"]:
        return "not_feet_first", metrics
    if abs(metrics["rotation"] - 2 * math.pi) > ROTATION_TOLERANCE:
        return "wrong_rotation", metrics
    if metrics["through_the_mat"]:
        return "through_the_mat", metrics
    if metrics["peak_landing_body_weights"] > PEAK_LANDING_LIMIT:
        return "hard_landing", metrics
    if metrics["balanced_time_at_end"] < BALANCED_TIME or metrics["final_com_speed"] >= STILL_SPEED:
        return "not_balanced", metrics
    if metrics.get("bow_feet_moved", 0.0) > NO_STEP:
        return "stepped_in_bow", metrics
    return "success", metrics
