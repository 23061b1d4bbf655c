"""The replay log of everything a run changed besides the state: model parameters the controller
set (servo gains, gravity of a tilting ground), the applied push forces and the equality
constraints switched on or off (a rider's foot let go of its pedal) and joint friction (a bicycle's
rim brakes). Each edit is
(tick, field, flat index, value); replay re-applies them before the same tick's physics steps.
A morph (sim_core.character.morph: the body turning into another while it runs) is one edit per
tick, ("morph", 0, f); the end model's arrays are stored once (``morph_end_<name>``), and replay
applies the same morph function to the logged model."""
from __future__ import annotations

import numpy as np

from .character.morph import Morph

# Model/data arrays a run may edit, by name. Replay looks them up with getattr.
EDITABLE_FIELDS = ("actuator_gainprm", "actuator_biasprm", "opt.gravity", "push_force", "eq_active", "dof_frictionloss",
                   "morph")
MORPH = EDITABLE_FIELDS.index("morph")
MORPH_END = "morph_end_"        # prefix of the arrays holding the morph's end model


class EditLog:
    def __init__(self):
        self.tick = 0
        self._ticks: list[int] = []
        self._fields: list[int] = []
        self._indices: list[int] = []
        self._values: list[float] = []
        self.morph = None

    def set_array(self, array: np.ndarray, field: str, rows: np.ndarray, col: int, values: np.ndarray) -> None:
        """array[rows, col] = values, logged (``array`` must be the live model/data array)."""
        array[rows, col] = values
        ncol = array.shape[1]
        code = EDITABLE_FIELDS.index(field)
        for r, v in zip(np.atleast_1d(rows), np.atleast_1d(values)):
            self._append(code, int(r) * ncol + col, float(v))

    def set_flat(self, array: np.ndarray, field: str, values: np.ndarray) -> None:
        """array[:] = values (flattened), logging only the entries that change."""
        flat = array.reshape(-1)
        new = np.asarray(values, dtype=float).reshape(-1)
        changed = np.nonzero(flat != new)[0]
        code = EDITABLE_FIELDS.index(field)
        for i in changed:
            self._append(code, int(i), float(new[i]))
        flat[:] = new

    def set_morph(self, morph, fraction: float) -> None:
        """The model ``fraction`` of the way to the morph's end (Morph.apply), logged."""
        if self.morph is not None and self.morph is not morph:
            raise ValueError("a run has at most one morph")
        self.morph = morph
        morph.apply(fraction)
        self._append(MORPH, 0, float(fraction))

    def _append(self, code: int, index: int, value: float) -> None:
        self._ticks.append(self.tick)
        self._fields.append(code)
        self._indices.append(index)
        self._values.append(value)

    def arrays(self) -> dict[str, np.ndarray]:
        return {"edit_tick": np.array(self._ticks, dtype=np.int64),
                "edit_field": np.array(self._fields, dtype=np.int64),
                "edit_index": np.array(self._indices, dtype=np.int64),
                "edit_value": np.array(self._values, dtype=np.float64),
                **({MORPH_END + k: v for k, v in self.morph.end_arrays().items()} if self.morph is not None else {})}


def applied_forces(data) -> np.ndarray:
    """The one array through which a push acts (world-frame force and torque at each body's COM;
    sim_core.perturbation's pushes write it through the log)."""
    return data.xfrc_applied          # written only by the logged pushes (sim_core.perturbation)


def resolve_field(model, data, field: str) -> np.ndarray | None:
    if field == "morph":                         # not an array: EditPlayer applies the morph
        return None
    if field == "opt.gravity":
        return model.opt.gravity
    if field == "push_force":                    # the pushes' forces (sim_core.perturbation)
        return applied_forces(data)
    if field == "eq_active":                     # equality constraints on or off (mjData: part of the state)
        return data.eq_active
    return getattr(model, field)


class EditPlayer:
    """Re-applies a recorded edit log tick by tick."""

    def __init__(self, model, data, arrays: dict[str, np.ndarray]):
        self.targets = [None if t is None else t.reshape(-1) for t in (resolve_field(model, data, f) for f in EDITABLE_FIELDS)]
        self.morph = None
        end = {k[len(MORPH_END):]: v for k, v in arrays.items() if k.startswith(MORPH_END)}
        if end:
            self.morph = Morph(model, end)
        self.ticks, self.fields = arrays["edit_tick"], arrays["edit_field"]
        self.indices, self.values = arrays["edit_index"], arrays["edit_value"]
        self.cursor = 0

    def apply(self, tick: int) -> None:
        n = len(self.ticks)
        while self.cursor < n and self.ticks[self.cursor] == tick:
            k = self.cursor
            if self.fields[k] == MORPH:
                self.morph.apply(float(self.values[k]))
            else:
                self.targets[self.fields[k]][self.indices[k]] = self.values[k]
            self.cursor += 1
