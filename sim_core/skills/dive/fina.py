"""FINA dive numbers: the name a diver, a judge and a dive sheet give a dive, read into the
dive's group, somersaults, twists and position (the behaviour's own parameters).

The form (FINA Competition Regulations, Appendix: Table of Degrees of Difficulty):

* groups 1-4, three digits and a letter: the group (1 forward, 2 back, 3 reverse, 4 inward), 0
  (1 is a flying dive: the first half somersault straight, not built here), the number of half
  somersaults; ``107C`` = forward 3½ somersaults tuck;
* group 5 (twisting), four digits and a letter: 5, the somersault's group (1-4 as above), the
  number of half somersaults, the number of half twists; ``5253B`` = back 2½ somersaults with
  1½ twists pike;
* the position: A straight (layout), B pike, C tuck, D free (twisting dives only: the diver
  chooses; the behaviour maps it, see behaviour.DiveSchema).

Group 6 (armstand) starts from a handstand the platform behaviour does not build, and flying
dives have a straight first half somersault it does not make: both are refused by name.

REPERTOIRE is the drop-down: the standard 10 m dives elite divers perform (the brief's list plus
the seed's and the forward and reverse 1½ the table held before), each group's 2½ and 3½, the
forward 4½, and the common twisting dives.
"""
from __future__ import annotations

import re
from dataclasses import dataclass

from ...errors import ParameterError
from ...schema import Choice

FINA_GROUPS = {"1": "forward", "2": "back", "3": "reverse", "4": "inward"}      # definition: the first digit
POSITION_LETTERS = {"A": "layout", "B": "pike", "C": "tuck", "D": "free"}  # definition: the letter
CUSTOM = "custom"                   # the drop-down's first option: the group, somersaults, twists and position as set

REPERTOIRE = (
    "103B", "105B", "107B", "107C", "109B", "109C",          # forward
    "205B", "207B", "207C",                                  # back
    "303C", "305C", "307C",                                  # reverse
    "403B", "405B", "407B", "407C",                          # inward
    "5154B", "5231D", "5235D", "5253B",                      # twisting
)

FORM = ("a FINA dive number: group 1-4 (forward, back, reverse, inward), 0, half somersaults, position "
        "A/B/C (straight, pike, tuck), e.g. 107C; or 5, group 1-4, half somersaults, half twists, position "
        "A/B/C/D (D free), e.g. 5253B")
PATTERN = re.compile(r"^(?:([1-4])([01])([1-9])|5([1-4])([1-9])([1-9]))([A-D])$")


@dataclass(frozen=True)
class FinaDive:
    number: str
    group: str              # one of FINA_GROUPS' names
    somersaults: float
    twists: float
    position: str           # layout, pike, tuck or free


def parse(number: str) -> FinaDive:
    """A FINA number (any case) -> its dive; a malformed one or one of the groups and forms the
    behaviour does not build -> ParameterError naming the form."""
    text = str(number).strip().upper()
    found = PATTERN.match(text)
    if re.match(r"^6\d{2,3}[A-D]$", text):
        raise ParameterError(f"dive={text}: armstand dives (group 6) are not built: they start from a handstand; "
                             f"the form is {FORM}")
    if not found:
        raise ParameterError(f"dive={text!r} is not {FORM}")
    group, flying, halves, twist_group, twist_halves, half_twists, letter = found.groups()
    if flying == "1":
        raise ParameterError(f"dive={text}: flying dives (second digit 1) are not built: their first half "
                             f"somersault is straight; use 0, e.g. {text[0]}0{text[2:]}")
    if group is None:
        group, halves = twist_group, twist_halves
    elif letter == "D":
        raise ParameterError(f"dive={text}: position D (free) is for twisting dives (group 5) only; "
                             f"use A, B or C")
    return FinaDive(text, FINA_GROUPS[group], int(halves) / 2, int(half_twists or 0) / 2,
                    POSITION_LETTERS[letter])


class DiveNumber(Choice):
    """The ``dive`` knob: CUSTOM or one of REPERTOIRE, by its FINA number (any case) or its
    position in the list. A well-formed number outside the repertoire, or a malformed one, is
    refused in one line with the form and the repertoire."""

    def validate(self, value) -> float:
        if isinstance(value, str):
            text = value.strip()
            if text.lower() == CUSTOM:
                return self.code(CUSTOM)
            if text.upper() in self.options:
                return self.code(text.upper())
            try:
                float(text)
            except ValueError:
                dive = parse(text)       # refuses a malformed number with the form
                raise ParameterError(f"dive={dive.number} is not in the repertoire (set group, somersaults, twists and "
                                     f"position for it); {self.allowed()}") from None
        return super().validate(value)

    def allowed(self) -> str:
        return f"allowed dives are {', '.join(self.options[1:])} (or {CUSTOM}: group, somersaults, twists, position as set)"
