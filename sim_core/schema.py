"""Parameter schemas: the one source for the CLI, the Blender panels, validation and the docs.

A schema is a list of knobs of four kinds, optionally gathered under headings (:class:`Group`):

* :class:`Parameter` - a number in a range with an SI unit ('bool' for 0/1, 'count' for a whole
  number);
* :class:`Choice` - one of a few named options (a drop-down in Blender; the CLI takes the name).
  A behaviour sees the option's position in the list as a float (0.0, 1.0, ...): the numeric code
  these knobs had before they had names, so stored runs, tables and replays are unchanged, and
  the old numbers are still accepted;
* :class:`Points` - a path: a list of (x, y) points in metres (on the CLI ``"x,y; x,y; ..."``; in
  Blender the evaluated points of a curve object). Absent unless given.

Every knob validates one value to what a behaviour reads, and refuses a bad one with a one-line
error that names the value and what is allowed.
"""
from __future__ import annotations

import json
import math
from dataclasses import asdict, dataclass, field
from typing import Callable, Union

from .errors import ParameterError


@dataclass(frozen=True)
class Parameter:
    name: str
    unit: str               # SI unit ('m', 'rad', 's', 'N', 'rad/m', '1' for a bare number, 'count' for a
                            # whole number, 'bool')
    default: float
    minimum: float
    maximum: float
    help: str
    special: float | None = None   # an out-of-range value with a documented meaning (e.g. 0 = standing)

    @property
    def kind(self) -> str:
        """'bool', 'count' or 'number' (what the panel makes of it)."""
        return self.unit if self.unit in ("bool", "count") else "number"

    def validate(self, value) -> float:
        if isinstance(value, str):
            text = value.strip()
            if self.unit == "bool" and text.lower() in ("true", "false", "yes", "no", "on", "off"):
                return 1.0 if text.lower() in ("true", "yes", "on") else 0.0
            try:
                value = float(text)
            except ValueError:
                raise ParameterError(f"parameter {self.name}={text!r} is not a number; {self.allowed()}") from None
        if isinstance(value, bool):
            value = float(value)
        if not isinstance(value, (int, float)):
            raise ParameterError(f"parameter {self.name}={value!r} is not a number; {self.allowed()}")
        value = float(value)
        if math.isnan(value) or math.isinf(value):
            raise ParameterError(f"parameter {self.name}={value} is not finite; {self.allowed()}")
        if self.special is not None and value == self.special:
            return value
        if self.unit == "bool" and value not in (0.0, 1.0):
            raise ParameterError(f"parameter {self.name}={value:g} must be 0 or 1")
        if self.unit == "count" and value != round(value):
            raise ParameterError(f"parameter {self.name}={value:g} must be a whole number; {self.allowed()}")
        if not self.minimum <= value <= self.maximum:
            raise ParameterError(f"parameter {self.name}={value:g} {self.unit} is out of range; {self.allowed()}")
        return value

    def allowed(self) -> str:
        text = f"allowed range for {self.name} is [{self.minimum:g}, {self.maximum:g}] {self.unit}"
        if self.special is not None:
            text += f" (or {self.special:g}: {self.help.split('; ')[-1]})" if "; " in self.help else f" (or {self.special:g})"
        return text

    def default_text(self) -> str:
        return f"{self.default:g}"

    def range_text(self) -> str:
        return f"{self.minimum:g} … {self.maximum:g}"

    def to_json_dict(self) -> dict:
        return dict(asdict(self), kind=self.kind)


@dataclass(frozen=True)
class Choice:
    """One of ``options`` (names). The value a behaviour reads is the option's index as a float;
    ``descriptions`` (one per option, optional) are the drop-down's tooltips."""
    name: str
    options: tuple[str, ...]
    default_option: str
    help: str
    descriptions: tuple[str, ...] = ()
    unit = "choice"
    kind = "choice"
    special = None

    def __post_init__(self):
        if self.default_option not in self.options:
            raise ValueError(f"choice {self.name}: default {self.default_option!r} is not one of {self.options}")
        if self.descriptions and len(self.descriptions) != len(self.options):
            raise ValueError(f"choice {self.name}: {len(self.descriptions)} descriptions for {len(self.options)} options")

    @property
    def default(self) -> float:
        return self.code(self.default_option)

    @property
    def minimum(self) -> float:
        return 0.0

    @property
    def maximum(self) -> float:
        return float(len(self.options) - 1)

    def code(self, option: str) -> float:
        return float(self.options.index(option))

    def option(self, code: float) -> str:
        """The option name of a validated value (its code)."""
        return self.options[int(round(code))]

    def validate(self, value) -> float:
        """An option name (any case) or, as before the names, its number -> the option's code."""
        if isinstance(value, str):
            text = value.strip()
            if text.lower() in self.options:
                return self.code(text.lower())
            try:
                value = float(text)
            except ValueError:
                raise ParameterError(f"parameter {self.name}={text!r} is not an option; {self.allowed()}") from None
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) \
                or value != round(value) or not 0 <= value < len(self.options):
            shown = f"{value:g}" if isinstance(value, float) and math.isfinite(value) else repr(value)
            raise ParameterError(f"parameter {self.name}={shown} is not an option; {self.allowed()}")
        return float(value)

    def allowed(self) -> str:
        return (f"allowed options for {self.name} are {', '.join(self.options)} "
                f"(or their numbers 0-{len(self.options) - 1})")

    def default_text(self) -> str:
        return self.default_option

    def range_text(self) -> str:
        return ", ".join(self.options)

    def to_json_dict(self) -> dict:
        return {"name": self.name, "kind": self.kind, "unit": self.unit, "options": list(self.options),
                "default": self.default_option, "help": self.help, "descriptions": list(self.descriptions)}


def parse_points(name: str, value, max_points: int) -> list[list[float]]:
    """Points from a list of pairs or from text 'x,y; x,y; ...' (the CLI's ``--set NAME=``)."""
    import numpy as np
    if isinstance(value, str):
        text = value.strip()
        if not text:
            raise ParameterError(f"parameter {name} is empty; give at least two points 'x,y; x,y' in metres")
        try:
            value = [[float(c) for c in item.replace(",", " ").split()] for item in text.split(";") if item.strip()]
        except ValueError:
            raise ParameterError(f"parameter {name}={text!r} is not a list of points 'x,y; x,y; ...' in metres") from None
    try:
        array = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise ParameterError(f"parameter {name} must be a list of [x, y] points in metres") from None
    if array.ndim != 2 or array.shape[1] != 2:
        raise ParameterError(f"parameter {name} must be a list of [x, y] points in metres (got shape {array.shape})")
    if not np.all(np.isfinite(array)):
        raise ParameterError(f"parameter {name} has a point that is not finite")
    if len(array) > max_points:
        raise ParameterError(f"parameter {name} has {len(array)} points; at most {max_points} are allowed")
    return array.tolist()


@dataclass(frozen=True)
class Points:
    """A path of (x, y) points in metres, absent unless given (an empty list is the same as
    absent). ``clean`` is the skill's own check of a parsed (N, 2) list (e.g. merge repeated
    points, refuse a degenerate path); it returns the points to store."""
    name: str
    help: str
    clean: Callable | None = field(default=None, compare=False)
    max_points: int = 10000
    unit = "m"
    kind = "points"
    default = None
    special = None

    def validate(self, value) -> list[list[float]]:
        points = parse_points(self.name, value, self.max_points)
        if self.clean is not None:
            points = self.clean(points)
        return [list(map(float, p)) for p in points]

    @staticmethod
    def is_absent(value) -> bool:
        return value is None or (isinstance(value, (list, tuple)) and len(value) == 0)

    def allowed(self) -> str:
        return f"{self.name} is a list of [x, y] points in metres"

    def default_text(self) -> str:
        return "none"

    def range_text(self) -> str:
        return f"[x, y] points, m (at most {self.max_points})"

    def to_json_dict(self) -> dict:
        return {"name": self.name, "kind": self.kind, "unit": self.unit, "default": None, "help": self.help,
                "max_points": self.max_points}


Knob = Union[Parameter, Choice, Points]


@dataclass(frozen=True)
class Group:
    """Knobs under a heading (a box in the panel, a heading in the docs); no effect on values."""
    heading: str
    knobs: tuple

    def __init__(self, heading: str, *knobs):
        object.__setattr__(self, "heading", heading)
        object.__setattr__(self, "knobs", tuple(knobs))


class Schema:
    def __init__(self, *items):
        self.groups: list[tuple[str | None, tuple]] = []
        loose: list = []
        for item in items:
            if isinstance(item, Group):
                if loose:
                    self.groups.append((None, tuple(loose)))
                    loose = []
                self.groups.append((item.heading, item.knobs))
            else:
                loose.append(item)
        if loose:
            self.groups.append((None, tuple(loose)))
        self.parameters: tuple = tuple(p for _, knobs in self.groups for p in knobs)
        self.by_name = {p.name: p for p in self.parameters}
        if len(self.by_name) != len(self.parameters):
            raise ValueError(f"a schema names a knob twice: {[p.name for p in self.parameters]}")

    def heading_of(self, name: str) -> str | None:
        return next(heading for heading, knobs in self.groups if any(p.name == name for p in knobs))

    def defaults(self) -> dict:
        return {p.name: p.default for p in self.parameters if p.default is not None}

    def validate(self, values: dict, defaults: dict | None = None) -> dict:
        """Full, validated parameter dict: defaults overridden by ``values``. ``defaults``: some
        knobs' defaults replaced (a character's, Behaviour.character_defaults)."""
        result = {**self.defaults(), **(defaults or {})}
        for name, value in values.items():
            if name not in self.by_name:
                raise ParameterError(f"unknown parameter {name!r}; known: {', '.join(self.by_name)}")
            knob = self.by_name[name]
            if knob.kind == "points" and Points.is_absent(value):
                result.pop(name, None)
                continue
            result[name] = knob.validate(value)
        return result

    def parse_assignments(self, assignments: list[str], defaults: dict | None = None) -> dict:
        """Parse CLI ``name=value`` strings and validate them (``defaults`` as in validate)."""
        values = {}
        for item in assignments:
            name, sep, value = item.partition("=")
            if not sep:
                raise ParameterError(f"--set {item!r} must look like name=value")
            values[name.strip()] = value
        return self.validate(values, defaults)

    def to_json_dict(self) -> list[dict]:
        rows = []
        for heading, knobs in self.groups:
            for p in knobs:
                row = p.to_json_dict()
                if heading is not None:
                    row["group"] = heading
                rows.append(row)
        return rows

    def to_json(self) -> str:
        return json.dumps(self.to_json_dict(), indent=1)

    def markdown(self) -> str:
        """The table of the docs: one row per knob, a bold row per heading."""
        rows = ["| parameter | unit | default | range | meaning |", "| --- | --- | --- | --- | --- |"]
        for heading, knobs in self.groups:
            if heading is not None:
                rows.append(f"| **{heading}** | | | | |")
            rows += [f"| `{p.name}` | {p.unit} | {p.default_text()} | {p.range_text()} | {p.help} |" for p in knobs]
        return "\n".join(rows)
