"""The landing calibration's grid (python -m sim_core calibrate land): the drops, horizontal speeds
and foot deltas it tries, the man's below, and for another body the man's scaled by Fig. 6 (drops
and deltas x L, speeds x L^1/2). The landing's plan (planning/land.py) steps by a share of its
delta step."""
from __future__ import annotations

from dataclasses import dataclass

from ...character.dimensions import leg_length_ratio
from ...character.spec import CharacterSpec, load_character

SPEEDS = [-1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0]
DELTA_STEP = 0.02            # m between the deltas tried (the landing's plan steps by a share of it, x L)
DELTAS = [round(-0.3 + DELTA_STEP * k, 2) for k in range(28)]     # -0.30 ... 0.24 m
DROPS = (0.2, 0.4, 0.6)      # m above standing: 0.2 puts the COM at about Wooten's 1.25 m (man) and
                             # lands like a standing broad jump (0.45 s in the air); 0.6 lands like a
                             # 0.6 m leap (forefoot first)


FAST_FROM, FAST_RAMP = 3.9, 0.2     # m/s: the extra delta ramps in over this vertical touchdown speed
FAST_DELTAS = [0.0, 0.02, 0.04, 0.06, 0.08]
HIGH_DROPS = [0.8, 0.9, 1.0, 1.1, 1.15, 1.2, 1.3]
# --drop-limits: the drops tried above the highest row and below the lowest (m, the man's; x L for another
# body), each planned and run as simulate land runs it, in order until one falls; and the sideways
# speeds (m/s, x L^1/2) tried from the highest row's drop at the slowest, no and the fastest forward speed
LIMIT_HIGH_DROPS = [0.8, 1.0, 1.2, 1.4, 1.5]
LIMIT_LOW_DROPS = [0.1, 0.0]
LIMIT_SIDE_SPEEDS = [0.15, 0.3, 0.45, 0.6]


@dataclass(frozen=True)
class Grid:
    """What the calibration tries for one body (the constants above are the man's)."""
    speeds: list
    deltas: list
    drops: tuple
    fast_from: float
    fast_ramp: float
    fast_deltas: list
    high_drops: list
    delta_step: float        # m between neighbouring deltas (a landing's plan steps by a share of it)
    limit_high_drops: list
    limit_low_drops: list
    limit_side_speeds: list

    @property
    def trials(self) -> int:
        return len(self.drops) * len(self.speeds) * len(self.deltas) + len(self.fast_deltas) * len(self.high_drops)


def grid(character) -> Grid:
    """The man's grid scaled to ``character`` (a name, a spec file or a CharacterSpec) by Fig. 6
    (lengths x L, speeds x L^1/2; the man's own numbers for the man, L = 1)."""
    spec = character if isinstance(character, CharacterSpec) else load_character(character)
    L = leg_length_ratio(load_character("man"), spec)
    length = lambda values: [round(v * L, 4) for v in values]
    speed = lambda values: [round(v * L ** 0.5, 4) for v in values]
    return Grid(speed(SPEEDS), length(DELTAS), tuple(length(DROPS)), speed([FAST_FROM])[0], speed([FAST_RAMP])[0],
                length(FAST_DELTAS), length(HIGH_DROPS), length([DELTA_STEP])[0], length(LIMIT_HIGH_DROPS),
                length(LIMIT_LOW_DROPS), speed(LIMIT_SIDE_SPEEDS))
