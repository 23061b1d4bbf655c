"""A model that turns into another while it runs (Hodgins & Pollard 1997, the metamorphosis): the
lengths, masses, inertias, shapes, contact spheres and servo strengths of a compiled model set,
at a fraction f, to those of the character f of the way to another of the same skeleton
(``make.between``), in place, so the state and the simulation carry on.

Why from the two compiled models and not by compiling ``between`` every tick: a compile costs
~18 ms, the runner's control tick is 5 ms. Every number ``between`` interpolates enters the
compiled arrays linearly except three, handled so the result is the compile of ``between``:
  * the inertia: the spec gives the full tensor, MuJoCo keeps its principal moments and axes;
    the tensors (R diag(I) R^T) are interpolated and re-diagonalised with MuJoCo's own mju_eig3;
  * a capsule (given by its end points): the end points are interpolated, its centre, half
    length and axis follow;
  * a box's axis (its ``along``): the x axes are interpolated and the box turned onto that.
Derived constants (subtree masses, the inverse weights that scale contact softness, the mean
inertia) come from mj_setConst; the geoms' and bodies' bounding boxes are recomputed, so the
broad phase never misses a contact of a grown shape.

The servos' gains are the behaviour's (it sets them as shares of the defaults): the morph
rescales the live kp and kv by the ratio of the interpolated defaults, so a share stays a share.
Torque limits are interpolated. The replay log stores the end model's arrays once and f per
tick (edit_log: the ``morph`` edit); replay applies the same function, so it is bit for bit.
"""
from __future__ import annotations

import math

import mujoco
import numpy as np

from ..errors import ParameterError
from .model import compile_model, excluded_pairs
from .spec import CharacterSpec

# arrays interpolated entry by entry (where the two models differ)
LINEAR = ("body_mass", "body_pos", "body_ipos", "site_pos", "actuator_forcerange", "qpos0", "qpos_spring", "dof_length")
# arrays read to interpolate the rest
SHAPED = ("body_inertia", "body_iquat", "geom_size", "geom_pos", "geom_quat")
DEFAULT_GAINS = ("kp", "kv")            # the servos' default gains (the spec's kp, kv) of each end
STRUCTURE = ("geom_type", "geom_bodyid", "body_parentid", "actuator_trnid", "bvh_child", "bvh_nodeid",
             "body_bvhadr", "body_bvhnum")
END_FIELDS = LINEAR + SHAPED + DEFAULT_GAINS


def model_arrays(model: mujoco.MjModel) -> dict[str, np.ndarray]:
    """The arrays of a freshly compiled model that a morph reads (its default servo gains: the
    compiled kp and kv, before any behaviour has changed them)."""
    out = {name: np.array(getattr(model, name), dtype=float) for name in LINEAR + SHAPED}
    out["kp"] = np.array(model.actuator_gainprm[:, 0], dtype=float)
    out["kv"] = -np.array(model.actuator_biasprm[:, 2], dtype=float)
    return out


def _lerp(a: np.ndarray, b: np.ndarray, f: float) -> np.ndarray:
    return a + f * (b - a)          # a where the ends agree, bit for bit


def _full_inertia(moments: np.ndarray, quats: np.ndarray) -> np.ndarray:
    out = np.zeros((len(moments), 3, 3))
    mat = np.zeros(9)
    for i, (m, q) in enumerate(zip(moments, quats)):
        mujoco.mju_quat2Mat(mat, q)
        r = mat.reshape(3, 3)
        out[i] = r @ np.diag(m) @ r.T
    return out


def _capsule_ends(pos: np.ndarray, quat: np.ndarray, half_length: float) -> tuple[np.ndarray, np.ndarray]:
    mat = np.zeros(9)
    mujoco.mju_quat2Mat(mat, quat)
    axis = mat.reshape(3, 3)[:, 2]
    return pos - half_length * axis, pos + half_length * axis


def _x_axis(quat: np.ndarray) -> np.ndarray:
    mat = np.zeros(9)
    mujoco.mju_quat2Mat(mat, quat)
    return mat.reshape(3, 3)[:, 0].copy()


def _quat_from_x_to(d: np.ndarray) -> np.ndarray:
    """As character.model turns a box onto its ``along`` (then normalised, as the compiler does)."""
    d = d / np.linalg.norm(d)
    c = float(d[0])
    if c < -0.999999:
        return np.array([0.0, 0.0, 0.0, 1.0])
    q = np.array([1.0 + c, 0.0, -d[2], d[1]])          # (1 + x.d, x cross d)
    return q / np.linalg.norm(q)


class Morph:
    """The morph of ``model`` (whose arrays, as compiled, are the start) into the end model's
    arrays (``model_arrays`` of a model of the same structure). ``apply(f)`` sets the model to
    the fraction f; ``fraction`` is the one last applied (0 at first)."""

    def __init__(self, model: mujoco.MjModel, end: dict[str, np.ndarray]):
        self.model = model
        self.start = model_arrays(model)
        self.end = {name: np.asarray(end[name], dtype=float) for name in END_FIELDS}
        for name in END_FIELDS:
            if self.start[name].shape != self.end[name].shape:
                raise ValueError(f"the morph's end model has another {name} shape "
                                 f"({self.end[name].shape} vs {self.start[name].shape})")
        self.scratch = mujoco.MjData(model)          # mj_setConst works on a data of its own
        self.fraction = 0.0
        self.kp, self.kv = self.start["kp"].copy(), self.start["kv"].copy()   # the defaults at ``fraction``
        self.changed = {name: np.nonzero((self.start[name] != self.end[name]).reshape(-1))[0] for name in LINEAR}
        self.inertia = (_full_inertia(self.start["body_inertia"], self.start["body_iquat"]),
                        _full_inertia(self.end["body_inertia"], self.end["body_iquat"]))
        self.bodies = [i for i in range(1, model.nbody)
                       if not np.array_equal(self.inertia[0][i], self.inertia[1][i])]
        self.geoms = [g for g in range(model.ngeom)
                      if any(not np.array_equal(self.start[n][g], self.end[n][g]) for n in ("geom_size", "geom_pos", "geom_quat"))]
        self.capsule_ends = {}
        for g in self.geoms:
            if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_CAPSULE:
                self.capsule_ends[g] = tuple(_capsule_ends(arrays["geom_pos"][g], arrays["geom_quat"][g],
                                                           arrays["geom_size"][g, 1])
                                             for arrays in (self.start, self.end))
        self.box_axes = {g: (_x_axis(self.start["geom_quat"][g]), _x_axis(self.end["geom_quat"][g]))
                         for g in self.geoms if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_BOX}

    def end_arrays(self) -> dict[str, np.ndarray]:
        return dict(self.end)

    def apply(self, f: float) -> None:
        """The model at fraction ``f`` of the way (0 = start, 1 = end)."""
        m, s, e = self.model, self.start, self.end
        for name, idx in self.changed.items():
            target = getattr(m, name).reshape(-1)
            target[idx] = _lerp(s[name].reshape(-1)[idx], e[name].reshape(-1)[idx], f)
        eigval, eigvec, quat = np.zeros(3), np.zeros(9), np.zeros(4)
        for i in self.bodies:
            tensor = _lerp(self.inertia[0][i], self.inertia[1][i], f)
            mujoco.mju_eig3(eigval, eigvec, quat, tensor.reshape(-1))
            m.body_inertia[i] = eigval
            m.body_iquat[i] = quat
        for g in self.geoms:
            self._shape(g, f)
        self._bounding_boxes()
        kp, kv = _lerp(s["kp"], e["kp"], f), _lerp(s["kv"], e["kv"], f)
        kp_ratio, kv_ratio = kp / self.kp, kv / self.kv
        m.actuator_gainprm[:, 0] *= kp_ratio
        m.actuator_biasprm[:, 1] *= kp_ratio
        m.actuator_biasprm[:, 2] *= kv_ratio
        self.kp, self.kv = kp, kv
        mujoco.mj_setConst(m, self.scratch)
        self.fraction = f

    def _shape(self, g: int, f: float) -> None:
        m, s, e = self.model, self.start, self.end
        m.geom_size[g] = _lerp(s["geom_size"][g], e["geom_size"][g], f)
        if g in self.capsule_ends:
            (a0, a1), (b0, b1) = self.capsule_ends[g]
            p0, p1 = _lerp(a0, b0, f), _lerp(a1, b1, f)
            axis = p1 - p0
            m.geom_pos[g] = 0.5 * (p0 + p1)
            m.geom_size[g, 1] = 0.5 * math.sqrt(float(axis @ axis))
            quat = np.zeros(4)
            mujoco.mju_quatZ2Vec(quat, axis)
            m.geom_quat[g] = quat
        else:
            m.geom_pos[g] = _lerp(s["geom_pos"][g], e["geom_pos"][g], f)
            if g in self.box_axes:
                a, b = self.box_axes[g]
                m.geom_quat[g] = _quat_from_x_to(_lerp(a, b, f))
        kind, size = m.geom_type[g], m.geom_size[g]
        if kind == mujoco.mjtGeom.mjGEOM_SPHERE:
            half = np.array([size[0]] * 3)
        elif kind == mujoco.mjtGeom.mjGEOM_CAPSULE:
            half = np.array([size[0], size[0], size[0] + size[1]])
        else:
            half = size.copy()
        m.geom_aabb[g] = [0.0, 0.0, 0.0, *half]
        m.geom_rbound[g] = float(np.linalg.norm(half)) if kind == mujoco.mjtGeom.mjGEOM_BOX else float(half[2])

    def _bounding_boxes(self) -> None:
        """Each body's bounding-volume tree (the compiled model's structure) over its geoms' boxes
        in the body frame, leaves first."""
        m = self.model
        mat = np.zeros(9)
        for body in {int(m.geom_bodyid[g]) for g in self.geoms}:
            first, count = int(m.body_bvhadr[body]), int(m.body_bvhnum[body])
            if first < 0:
                continue
            lo, hi = np.zeros((count, 3)), np.zeros((count, 3))
            for k in reversed(range(count)):
                node = first + k
                g = int(m.bvh_nodeid[node])
                if g >= 0:
                    mujoco.mju_quat2Mat(mat, m.geom_quat[g])
                    centre = m.geom_pos[g] + mat.reshape(3, 3) @ m.geom_aabb[g, :3]
                    half = np.abs(mat.reshape(3, 3)) @ m.geom_aabb[g, 3:]
                    lo[k], hi[k] = centre - half, centre + half
                else:
                    children = [int(c) for c in m.bvh_child[node] if c >= 0]     # relative to the body's first node
                    lo[k] = np.min([lo[c] for c in children], axis=0)
                    hi[k] = np.max([hi[c] for c in children], axis=0)
                m.bvh_aabb[node] = [*(0.5 * (lo[k] + hi[k])), *(0.5 * (hi[k] - lo[k]))]


def morph_models(start: CharacterSpec, end: CharacterSpec, world=None, strength="human"):
    """(model, mjcf_text, Morph): ``start``'s model, compiled with the contact exclusions of both
    (the woman's upper arms rest on her chest, the man's do not; the exclusions are fixed in a
    compiled model), and its morph into ``end`` compiled the same way."""
    if start.body_names != end.body_names or [d.name for d in start.dofs] != [d.name for d in end.dofs]:
        raise ParameterError(f"the {start.name} cannot morph into the {end.name}: only characters of the same "
                             "skeleton (bodies and joints) can")
    pairs = tuple(sorted(set(excluded_pairs(start)) | set(excluded_pairs(end))))
    model, xml = compile_model(start, world, strength, also_excluded=pairs)
    end_model, _ = compile_model(end, world, strength, also_excluded=pairs)
    return model, xml, Morph(model, model_arrays(end_model))
