"""Parameter schemas: the one source for the CLI, the Blender panels, validation and the docs."""
from __future__ import annotations

import json
import math
from dataclasses import asdict, dataclass

from sim_core.errors import ParameterError


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


class Schema:
    def __init__(self, *parameters: Parameter):
        self.parameters = parameters
        self.by_name = {p.name: p for p in parameters}

    def defaults(self) -> dict[str, float]:
        return {p.name: p.default for p in self.parameters}

    def validate(self, values: dict) -> dict[str, float]:
        """Full, validated parameter dict: defaults overridden by ``values``."""
        result = self.defaults()
        for name, value in values.items():
            if name not in self.by_name:
                raise ParameterError(f"unknown parameter {name!r}; known: {', '.join(self.by_name)}")
            result[name] = self.by_name[name].validate(value)
        return result

    def parse_assignments(self, assignments: list[str]) -> dict[str, float]:
        """Parse CLI ``name=value`` strings and validate them."""
        values = {}
        for item in assignments:
            name, sep, value = item.partition("=")
            if not sep:
                raise ParameterError(f"--set {item!r} must look like name=value")
            values[name.strip()] = value
        return self.validate(values)

    def to_json_dict(self) -> list[dict]:
        return [asdict(p) for p in self.parameters]

    def to_json(self) -> str:
        return json.dumps(self.to_json_dict(), indent=1)
