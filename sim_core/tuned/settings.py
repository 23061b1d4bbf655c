"""A behaviour's two schemas in one validator: the animator's parameters (what a person sets: the
panel, ``describe``, the README's tables) and the tuned settings (what a search sets and a table
stores; the panel folds them into a closed sub-panel). ``--set`` and a request may still set a tuned
setting by its name - the one name it has in the schema, the table and the code."""
from __future__ import annotations

import dataclasses

from ..schema import Parameter, Schema


class SkillSchema(Schema):
    """``parameters`` are the animator's; ``settings`` the tuned settings' schema. Validation
    accepts both (a run's parameter dict holds both, the settings at their defaults unless set)."""

    def __init__(self, *parameters, settings: Schema):
        super().__init__(*parameters)
        self.settings = settings
        clash = sorted(set(self.by_name) & set(settings.by_name))
        if clash:
            raise ValueError(f"{', '.join(clash)}: both an animator parameter and a tuned setting")
        self.by_name = {**self.by_name, **settings.by_name}

    def defaults(self) -> dict[str, float]:
        return {**super().defaults(), **self.settings.defaults()}


def with_defaults(ranges: Schema, values: dict) -> Schema:
    """``ranges`` with the defaults taken from ``values`` (a table's row: data), for the settings
    whose default is a calibrated or hand-tuned number; the others keep theirs."""
    return Schema(*(dataclasses.replace(p, default=float(values[p.name])) if p.name in values else p
                    for p in ranges.parameters))


def ranged(name: str, unit: str, minimum: float, maximum: float, help_text: str) -> Parameter:
    """A schema entry whose value is data (a table's row or constants): its unit, its range (a
    sanity bound a stored value is checked against) and help; the default is only the range's low
    end until ``with_defaults`` sets it from the table."""
    return Parameter(name, unit, minimum, minimum, maximum, help_text)


def prefixed(pieces: Schema, prefix: str, what: str, exclude: tuple[str, ...] = ()) -> tuple[Parameter, ...]:
    """A control piece's parameters as a skill's settings named ``prefix`` + name (its table stores them;
    the piece's schema stays their one declaration): the same unit, range and help, the help led by ``what``;
    ``exclude`` the ones the skill gives from other settings."""
    return tuple(ranged(prefix + p.name, p.unit, p.minimum, p.maximum, f"{what}: {p.help}")
                 for p in pieces.parameters if p.name not in exclude)


def unprefixed(pieces: Schema, prefix: str, values: dict, **given) -> dict:
    """The piece's parameters back from a skill's ``prefixed`` settings (plus ``given``), validated."""
    return pieces.validate({**{p.name: values[prefix + p.name] for p in pieces.parameters if p.name not in given},
                            **given})
