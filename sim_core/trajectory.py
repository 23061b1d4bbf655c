"""Trajectory: what a run produced, and the log that reproduces it (saved as .npz + JSON meta).

Arrays (N recorded frames at the control rate, B bodies, S foot contact sites):
  time (N), qpos (N x nq), qvel (N x nv), body_names (B), body_pos (N x B x 3, world),
  body_quat (N x B x 4, world, w first), com (N x 3), com_vel (N x 3), angmom (N x 3: whole-body
  angular momentum about the COM, kg m^2/s), grf (N x 3: ground
  reaction force on the character), ground_contact (N x B: body touches the ground),
  support_points (N x S x 3: foot contact sites), push_force (N x 3), contact_force (N x B x G x 3:
  world-frame force of each named world geom on each body, summed over its contacts in the last
  physics step; the geoms' names are meta["world_geoms"]; zero at frame 0).
A scene's trajectory (meta["scene"] true) has every actor in one model: qpos, qvel, body_*,
ground_contact, support_points and contact_force cover all actors (each actor's columns are in
meta["actors"]), and com, com_vel, angmom, grf, push_force have an actor axis (N x A x 3).
``Trajectory.actor(name)`` is one actor's view with a one-character run's shapes.
Replay log: initial_state (mjSTATE_INTEGRATION), control (K x nu, the control vector of each
control tick, constant over its ``steps_per_tick`` physics steps), step_division (K: that tick's
physics step is the model's divided by this, and it takes that many times the steps; 1 unless a
behaviour asked for a finer step), and the edit log
(edit_tick, edit_field, edit_index, edit_value) of every model/data parameter the run set.
meta (JSON string): model_xml, character, behaviour, params, outcome, metrics, pushes, world,
strength, timestep, steps_per_tick, phase_events, edit_fields, world_geoms, mujoco_version, format
version; a scene's: actors (per actor: name, prefix, character, behaviour, params, placement, the
column ranges, outcome, metrics, ...) instead of the one character's keys.
No pickle: every array is numeric or a fixed-width string.
"""
from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .files import write_atomically

FORMAT = "sim_athletics.trajectory"
VERSION = 1
FRAME_FIELDS = ("time", "qpos", "qvel", "body_pos", "body_quat", "com", "com_vel", "angmom", "grf",
                "ground_contact", "support_points", "push_force", "contact_force")
PER_ACTOR_FIELDS = ("com", "com_vel", "angmom", "grf", "push_force")     # a scene's have an actor axis
BODY_FIELDS = ("body_pos", "body_quat", "ground_contact", "contact_force")
# meta a scene shares with each of its actors' views
SHARED_META = ("model_xml", "duration", "ended_early", "world", "timestep", "steps_per_tick", "control_rate",
               "edit_fields", "state_spec", "pushes", "start_state", "world_geoms", "mujoco_version")
ACTOR_META = ("character", "behaviour", "params", "strength", "phase_events", "total_mass", "dof_names",
              "support_site_side", "placement", "outcome", "metrics", "start_state")
LOG_FIELDS = ("initial_state", "control", "step_division", "edit_tick", "edit_field", "edit_index", "edit_value")


@dataclass
class Trajectory:
    arrays: dict[str, np.ndarray]
    meta: dict = field(default_factory=dict)
    scene: "Trajectory | None" = field(default=None, repr=False, compare=False)   # an actor's view: the whole scene

    def __getattr__(self, name):
        arrays = self.__dict__.get("arrays", {})
        if name in arrays:
            return arrays[name]
        raise AttributeError(name)

    @property
    def body_names(self) -> list[str]:
        return [str(n) for n in self.arrays["body_names"]]

    def body_index(self, name: str) -> int:
        return self.body_names.index(name)

    @property
    def actor_names(self) -> list[str]:
        return [a["name"] for a in self.meta.get("actors", [])]

    def actor(self, name: str) -> "Trajectory":
        """One actor of a scene as a one-character trajectory: its qpos/qvel slices, its bodies
        (names without the "<actor>/" prefix), its COM, ground reaction and support points, the
        scene's time and edit log, and the meta a behaviour's ``assess`` reads. Positions stay in
        the world frame (meta["placement"] says where the actor started); ``scene`` is the whole
        scene (a rider's bicycle is judged off it)."""
        actors = self.meta.get("actors", [])
        for k, m in enumerate(actors):
            if m["name"] == name:
                break
        else:
            raise KeyError(f"no actor {name!r} in this trajectory; actors: {', '.join(self.actor_names) or 'none'}")
        a = self.arrays
        end = m.get("end_frame", len(a["time"]))        # an actor whose skill ended early: up to there
        frames = slice(0, end)
        bodies, sites = slice(*m["bodies"]), slice(*m["support_sites"])
        view = {"time": a["time"][frames], "qpos": a["qpos"][frames, slice(*m["qpos"])],
                "qvel": a["qvel"][frames, slice(*m["qvel"])], "support_points": a["support_points"][frames, sites],
                "body_names": np.array([str(n)[len(m["prefix"]):] for n in a["body_names"][bodies]])}
        for field_name in BODY_FIELDS:
            view[field_name] = a[field_name][frames, bodies]
        for field_name in PER_ACTOR_FIELDS:
            view[field_name] = a[field_name][frames, k]
        for field_name in LOG_FIELDS:
            if field_name in a:
                view[field_name] = a[field_name]
        view["control"] = a["control"][: end - 1, slice(*m["actuators"])]
        view["step_division"] = a["step_division"][: end - 1]
        meta = {key: self.meta[key] for key in SHARED_META if key in self.meta}
        meta.update({key: m[key] for key in ACTOR_META if key in m})
        meta.update(actor=name, actor_prefix=m["prefix"])
        if end < len(a["time"]):
            tick_time = self.meta["steps_per_tick"] * self.meta["timestep"]
            meta.update(ended_early=True, duration=float((end - 1) * tick_time))   # as a lone run counts it
        return Trajectory(view, meta, scene=self)

    def save(self, path: str | Path) -> Path:
        """Write atomically: a failed save leaves no partial file."""
        meta = dict(self.meta, format=FORMAT, version=VERSION)
        return write_atomically(path, write=lambda tmp: np.savez_compressed(tmp, meta=np.array(json.dumps(meta)),
                                                                             **self.arrays))

    @classmethod
    def load(cls, path: str | Path) -> "Trajectory":
        with np.load(path, allow_pickle=False) as f:
            arrays = {k: f[k] for k in f.files}
        meta = json.loads(str(arrays.pop("meta")))
        if meta.get("format") != FORMAT:
            raise ValueError(f"{path} is not a Sim Athletics trajectory")
        return cls(arrays, meta)
