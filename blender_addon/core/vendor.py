"""The legacy add-on's vendored wheels (Blender 3.4-4.1 cannot install wheels): build.py unpacks
them into ``<add-on>/vendor``. The folder is *appended* to sys.path, after Blender's own
packages, so it only supplies what Blender lacks (mujoco and scipy; numpy where the Blender has
none, as Debian's 3.4 build): a numpy that Blender brings always wins. An extension (4.2+) has
no vendor folder - Blender installs its wheels itself."""
from __future__ import annotations

import sys
from pathlib import Path


def add_vendored(folder: Path) -> bool:
    """Append ``folder`` to sys.path if it exists and is not there yet; True if it was added."""
    text = str(folder)
    if not folder.is_dir() or text in sys.path:
        return False
    sys.path.append(text)
    return True
