"""Low-level control: a bank of PD servos (MuJoCo position actuators) whose targets move along
Hermite curves with zero end slopes (Wooten §3.2), never in steps, and whose gains can change per
behaviour and per state. Every gain change is written to the run's edit log so a replay can
reproduce it."""
from __future__ import annotations

import mujoco
import numpy as np

from sim_core.character.spec import CharacterSpec
from sim_core.edit_log import EditLog


def hermite_blend(s: np.ndarray) -> np.ndarray:
    """Cubic Hermite from 0 to 1 with zero slope at both ends, for s in [0, 1]."""
    s = np.clip(s, 0.0, 1.0)
    return s * s * (3.0 - 2.0 * s)


def hermite_scalar(s: float) -> float:
    """hermite_blend for one number (no array overhead in per-tick code)."""
    s = 0.0 if s < 0.0 else 1.0 if s > 1.0 else s
    return s * s * (3.0 - 2.0 * s)


class ServoBank:
    def __init__(self, model: mujoco.MjModel, data: mujoco.MjData, character: CharacterSpec, log: EditLog):
        self.model, self.data, self.log = model, data, log
        self.names = [model.actuator(i).name for i in range(model.nu)]
        self.index = {n: i for i, n in enumerate(self.names)}
        self.qpos_adr = np.array([model.jnt_qposadr[model.actuator_trnid[i, 0]] for i in range(model.nu)])
        self.dof_adr = np.array([model.jnt_dofadr[model.actuator_trnid[i, 0]] for i in range(model.nu)])
        self.default_kp = model.actuator_gainprm[:, 0].copy()
        self.default_kv = -model.actuator_biasprm[:, 2].copy()
        self.start = data.qpos[self.qpos_adr].copy()
        self.goal = self.start.copy()
        self.t0 = np.zeros(model.nu)
        self.duration = np.ones(model.nu) * 1e-9
        self.offset = np.zeros(model.nu)      # feedback added on top of the smoothed target
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
        self.log.set_array(self.model.actuator_gainprm, "actuator_gainprm", idx, 0, kp)
        self.log.set_array(self.model.actuator_biasprm, "actuator_biasprm", idx, 1, -kp)
        self.log.set_array(self.model.actuator_biasprm, "actuator_biasprm", idx, 2, -kv)

    def write(self, t: float) -> None:
        if self._moving:
            self.data.ctrl[:] = self.smoothed_target(t) + self.offset
        else:
            np.add(self.goal, self.offset, out=self.data.ctrl)
