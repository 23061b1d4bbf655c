"""Scene settings of the panel, generated from the schemas: one property group per behaviour for
its animator parameters (``schema``), one per behaviour for its tuned settings
(``settings_schema``, where the behaviour has one), and one for the run request (the request
schema: start height and speed, slope, backpack, push, strength, duration). No behaviour has UI
code of its own (Rigify's rig types are the model).

    number, unit 'rad'  -> FloatProperty(subtype ANGLE): stored in radians, shown in degrees
    number, unit 'm'    -> FloatProperty(subtype DISTANCE, unit LENGTH)
    number, unit 's'    -> FloatProperty(unit TIME_ABSOLUTE) where Blender has it
    bool                -> BoolProperty
    count               -> IntProperty (a whole number)
    choice              -> EnumProperty (a drop-down of the option names)
    points              -> PointerProperty to a curve object (its evaluated points are the path)
    other units         -> FloatProperty labelled with the unit
Hard limits come from the schema's range (widened to admit a documented special value, such as
``pelvis_height = 0``: standing); the schema still validates before anything runs.
"""
from __future__ import annotations

import bpy
from bpy.props import BoolProperty, EnumProperty, FloatProperty, IntProperty, PointerProperty

from .core.simcore import sim
from .core.values import as_typed, knob_value  # noqa: F401 - as_typed is part of this module's API

_generated: list[type] = []


def label(name: str) -> str:
    return name.replace("_", " ").capitalize()


def tooltip(p) -> str:
    text = f"{p.help[:1].upper()}{p.help[1:]}"
    if p.kind == "choice":
        return f"{text}. Options: {', '.join(p.options)}"
    if p.kind == "points":
        return f"{text}. A curve object: its evaluated points, in the rig's frame"
    text += f". Allowed: [{p.minimum:g}, {p.maximum:g}] {p.unit}"
    if p.special is not None:
        text += f" (or {p.special:g})"
    return text


def _has_unit(unit: str) -> bool:
    try:
        FloatProperty(unit=unit)
        return True
    except TypeError:
        return False


def _is_curve(self, obj) -> bool:
    return obj.type == "CURVE"


def parameter_property(p):
    """A bpy property for one schema knob."""
    if p.kind == "choice":
        descriptions = p.descriptions or tuple(label(o) for o in p.options)
        items = [(o, label(o), d) for o, d in zip(p.options, descriptions)]
        return EnumProperty(name=label(p.name), description=tooltip(p), items=items, default=p.default_option)
    if p.kind == "points":
        return PointerProperty(name=label(p.name), description=tooltip(p), type=bpy.types.Object, poll=_is_curve)
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


def behaviour_schema(behaviour: str):
    return sim("skills").behaviour_class(behaviour).schema


def settings_schema(behaviour: str):
    """The behaviour's tuned settings (what a search sets), or None if it declares none."""
    schema = getattr(sim("skills").behaviour_class(behaviour), "settings_schema", None)
    return schema if schema is not None and schema.parameters else None


def request_schema():
    return sim("request").REQUEST_SCHEMA


def takes_target(behaviour: str) -> bool:
    """True when the behaviour's schema has a target point (a jump to a target)."""
    return all(n in behaviour_schema(behaviour).by_name for n in TARGET_PARAMETERS)


def _attr(prefix: str, behaviour: str) -> str:
    return prefix + "".join(c if c.isalnum() else "_" for c in behaviour)


def group_attr(behaviour: str) -> str:
    return _attr("params_", behaviour)


def settings_attr(behaviour: str) -> str:
    return _attr("tuned_", behaviour)


def params_group(settings, behaviour: str):
    return getattr(settings, group_attr(behaviour))


def tuned_group(settings, behaviour: str):
    """The panel's tuned-settings group of ``behaviour`` (None if it has no settings schema)."""
    return getattr(settings, settings_attr(behaviour), None)


def _values(group, schema) -> dict:
    """The panel's values of ``schema``'s knobs, as the CLI would give them (points are left to
    :func:`panel_paths`: they need the rig's frame)."""
    return {p.name: knob_value(p, getattr(group, p.name)) for p in schema.parameters if p.kind != "points"}


def panel_params(settings, behaviour: str) -> dict:
    """The panel's parameter values for ``behaviour`` as the CLI would give them (a choice by its
    option name, bool -> 0/1); the schema validates them with the rest of the request."""
    return _values(params_group(settings, behaviour), behaviour_schema(behaviour))


def panel_paths(settings, behaviour: str) -> dict:
    """{points knob: curve object} of the ones the panel has a curve for."""
    group = params_group(settings, behaviour)
    return {p.name: getattr(group, p.name) for p in behaviour_schema(behaviour).parameters
            if p.kind == "points" and getattr(group, p.name) is not None}


def panel_settings(settings, behaviour: str) -> dict:
    """The tuned-settings sub-panel's values of ``behaviour`` ({} if it has none)."""
    schema, group = settings_schema(behaviour), tuned_group(settings, behaviour)
    return _values(group, schema) if schema is not None and group is not None else {}


def panel_tuned_overrides(settings, behaviour: str) -> dict:
    """The tuned settings the user changed in the sub-panel (those off their schema default): a
    run takes them on top of the calibrated ones; the untouched ones stay the table's."""
    schema = settings_schema(behaviour)
    defaults = schema.defaults() if schema is not None else {}
    return {k: v for k, v in panel_settings(settings, behaviour).items() if v != defaults.get(k)}


def use_character_defaults(settings, character: str) -> list[str]:
    """Put ``character``'s own defaults (Behaviour.character_defaults: the child's leap height,
    a runner's speed) into the panel's parameters that still show their schema default, so the
    panel offers what that body can do; a value the user set is kept. Returns what changed, as
    "behaviour: name=value"."""
    behaviours, changed = sim("skills"), []
    for name in behaviours.available_behaviours():
        cls, group = behaviours.behaviour_class(name), getattr(settings, group_attr(name), None)
        for knob, value in cls.character_defaults(character).items():
            p = cls.schema.by_name[knob]
            if group is not None and knob_value(p, getattr(group, knob)) == knob_value(p, p.default):
                setattr(group, knob, value)
                changed.append(f"{name}: {knob}={value:g}")
    return changed


def panel_request(settings) -> dict:
    """The run request's values from the panel (the request schema's knobs)."""
    return _values(settings.request, request_schema())


_ITEMS: dict[str, list] = {}          # enum items must stay referenced while Blender shows them


def _behaviour_items(self, context):
    behaviours = sim("skills")
    _ITEMS["behaviour"] = [(n, label(n), behaviours.behaviour_class(n).summary) for n in behaviours.available_behaviours()]
    return _ITEMS["behaviour"]


def _character_items(self, context):
    """The characters that can be added: those with a rigged skin (rigs/<name>.glb) beside their spec."""
    spec = sim("character.spec")
    _ITEMS["character"] = [(n, label(n), f"rigs/{n}.json") for n in spec.available_characters()
                           if (spec.RIGS_DIR / f"{n}.glb").exists()]
    return _ITEMS["character"]


def _group_class(name: str, schema) -> type:
    return type(f"SIMATHLETICS_PG_{name}", (bpy.types.PropertyGroup,),
                {"__annotations__": {p.name: parameter_property(p) for p in schema.parameters}})


def _build_classes() -> list[type]:
    behaviours = sim("skills")
    request = _group_class("request", request_schema())
    groups = [request]
    annotations = {
        "character": EnumProperty(name="Character", items=_character_items,
                                  description="Character to add (a rig from rigs/)"),
        "behaviour": EnumProperty(name="Behaviour", items=_behaviour_items,
                                  description="Behaviour to simulate"),
        "request": PointerProperty(type=request),
        "start_frame": IntProperty(name="Start frame", default=1,
                                   description="Scene frame of the run's first key"),
        "fit_scene_range": BoolProperty(name="Fit scene range", default=False,
                                        description="Set the scene's start/end frames to the bake"),
        "target_object": PointerProperty(
            name="Target", type=bpy.types.Object,
            description="Object (an Empty, a box...) whose origin sets the target of a jump: it overrides "
                        "the target parameters, measured from the middle of the character's feet"),
    }
    for name in behaviours.available_behaviours():
        cls = behaviours.behaviour_class(name)
        group = _group_class(group_attr(name), cls.schema)
        groups.append(group)
        annotations[group_attr(name)] = PointerProperty(type=group)
        tuned = settings_schema(name)
        if tuned is not None:
            group = _group_class(settings_attr(name), tuned)
            groups.append(group)
            annotations[settings_attr(name)] = PointerProperty(type=group)
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
