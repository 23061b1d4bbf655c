"""Write a rigged character as glTF binary (.glb) with pygltflib: a joint hierarchy (one node per
body, at its bone head, no rotation, so the bind pose is the rest pose), one skinned mesh with
JOINTS_0/WEIGHTS_0, and a plain skin-coloured material.

Coordinates: the armature space of :mod:`blender_addon.core.axes`, mapped to glTF's own axes with
``BLENDER_TO_GLTF`` so that Blender's importer puts every vertex and bone back where the
armature space says.
"""
from __future__ import annotations

import os
from pathlib import Path

import numpy as np

from blender_addon.core.axes import BLENDER_TO_GLTF

SKIN_COLOUR = [0.80, 0.62, 0.52, 1.0]


def _pad4(data: bytes) -> bytes:
    return data + b"\x00" * (-len(data) % 4)


def write_rig_glb(path: Path, name: str, bone_names: list[str], parents: list[int], heads: np.ndarray,
                  vertices: np.ndarray, normals: np.ndarray, faces: np.ndarray,
                  joints: np.ndarray, weights: np.ndarray, extras: dict | None = None) -> Path:
    """``heads``, ``vertices``, ``normals`` in armature space; ``joints``/``weights`` (V, 4).
    Written to a temporary file and renamed, so a failed build leaves no partial rig."""
    import pygltflib as g

    to_gltf = lambda a: (np.asarray(a, dtype=float) @ BLENDER_TO_GLTF.T).astype(np.float32)
    heads_g = to_gltf(heads)
    pos_g, nrm_g = to_gltf(vertices), to_gltf(normals)
    nrm_g /= np.maximum(np.linalg.norm(nrm_g, axis=1, keepdims=True), 1e-12)
    faces = np.asarray(faces, dtype=np.uint32)
    joints = np.asarray(joints, dtype=np.uint16)
    weights = np.asarray(weights, dtype=np.float32)

    blobs: list[bytes] = []
    views: list[g.BufferView] = []
    accessors: list[g.Accessor] = []
    offset = 0

    def add(array: np.ndarray, component: int, kind: str, target=None, minmax=False) -> int:
        nonlocal offset
        data = np.ascontiguousarray(array).tobytes()
        views.append(g.BufferView(buffer=0, byteOffset=offset, byteLength=len(data), target=target))
        blobs.append(_pad4(data))
        offset += len(blobs[-1])
        acc = g.Accessor(bufferView=len(views) - 1, componentType=component,
                         count=int(array.shape[0]), type=kind)
        if minmax:
            acc.min = array.min(axis=0).tolist()
            acc.max = array.max(axis=0).tolist()
        accessors.append(acc)
        return len(accessors) - 1

    a_pos = add(pos_g, g.FLOAT, g.VEC3, g.ARRAY_BUFFER, minmax=True)
    a_nrm = add(nrm_g, g.FLOAT, g.VEC3, g.ARRAY_BUFFER)
    a_jnt = add(joints, g.UNSIGNED_SHORT, g.VEC4, g.ARRAY_BUFFER)
    a_wgt = add(weights, g.FLOAT, g.VEC4, g.ARRAY_BUFFER)
    a_idx = add(faces.reshape(-1), g.UNSIGNED_INT, g.SCALAR, g.ELEMENT_ARRAY_BUFFER)
    # inverse bind matrices: the joints are unrotated, so each is a translation by -head
    # (glTF matrices are column-major: the translation is elements 12..14)
    ibm = np.tile(np.eye(4, dtype=np.float32), (len(bone_names), 1, 1))
    ibm[:, 3, :3] = -heads_g
    a_ibm = add(ibm.reshape(len(bone_names), 16), g.FLOAT, g.MAT4)

    nodes = []
    for i, bone in enumerate(bone_names):
        p = parents[i]
        local = heads_g[i] - (heads_g[p] if p >= 0 else 0.0)
        kids = [k for k, q in enumerate(parents) if q == i]
        nodes.append(g.Node(name=bone, translation=[float(v) for v in local], children=kids or None))
    mesh_node = len(nodes)
    nodes.append(g.Node(name=f"{name}_skin", mesh=0, skin=0))
    roots = [i for i, p in enumerate(parents) if p < 0]

    gltf = g.GLTF2(
        asset=g.Asset(version="2.0", generator="Sim Athletics build.py",
                      extras=extras or {}),
        scene=0,
        scenes=[g.Scene(name=name, nodes=roots + [mesh_node])],
        nodes=nodes,
        meshes=[g.Mesh(name=f"{name}_skin", primitives=[g.Primitive(
            attributes=g.Attributes(POSITION=a_pos, NORMAL=a_nrm, JOINTS_0=a_jnt, WEIGHTS_0=a_wgt),
            indices=a_idx, material=0)])],
        materials=[g.Material(name=f"{name}_skin", pbrMetallicRoughness=g.PbrMetallicRoughness(
            baseColorFactor=SKIN_COLOUR, metallicFactor=0.0, roughnessFactor=0.6))],
        skins=[g.Skin(name=name, joints=list(range(len(bone_names))), skeleton=roots[0],
                      inverseBindMatrices=a_ibm)],
        accessors=accessors,
        bufferViews=views,
        buffers=[g.Buffer(byteLength=offset)],
    )
    gltf.set_binary_blob(b"".join(blobs))
    path = Path(path)
    tmp = path.with_suffix(".glb.tmp")
    gltf.save_binary(str(tmp))
    os.replace(tmp, path)
    return path


def read_rig_glb(path: Path) -> dict:
    """Read back what ``write_rig_glb`` wrote (armature space), for checks and tests."""
    import pygltflib as g

    gltf = g.GLTF2().load_binary(str(path))
    blob = gltf.binary_blob()
    from_gltf = BLENDER_TO_GLTF           # orthonormal: armature = gltf @ BLENDER_TO_GLTF

    def read(index: int, dtype, width: int) -> np.ndarray:
        acc = gltf.accessors[index]
        view = gltf.bufferViews[acc.bufferView]
        data = np.frombuffer(blob, dtype=dtype, count=acc.count * width,
                             offset=view.byteOffset + (acc.byteOffset or 0))
        return data.reshape(acc.count, width) if width > 1 else data

    prim = gltf.meshes[0].primitives[0]
    names = [n.name for n in gltf.nodes[: len(gltf.skins[0].joints)]]
    parents = [-1] * len(names)
    for i, node in enumerate(gltf.nodes[: len(names)]):
        for k in node.children or []:
            parents[k] = i
    heads = np.zeros((len(names), 3))
    for i, node in enumerate(gltf.nodes[: len(names)]):
        heads[i] = np.array(node.translation) + (heads[parents[i]] if parents[i] >= 0 else 0.0)
    return {
        "names": names, "parents": parents,
        "heads": heads @ from_gltf,
        "vertices": read(prim.attributes.POSITION, np.float32, 3).astype(float) @ from_gltf,
        "faces": read(prim.indices, np.uint32, 1).reshape(-1, 3),
        "joints": read(prim.attributes.JOINTS_0, np.uint16, 4),
        "weights": read(prim.attributes.WEIGHTS_0, np.float32, 4),
        "extras": gltf.asset.extras or {},
    }

