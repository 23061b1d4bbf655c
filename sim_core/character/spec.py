"""The character spec: the one description of a character every room reads.

A spec is JSON (``rigs/<name>.json``) made by ``build.py`` from the SD/FAST transcription plus
:mod:`sim_core.character.anthropometry`. Frame: X forward, Y left, Z up, metres, feet on z = 0,
all positions in world coordinates of the reference configuration (the thesis's T-pose, every
joint angle zero). Angles in radians.
"""
from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from . import anthropometry as anthro
from .sdfast import SdBody, parse_sdfast
from ..errors import RigFileError, UnknownNameError
from ..resources import rigs_dir

RIGS_DIR = rigs_dir()
SPEC_VERSION = 1
STRENGTH_CHOICES = ("human", "unlimited")
# A body made by scaling carries Fig. 6's time scale (physics step and control period x L^1/2,
# sim_core.adapt.servos.scaled_time_scale); the thesis man and woman have none, i.e. 1.
TIME_SCALE_RANGE = (0.5, 2.0)      # L^1/2 for L = 0.25-4: far beyond the 0.8-2.2 m bodies `make` takes


@dataclass(frozen=True)
class Dof:
    name: str
    body: str
    axis: tuple[float, float, float]
    range: tuple[float, float]
    kp: float
    kv: float
    torque_limit: float


def build_spec_from_sdfast(name: str, sd_path: Path, source: str) -> dict:
    """Assemble a full spec dict for a thesis character (used by build.py)."""
    bodies = parse_sdfast(sd_path)
    by_name = {b.name: b for b in bodies}
    joints = {b.name: b.original_com + b.body_to_joint for b in bodies if b.parent}
    children: dict[str, list[str]] = {}
    for b in bodies:
        if b.parent:
            children.setdefault(b.parent, []).append(b.name)
    man_mass = 97.84
    total = sum(b.mass for b in bodies)
    is_man = name == "man"
    strength_ratio = 1.0 if is_man else anthro.WOMAN_STRENGTH_RATIO
    mass_ratio = total / man_mass
    scale = (joints["HEAD"][2] - 0.0) / 1.555          # neck height relative to the man's
    shapes = {b.name: anthro.segment_shapes(b, joints, children, scale) for b in bodies}
    contacts: dict[str, list[dict]] = {}
    for side in "RL":
        foot, toe = by_name["FOOT" + side], by_name["TOE" + side]
        contacts.update(anthro.foot_contacts(foot, toe, joints[foot.name], joints[toe.name], scale))
        for body, extra in anthro.foot_shapes(foot, toe, joints[foot.name], joints[toe.name], scale).items():
            shapes[body] = shapes[body] + extra
    out_bodies = []
    for b in bodies:
        entry = {
            "name": b.name, "parent": b.parent, "mass": b.mass,
            "com": b.original_com.tolist(), "inertia": b.inertia.tolist(),
            "density": anthro.DENSITY[anthro.segment_kind(b.name)],
            "shapes": shapes[b.name], "contacts": contacts.get(b.name, []),
        }
        if b.parent:
            jname = anthro.JOINT_NAMES[b.joint_name]
            dofs = []
            for pin in b.pins:
                axis = "xyz"[int(np.argmax(np.abs(pin)))]
                lo, hi = anthro.dof_range(jname, axis)
                kp, kv = anthro.dof_gains(jname, mass_ratio)
                dofs.append({"name": f"{jname}_{axis}", "axis": pin.tolist(), "range": [lo, hi],
                             "kp": kp, "kv": kv,
                             "torque_limit": anthro.dof_torque_limit(jname, axis, strength_ratio)})
            entry["joint"] = {"name": jname, "sdfast_name": b.joint_name, "type": b.joint_type,
                              "pos": joints[b.name].tolist(), "dofs": dofs}
        out_bodies.append(entry)
    return {
        "format": "sim_athletics.character", "version": SPEC_VERSION, "name": name,
        "source": source, "total_mass": total, "height": float(max(
            s["pos"][2] + s["radius"] for s in shapes["HEAD"])),
        "frame": "X forward, Y left, Z up; metres, kg, radians; reference configuration = T-pose",
        "strength": {"ratio_to_man": strength_ratio,
                     "note": "torque limits are human-plausible peaks; see anthropometry.py"},
        "bodies": out_bodies,
        "standing_pose": dict(anthro.STANDING_POSE),
    }


class CharacterSpec:
    """A validated character spec with convenient views (DOFs in model order, etc.)."""

    def __init__(self, data: dict, path: str = "<memory>"):
        self.data = data
        self.path = path
        _validate(data, path)
        self.name: str = data["name"]
        self.bodies: list[dict] = data["bodies"]
        self.body_names = [b["name"] for b in self.bodies]
        self.dofs: list[Dof] = [
            Dof(d["name"], b["name"], tuple(d["axis"]), tuple(d["range"]), d["kp"], d["kv"], d["torque_limit"])
            for b in self.bodies if b.get("joint") for d in b["joint"]["dofs"]]
        self.dof_index = {d.name: i for i, d in enumerate(self.dofs)}
        self.standing_pose = np.array([data["standing_pose"].get(d.name, 0.0) for d in self.dofs])

    @property
    def time_scale(self) -> float:
        """Fig. 6's time factor against the man's (his 1 ms physics step and each behaviour's
        control period are multiplied by it); 1 for a spec without ``time_scale``."""
        return float(self.data.get("time_scale", 1.0))

    @property
    def total_mass(self) -> float:
        return float(sum(b["mass"] for b in self.bodies))

    def body(self, name: str) -> dict:
        return self.bodies[self.body_names.index(name)]

    def joint_position(self, body: str) -> np.ndarray:
        return np.array(self.body(body)["joint"]["pos"])


def available_characters() -> list[str]:
    return sorted(p.stem for p in RIGS_DIR.glob("*.json"))


def load_character(name_or_path: str) -> CharacterSpec:
    """Load by name (``man``) from rigs/, or from a path to a spec JSON file."""
    path = Path(name_or_path)
    if path.suffix != ".json":
        path = RIGS_DIR / f"{name_or_path}.json"
        if not path.exists():
            raise UnknownNameError(
                f"unknown character {name_or_path!r}; available: {', '.join(available_characters())}")
    try:
        data = json.loads(path.read_text())
    except FileNotFoundError:
        raise UnknownNameError(f"character file {str(path)!r} does not exist") from None
    except json.JSONDecodeError as exc:
        raise RigFileError(f"{path}: not valid JSON ({exc.msg} at line {exc.lineno})") from None
    return CharacterSpec(data, str(path))


def character_name(name_or_path: str) -> str:
    """The name a character's tables are stored under: a preset's own, or a spec file's ``name``."""
    return load_character(name_or_path).name if Path(name_or_path).suffix == ".json" else name_or_path


def _validate(data: dict, path: str) -> None:
    def fail(msg):
        raise RigFileError(f"{path}: {msg}")

    if not isinstance(data, dict) or data.get("format") != "sim_athletics.character":
        fail("not a Sim Athletics character spec (missing format 'sim_athletics.character')")
    if data.get("version") != SPEC_VERSION:
        fail(f"spec version {data.get('version')!r} not supported (expected {SPEC_VERSION})")
    time_scale = data.get("time_scale", 1.0)
    low, high = TIME_SCALE_RANGE
    if not (isinstance(time_scale, (int, float)) and not isinstance(time_scale, bool) and math.isfinite(time_scale)
            and low <= time_scale <= high):
        fail(f"time_scale {time_scale!r} is out of range; allowed range is [{low:g}, {high:g}]")
    bodies = data.get("bodies")
    if not isinstance(bodies, list) or not bodies:
        fail("'bodies' must be a non-empty list")
    seen = set()
    for i, b in enumerate(bodies):
        where = f"bodies[{i}]"
        for key in ("name", "mass", "com", "inertia"):
            if key not in b:
                fail(f"{where} has no {key!r}")
        where = f"body {b['name']!r}"
        if not (isinstance(b["mass"], (int, float)) and math.isfinite(b["mass"]) and b["mass"] > 0):
            fail(f"{where}: mass {b['mass']!r} must be a finite number > 0")
        inertia = np.asarray(b["inertia"], dtype=float)
        if inertia.shape != (3, 3) or not np.all(np.isfinite(inertia)) or np.any(np.linalg.eigvalsh(inertia) <= 0):
            fail(f"{where}: inertia must be a symmetric positive-definite 3x3 matrix")
        if len(b["com"]) != 3 or not all(math.isfinite(v) for v in b["com"]):
            fail(f"{where}: com must be 3 finite numbers")
        if i == 0:
            if b.get("parent") is not None:
                fail(f"{where}: the first body is the root and has no parent")
        else:
            if b.get("parent") not in seen:
                fail(f"{where}: parent {b.get('parent')!r} must be a body listed before it")
            joint = b.get("joint")
            if not joint or not joint.get("dofs"):
                fail(f"{where}: a non-root body needs a joint with dofs")
            for d in joint["dofs"]:
                lo, hi = d["range"]
                if not lo < hi:
                    fail(f"{where}: dof {d['name']} range [{lo}, {hi}] must have lower < upper")
                for key in ("kp", "kv", "torque_limit"):
                    if not (isinstance(d.get(key), (int, float)) and d[key] >= 0):
                        fail(f"{where}: dof {d['name']} {key} {d.get(key)!r} must be a number >= 0")
        seen.add(b["name"])
