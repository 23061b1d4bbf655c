"""One smooth, watertight skin for a character, made from its spec's shapes (dm_control's
``create_skin.py`` is the model: the skin is generated from the bodies, by a script, as data).

Pipeline, each step a function:
  1. ``segment_distances``: signed distance of grid points to every body's shapes (the shapes are
     the spec's, in world coordinates of the reference T-pose, each sized so that its volume x the
     segment's density = its mass). The torso's slices become one lofted trunk (``TorsoLoft``);
     a body whose shape stops short of its joint gets a skin-only connector (``connector``: the
     neck, the ankle).
  2. ``skin_field``: the union of all bodies; neighbouring bodies (parent and child) are joined
     with a smooth minimum so that joints get a fillet instead of a crease, while bodies that
     merely touch (the two thighs, the arm and the chest) keep a hard union and no web between
     them.
  3. ``calibrate_offsets``: the union loses the volume where two shapes overlap and the fillets
     add some; each body's surface is moved out or in by a small offset until the interior
     assigned to it (``segment_volumes``: interior grid cells labelled by the nearest body) x its
     density equals its mass.
  4. ``mesh_from_field``: marching cubes, then Taubin smoothing (which keeps the volume), on a
     grid whose cell size sets the vertex count (about 1 cm -> ~20k vertices for the man).
  5. ``joint_weights``: per-vertex weights that blend linearly-smoothly across each joint's
     plane (Wooten Fig. 3.6), so a knee bends instead of shearing; a vertex far from any joint
     belongs to one body only.

No bpy: build.py runs this with NumPy, scikit-image and trimesh.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

SMOOTH_UNION = 0.025        # m: fillet size where a parent and a child limb meet
SLAB_UNION = 0.04           # m: fillet between the trunk and a limb, the neck or a thigh
BOX_ROUNDING = 0.008        # m: edge radius of boxes (hands, feet)
SLAB_ROUNDING = 0.03        # m: edge radius of the trunk's bottom and top
SEAM_BRIDGE = 0.02          # m: half-height of the whole trunk put back across a spine joint where it shrinks
TRUNK_BLEND = 0.06          # m: half-width of the smooth change between two torso slices
MAX_INFLUENCES = 4          # weights per vertex (glTF JOINTS_0/WEIGHTS_0)


# ----------------------------------------------------------------------------- shapes

def _rotation_x_to(direction) -> np.ndarray:
    """Rotation matrix turning +X onto ``direction`` (the same rotation as the model builder's
    box quaternion, so a skin box sits exactly where the simulated box is)."""
    d = np.asarray(direction, dtype=float)
    d = d / np.linalg.norm(d)
    x = np.array([1.0, 0.0, 0.0])
    c = float(np.dot(x, d))
    if c < -0.999999:
        return np.diag([-1.0, 1.0, -1.0])
    v = np.cross(x, d)
    vx = np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])
    return np.eye(3) + vx + vx @ vx / (1.0 + c)


def sdf_capsule(p: np.ndarray, a, b, radius: float) -> np.ndarray:
    a, b = np.asarray(a, float), np.asarray(b, float)
    ab = b - a
    t = np.clip(((p - a) @ ab) / float(ab @ ab), 0.0, 1.0)
    return np.linalg.norm(p - (a + t[:, None] * ab), axis=1) - radius


def sdf_sphere(p: np.ndarray, centre, radius: float) -> np.ndarray:
    return np.linalg.norm(p - np.asarray(centre, float), axis=1) - radius


def sdf_box(p: np.ndarray, pos, half, along=(1.0, 0.0, 0.0), rounding: float = 0.0) -> np.ndarray:
    """Box with edges rounded by ``rounding`` (kept inside the box's outline)."""
    local = (p - np.asarray(pos, float)) @ _rotation_x_to(along)
    r = min(rounding, 0.45 * min(half))
    q = np.abs(local) - (np.asarray(half, float) - r)
    outside = np.linalg.norm(np.maximum(q, 0.0), axis=1)
    inside = np.minimum(q.max(axis=1), 0.0)
    return outside + inside - r


def sdf_ellipse_slab(p: np.ndarray, pos, half, rounding: float = 0.0) -> np.ndarray:
    """Elliptic cylinder along Z: semi-axes half[0] (X), half[1] (Y), half-height half[2] (Z);
    the torso slices of the spec (volume pi a b h)."""
    local = p - np.asarray(pos, float)
    a, b, h = half
    r = min(rounding, 0.45 * min(half))
    return _rounded_elliptic_cylinder(local[:, 0], local[:, 1], np.abs(local[:, 2]) - (h - r), a - r, b - r, r)


def _rounded_elliptic_cylinder(x, y, d_z, ra, rb, r) -> np.ndarray:
    """Distance to an elliptic cylinder (semi-axes ``ra``, ``rb``; ``d_z`` = signed distance to
    its end planes) grown by ``r``, which rounds its rims. The ellipse distance is the usual
    first-order one (exact on the axes, accurate near the curve)."""
    k0 = np.sqrt((x / ra) ** 2 + (y / rb) ** 2)
    k1 = np.sqrt((x / ra ** 2) ** 2 + (y / rb ** 2) ** 2)
    d_xy = np.where(k1 > 1e-12, k0 * (k0 - 1.0) / np.maximum(k1, 1e-12), -np.minimum(ra, rb))
    w = np.stack([d_xy, d_z], axis=1)
    return np.minimum(w.max(axis=1), 0.0) + np.linalg.norm(np.maximum(w, 0.0), axis=1) - r


def shape_distance(p: np.ndarray, shape: dict) -> np.ndarray:
    kind = shape["type"]
    if kind == "capsule":
        return sdf_capsule(p, shape["from"], shape["to"], shape["radius"])
    if kind == "sphere":
        return sdf_sphere(p, shape["pos"], shape["radius"])
    if kind == "box":
        return sdf_box(p, shape["pos"], shape["half"], shape.get("along", (1, 0, 0)), BOX_ROUNDING)
    if kind == "ellipse_slab":
        return sdf_ellipse_slab(p, shape["pos"], shape["half"], SLAB_ROUNDING)
    raise ValueError(f"unknown shape type {kind!r}")


class TorsoLoft:
    """The torso slices (the spec's ``ellipse_slab`` shapes, stacked along Z) as one trunk: each
    slice keeps its own ellipse through its middle, and at every spine joint the semi-axes and
    the centre pass to the next slice's along a smoothstep over +/- ``TRUNK_BLEND`` (at most 90 %
    of either slice's half-height). The steps become smooth waists and bulges, while each slice's
    volume stays close to its own (what is added below a joint is taken above it)."""

    def __init__(self, slabs: list[dict]):
        slabs = sorted(slabs, key=lambda sh: sh["pos"][2])
        self.columns = np.array([[sh["half"][0], sh["half"][1], sh["pos"][0], sh["pos"][1]] for sh in slabs])
        self.joints = [0.5 * (lo["pos"][2] + lo["half"][2] + hi["pos"][2] - hi["half"][2])
                       for lo, hi in zip(slabs, slabs[1:])]
        self.widths = [min(TRUNK_BLEND, 0.9 * lo["half"][2], 0.9 * hi["half"][2])
                       for lo, hi in zip(slabs, slabs[1:])]
        self.z_range = (slabs[0]["pos"][2] - slabs[0]["half"][2], slabs[-1]["pos"][2] + slabs[-1]["half"][2])

    def profile(self, z: np.ndarray) -> np.ndarray:
        """(N, 4): semi-axis X, semi-axis Y, centre X, centre Y at heights ``z``."""
        out = np.repeat(self.columns[:1], len(z), axis=0)
        for k, (joint, width) in enumerate(zip(self.joints, self.widths)):
            t = _smoothstep((z - joint + width) / (2.0 * width))
            out += t[:, None] * (self.columns[k + 1] - self.columns[k])
        return out

    def distance(self, p: np.ndarray, rounding: float = 0.0) -> np.ndarray:
        a, b, cx, cy = np.moveaxis(self.profile(p[:, 2]), -1, 0)
        r = min(rounding, 0.45 * float(self.columns[:, :2].min()))
        lo, hi = self.z_range
        d_z = np.maximum(lo + r - p[:, 2], p[:, 2] - (hi - r))
        return _rounded_elliptic_cylinder(p[:, 0] - cx, p[:, 1] - cy, d_z, a - r, b - r, r)


def torso_slices(bodies: list[dict]) -> list[int]:
    """Bodies whose only shape is an ellipse slab: the pelvis and the spine's slices."""
    return [i for i, b in enumerate(bodies) if len(b["shapes"]) == 1 and b["shapes"][0]["type"] == "ellipse_slab"]


def segment_distances(bodies: list[dict], points: np.ndarray) -> np.ndarray:
    """(B, N) signed distance of each point to each body's shapes (min over its shapes); the
    torso slices are cut from one lofted trunk (``TorsoLoft``) by their own height ranges."""
    out = np.empty((len(bodies), len(points)), dtype=np.float32)
    slices = torso_slices(bodies)
    if slices:
        trunk = TorsoLoft([bodies[i]["shapes"][0] for i in slices]).distance(points, SLAB_ROUNDING)
        for i in slices:
            sh = bodies[i]["shapes"][0]
            lo, hi = sh["pos"][2] - sh["half"][2], sh["pos"][2] + sh["half"][2]
            out[i] = np.maximum(trunk, np.maximum(lo - points[:, 2], points[:, 2] - hi))
    for i, body in enumerate(bodies):
        if i in slices:
            continue
        shapes = body["shapes"]
        if not shapes:
            raise ValueError(f"body {body['name']!r} has no shapes to make a skin from")
        d = shape_distance(points, shapes[0])
        for shape in shapes[1:] + connector(body):
            d = np.minimum(d, shape_distance(points, shape))
        out[i] = d
    return out


def connector(body: dict) -> list[dict]:
    """A skin-only capsule from a body's joint to its shape when the shape stops short of the
    joint by more than a centimetre (the head's sphere sits 3 cm above the neck joint: this is
    the neck; the foot's box sits below the ankle). Half the shape's thickness."""
    if not body.get("joint"):
        return []
    joint = np.array(body["joint"]["pos"], dtype=float)
    shape = body["shapes"][0]
    if float(shape_distance(joint[None], shape)[0]) <= 0.01:
        return []
    if shape["type"] == "capsule":
        centre, size = 0.5 * (np.array(shape["from"]) + np.array(shape["to"])), shape["radius"]
    elif shape["type"] == "sphere":
        centre, size = np.array(shape["pos"]), shape["radius"]
    else:
        centre, size = np.array(shape["pos"]), min(shape["half"])
    return [{"type": "capsule", "from": joint.tolist(), "to": centre.tolist(), "radius": 0.5 * size}]


def tree_edges(bodies: list[dict]) -> list[tuple[int, int, float]]:
    """(parent, child, fillet size) for every joint where two shapes meet: limbs with a small
    fillet, a limb (or the head) on the trunk with a larger one. Two torso slices need none:
    they are cut from one lofted trunk and meet without a seam."""
    index = {b["name"]: i for i, b in enumerate(bodies)}
    trunk = set(torso_slices(bodies))
    edges = []
    for i, b in enumerate(bodies):
        if b.get("parent"):
            p = index[b["parent"]]
            if p in trunk and i in trunk:
                continue
            edges.append((p, i, SLAB_UNION if p in trunk or i in trunk else SMOOTH_UNION))
    return edges


def smooth_min(a: np.ndarray, b: np.ndarray, k: float) -> np.ndarray:
    """Polynomial smooth minimum: equals min(a, b) where |a - b| >= k, rounds the crease below."""
    h = np.maximum(k - np.abs(a - b), 0.0) / k
    return np.minimum(a, b) - h * h * k * 0.25


def skin_field(distances: np.ndarray, edges: list[tuple[int, int, float]]) -> np.ndarray:
    field = distances.min(axis=0)
    for i, j, k in edges:
        field = np.minimum(field, smooth_min(distances[i], distances[j], k))
    return field


# ----------------------------------------------------------------------------- grid and volume

@dataclass
class Grid:
    origin: np.ndarray      # world position of cell (0, 0, 0)
    spacing: float
    shape: tuple[int, int, int]

    def points(self) -> np.ndarray:
        axes = [self.origin[i] + self.spacing * np.arange(self.shape[i]) for i in range(3)]
        return np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)

    @property
    def cell_volume(self) -> float:
        return self.spacing ** 3


def bounding_grid(bodies: list[dict], spacing: float, margin: float = 0.04) -> Grid:
    lo, hi = np.full(3, np.inf), np.full(3, -np.inf)
    for body in bodies:
        for s in body["shapes"]:
            if s["type"] == "capsule":
                pts = np.array([s["from"], s["to"]])
                ext = s["radius"]
            elif s["type"] == "sphere":
                pts, ext = np.array([s["pos"]]), s["radius"]
            else:
                pts, ext = np.array([s["pos"]]), float(np.linalg.norm(s["half"]))
            lo = np.minimum(lo, pts.min(axis=0) - ext)
            hi = np.maximum(hi, pts.max(axis=0) + ext)
    lo, hi = lo - margin, hi + margin
    shape = tuple(int(math.ceil((hi[i] - lo[i]) / spacing)) + 1 for i in range(3))
    return Grid(lo, spacing, shape)


def occupancy(field: np.ndarray, spacing: float) -> np.ndarray:
    """Fraction of each grid cell inside the skin, from the signed distance at its centre (a
    linear ramp over one cell): much less sampling noise than counting cells in or out."""
    return np.clip(0.5 - field / spacing, 0.0, 1.0)


def segment_volumes(distances: np.ndarray, field: np.ndarray, spacing: float) -> np.ndarray:
    """Volume of the skin's interior assigned to each body: interior cells labelled by the body
    whose own surface is nearest (deepest inside), each counted by its occupancy."""
    occ = occupancy(field, spacing)
    used = occ > 0.0
    labels = np.argmin(distances[:, used], axis=0)
    return np.bincount(labels, weights=occ[used], minlength=len(distances)) * spacing ** 3


def growth_areas(distances: np.ndarray, field: np.ndarray, spacing: float) -> np.ndarray:
    """d(volume)/d(offset) of each body (m^2): its share of the skin's surface, plus half its
    interfaces with the other bodies inside (growing one body moves an interface by half the
    offset). Both are counted as grid cells in a band one cell thick."""
    band = np.abs(field) < 0.5 * spacing
    area = np.bincount(np.argmin(distances[:, band], axis=0), minlength=len(distances)) * spacing ** 2
    inside = field < 0.0
    d = distances[:, inside]
    two = np.partition(d, 1, axis=0)[:2]
    near = (two[1] - two[0]) < spacing
    labels = np.argmin(d[:, near], axis=0)
    return area + 0.5 * np.bincount(labels, minlength=len(distances)) * spacing ** 2


class Offsets:
    """Moves each body's surface out by its offset. The trunk's slices share one offset that
    varies smoothly with height (interpolated between the slices' mid-heights), so the lofted
    trunk stays seamless where two slices with different offsets meet."""

    def __init__(self, bodies: list[dict], points: np.ndarray):
        self.slices = torso_slices(bodies)
        self.mids = np.array([bodies[i]["shapes"][0]["pos"][2] for i in self.slices])
        order = np.argsort(self.mids)
        self.slices, self.mids = [self.slices[k] for k in order], self.mids[order]
        self.z = points[:, 2]

    def trunk_offset(self, offsets: np.ndarray, z: np.ndarray | None = None) -> np.ndarray:
        """The trunk's offset at heights ``z`` (default: the grid's), between the slices' own."""
        return np.interp(self.z if z is None else z, self.mids, offsets[self.slices])

    def apply(self, distances: np.ndarray, offsets: np.ndarray) -> np.ndarray:
        shifted = distances - offsets[:, None]
        if self.slices:
            along = self.trunk_offset(offsets).astype(distances.dtype)
            shifted[self.slices] = distances[self.slices] - along
        return shifted


class SeamBridge:
    """Makes the trunk whole across every spine joint where it shrinks. Each torso slice is cut
    by its own end planes, so at a joint the skin field is minus the trunk's offset there: a
    trunk that grows (the thesis characters) stays joined, one that shrinks (a made character's
    thin trunk slice) splits there into two surfaces, and the mesh keeps only the larger. With
    the bridge, the loft itself, shifted by its offset, fills +/- SEAM_BRIDGE about such a joint;
    near the surface it equals the slices' own field, so only the split closes. build_rig uses it
    only when the skin without it falls apart (so the rigs that never split are unchanged)."""

    def __init__(self, bodies: list[dict], points: np.ndarray, offsets_of: Offsets):
        self.offsets_of = offsets_of
        slabs = [bodies[i]["shapes"][0] for i in offsets_of.slices]
        self.joints = [0.5 * (low["pos"][2] + low["half"][2] + up["pos"][2] - up["half"][2])
                       for low, up in zip(slabs, slabs[1:])]
        self.loft = TorsoLoft(slabs).distance(points, SLAB_ROUNDING).astype(np.float32) if slabs else None
        self.z = points[:, 2]

    def __call__(self, field: np.ndarray, offsets: np.ndarray) -> np.ndarray:
        shrunk = [j for j in self.joints if self.offsets_of.trunk_offset(offsets, np.array([j]))[0] < 0.0]
        if not shrunk:
            return field
        loft = self.loft - self.offsets_of.trunk_offset(offsets).astype(np.float32)
        for joint in shrunk:
            field = np.minimum(field, np.maximum(loft, np.abs(self.z - joint) - SEAM_BRIDGE))
        return field


def calibrate_offsets(distances: np.ndarray, edges, targets: np.ndarray, spacing: float,
                      offsets_of: Offsets, iterations: int = 40, tolerance: float = 0.01,
                      damping: float = 0.3, bridge: SeamBridge | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Per-body offsets (m, positive = grow) so that each body's assigned interior volume x its
    density matches its mass; returns (offsets, volumes). Damped Newton steps per body: a body
    short of ``dV`` grows by ``dV / growth_area`` (buried bodies such as the sternum take their
    growth from their neighbours, which the next steps correct)."""
    offsets = np.zeros(len(distances), dtype=np.float32)
    for _ in range(iterations):
        shifted = offsets_of.apply(distances, offsets)
        field = skin_field(shifted, edges)
        if bridge is not None:
            field = bridge(field, offsets)
        volumes = segment_volumes(shifted, field, spacing)
        if np.all(np.abs(volumes / targets - 1.0) < tolerance):
            break
        area = np.maximum(growth_areas(shifted, field, spacing), 1e-4)
        step = damping * (targets - volumes) / area
        offsets = offsets + np.clip(step, -0.005, 0.005).astype(np.float32)
    else:
        shifted = offsets_of.apply(distances, offsets)
        field = skin_field(shifted, edges)
        volumes = segment_volumes(shifted, field if bridge is None else bridge(field, offsets), spacing)
    return offsets, volumes


# ----------------------------------------------------------------------------- mesh

def mesh_from_field(field: np.ndarray, grid: Grid, smoothing_iterations: int = 10):
    """Marching cubes of the zero level, oriented outward, then Taubin-smoothed (trimesh); only
    the body's one connected surface is kept."""
    import trimesh
    from skimage.measure import marching_cubes

    volume = field.reshape(grid.shape)
    verts, faces, _normals, _values = marching_cubes(volume, level=0.0, spacing=(grid.spacing,) * 3)
    mesh = trimesh.Trimesh(verts + grid.origin, faces, process=True)
    mesh.update_faces(mesh.nondegenerate_faces())
    pieces = mesh.split(only_watertight=False)
    if len(pieces) > 1:          # specks where the field grazes zero between grid points
        mesh = max(pieces, key=lambda piece: len(piece.faces))
    mesh.remove_unreferenced_vertices()
    if mesh.volume < 0:
        mesh.invert()
    if smoothing_iterations:
        trimesh.smoothing.filter_taubin(mesh, lamb=0.5, nu=0.53, iterations=smoothing_iterations)
    return mesh


# ----------------------------------------------------------------------------- weights

def _body_axis(bodies: list[dict], i: int, children: dict[int, list[int]]) -> np.ndarray:
    """Direction of a body's bone: from its joint to its first child's joint, or to its COM."""
    body = bodies[i]
    start = np.array(body["joint"]["pos"]) if body.get("joint") else np.array(body["com"])
    kids = children.get(i, [])
    end = np.array(bodies[kids[0]]["joint"]["pos"]) if kids else np.array(body["com"])
    d = end - start
    if np.linalg.norm(d) < 1e-6:
        d = np.array([0.0, 0.0, 1.0])
    return d / np.linalg.norm(d)


def joint_blend_width(body: dict) -> float:
    """Half-width (m) of the band across a body's inboard joint where weights blend: 60 % of a
    limb's radius (hip ~4.7 cm, knee ~3.3 cm, elbow ~2.2 cm), fixed for the others."""
    shape = body["shapes"][0]
    if shape["type"] == "capsule" and not body["name"].startswith("CHEST"):
        return float(np.clip(0.6 * shape["radius"], 0.02, 0.05))
    kind = body["name"].rstrip("RL") if body["name"] not in ("CHEST1", "CHEST2", "CHEST3") else "SPINE"
    return {"SPINE": 0.03, "STERNUM": 0.03, "HEAD": 0.03, "CHEST": 0.03,
            "HAND": 0.02, "FOOT": 0.02, "TOE": 0.015}.get(kind, 0.03)


def _smoothstep(x: np.ndarray) -> np.ndarray:
    t = np.clip(x, 0.0, 1.0)
    return t * t * (3.0 - 2.0 * t)


def joint_weights(bodies: list[dict], vertices: np.ndarray, reach: float = 0.22,
                  max_influences: int = MAX_INFLUENCES) -> tuple[np.ndarray, np.ndarray]:
    """(indices (V, k) uint16, weights (V, k) float32 summing to 1) for each vertex.

    A vertex first belongs to the body whose shape surface is nearest. Across the plane of each
    joint of that body (through the joint, normal to the child's bone) the weight passes from
    parent to child along a smoothstep over +/- the child's blend width; the blend fades out
    beyond ``reach`` from the joint so that a joint plane does not cut through a whole torso
    slice. Parent and child compute the same shares at the same point, so the weights are
    continuous where the nearest body changes at a joint.
    """
    nb, nv = len(bodies), len(vertices)
    index = {b["name"]: i for i, b in enumerate(bodies)}
    children: dict[int, list[int]] = {}
    for i, b in enumerate(bodies):
        if b.get("parent"):
            children.setdefault(index[b["parent"]], []).append(i)
    primary = np.argmin(segment_distances(bodies, vertices), axis=0)

    # per joint (indexed by its child body): the child's side of the plane (0..1) and the fade
    side = np.ones((nb, nv))
    fade = np.zeros((nb, nv))
    for c, body in enumerate(bodies):
        if not body.get("parent"):
            continue
        joint = np.array(body["joint"]["pos"])
        width = joint_blend_width(body)
        along = (vertices - joint) @ _body_axis(bodies, c, children)
        side[c] = _smoothstep((along + width) / (2.0 * width))
        dist = np.linalg.norm(vertices - joint, axis=1)
        fade[c] = 1.0 - _smoothstep((dist - (reach - 0.05)) / 0.05)

    raw = np.zeros((nv, nb))
    rows = np.arange(nv)
    own = np.ones(nv)
    parent_of = np.array([index[b["parent"]] if b.get("parent") else -1 for b in bodies])
    par = parent_of[primary]
    has_parent = par >= 0
    to_parent = np.where(has_parent, fade[primary, rows] * (1.0 - side[primary, rows]), 0.0)
    raw[rows[has_parent], par[has_parent]] += to_parent[has_parent]
    own *= 1.0 - to_parent
    for p in range(nb):
        sel = primary == p
        for c in children.get(p, []):
            to_child = fade[c, sel] * side[c, sel]
            raw[sel, c] += to_child
            own[sel] *= 1.0 - to_child
    raw[rows, primary] += own
    return _top_influences(raw, max_influences)


def _top_influences(raw: np.ndarray, k: int) -> tuple[np.ndarray, np.ndarray]:
    order = np.argsort(-raw, axis=1)[:, :k]
    weights = np.take_along_axis(raw, order, axis=1)
    weights[weights < 1e-4] = 0.0
    weights /= weights.sum(axis=1, keepdims=True)
    order[weights == 0.0] = 0
    return order.astype(np.uint16), weights.astype(np.float32)
