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


def lerp(a, b, f: float):
    """``f`` of the way from ``a`` to ``b`` (numbers or arrays): a where the ends agree, bit for bit.
    The one interpolation of a body between two (character.make.between, the morph, the running
    controller's tables)."""
    return a + f * (b - a)


def _matrices(quats: np.ndarray) -> np.ndarray:
    """Unit quaternions (n, 4), w first -> rotation matrices (n, 3, 3)."""
    w, x, y, z = quats.T
    return np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
                     2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                     2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], axis=1).reshape(-1, 3, 3)


def _full_inertia(moments: np.ndarray, quats: np.ndarray) -> np.ndarray:
    r = _matrices(quats)
    return r @ (moments[:, :, None] * np.swapaxes(r, 1, 2))


def _z_to(vectors: np.ndarray) -> np.ndarray:
    """Quaternions turning +Z onto each vector (as mju_quatZ2Vec, which the compiler's ``fromto``
    follows): about z x v by the angle between them."""
    v = vectors / np.linalg.norm(vectors, axis=1, keepdims=True)
    axis = np.stack([-v[:, 1], v[:, 0], np.zeros(len(v))], axis=1)
    sin = np.linalg.norm(axis, axis=1)
    angle = np.arctan2(sin, v[:, 2])
    unit = axis / np.where(sin > 0, sin, 1.0)[:, None]
    out = np.concatenate([np.cos(angle / 2)[:, None], np.sin(angle / 2)[:, None] * unit], axis=1)
    out[sin == 0] = np.where(v[sin == 0, 2:3] < 0, [0.0, 1.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0])
    return out


def _x_to(vectors: np.ndarray) -> np.ndarray:
    """As character.model turns a box onto its ``along``: (1 + x.d, x cross d), normalised."""
    d = vectors / np.linalg.norm(vectors, axis=1, keepdims=True)
    q = np.stack([1.0 + d[:, 0], np.zeros(len(d)), -d[:, 2], d[:, 1]], axis=1)
    q = q / np.linalg.norm(q, axis=1, keepdims=True)
    q[d[:, 0] < -0.999999] = [0.0, 0.0, 0.0, 1.0]
    return q


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
        s, e = self.start, self.end
        self.changed = {name: np.nonzero((s[name] != e[name]).reshape(-1))[0] for name in LINEAR}
        tensors = (_full_inertia(s["body_inertia"], s["body_iquat"]), _full_inertia(e["body_inertia"], e["body_iquat"]))
        self.bodies = np.array([i for i in range(1, model.nbody) if not np.array_equal(tensors[0][i], tensors[1][i])],
                               dtype=int)
        self.inertia = (tensors[0][self.bodies], tensors[1][self.bodies])
        geoms = np.array([g for g in range(model.ngeom) if any(not np.array_equal(s[n][g], e[n][g])
                                                                for n in ("geom_size", "geom_pos", "geom_quat"))], dtype=int)
        kind = model.geom_type[geoms]
        self.geoms = geoms
        self.capsules = geoms[kind == mujoco.mjtGeom.mjGEOM_CAPSULE]
        self.spheres = geoms[kind == mujoco.mjtGeom.mjGEOM_SPHERE]
        self.boxes = geoms[kind == mujoco.mjtGeom.mjGEOM_BOX]
        self.others = geoms[kind != mujoco.mjtGeom.mjGEOM_CAPSULE]     # centred on their ``pos``
        if len(geoms) != len(self.capsules) + len(self.spheres) + len(self.boxes):
            raise ValueError("a morph moves capsules, spheres and boxes only")
        c = self.capsules
        self.capsule_ends = [(arrays["geom_pos"][c] - arrays["geom_size"][c, 1:2] * _matrices(arrays["geom_quat"][c])[:, :, 2],
                              arrays["geom_pos"][c] + arrays["geom_size"][c, 1:2] * _matrices(arrays["geom_quat"][c])[:, :, 2])
                             for arrays in (s, e)]
        self.box_axes = (_matrices(s["geom_quat"][self.boxes])[:, :, 0], _matrices(e["geom_quat"][self.boxes])[:, :, 0])
        self._prepare_trees()

    def _prepare_trees(self) -> None:
        """The bounding-volume nodes of the bodies whose geoms move: the leaves (a node per geom)
        and the inner nodes, children before parents (the compiled model's tree)."""
        m = self.model
        bodies = sorted({int(m.geom_bodyid[g]) for g in self.geoms})
        nodes = [n for b in bodies if m.body_bvhadr[b] >= 0
                 for n in range(int(m.body_bvhadr[b]), int(m.body_bvhadr[b] + m.body_bvhnum[b]))]
        self.leaves = np.array([n for n in nodes if m.bvh_nodeid[n] >= 0], dtype=int)
        self.leaf_geoms = m.bvh_nodeid[self.leaves].astype(int)
        first = {n: int(m.body_bvhadr[b]) for b in bodies for n in range(int(m.body_bvhadr[b]),
                                                                          int(m.body_bvhadr[b] + m.body_bvhnum[b]))}
        # children are stored relative to their body's first node, and come after their parent
        self.inner = [(n, [first[n] + int(c) for c in m.bvh_child[n] if c >= 0])
                      for n in sorted(nodes, reverse=True) if m.bvh_nodeid[n] < 0]

    def end_arrays(self) -> dict[str, np.ndarray]:
        return dict(self.end)

    def apply(self, f: float) -> None:
        """The model at fraction ``f`` of the way (0 = start, 1 = end)."""
        m, s, e = self.model, self.start, self.end
        for name, idx in self.changed.items():
            target = getattr(m, name).reshape(-1)
            target[idx] = lerp(s[name].reshape(-1)[idx], e[name].reshape(-1)[idx], f)
        eigval, eigvec, quat = np.zeros(3), np.zeros(9), np.zeros(4)
        for i, tensor in zip(self.bodies, lerp(self.inertia[0], self.inertia[1], f).reshape(-1, 9)):
            mujoco.mju_eig3(eigval, eigvec, quat, tensor)
            m.body_inertia[i] = eigval
            m.body_iquat[i] = quat
        self._shapes(f)
        self._bounding_boxes()
        kp, kv = lerp(s["kp"], e["kp"], f), lerp(s["kv"], e["kv"], f)
        kp_ratio, kv_ratio = kp / self.kp, kv / self.kv
        m.actuator_gainprm[:, 0] *= kp_ratio
        m.actuator_biasprm[:, 1] *= kp_ratio
        m.actuator_biasprm[:, 2] *= kv_ratio
        self.kp, self.kv = kp, kv
        mujoco.mj_setConst(m, self.scratch)
        self.fraction = f

    def _shapes(self, f: float) -> None:
        m, s, e = self.model, self.start, self.end
        g = self.geoms
        m.geom_size[g] = lerp(s["geom_size"][g], e["geom_size"][g], f)
        g = self.others
        m.geom_pos[g] = lerp(s["geom_pos"][g], e["geom_pos"][g], f)
        if len(self.boxes):
            m.geom_quat[self.boxes] = _x_to(lerp(self.box_axes[0], self.box_axes[1], f))
        if len(self.capsules):
            (a0, a1), (b0, b1) = self.capsule_ends
            p0, p1 = lerp(a0, b0, f), lerp(a1, b1, f)
            axis = p1 - p0
            m.geom_pos[self.capsules] = 0.5 * (p0 + p1)
            m.geom_size[self.capsules, 1] = 0.5 * np.linalg.norm(axis, axis=1)
            m.geom_quat[self.capsules] = _z_to(axis)
        # MuJoCo's bounding box (centre, half sizes) and radius of each primitive
        r = m.geom_size[self.spheres, 0]
        m.geom_aabb[self.spheres] = np.stack([0 * r, 0 * r, 0 * r, r, r, r], axis=1)
        m.geom_rbound[self.spheres] = r
        r, h = m.geom_size[self.capsules, 0], m.geom_size[self.capsules, 1]
        m.geom_aabb[self.capsules] = np.stack([0 * r, 0 * r, 0 * r, r, r, r + h], axis=1)
        m.geom_rbound[self.capsules] = r + h
        half = m.geom_size[self.boxes]
        m.geom_aabb[self.boxes] = np.concatenate([0 * half, half], axis=1)
        m.geom_rbound[self.boxes] = np.linalg.norm(half, axis=1)

    def _bounding_boxes(self) -> None:
        """Each moved body's bounding-volume tree (the compiled model's structure) over its geoms'
        boxes in the body frame: the leaves at once, then the inner nodes, children first."""
        m = self.model
        g = self.leaf_geoms
        rot = _matrices(m.geom_quat[g])
        centre = m.geom_pos[g] + (rot @ m.geom_aabb[g, :3, None])[:, :, 0]
        half = (np.abs(rot) @ m.geom_aabb[g, 3:, None])[:, :, 0]
        lo, hi = {}, {}
        for n, c, h in zip(self.leaves, centre, half):
            lo[n], hi[n] = c - h, c + h
        for n, children in self.inner:
            lo[n] = np.min([lo[c] for c in children], axis=0)
            hi[n] = np.max([hi[c] for c in children], axis=0)
        nodes = list(lo)
        low, high = np.array([lo[n] for n in nodes]), np.array([hi[n] for n in nodes])
        m.bvh_aabb[nodes] = np.concatenate([0.5 * (low + high), 0.5 * (high - low)], axis=1)


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
