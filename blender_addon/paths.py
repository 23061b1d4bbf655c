"""Make ``sim_core`` and the bundled third-party packages importable (no bpy here).

Layouts this handles:
  * repository checkout: ``<repo>/blender_addon`` next to ``<repo>/sim_core`` and ``<repo>/rigs``;
  * installed add-on or extension: ``<addon>/lib/sim_core`` and ``<addon>/lib/rigs`` (sim_core
    finds its rigs two folders up from its ``character`` package), plus, for the legacy 3.4
    add-on, ``<addon>/vendor`` with the unpacked wheels (numpy, scipy, mujoco and the rest);
    Blender 4.2+ installs an extension's wheels itself.
"""
from __future__ import annotations

import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent


def search_paths() -> list[Path]:
    found = [p for p in (HERE / "vendor", HERE / "lib") if p.is_dir()]
    if (HERE.parent / "sim_core").is_dir() and (HERE.parent / "rigs").is_dir():
        found.append(HERE.parent)
    return found


def ensure() -> None:
    """Put our folders first on sys.path (the bundled numpy must win over an older system one)."""
    for path in reversed(search_paths()):
        text = str(path)
        if text not in sys.path:
            sys.path.insert(0, text)
