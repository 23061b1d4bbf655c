"""The skills, one room each (sim_core/skills/<name>/: behaviour.py, and calibrate.py and report.py
where the skill has them), found by a scan of this folder like Rigify's rig types: a new skill is
a new folder, no list to edit. Each room's behaviour module registers its Behaviour class with
sim_core.control.behaviour.register."""
from __future__ import annotations

import importlib
import pkgutil

from ..control.behaviour import REGISTRY, Behaviour
from ..errors import UnknownNameError


def _load_rooms() -> None:
    for info in pkgutil.iter_modules(__path__):
        if info.ispkg:
            importlib.import_module(f"{__name__}.{info.name}.behaviour")


def behaviour_class(name: str) -> type[Behaviour]:
    _load_rooms()
    try:
        return REGISTRY[name]
    except KeyError:
        raise UnknownNameError(f"unknown behaviour {name!r}; available: {', '.join(sorted(REGISTRY))}") from None


def available_behaviours() -> list[str]:
    _load_rooms()
    return sorted(REGISTRY)


def skill_module(skill: str, part: str):
    """A skill room's ``calibrate`` or ``report`` module (for python -m sim_core calibrate/report)."""
    behaviour_class(skill)
    rooms = sorted(n for n in available_behaviours()
                   if importlib.util.find_spec(f"{__name__}.{n}.{part}") is not None)
    if skill not in rooms:
        raise UnknownNameError(f"the skill {skill!r} has no {part}; skills with one: {', '.join(rooms)}")
    return importlib.import_module(f"{__name__}.{skill}.{part}")
