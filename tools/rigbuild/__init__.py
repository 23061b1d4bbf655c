"""Build-time only (build.py): the rigged skin of a character, written as glTF binary.
Needs scikit-image, trimesh and pygltflib (pip install -e ".[rigs]"); not shipped in the add-on."""
from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from blender_addon.core.axes import sim_to_blender_points
from blender_addon.core.rig_frames import rest_frames, spec_digest
from . import skin
from .gltf import write_rig_glb

GRID_SPACING = 0.012        # m: marching-cubes cell; ~21k vertices for the man, ~15k for the woman
MASS_TOLERANCE = 0.15       # issue 3: skin volume x density within 15 % of each segment's mass
MESH_VOLUME_TOLERANCE = 0.02   # the kept surface holds the level set's volume (else a piece was dropped)


@dataclass
class RigReport:
    name: str
    vertices: int
    faces: int
    watertight: bool
    mesh_volume: float                  # m^3, of the final (smoothed) mesh
    field_volume: float                 # m^3, of the level set it was meshed from
    segment_mass: dict[str, tuple[float, float]]   # body -> (skin volume x density, spec mass)
    offsets_mm: dict[str, float]
    rigid_vertices: float               # fraction of vertices weighted to a single bone

    def worst_mass_error(self) -> tuple[str, float]:
        name = max(self.segment_mass, key=lambda n: abs(self.segment_mass[n][0] / self.segment_mass[n][1] - 1))
        skin_mass, mass = self.segment_mass[name]
        return name, skin_mass / mass - 1.0

    def table(self) -> str:
        lines = [f"{'body':8s} {'skin kg':>8s} {'spec kg':>8s} {'error':>7s} {'offset':>7s}"]
        for body, (skin_mass, mass) in self.segment_mass.items():
            lines.append(f"{body:8s} {skin_mass:8.3f} {mass:8.3f} {100 * (skin_mass / mass - 1):+6.1f}% "
                         f"{self.offsets_mm[body]:+5.1f}mm")
        return "\n".join(lines)


def check_rig(report: RigReport) -> str | None:
    """None if the skin passes build.py's check (every segment's skin volume x density within
    MASS_TOLERANCE of its mass, one watertight surface holding the level set's volume), else the
    one-line reason: a skin that drops part of the body is not written as a character's rig."""
    worst, error = report.worst_mass_error()
    if abs(error) > MASS_TOLERANCE:
        return f"segment {worst}: skin mass {100 * error:+.1f} % off (allowed +-{100 * MASS_TOLERANCE:g} %)"
    if not report.watertight:
        return "the skin is not watertight"
    if abs(report.mesh_volume / report.field_volume - 1.0) > MESH_VOLUME_TOLERANCE:
        return (f"the skin's one surface holds {100 * report.mesh_volume / report.field_volume:.0f} % of the level "
                f"set's volume (allowed {100 * (1 - MESH_VOLUME_TOLERANCE):g}-{100 * (1 + MESH_VOLUME_TOLERANCE):g} %): "
                "the level set falls apart into pieces")
    return None


def write_checked_rig(spec, out_path: Path) -> tuple[RigReport, str | None]:
    """Build ``spec``'s rig and write ``out_path`` only if it passes check_rig (through a
    temporary file, so a failed or half-written skin never replaces a good one); returns the
    report and the failure (None when written)."""
    out_path = Path(out_path)
    tmp = out_path.with_name(out_path.stem + ".tmp.glb")
    report = build_rig(spec, tmp)
    failure = check_rig(report)
    if failure:
        tmp.unlink()
    else:
        os.replace(tmp, out_path)
    return report, failure


def build_rig(spec, out_path: Path, spacing: float = GRID_SPACING) -> RigReport:
    """Skin the character ``spec`` (a CharacterSpec) and write ``out_path`` (.glb)."""
    bodies = spec.bodies
    grid = skin.bounding_grid(bodies, spacing)
    points = grid.points().astype(np.float32)
    raw = skin.segment_distances(bodies, points)
    edges = skin.tree_edges(bodies)
    targets = np.array([b["mass"] / b["density"] for b in bodies])
    offsets_of = skin.Offsets(bodies, points)
    bridge = None
    while True:          # a second pass, with the trunk bridged, only if the first skin falls apart
        offsets, _ = skin.calibrate_offsets(raw, edges, targets, spacing, offsets_of, bridge=bridge)
        distances = offsets_of.apply(raw, offsets)
        field = skin.skin_field(distances, edges)
        if bridge is not None:
            field = bridge(field, offsets)
        field_volume = float(skin.occupancy(field, spacing).sum() * spacing ** 3)
        mesh = skin.mesh_from_field(field, grid)
        if bridge is not None or abs(mesh.volume / field_volume - 1.0) <= MESH_VOLUME_TOLERANCE:
            break
        bridge = skin.SeamBridge(bodies, points, offsets_of)
    del points, raw
    volumes = skin.segment_volumes(distances, field, spacing)      # measured on the final field
    del distances
    vertices_sim = np.asarray(mesh.vertices)
    joints, weights = skin.joint_weights(bodies, vertices_sim)
    frames = rest_frames(bodies)
    write_rig_glb(out_path, spec.name, frames.names, frames.parents, frames.heads,
                  sim_to_blender_points(vertices_sim), sim_to_blender_points(np.asarray(mesh.vertex_normals)),
                  np.asarray(mesh.faces), joints, weights,
                  extras={"sim_athletics_character": spec.name, "spec_digest": spec_digest(bodies),
                          "root_bone_head": "pelvis centre of mass"})
    return RigReport(
        name=spec.name, vertices=len(mesh.vertices), faces=len(mesh.faces),
        watertight=bool(mesh.is_watertight), mesh_volume=float(mesh.volume), field_volume=field_volume,
        segment_mass={b["name"]: (float(v * b["density"]), float(b["mass"])) for b, v in zip(bodies, volumes)},
        offsets_mm={b["name"]: float(o * 1000) for b, o in zip(bodies, offsets)},
        rigid_vertices=float(np.mean(weights.max(axis=1) > 0.999)),
    )
