"""Trajectory: what a run produced, and the log that reproduces it (saved as .npz + JSON meta).

Arrays (N recorded frames at the control rate, B bodies, S foot contact sites):
  time (N), qpos (N x nq), qvel (N x nv), body_names (B), body_pos (N x B x 3, world),
  body_quat (N x B x 4, world, w first), com (N x 3), com_vel (N x 3), angmom (N x 3: whole-body
  angular momentum about the COM, kg m^2/s), grf (N x 3: ground
  reaction force on the character), ground_contact (N x B: body touches the ground),
  support_points (N x S x 3: foot contact sites), push_force (N x 3).
Replay log: initial_state (mjSTATE_INTEGRATION), control (K x nu, the control vector of each
control tick, constant over its ``steps_per_tick`` physics steps), step_division (K: that tick's
physics step is the model's divided by this, and it takes that many times the steps; 1 unless a
behaviour asked for a finer step), and the edit log
(edit_tick, edit_field, edit_index, edit_value) of every model/data parameter the run set.
meta (JSON string): model_xml, character, behaviour, params, outcome, metrics, pushes, world,
strength, timestep, steps_per_tick, phase_events, edit_fields, format version.
No pickle: every array is numeric or a fixed-width string.
"""
from __future__ import annotations

import json
import os
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

FORMAT = "sim_athletics.trajectory"
VERSION = 1
FRAME_FIELDS = ("time", "qpos", "qvel", "body_pos", "body_quat", "com", "com_vel", "angmom", "grf",
                "ground_contact", "support_points", "push_force")
LOG_FIELDS = ("initial_state", "control", "step_division", "edit_tick", "edit_field", "edit_index", "edit_value")


@dataclass
class Trajectory:
    arrays: dict[str, np.ndarray]
    meta: dict = field(default_factory=dict)

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

    def save(self, path: str | Path) -> Path:
        """Write atomically: a failed save leaves no partial file."""
        path = Path(path)
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=path.parent, suffix=".tmp.npz")
        os.close(fd)
        try:
            meta = dict(self.meta, format=FORMAT, version=VERSION)
            np.savez_compressed(tmp, meta=np.array(json.dumps(meta)), **self.arrays)
            os.replace(tmp, path)
        finally:
            if os.path.exists(tmp):
                os.unlink(tmp)
        return path

    @classmethod
    def load(cls, path: str | Path) -> "Trajectory":
        with np.load(path, allow_pickle=False) as f:
            arrays = {k: f[k] for k in f.files}
        meta = json.loads(str(arrays.pop("meta")))
        if meta.get("format") != FORMAT:
            raise ValueError(f"{path} is not a Sim Athletics trajectory")
        return cls(arrays, meta)
