"""Low-level control: a bank of PD servos (MuJoCo position actuators) whose targets move along
Hermite curves with zero end slopes (Wooten §3.2), never in steps, and whose gains can change per
behaviour and per state. Every gain change is written to the run's edit log so a replay can
reproduce it."""
from __future__ import annotations

import mujoco
import numpy as np

from ..character.spec import CharacterSpec
from .actor import ActorView
from ..edit_log import EditLog


def hermite_blend(s: np.ndarray) -> np.ndarray:
    """Cubic Hermite from 0 to 1 with zero slope at both ends, for s in [0, 1]."""
    s = np.clip(s, 0.0, 1.0)
    return s * s * (3.0 - 2.0 * s)       # definition: the smoothstep polynomial 3s^2 - 2s^3


def hermite_scalar(s: float) -> float:
    """hermite_blend for one number (no array overhead in per-tick code)."""
    s = 0.0 if s < 0.0 else 1.0 if s > 1.0 else s
    return s * s * (3.0 - 2.0 * s)       # definition: the smoothstep polynomial 3s^2 - 2s^3


class ServoBank:
    def __init__(self, model: mujoco.MjModel, data: mujoco.MjData, character: CharacterSpec, log: EditLog,
                 actor: ActorView | None = None):
        """The servos of ``actor`` (default: the model's only character); it writes only its own
        slice of the control vector and logs gain edits at the model's actuator indices."""
        self.model, self.data, self.log = model, data, log
        actor = actor or ActorView.of(model)
        first, count = actor.actuators.start, actor.actuators.stop - actor.actuators.start
        ids = range(first, first + count)
        self.first = first                   # model index of this bank's servo 0
        self.actuators = actor.actuators     # its slice of the model's actuator arrays
        self.ctrl = data.ctrl[actor.actuators]   # a view: the bank's slice of the control vector
        self.names = [model.actuator(i).name[len(actor.prefix):] for i in ids]
        self.index = {n: i for i, n in enumerate(self.names)}
        self.qpos_adr = np.array([model.jnt_qposadr[model.actuator_trnid[i, 0]] for i in ids])
        self.dof_adr = np.array([model.jnt_dofadr[model.actuator_trnid[i, 0]] for i in ids])
        self.default_kp = model.actuator_gainprm[actor.actuators, 0].copy()
        self.default_kv = -model.actuator_biasprm[actor.actuators, 2].copy()
        self.start = data.qpos[self.qpos_adr].copy()
        self.goal = self.start.copy()
        self.t0 = np.zeros(count)
        self.duration = np.ones(count) * 1e-9
        self.offset = np.zeros(count)         # feedback added on top of the smoothed target
        self._moving = False

    def indices(self, names) -> np.ndarray:
        return np.array([self.index[n] for n in names], dtype=int)

    def angles(self) -> np.ndarray:
        return self.data.qpos[self.qpos_adr]

    def velocities(self) -> np.ndarray:
        return self.data.qvel[self.dof_adr]

    def smoothed_target(self, t: float) -> np.ndarray:
        s = (t - self.t0) / self.duration
        return self.start + (self.goal - self.start) * hermite_blend(s)

    def move_to(self, idx: np.ndarray, goal, duration: float, t: float) -> None:
        """Start a Hermite move of the targets ``idx`` from where they are now to ``goal``."""
        self._moving = True
        current = self.smoothed_target(t)
        self.start[idx] = current[idx]
        self.goal[idx] = goal
        self.t0[idx] = t
        self.duration[idx] = max(duration, 1e-9)

    def hold(self, values: np.ndarray, t: float) -> None:
        """Set every target at once, without a Hermite move: for behaviours whose targets are
        feedback laws evaluated every tick (their smoothness comes from the law itself)."""
        self.start[:] = values
        self.goal[:] = values
        self.t0[:] = t
        self._moving = False

    def set_gains(self, idx: np.ndarray, kp, kv) -> None:
        kp = np.broadcast_to(np.asarray(kp, dtype=float), idx.shape)
        kv = np.broadcast_to(np.asarray(kv, dtype=float), idx.shape)
        idx = idx + self.first if self.first else idx
        self.log.set_array(self.model.actuator_gainprm, "actuator_gainprm", idx, 0, kp)
        self.log.set_array(self.model.actuator_biasprm, "actuator_biasprm", idx, 1, -kp)
        self.log.set_array(self.model.actuator_biasprm, "actuator_biasprm", idx, 2, -kv)

    def write(self, t: float) -> None:
        if self._moving:
            self.ctrl[:] = self.smoothed_target(t) + self.offset
        else:
            np.add(self.goal, self.offset, out=self.ctrl)
