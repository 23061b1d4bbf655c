"""The generated rigs (rigs/<name>.glb): one bone per body at its joint, one watertight skin whose
volume per segment x density matches the segment's mass, weights that blend across joints."""
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("pygltflib")

from blender_addon.core.rig_frames import rest_frames, spec_digest  # noqa: E402
from tools.rigbuild.gltf import read_rig_glb          # noqa: E402
from sim_core.character.spec import RIGS_DIR, load_character  # noqa: E402

CHARACTERS = ["man", "woman"]


@pytest.fixture(scope="module", params=CHARACTERS)
def rig(request):
    return request.param, read_rig_glb(RIGS_DIR / f"{request.param}.glb"), load_character(request.param)


def test_rig_is_built_from_the_current_spec(rig):
    name, glb, spec = rig
    assert glb["extras"]["spec_digest"] == spec_digest(spec.bodies), \
        f"rigs/{name}.glb is stale: the spec changed since it was built; run 'python build.py rigs'"


def test_one_bone_per_body_with_its_head_on_the_joint(rig):
    name, glb, spec = rig
    assert glb["names"] == spec.body_names
    frames = rest_frames(spec.bodies)
    assert glb["parents"] == frames.parents
    assert np.max(np.abs(glb["heads"] - frames.heads)) < 1e-6


def test_skin_is_one_closed_manifold_of_sensible_size(rig):
    name, glb, spec = rig
    faces = glb["faces"]
    assert 3000 <= len(glb["vertices"]) <= 25000
    edges = np.sort(np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]]), axis=1)
    _, counts = np.unique(edges, axis=0, return_counts=True)
    assert np.all(counts == 2), "every edge is shared by exactly two triangles (watertight)"
    # one connected piece: Euler characteristic V - E + F = 2 (a sphere), not disjoint boxes
    assert len(glb["vertices"]) - len(counts) + len(faces) == 2
    # outward orientation and total volume: the skin holds the body's mass at segment densities
    v = glb["vertices"][faces]
    volume = np.sum(np.einsum("ij,ij->i", v[:, 0], np.cross(v[:, 1], v[:, 2]))) / 6.0
    spec_volume = sum(b["mass"] / b["density"] for b in spec.bodies)
    assert abs(volume / spec_volume - 1.0) < 0.02


def test_weights_are_normalised_and_blend_across_every_joint(rig):
    name, glb, spec = rig
    joints, weights = glb["joints"], glb["weights"]
    assert np.allclose(weights.sum(axis=1), 1.0, atol=1e-5)
    full = np.zeros((len(weights), len(spec.body_names)))
    np.add.at(full, (np.repeat(np.arange(len(weights)), 4), joints.reshape(-1)), weights.reshape(-1))
    index = {n: i for i, n in enumerate(spec.body_names)}
    for body in spec.bodies[1:]:
        child, parent = index[body["name"]], index[body["parent"]]
        both = (full[:, child] > 0.2) & (full[:, parent] > 0.2)
        assert both.sum() >= 5, f"no blending across the joint {body['parent']}-{body['name']}"
    # mid-segment vertices move with one bone only (so a shin vertex is rigid with the shin)
    assert np.sum(full[:, index["LLEGR"]] > 0.999) > 100


@pytest.mark.slow
@pytest.mark.parametrize("character", CHARACTERS)
def test_rebuilt_skin_mass_per_segment_within_15_percent(character, tmp_path: Path):
    pytest.importorskip("skimage")
    pytest.importorskip("trimesh")
    from tools.rigbuild import MASS_TOLERANCE, build_rig
    report = build_rig(load_character(character), tmp_path / f"{character}.glb")
    print(f"\n{character}: {report.vertices} vertices\n{report.table()}")
    worst, error = report.worst_mass_error()
    assert abs(error) < MASS_TOLERANCE, f"{worst}: skin mass {100 * error:+.1f} % off"
    assert report.watertight
    assert abs(report.mesh_volume / report.field_volume - 1.0) < 0.02
    # the committed rig is this build (same vertex count; same bones)
    committed = read_rig_glb(RIGS_DIR / f"{character}.glb")
    assert len(committed["vertices"]) == report.vertices
