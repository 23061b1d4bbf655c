"""Measure the turn's hop (control/turn.py, the leap's ``turn_angle``) on a fine grid of angles and write
the heading each reached into the character's commanded table (``turn_headings``, read by
skills/jump_to_target/commanded.py turn_for_heading): every angle runs the hop from the standing start,
then the heading of the pelvis when the leap's own crouch begins is read off the simulation; a hop that
fell (the COM below ``--fall-height`` m before the leap began) is left out. The hop does not depend on the
jump that follows (the same angle reaches the same heading for any target), so one run each is the map:

    tools/turn_headings.py --character woman --from -1.2 --to 1.2 --step 0.005 --write

``--quarter``: the quarter turn instead (the leap's ``turn_first``, its two hops scaled; --from/--to are the
scale's magnitudes, both sides run) and the commanded jump straight to that side after it (planning/turn_map.py
quarter_line), written as ``quarter_lines`` (merged with the rows already stored: a finer grid fills the gaps):

    tools/turn_headings.py --character woman --quarter --from 0.95 --to 1.2 --step 0.0025 --write
    tools/turn_headings.py --character woman --quarter --from 1.00125 --to 1.19875 --step 0.0025 --write

``--way sideways_<row>`` with ``--quarter``: each quarter turn of the stored ``quarter_lines`` and that row's own jump
after it (quarter_line's ``way``), written as ``sideways_<row>_lines`` (the row steers by them, commanded.quarter_lines_of):

    tools/turn_headings.py --character woman --quarter --way sideways_long_short --write

``--lines``: each hop of the stored ``turn_headings`` whose heading is within ``--max-heading`` deg and the two
commanded jumps along it after it (planning/turn_map.py hop_line), written as ``turn_lines`` (the turned plan
chooses its hop by the line of the jump after it, commanded.turn_for_point):

    tools/turn_headings.py --character woman --lines --max-heading 40 --write
"""
from __future__ import annotations

import argparse
import math

import numpy as np

from sim_core.planning.turn_map import hop_heading, hop_line, quarter_line
from sim_core.tuned.store import read, save


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--character", default="woman")
    ap.add_argument("--from", dest="low", type=float, default=-1.2)
    ap.add_argument("--to", dest="high", type=float, default=1.2)
    ap.add_argument("--step", type=float, default=0.005)
    ap.add_argument("--fall-height", type=float, default=0.5, help="m: a hop whose COM went lower fell")
    ap.add_argument("--quarter", action="store_true", help="the quarter turn (turn_first) and the jump after it")
    ap.add_argument("--way", default="sideways", help="--quarter: the sideways row whose jump follows the turn")
    ap.add_argument("--lines", action="store_true", help="the stored hops and the jumps after them (turn_lines)")
    ap.add_argument("--max-heading", type=float, default=40.0, help="deg: --lines runs the hops turned at most this far")
    ap.add_argument("--write", action="store_true", help="store the map in the character's commanded table")
    args = ap.parse_args()
    if args.quarter:
        quarter(args)
        return
    if args.lines:
        lines(args)
        return
    angles, headings = [], []
    for angle in np.round(np.arange(args.low, args.high + 1e-9, args.step), 4):
        if not angle:
            continue
        heading, lowest, began = hop_heading(args.character, float(angle))
        kept = began and lowest >= args.fall_height
        print(f"turn_angle {angle:+.3f} rad: heading {math.degrees(heading):+7.2f} deg, lowest COM {lowest:.2f} m"
              f"{'' if kept else ' (fell: left out)'}", flush=True)
        if kept:
            angles.append(float(angle))
            headings.append(round(heading, 5))
    if args.write:
        body = read("jump_commanded", args.character)
        body["turn_headings"] = {"turn_angle": angles, "heading": headings}
        path = save("jump_commanded", args.character, body, body["strengths"])    # checked, written whole
        print(f"wrote {len(angles)} hops to {path}")


def line_text(row: dict) -> str:
    """A measured turn's heading, where it left the feet and the line its jump flew (quarter_line, hop_line)."""
    return (f"heading {math.degrees(row['heading']):+7.2f} deg, feet ({row['feet_x']:.3f}, {row['feet_y']:+.3f}) m, "
            f"line {math.degrees(row['line']):+7.2f} deg")


def measured_lines(values, measure, label, stood) -> list[dict]:
    """``measure(value)`` (quarter_line, hop_line) for each value, printed as it goes (``label(value)``, the row's
    line_text and ``stood(row)``); the rows whose turn kept its feet."""
    rows = []
    for value in values:
        row = measure(value)
        print(f"{label(value)}: " + ("fell (left out)" if row is None else f"{line_text(row)}, {stood(row)}"), flush=True)
        if row is not None:
            rows.append(row)
    return rows


def write_lines(character: str, key: str, rows: list[dict], columns, what: str) -> None:
    """The rows as the commanded table's ``key`` (``columns``), checked and written whole."""
    body = read("jump_commanded", character)
    body[key] = {k: [round(float(r[k]), 5) for r in rows] for k in columns}
    path = save("jump_commanded", character, body, body["strengths"])
    print(f"wrote {len(rows)} {what} to {path}")


def quarter(args) -> None:
    """--quarter: quarter_line for each scale of the grid, both sides; the rows whose hops stood are kept (merged
    with the stored ones by scale); --way a sideways row: the stored quarter turns with that row's jump."""
    if args.way != "sideways":      # a row's own map: the stored quarter turns (their hops stood) with its jump
        scales = read("jump_commanded", args.character)["quarter_lines"]["turn_first"]
        rows = measured_lines(scales, lambda scale: quarter_line(args.character, float(scale), args.way),
                              lambda scale: f"turn_first {scale:+.4f}", lambda row: "stood" if row["stood"] else "fell")
        if args.write:
            write_lines(args.character, f"{args.way}_lines", rows, QUARTER_COLUMNS, f"quarter turns with {args.way}")
        return
    grid = np.round(np.arange(args.low, args.high + 1e-9, args.step), 4)
    rows = measured_lines(np.concatenate([-grid[::-1], grid]), lambda scale: quarter_line(args.character, float(scale)),
                          lambda scale: f"turn_first {scale:+.4f}", lambda row: "stood" if row["stood"] else "fell")
    if args.write:
        stored = read("jump_commanded", args.character).get("quarter_lines", {})
        old = [dict(zip(stored, values)) for values in zip(*stored.values())] if stored else []
        merged = sorted({r["turn_first"]: r for r in old + rows}.values(), key=lambda r: r["turn_first"])
        write_lines(args.character, "quarter_lines", merged, QUARTER_COLUMNS, "quarter turns")


def lines(args) -> None:
    """--lines: hop_line for each stored hop turned at most --max-heading deg; the rows whose hop stood are kept."""
    pairs = read("jump_commanded", args.character)["turn_headings"]
    angles = [a for a, h in zip(pairs["turn_angle"], pairs["heading"]) if abs(math.degrees(h)) <= args.max_heading]
    rows = measured_lines(angles, lambda angle: hop_line(args.character, float(angle)),
                          lambda angle: f"turn_angle {angle:+.3f}", lambda row: f"stood {row['stood']:.1f}")
    if args.write:
        write_lines(args.character, "turn_lines", rows, LINE_COLUMNS, "hops' lines")


QUARTER_COLUMNS = ("turn_first", "heading", "feet_x", "feet_y", "line", "stood")
LINE_COLUMNS = ("turn_angle", "heading", "feet_x", "feet_y", "line", "stood")


if __name__ == "__main__":
    main()
