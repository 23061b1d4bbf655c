"""A calibration's bookkeeping (what a search keeps, which settings it varies, how a skill with no
calibrated row is refused); the tables themselves are read and written by the one store,
sim_core.tuned."""
from __future__ import annotations

import argparse

from .. import tuned
from ..errors import ParameterError


def names_option(parser, space, example: tuple) -> None:
    """A calibration script's ``--names`` option: search only these settings (comma-separated, each
    one of ``space``'s), the others staying as the search starts; ``example`` is named in the help."""
    def names(text: str) -> list[str]:
        chosen = text.split(",")
        unknown = [n for n in chosen if n not in space]
        if unknown:
            raise argparse.ArgumentTypeError(f"{', '.join(unknown)}: not searched settings; choose from {', '.join(space)}")
        return chosen

    parser.add_argument("--names", type=names, help="search only these settings (comma-separated, e.g. "
                        f"{','.join(example)}); the others stay as the search starts")


def searched_and_fixed(settings, space, only: list | None, start: dict) -> tuple[list[str], dict]:
    """The settings a search varies (those of ``space``, or of ``only`` among them), in the skill's
    order, and the others at their ``start`` values (the flight step, those left out of ``only``)."""
    names = [n for n in settings if n in space and (only is None or n in only)]
    return names, {n: start[n] for n in settings if n not in names}


def uncalibrated(character: str, skill: str, strength: str, calibrated: list[str], best: str | None,
                 script: str) -> ParameterError:
    """The refusal of a skill with no calibrated settings: which skill and strength, what the
    calibration's best run did (``best``, if it searched), and what is calibrated instead."""
    why = f" (best searched: {best})" if best else ""
    limits = "unlimited strength" if strength == "unlimited" else "human torque limits"
    return ParameterError(f"the {character} has no calibrated {skill} with {limits}: {script} found none that "
                          f"lands{why}; calibrated: {', '.join(calibrated) or 'none'}")


def merge_search(rows: list[dict], not_found: list[dict], key: dict, found: bool, row: dict,
                 best: str) -> tuple[list[dict], list[dict]]:
    """A table's rows and not-found records after a search for the entry ``key`` (e.g.
    ``{"direction": "backward", "strength": "human"}``): a found ``row`` replaces the key's row;
    else the old row stays if there is one; else the search's ``best`` run (a description) is
    recorded as not found, with the settings it tried and its score - unless an earlier search
    recorded a better (lower-scoring) one, which stays: a short search does not overwrite a
    longer one's best. Other keys' entries are kept as they are."""
    def mine(entry: dict) -> bool:
        return all(entry.get(k) == v for k, v in key.items())

    old = [e for e in rows if mine(e)]
    rows = [e for e in rows if not mine(e)]
    earlier = [e for e in not_found if mine(e)]
    missing = [e for e in not_found if not mine(e)]
    if found:
        rows.append({**key, **row})
    elif old:
        rows.extend(old)
    elif earlier and earlier[0].get("score", float("inf")) <= row.get("score", float("inf")):
        missing.extend(earlier)
    else:
        missing.append({**key, "settings": row["settings"], "best": best,
                        **({"score": row["score"]} if "score" in row else {})})
    return rows, missing


def kept_message(found: bool, succeeded: bool, drift_goal: float, had_row: bool) -> str:
    """What a calibration did with its best run, for its last line: a run that succeeded is kept
    only when its flight's angular momentum drift is below the goal."""
    if found:
        return "written to the table"
    why = (f"a found one needs a flight drift below {100 * drift_goal:.1f} %" if succeeded else "none succeeded")
    return f"not kept ({why}); " + ("the old row stays" if had_row else "recorded as not found")


def keep_search(table: str, character: str, section: str, stored: dict, key: dict, found: bool, row: dict,
                best: str, header: dict, directory=None) -> None:
    """A calibration's last step: the search's ``row`` merged into ``stored[section]`` and its
    not-found records for the entry ``key`` (merge_search), and the table written whole through
    the store, with ``header`` (script, duration) first, into ``directory`` (None: the shipped one)."""
    rows, missing = merge_search(stored[section], stored.get("not_found", []), key, found, row, best)
    tuned.save(table, character, {**header, section: rows, "not_found": missing},
               strengths=sorted({e["strength"] for e in rows + missing}), directory=directory)
