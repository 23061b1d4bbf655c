"""Parse an SD/FAST system description file (Wooten 1998, Appendix A).

Why a parser and not hand-copied numbers: the rig data must stay traceable to the thesis.
The cleaned transcription lives in ``rigs/sdfast/*.sd``; everything else about a character
(ranges, strength, shapes) is added on top by :mod:`sim_core.character.anthropometry`.

SD/FAST conventions used here: every body frame sits at the body's centre of mass with axes
parallel to the world in the reference configuration; ``bodyToJoint`` is the vector from the
body's COM to its inboard joint, ``inbToJoint`` the vector from the parent's COM to the same
joint; ``pin`` lines give the joint axes in order (a gimbal's first axis is fixed in the
parent). A ball joint has no pins; we give it X, Y, Z.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..errors import RigFileError

JOINT_DOF_COUNT = {"gimbal": 3, "ujoint": 2, "pin": 1, "ball": 3}


@dataclass
class SdBody:
    name: str
    parent: str | None
    joint_name: str | None
    joint_type: str | None
    mass: float
    inertia: np.ndarray                 # 3x3 about the COM, world-aligned axes
    original_com: np.ndarray            # world position in the reference configuration
    body_to_joint: np.ndarray = field(default_factory=lambda: np.zeros(3))
    inb_to_joint: np.ndarray = field(default_factory=lambda: np.zeros(3))
    pins: list[np.ndarray] = field(default_factory=list)


_NUM = r"[-+]?\d*\.?\d+(?:[eE][-+]?\d+)?"


def _floats(text: str, where: str, count: int | None = None) -> np.ndarray:
    values = [float(v) for v in re.findall(_NUM, text)]
    if count is not None and len(values) != count:
        raise RigFileError(f"{where}: expected {count} numbers, found {len(values)} in {text!r}")
    return np.array(values, dtype=float)


def parse_sdfast(path: str | Path) -> list[SdBody]:
    """Return the bodies of an SD/FAST file in file order (parents before children)."""
    path = Path(path)
    bodies: list[SdBody] = []
    pending_com = None
    pending_joint = None
    inertia_rows: list[np.ndarray] = []
    for lineno, raw in enumerate(path.read_text().splitlines(), 1):
        line = raw.strip()
        where = f"{path.name}:{lineno}"
        if not line:
            continue
        if line.startswith("#"):
            m = re.match(r"#\s*original center of mass\s*=\s*(.*)", line)
            if m:
                pending_com = _floats(m.group(1), where, 3)
            m = re.match(r"#\s*with joint\s+(\w+)", line)
            if m:
                pending_joint = m.group(1)
            continue
        key, _, value = (part.strip() for part in line.partition("="))
        if key == "body":
            m = re.match(r"(\w+)(?:\s+inboard\s*=\s*(\w+)\s+joint\s*=\s*(\w+))?", value)
            if not m:
                raise RigFileError(f"{where}: cannot read body line {line!r}")
            name, parent, jtype = m.groups()
            if jtype is not None and jtype not in JOINT_DOF_COUNT:
                raise RigFileError(f"{where}: joint type {jtype!r} not one of {sorted(JOINT_DOF_COUNT)}")
            if pending_com is None:
                raise RigFileError(f"{where}: body {name} has no 'original center of mass' comment")
            bodies.append(SdBody(name=name, parent=parent, joint_name=pending_joint if parent else None,
                                 joint_type=jtype, mass=float("nan"), inertia=np.zeros((3, 3)),
                                 original_com=pending_com))
            pending_com, pending_joint, inertia_rows = None, None, []
            continue
        if not bodies:
            if key in ("gravity", "constraints"):
                continue
            raise RigFileError(f"{where}: {key!r} before the first body")
        body = bodies[-1]
        if key == "mass":
            body.mass = float(_floats(value, where, 1)[0])
        elif key == "inertia":
            inertia_rows.append(_floats(value, where, 3))
            if len(inertia_rows) == 1:
                body.inertia = np.diag(inertia_rows[0])
            elif len(inertia_rows) == 3:
                body.inertia = np.vstack(inertia_rows)
        elif key == "bodyToJoint":
            body.body_to_joint = _floats(value, where, 3)
        elif key == "inbToJoint":
            body.inb_to_joint = _floats(value, where, 3)
        elif key == "pin":
            body.pins.append(_floats(value, where, 3))
        elif key in ("gravity", "constraints"):
            continue
        else:
            raise RigFileError(f"{where}: unknown key {key!r}")
    _check(bodies, path.name)
    return bodies


def _check(bodies: list[SdBody], source: str) -> None:
    names = {b.name for b in bodies}
    for b in bodies:
        if not np.isfinite(b.mass) or b.mass <= 0:
            raise RigFileError(f"{source}: body {b.name} has mass {b.mass}; must be > 0")
        if not np.allclose(b.inertia, b.inertia.T):
            raise RigFileError(f"{source}: body {b.name} inertia is not symmetric")
        if b.parent is None:
            continue
        if b.parent not in names:
            raise RigFileError(f"{source}: body {b.name} has unknown parent {b.parent}")
        if b.joint_type == "ball":
            if b.pins:
                raise RigFileError(f"{source}: ball joint of {b.name} must have no pins")
            b.pins = [np.eye(3)[i] for i in range(3)]
        if len(b.pins) != JOINT_DOF_COUNT[b.joint_type]:
            raise RigFileError(f"{source}: joint of {b.name} ({b.joint_type}) has {len(b.pins)} pins, "
                               f"expected {JOINT_DOF_COUNT[b.joint_type]}")
