"""Scene settings of the panel, with one property group per behaviour generated from its
parameter schema: no behaviour has UI code of its own (Rigify's rig types are the model).

    unit 'rad'  -> FloatProperty(subtype ANGLE): stored in radians, shown in degrees
    unit 'm'    -> FloatProperty(subtype DISTANCE, unit LENGTH)
    unit 's'    -> FloatProperty(unit TIME_ABSOLUTE) where Blender has it
    unit 'bool' -> BoolProperty
    unit 'count' -> IntProperty (a whole number)
    other units -> FloatProperty labelled with the unit
Hard limits come from the schema's range (widened to admit a documented special value, such as
``pelvis_height = 0``: standing); the schema still validates before anything runs.
"""
from __future__ import annotations

import bpy
from bpy.props import BoolProperty, EnumProperty, FloatProperty, IntProperty, PointerProperty

_generated: list[type] = []


def label(name: str) -> str:
    return name.replace("_", " ").capitalize()


def tooltip(p) -> str:
    text = f"{p.help[:1].upper()}{p.help[1:]}. Allowed: [{p.minimum:g}, {p.maximum:g}] {p.unit}"
    if p.special is not None:
        text += f" (or {p.special:g})"
    return text


def _has_unit(unit: str) -> bool:
    try:
        FloatProperty(unit=unit)
        return True
    except TypeError:
        return False


def parameter_property(p):
    """A bpy property for one schema Parameter."""
    if p.unit == "bool":
        return BoolProperty(name=label(p.name), description=tooltip(p), default=bool(p.default))
    lo, hi = p.minimum, p.maximum
    if p.special is not None:
        lo, hi = min(lo, p.special), max(hi, p.special)
    if p.unit == "count":
        return IntProperty(name=f"{label(p.name)} (count)", description=tooltip(p), default=int(p.default),
                           min=int(lo), max=int(hi))
    kw = dict(name=label(p.name), description=tooltip(p), default=float(p.default), min=lo, max=hi,
              precision=3)
    if p.unit == "rad":
        kw.update(subtype="ANGLE", unit="ROTATION", step=100)
    elif p.unit == "m":
        kw.update(subtype="DISTANCE", unit="LENGTH")
    elif p.unit == "s" and _has_unit("TIME_ABSOLUTE"):
        kw.update(unit="TIME_ABSOLUTE")
    else:
        kw["name"] = f"{label(p.name)} ({p.unit})"
    return FloatProperty(**kw)


TARGET_PARAMETERS = ("target_x", "target_y", "target_z")


def takes_target(behaviour: str) -> bool:
    """True when the behaviour's schema has a target point (a jump to a target)."""
    from sim_core.control.behaviour import behaviour_class
    names = {p.name for p in behaviour_class(behaviour).schema.parameters}
    return all(n in names for n in TARGET_PARAMETERS)


def group_attr(behaviour: str) -> str:
    return "params_" + "".join(c if c.isalnum() else "_" for c in behaviour)


def params_group(settings, behaviour: str):
    return getattr(settings, group_attr(behaviour))


def as_typed(value) -> float:
    """A panel value as the number the user typed: Blender stores floats in single precision
    (0.2 comes back as 0.20000000298...), so take the shortest decimal that the float32 rounds
    to. The same request then gives the same run as the CLI, bit for bit."""
    import numpy as np
    return float(str(np.float32(value)))


def panel_params(settings, behaviour: str) -> dict[str, float]:
    """The panel's parameter values for ``behaviour`` as the schema's dict (bool -> 0/1)."""
    from sim_core.control.behaviour import behaviour_class
    group = params_group(settings, behaviour)
    return {p.name: as_typed(getattr(group, p.name)) for p in behaviour_class(behaviour).schema.parameters}


STRENGTH_ITEMS = [("human", "Human", "Human-plausible joint torque limits (the rig's, with their sources)"),
                  ("unlimited", "Unlimited", "No joint torque limits, as Wooten's 1998 simulations ran")]
_ITEMS: dict[str, list] = {}          # enum items must stay referenced while Blender shows them


def _behaviour_items(self, context):
    from sim_core.control.behaviour import available_behaviours, behaviour_class
    _ITEMS["behaviour"] = [(n, label(n), behaviour_class(n).summary) for n in available_behaviours()]
    return _ITEMS["behaviour"]


def _character_items(self, context):
    from sim_core.character.spec import available_characters
    _ITEMS["character"] = [(n, label(n), f"rigs/{n}.json") for n in available_characters()]
    return _ITEMS["character"]


def _build_classes() -> list[type]:
    from sim_core.control.behaviour import available_behaviours, behaviour_class
    groups = []
    annotations = {
        "character": EnumProperty(name="Character", items=_character_items,
                                  description="Character to add (a rig from rigs/)"),
        "behaviour": EnumProperty(name="Behaviour", items=_behaviour_items,
                                  description="Behaviour to simulate"),
        "strength": EnumProperty(name="Strength", items=STRENGTH_ITEMS, default="human",
                                 description="Joint torque limits of the run"),
        "duration": FloatProperty(name="Duration", default=0.0, min=0.0, max=3600.0, precision=2,
                                  description="Seconds to simulate; 0 = the behaviour's default"),
        "start_frame": IntProperty(name="Start frame", default=1,
                                   description="Scene frame of the run's first key"),
        "fit_scene_range": BoolProperty(name="Fit scene range", default=False,
                                        description="Set the scene's start/end frames to the bake"),
        "target_object": PointerProperty(
            name="Target", type=bpy.types.Object,
            description="Object (an Empty, a box...) whose origin sets the target of a jump: it overrides "
                        "the target parameters, measured from the middle of the character's feet"),
    }
    for name in available_behaviours():
        schema = behaviour_class(name).schema
        group = type(f"SIMATHLETICS_PG_{group_attr(name)}", (bpy.types.PropertyGroup,),
                     {"__annotations__": {p.name: parameter_property(p) for p in schema.parameters}})
        groups.append(group)
        annotations[group_attr(name)] = PointerProperty(type=group)
    settings = type("SIMATHLETICS_PG_settings", (bpy.types.PropertyGroup,), {"__annotations__": annotations})
    return groups + [settings]


def register() -> None:
    _generated[:] = _build_classes()
    for cls in _generated:
        bpy.utils.register_class(cls)
    bpy.types.Scene.sim_athletics = PointerProperty(type=_generated[-1])


def unregister() -> None:
    if hasattr(bpy.types.Scene, "sim_athletics"):
        del bpy.types.Scene.sim_athletics
    for cls in reversed(_generated):
        bpy.utils.unregister_class(cls)
    _generated.clear()
