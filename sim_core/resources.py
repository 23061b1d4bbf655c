"""Where sim_core's data files are, found through importlib.resources rather than by counting
folders up from a module: the character rigs (``<name>.json`` specs, ``<name>.glb`` skins) and
their tuned tables (``tuned/``).

A shipped sim_core (inside the Blender add-on, or any copy build.py makes) carries them in its
own ``rigs/`` folder; a repository checkout keeps them in ``rigs/`` beside the package, where
``python build.py rigs`` and the tuning scripts write them.
"""
from __future__ import annotations

from importlib import resources
from pathlib import Path

PACKAGE = __name__.rpartition(".")[0]          # "sim_core", or "<add-on>.sim_core" when shipped


def rigs_dir() -> Path:
    """The folder of the character rigs (and of their ``tuned/`` tables)."""
    package = Path(str(resources.files(PACKAGE)))
    bundled = package / "rigs"
    return bundled if bundled.is_dir() else package.parent / "rigs"
