"""The one store of calibrated tables: every number a search or a hand tuning produced is read from
here and written here, never pasted into code (HOUSE.md "data vs code").

A table is one JSON file ``<skill>_<character>.json`` in the package data folder
``sim_core/tuned/tables`` (found with importlib.resources, so it travels with the package)::

    {"schema_version": 1, "skill": "handspring", "character": "man", "strengths": ["human", "unlimited"],
     ...the skill's own sections (rows, columns, records)...}

Each skill declares its row type (a :class:`TableType`): the settings schema its rows are checked
against and where in the file its rows are. Loading checks the header and every row; saving checks
the same and writes the file whole through a temporary file and a rename, so a reader never sees a
half-written table. JSON floats round-trip exactly (``repr``), so a stored row reproduces bit for bit.
"""
from __future__ import annotations

import json
from contextlib import contextmanager
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Callable, Iterable

from ..errors import ParameterError
from ..files import write_atomically
from ..schema import Schema

SCHEMA_VERSION = 1              # the layout of a table file; a file of another version is refused
HEADER = ("schema_version", "skill", "character", "strengths")
STRENGTHS = ("human", "unlimited")
# the folder of the tables: package data of sim_core (a test may point it at a temporary folder)
DIRECTORY = Path(str(resources.files(__package__) / "tables"))


class TableError(ParameterError):
    """A table file that is not what its skill's row type says: wrong version, unknown or
    out-of-range setting, missing header field. The message is one line naming the file and value."""


@dataclass(frozen=True)
class TableType:
    """What a skill's table holds. ``settings``: the schema of the tuned settings its rows set
    (units, ranges, help; the same names the behaviour reads). ``rows(body)``: the settings rows
    of a table body, as (where, {setting: value}) pairs - the check reads every row through it.
    ``lookup``: the skill's function(s) that pick a row from a table body for a request (nearest,
    interpolated, keyed); the behaviour calls them, and their docstrings say how."""
    skill: str
    settings: Schema
    rows: Callable[[dict], Iterable[tuple[str, dict]]]
    lookup: tuple[Callable, ...]

    def describe_lookup(self) -> str:
        """How the skill picks a row: the first sentence of each lookup's docstring."""
        return "; ".join(f"{f.__name__}: " + (f.__doc__ or "").strip().split(". ")[0].replace("\n", " ").replace("    ", "")
                         for f in self.lookup)


_TYPES: dict[str, TableType] = {}


def register(table_type: TableType) -> TableType:
    """Declare a skill's row type (at import of the skill's module)."""
    _TYPES[table_type.skill] = table_type
    return table_type


def keyed(rows: list[dict], **key) -> dict | None:
    """The first row whose fields equal ``key`` (e.g. direction="backward", strength="human"), or
    None: the lookup of a table keyed by the request."""
    return next((row for row in rows if all(row.get(k) == v for k, v in key.items())), None)


def table_type(skill: str) -> TableType:
    try:
        return _TYPES[skill]
    except KeyError:
        raise TableError(f"no row type is declared for tables of skill {skill!r}; declared: "
                         f"{', '.join(sorted(_TYPES)) or 'none'}") from None


def table_path(skill: str, character: str, directory: Path | None = None) -> Path:
    """Where ``<skill>_<character>.json`` is: in ``directory`` (a calibration's --tables, a test's
    folder) or the shipped tables."""
    return (DIRECTORY if directory is None else Path(directory)) / f"{skill}_{character}.json"


def exists(skill: str, character: str, directory: Path | None = None) -> bool:
    return table_path(skill, character, directory).exists()


def characters_of(skill: str, directory: Path | None = None) -> list[str]:
    """The characters that have a ``skill`` table of their own (not the ``any`` design table)."""
    folder = DIRECTORY if directory is None else Path(directory)
    names = (p.stem[len(skill) + 1:] for p in folder.glob(f"{skill}_*.json"))
    return sorted(n for n in names if n != "any" and not n.endswith(".tmp"))


def require_calibrated(table: str, character: str, skill: str) -> None:
    """Refuse a run of ``skill`` for a character with no ``table`` of its own: the design (``any``)
    table or another character's is not a calibration, and a skill run on one falls (measured: the
    woman on the man's running table falls 0.9 s into the run; the child drops from 0.5 m and
    falls on the landing's design values)."""
    if not exists(table, character):
        raise TableError(f"{skill} is not calibrated for the {character} (calibrated for: "
                         f"{', '.join(characters_of(table)) or 'nobody'}): another body's settings make it "
                         f"fall; `python -m sim_core calibrate {skill}` writes a character's table")


def load(skill: str, character: str, directory: Path | None = None) -> dict | None:
    """The checked body of ``<skill>_<character>.json`` (every section but the header), or None
    when there is no such table."""
    data = read(skill, character, directory)
    return None if data is None else check(table_path(skill, character, directory).name, skill, character, data)


def load_fresh(skill: str, character: str) -> dict | None:
    """``load`` of a shipped table, kept in memory and read again only when its file changes (its
    modification time): for lookups made per request (a region's bounds, a planner's table)."""
    path = table_path(skill, character)
    stamp = path.stat().st_mtime_ns if path.exists() else None
    if stamp is None or _FRESH.get((skill, character), (None,))[0] != stamp:
        _FRESH[(skill, character)] = (stamp, load(skill, character))
    return _FRESH[(skill, character)][1]


_FRESH: dict = {}


def read(skill: str, character: str, directory: Path | None = None) -> dict | None:
    """The parsed file ``<skill>_<character>.json``, unchecked (None when there is none)."""
    path = table_path(skill, character, directory)
    try:
        text = path.read_text()
    except FileNotFoundError:
        return None
    try:
        return json.loads(text)
    except json.JSONDecodeError as error:
        raise TableError(f"{path.name}: not valid JSON ({error})") from None


def save(skill: str, character: str, body: dict, strengths: Iterable[str], directory: Path | None = None) -> Path:
    """Check ``body`` against the skill's row type and write it whole (temporary file, then
    rename) as ``<skill>_<character>.json``; returns the path."""
    data = {"schema_version": SCHEMA_VERSION, "skill": skill, "character": character,
            "strengths": list(strengths), **{k: v for k, v in body.items() if k not in HEADER}}
    path = table_path(skill, character, directory)
    check(path.name, skill, character, data)
    return write_atomically(path, dumps(data))


class Provisional:
    """A table that may be written for trials and then must not stay: ``keep()`` keeps what is there
    when the block ends; otherwise the file that was there before is put back byte for byte (or the
    one written removed), also when the block ends by an exception or Ctrl-C."""

    def __init__(self, path: Path):
        self.path, self.before, self.kept = path, (path.read_bytes() if path.exists() else None), False

    def keep(self) -> None:
        self.kept = True

    def restore(self) -> None:
        """The file as it was when the block began."""
        if self.before is None:
            self.path.unlink(missing_ok=True)
        else:
            write_atomically(self.path, write=lambda tmp: Path(tmp).write_bytes(self.before))


@contextmanager
def provisional(skill: str, character: str, directory: Path | None = None):
    """``with provisional(skill, character) as table: ...; table.keep()`` (Provisional)."""
    table = Provisional(table_path(skill, character, directory))
    try:
        yield table
    finally:
        if not table.kept:
            table.restore()


def delete(skill: str, character: str, directory: Path | None = None) -> None:
    """Remove a table (a calibration that must run against none, e.g. the landing's)."""
    table_path(skill, character, directory).unlink(missing_ok=True)


def dumps(data: dict) -> str:
    """The file text of a table: one layout for every table, so load-then-save is byte-stable."""
    return json.dumps(data, indent=1) + "\n"


def check(name: str, skill: str, character: str, data: dict) -> dict:
    """``data`` (a whole file) checked: header, then every row against the skill's settings
    schema; returns the body. Refusals are one line naming the file and the bad value."""
    body = check_header(name, skill, character, data)
    check_rows(name, skill, body)
    return body


def check_header(name: str, skill: str, character: str, data: dict) -> dict:
    """The header of ``data`` (a whole file) checked; returns the body (every section but the header)."""
    version = data.get("schema_version")
    if version != SCHEMA_VERSION:
        raise TableError(f"{name}: schema_version={version!r}, this sim_core reads version {SCHEMA_VERSION}")
    for key, want in (("skill", skill), ("character", character)):
        if data.get(key) != want:
            raise TableError(f"{name}: {key}={data.get(key)!r}, expected {want!r}")
    strengths = data.get("strengths")
    if not isinstance(strengths, list) or any(s not in STRENGTHS for s in strengths):
        raise TableError(f"{name}: strengths={strengths!r} must be a list of {', '.join(STRENGTHS)}")
    return {k: v for k, v in data.items() if k not in HEADER}


def check_rows(name: str, skill: str, body: dict) -> None:
    """Every settings row of a table body (a file's, or a candidate a tuner passes to a run) against
    the skill's settings schema."""
    kind = table_type(skill)
    for where, row in kind.rows(body):
        check_row(name, where, kind.settings, row)


def check_row(name: str, where: str, settings: Schema, row: dict) -> None:
    """One row: every setting known to the schema and within its range."""
    for setting, value in row.items():
        parameter = settings.by_name.get(setting)
        if parameter is None:
            raise TableError(f"{name} {where}: unknown setting {setting!r}; known: {', '.join(settings.by_name)}")
        try:
            parameter.validate(value)
        except ParameterError as error:
            raise TableError(f"{name} {where}: {error}") from None
