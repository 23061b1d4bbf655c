"""The built characters against Hodgins & Pollard 1997, Fig. 3, row by row (docs/bodies.md).

    python -m sim_core character report --out docs/bodies.md

Each row: our value, Fig. 3's, the error and whether it is inside issue 28's band (masses 5 %,
lengths 3 %, inertias 10 %), then the geometric factor against OUR man by Fig. 3's convention
(lengths: ratio; masses: (m'/m)^1/3; inertias: (I'/I)^1/5) beside the figure's factor against
ITS man (~75 kg, not ours: trap 4 of SEEDS-WAVE2.md).
"""
from __future__ import annotations

import re
from pathlib import Path

from .dimensions import fig3_measures
from .fig3 import FIG3, FIG3_FACTORS, KIND, PRESETS, TOLERANCE
from .spec import load_character
from ..errors import ParameterError

POWER = {"mass": 3, "length": 1, "inertia": 5}
UNIT = {"mass": "kg", "length": "m", "inertia": "kg m²"}
BEGIN, END = "<!-- fig3:begin -->", "<!-- fig3:end -->"


def fig3_rows(name: str) -> list[dict]:
    """The comparison rows of the stored character ``name`` (rigs/<name>.json)."""
    ours, man = fig3_measures(load_character(name)), fig3_measures(load_character("man"))
    rows = []
    for (row, target), paper_factor in zip(FIG3[name].items(), FIG3_FACTORS[name]):
        kind = KIND[row]
        error = ours[row] / target - 1
        rows.append({"row": row, "kind": kind, "ours": ours[row], "fig3": target, "error": error,
                     "within": abs(error) <= TOLERANCE[kind],
                     "factor_vs_our_man": (ours[row] / man[row]) ** (1 / POWER[kind]),
                     "fig3_factor": paper_factor})
    return rows


COMPARED = ("woman",)     # thesis characters shown beside Fig. 3's, not fitted to it


def report_markdown(names=PRESETS + COMPARED) -> str:
    lines = []
    for name in names:
        what = "not fitted: the thesis woman beside Fig. 3's" if name in COMPARED else "fitted"
        lines += [f"**{name}** (rigs/{name}.json; {what})", "",
                  "| row | ours | Fig. 3 | error | band | factor vs our man | Fig. 3 factor vs its man |",
                  "| --- | --- | --- | --- | --- | --- | --- |"]
        for r in fig3_rows(name):
            band = f"{'ok' if r['within'] else 'OUT'} (±{100 * TOLERANCE[r['kind']]:.0f} %)"
            lines.append(f"| {r['row']} ({UNIT[r['kind']]}) | {r['ours']:.3f} | {r['fig3']:.3f} | "
                         f"{100 * r['error']:+.1f} % | {band} | {r['factor_vs_our_man']:.2f} | {r['fig3_factor']:.2f} |")
        lines.append("")
    return "\n".join(lines).rstrip() + "\n"


def write_report(out: str | None = None) -> str:
    """The report's Markdown; with ``out``, also rewrite the block between the fig3 markers of that
    file (the rest of the file is prose written by hand)."""
    table = report_markdown()
    if out:
        path = Path(out)
        text = path.read_text() if path.exists() else f"{BEGIN}\n{END}\n"
        if BEGIN not in text or END not in text:
            raise ParameterError(f"{out} has no {BEGIN} ... {END} block to rewrite")
        new = re.sub(rf"{re.escape(BEGIN)}.*?{re.escape(END)}", lambda _: f"{BEGIN}\n{table}{END}", text, flags=re.S)
        path.write_text(new)
    return table
