"""A controller's hand-set constants as data: the "constants" section of a ``<table>_any.json``.

A basis controller (control/balance.py, crouch.py, leap.py, takeoff.py, tumble.py) or a skill
keeps the numbers someone tuned by hand - gains, times, shares, joint poses - in its table, not in
its code (HOUSE.md "data vs code"; docs/tables.md). Each constant has an entry in the controller's
constants schema (unit, a sanity range the stored value is checked against, one line of help),
declared next to the code that reads it. A constant is a number, a list of numbers (a tuple in
the code: e.g. hip, knee and ankle times) or a map of names to numbers or to such maps (joint
poses by joint name); every number in it is checked against the one range of its entry.

One table section per basis controller, shared by every skill that composes it: the leap's thrust
and landing read ``leap_any``'s constants whether a leap, a dive or a handspring runs them.
"""
from __future__ import annotations

from types import SimpleNamespace
from typing import Iterable

from ..schema import Schema
from .settings import ranged as constant   # a constant's schema entry: unit, sanity range, help
from .store import TableError, TableType, check_header, check_row, load, read, register, table_path

__all__ = ["as_constants", "constant", "constant_rows", "own_constants", "read_constants", "register_constants",
           "with_constants"]


def constant_rows(body: dict) -> Iterable[tuple[str, dict]]:
    """The "constants" section of a table body as settings rows the store checks: a number as
    itself, each number of a list or map as its own row (named by its place)."""
    def numbers(where: str, name: str, value):
        if isinstance(value, list):
            for k, item in enumerate(value):
                yield from numbers(f"{where}[{k}]", name, item)
        elif isinstance(value, dict):
            for key, item in value.items():
                yield from numbers(f"{where}[{key}]", name, item)
        else:
            yield where, {name: value}
    for name, value in body.get("constants", {}).items():
        yield from numbers(f"constants {name}", name, value)


def as_constants(body: dict) -> SimpleNamespace:
    """The constants section as they are (lists as tuples), one attribute per constant."""
    frozen = lambda v: tuple(frozen(x) for x in v) if isinstance(v, list) else (
        {k: frozen(x) for k, x in v.items()} if isinstance(v, dict) else v)
    return SimpleNamespace(**{name: frozen(value) for name, value in body["constants"].items()})


def register_constants(table: str, schema: Schema) -> TableType:
    """Declare the row type of a basis controller's own constants table ``<table>_any.json``
    (a table that holds nothing but its "constants")."""
    return register(TableType(table, schema, constant_rows, (as_constants,)))


def read_constants(table: str, schema: Schema) -> SimpleNamespace:
    """The constants of ``<table>_any.json``, checked against ``schema`` (every entry present, none
    unknown, every number within its entry's range). Only the header and this section are checked
    here, so a module reads its constants at import before its table's row type is declared (the
    leap's thrust takes them as default arguments); a load of the whole table checks them again."""
    name = table_path(table, "any").name
    data = read(table, "any")
    if data is None:
        raise TableError(f"{name}: no such table; it holds the constants {', '.join(schema.by_name)}")
    stored = check_header(name, table, "any", data).get("constants")
    if stored is None:
        raise TableError(f"{name}: no constants section; it must hold {', '.join(schema.by_name)}")
    missing = [n for n in schema.by_name if n not in stored]
    if missing:
        raise TableError(f"{name} constants: missing {', '.join(missing)}")
    for where, row in constant_rows({"constants": stored}):
        check_row(name, where, schema, row)
    return as_constants({"constants": stored})


def own_constants(table: str, character: str, shared: SimpleNamespace) -> SimpleNamespace:
    """A controller's constants for ``character``: ``shared`` (its ``<table>_any.json``'s), each one
    the character's own table ``<table>_<character>.json`` holds in its "constants" section replaced."""
    own = (load(table, character) or {}).get("constants")
    return shared if not own else SimpleNamespace(**{**vars(shared), **vars(as_constants({"constants": own}))})


def with_constants(settings: Schema, constants: Schema) -> Schema:
    """A table's row schema when its file also holds a constants section: the settings' entries and
    the constants' (no name in both)."""
    clash = sorted(set(settings.by_name) & set(constants.by_name))
    if clash:
        raise ValueError(f"{', '.join(clash)}: both a setting and a constant")
    return Schema(*settings.parameters, *constants.parameters)
