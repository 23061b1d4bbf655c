"""Which sim_core the add-on runs, found without touching sys.path:

* installed (a legacy add-on or an extension): the copy build.py ships inside the add-on's own
  package, ``<add-on>/sim_core`` - imported as a subpackage (``sim_athletics.sim_core``,
  ``bl_ext.user_default.sim_athletics.sim_core``), so it cannot clash with another add-on's or
  the user's own ``sim_core``;
* a repository checkout (tests, ``python blender_addon/batch.py``): the repository's top-level
  ``sim_core``, which is importable there already.

    from .core.simcore import sim
    run = sim("simulate").run
"""
from __future__ import annotations

import importlib
import importlib.util

ADDON_PACKAGE = __name__.rsplit(".", 2)[0]         # the add-on's package (this is <add-on>.core.simcore)


def _root() -> str:
    bundled = f"{ADDON_PACKAGE}.sim_core"
    return bundled if importlib.util.find_spec(bundled) is not None else "sim_core"


SIM_CORE = _root()


def sim(module: str):
    """``sim("simulate")`` -> the module ``simulate`` of the sim_core in use."""
    return importlib.import_module(f"{SIM_CORE}.{module}")
