"""Leap and landing report, every figure measured off the simulation: commanded vs achieved COM
rise of the vertical leap with human torque limits and with unlimited strength (like Wooten Fig.
4.1), the thrust's peak vertical ground force in body weights, commanded vs achieved COM travel of
the broad jump (like Fig. 4.4), the highest drop from rest each character lands balanced from,
and landings with horizontal COM speed (§6.2). Writes docs/leap_report.md, docs/leap_commanded.png
and docs/leap_broad.png:

    python scripts/leap_report.py [--processes 1]       # a few minutes on one core
    python scripts/leap_report.py --dense --processes 2  # also every height 1 cm apart (~350 more leaps)
"""
from __future__ import annotations

import argparse
import sys
from multiprocessing import Pool
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

import matplotlib                                                      # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt                                        # noqa: E402

from sim_core.control.leap import height_grid, load_mapping, rise_tolerance   # noqa: E402
from sim_core.errors import ParameterError                              # noqa: E402
from sim_core.simulate import RunRequest, StartState, run               # noqa: E402

CHARACTERS = ("man", "woman")
STRENGTHS = {"human": "vertical", "unlimited": "vertical_unlimited"}
LEAP_HEIGHTS = (0.1, 0.16, 0.2, 0.3, 0.33, 0.4, 0.5, 0.58, 0.6, 0.7, 0.8, 0.9, 1.0)
BROAD_DISTANCES = {"man": (0.3, 0.5, 0.75, 1.0, 1.1, 1.3, 1.6, 1.9, 2.1),
                   "woman": (0.3, 0.5, 0.75, 1.0, 1.3, 1.6)}
DROPS = [round(0.1 * k, 1) for k in range(1, 21)]          # 0.1 ... 2.0 m
SPEEDS = [-1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0]
SPEED_DROP = 0.2        # m: the standing COM (~1.05 m man) raised to about the thesis's 1.25 m
DENSE_STEP = 0.01       # m: --dense commands every height this far apart


def dense_heights(character: str, strength: str) -> list[float]:
    return height_grid(load_mapping(character)[STRENGTHS[strength]]["com_rise"], DENSE_STEP)


def label_axes(ax, title: str, xlabel: str, ylabel: str) -> None:
    ax.set_title(title)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.legend(fontsize=7)


def save_figure(fig, name: str) -> None:
    fig.tight_layout()
    fig.savefig(ROOT / "docs" / name, dpi=110)
    plt.close(fig)


def leap(args):
    character, strength, height = args
    try:
        traj = run(RunRequest("leap", character, params=dict(height=height), duration=5.0, strength=strength))
    except ParameterError as exc:
        return dict(character=character, strength=strength, height=height, refused=str(exc))
    m = traj.meta["metrics"]
    return dict(character=character, strength=strength, height=height, rise=m["com_rise"], travel=m["com_travel"],
                grf=m.get("peak_thrust_grf_body_weights", float("nan")),
                landing_grf=m.get("peak_landing_grf_body_weights", float("nan")), outcome=traj.meta["outcome"])


def broad(args):
    character, distance = args
    try:
        traj = run(RunRequest("leap", character, params=dict(distance=distance), duration=5.0))
    except ParameterError as exc:
        return dict(character=character, distance=distance, refused=str(exc))
    m = traj.meta["metrics"]
    return dict(character=character, distance=distance, travel=m["com_travel"], outcome=traj.meta["outcome"],
                grf=m.get("peak_thrust_grf_body_weights", float("nan")))


def landing(args):
    character, height, speed = args
    traj = run(RunRequest("land", character, start=StartState(height=height, velocity=(speed, 0.0, 0.0)),
                          duration=3.0))
    return character, height, speed, traj.meta["outcome"]


def within(commanded: float, achieved: float) -> bool:
    """TARGETS.md tolerance: +-10 %, or +-3 cm below 0.3 m."""
    return abs(achieved - commanded) <= rise_tolerance(commanded)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--processes", type=int, default=1)
    parser.add_argument("--dense", action="store_true",
                        help="also command every height DENSE_STEP apart up to the highest calibrated leap")
    args = parser.parse_args()
    with Pool(args.processes) as pool:
        leaps = pool.map(leap, [(c, s, h) for c in CHARACTERS for s in STRENGTHS for h in LEAP_HEIGHTS])
        broads = pool.map(broad, [(c, d) for c in CHARACTERS for d in BROAD_DISTANCES[c]])
        drops = pool.map(landing, [(c, h, 0.0) for c in CHARACTERS for h in DROPS])
        speeds = pool.map(landing, [(c, SPEED_DROP, v) for c in CHARACTERS for v in SPEEDS])
        dense = pool.map(leap, [(c, s, h) for c in CHARACTERS for s in STRENGTHS for h in dense_heights(c, s)]
                         ) if args.dense else []

    lines = ["# Leap and landing report", "",
             "Generated by `python scripts/leap_report.py` from simulation; every number is read off the "
             "simulated trajectory. Outcome `success` = landed balanced (no body but the feet touched the "
             "ground, pelvis above half its standing height, the middle of the feet moved at most 5 cm from "
             "where they touched down - no skid or hop back under the body - and not after they settled, "
             "COM still at the end; `skidded` = landed and stood, but the feet slid or hopped more than that). Tolerance (TARGETS.md): COM rise / travel within 10 %, or 3 cm below 0.3 m.", "",
             "## Vertical leap: commanded vs achieved COM rise (Wooten Fig. 4.1)", "",
             "![commanded vs achieved COM rise](leap_commanded.png)", ""]
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.2))
    for ax, character in zip(axes, CHARACTERS):
        for strength, colour in zip(STRENGTHS, ("b", "g")):
            rows = [r for r in leaps if r["character"] == character and r["strength"] == strength and "rise" in r]
            ok = [r for r in rows if r["outcome"] == "success"]
            bad = [r for r in rows if r["outcome"] != "success"]
            ax.scatter([r["height"] for r in ok], [r["rise"] for r in ok], c=colour,
                       label=f"{strength} strength, landed balanced")
            if bad:
                ax.scatter([r["height"] for r in bad], [r["rise"] for r in bad], c=colour, marker="x",
                           label=f"{strength} strength, fell / stepped")
        ax.plot([0, 1.1], [0, 1.1], "k--", lw=0.8, label="achieved = commanded")
        ax.fill_between([0, 0.3, 0.3, 1.1], [-0.03, 0.27, 0.27, 0.99], [0.03, 0.33, 0.33, 1.21], color="0.9", zorder=0,
                        label="tolerance (TARGETS.md)")
        label_axes(ax, f"{character}: vertical leap", "commanded COM rise (m)", "achieved COM rise (m)")
    save_figure(fig, "leap_commanded.png")
    for strength, key in STRENGTHS.items():
        lines += [f"### {strength} strength", "",
                  "| character | commanded (m) | achieved (m) | within tolerance | horizontal COM travel (m) "
                  "| thrust peak GRF (body weights) | landing peak GRF (body weights) | outcome |",
                  "| --- | --- | --- | --- | --- | --- | --- | --- |"]
        for r in (r for r in leaps if r["strength"] == strength):
            if "refused" in r:
                lines.append(f"| {r['character']} | {r['height']:.2f} | - | - | - | - | - | refused: "
                             f"{r['refused'].split(';')[0].replace('parameter ', '')} |")
            else:
                lines.append(f"| {r['character']} | {r['height']:.2f} | {r['rise']:.3f} | "
                             f"{'yes' if within(r['height'], r['rise']) else 'no'} | {r['travel']:+.2f} | {r['grf']:.2f} | "
                             f"{r['landing_grf']:.1f} | {r['outcome']} |")
        for character in CHARACTERS:
            rises = load_mapping(character).get(key, {}).get("com_rise", [])
            if rises:
                lines.append(f"\nCalibrated range ({character}, {strength}): {min(rises):.2f} … {max(rises):.2f} m "
                             f"(sim_core/tuned/tables/leap_{character}.json `{key}`).")
        lines.append("")

    lines += ["## Broad jump: commanded vs achieved COM travel (Wooten Fig. 4.4)", "",
              "![commanded vs achieved COM travel](leap_broad.png)", "",
              "| character | commanded (m) | achieved (m) | within 10 % | thrust peak GRF (body weights) | outcome |",
              "| --- | --- | --- | --- | --- | --- |"]
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.2))
    for ax, character in zip(axes, CHARACTERS):
        rows = [r for r in broads if r["character"] == character and "travel" in r]
        ok = [r for r in rows if r["outcome"] == "success"]
        bad = [r for r in rows if r["outcome"] != "success"]
        ax.scatter([r["distance"] for r in ok], [r["travel"] for r in ok], c="b", label="landed balanced")
        ax.scatter([r["distance"] for r in bad], [r["travel"] for r in bad], c="r", marker="x", label="fell / stepped")
        refused = [r["distance"] for r in broads if r["character"] == character and "refused" in r]
        ax.scatter(refused, [0.0] * len(refused), c="0.5", marker="|", s=200, label="refused (not calibrated)")
        ax.plot([0, 2.3], [0, 2.3], "k--", lw=0.8, label="achieved = commanded")
        label_axes(ax, f"{character}: broad jump (human strength)", "commanded COM travel (m)", "achieved COM travel (m)")
    save_figure(fig, "leap_broad.png")
    for r in broads:
        if "refused" in r:
            lines.append(f"| {r['character']} | {r['distance']:.2f} | - | - | - | refused: "
                         f"{r['refused'].split(' (nearest')[0].replace('parameter ', '')} |")
        else:
            lines.append(f"| {r['character']} | {r['distance']:.2f} | {r['travel']:.3f} | "
                         f"{'yes' if abs(r['travel'] - r['distance']) <= 0.1 * r['distance'] else 'no'} | "
                         f"{r['grf']:.2f} | {r['outcome']} |")

    lines += ["", "## Landing (Wooten §6.2)", "",
              "Drops from rest: the standing pose raised by the drop height, falling from rest "
              "(`python -m sim_core simulate land --start-height H`). Horizontal speeds: from a "
              f"{SPEED_DROP} m drop (COM at about the thesis's 1.25 m) with that COM speed.", "",
              "| character | highest drop landed balanced, every lower one too (m) | drops landed balanced (m) "
              "| horizontal speeds landed balanced (m/s) | failed speeds (outcome) |",
              "| --- | --- | --- | --- | --- |"]
    for character in CHARACTERS:
        mine = [(h, o) for c, h, v, o in drops if c == character]
        contiguous = 0.0
        for h, o in mine:
            if o != "success":
                break
            contiguous = h
        held = [h for h, o in mine if o == "success"]
        fast = [v for c, h, v, o in speeds if c == character and o == "success"]
        failed = [f"{v:+.1f} ({o})" for c, h, v, o in speeds if c == character and o != "success"]
        lines.append(f"| {character} | {contiguous:.1f} | {', '.join(f'{h:.1f}' for h in held)} | "
                     f"{', '.join(f'{v:+.1f}' for v in fast)} | {', '.join(failed) or '-'} |")
    lines += ["", "Seed (Wooten): drops up to 1.15 m (man) / 0.92 m (woman); speeds -1.0 … +3.0 m/s; "
              "thrust peak GRF 5.8 × body weight for a 0.5 m leap (humans ~2.5 ×; goal ≤ 3.5 ×).", "",
              "## Against the targets", ""]
    for strength, goal in (("human", 0.6), ("unlimited", 1.0)):
        reached = []
        for character in CHARACTERS:
            top = None
            for r in (r for r in leaps if r["character"] == character and r["strength"] == strength):
                if "rise" not in r or r["outcome"] != "success" or not within(r["height"], r["rise"]):
                    break
                top = r
            first = next(r for r in leaps if r["character"] == character and r["strength"] == strength)
            reached.append(f"{character} {first['height']:.2f} … {top['height']:.2f} m (rises {first['rise']:.3f} … "
                           f"{top['rise']:.3f} m)" if top else f"{character}: not from {first['height']:.2f} m")
        lines.append(f"- **Vertical leaps, {strength} strength** (goal: at least {goal} m; every commanded height "
                     f"up to it within tolerance and balanced): {'; '.join(reached)}.")
    for strength in STRENGTHS:
        peaks = [r["grf"] for r in leaps if r["strength"] == strength and "grf" in r]
        if peaks:
            under = sum(p <= 3.5 for p in peaks)
            lines.append(f"- **Peak thrust GRF ≤ 3.5 × body weight**, vertical leaps with {strength} strength: "
                         f"{under} of {len(peaks)} leaps; peaks {min(peaks):.1f}–{max(peaks):.1f} ×.")
    peaks = [r["grf"] for r in broads if "grf" in r]
    if peaks:
        lines.append(f"- **Peak thrust GRF ≤ 3.5 × body weight**, broad jumps: {sum(p <= 3.5 for p in peaks)} of "
                     f"{len(peaks)}; peaks {min(peaks):.1f}–{max(peaks):.1f} ×.")
    drift = [abs(r["travel"]) for r in leaps if r["character"] == "woman" and "travel" in r
             and r["outcome"] == "success" and r["height"] >= 0.5]
    if drift:
        lines.append(f"- **The woman's high leaps drift forward** ({min(drift):.2f}–{max(drift):.2f} m of COM travel "
                     "from 0.5 m up): her fast thrust leaves with forward speed whatever the crouch offset.")
    for character in CHARACTERS if dense else ():
        for strength in STRENGTHS:
            runs = [r for r in dense if r["character"] == character and r["strength"] == strength]
            misses = [r for r in runs if "rise" not in r or r["outcome"] != "success" or not within(r["height"], r["rise"])]
            missed = ", ".join(f"{r['height']:.2f} m" + (f" -> {r['rise']:.3f} m {r['outcome']}" if "rise" in r else
                                                         " refused") for r in misses)
            lines.append(f"- **Every height {100 * DENSE_STEP:.0f} cm apart** (`--dense`), {character}, {strength} "
                         f"strength, {runs[0]['height']:.2f} … {runs[-1]['height']:.2f} m: {len(runs) - len(misses)} "
                         f"of {len(runs)} within tolerance and balanced" + (f"; missed: {missed}." if misses else "."))
    lines += [
              "- **Heights between calibrated leaps**: a command runs the calibrated leap nearest it when that "
              "leap's measured rise is within the tolerance, and is interpolated between the leaps around it "
              "only when none is - an interpolated leap is not always good (the thrust starts on a state "
              "condition, so neighbouring crouches can leap quite differently: interpolated, the man's 0.40 m "
              "rose 0.48 m and the woman's 0.40 / 0.70 m fell), so `scripts/calibrate_leap.py --fill` adds "
              "calibrated leaps wherever no row is within the tolerance: from 0.1 m up, none is interpolated.",
              "- **Broad jumps** are planned jumps (the jump-to-target planner, straight ahead, 0.45 s in the "
              "air), one row per distance, run as they were planned; a distance is served by the row nearest "
              "it, within 10 %: every TARGETS.md distance of both characters is served (0.3-2.1 m man, "
              "0.3-1.6 m woman); a distance between rows may be refused.",
              "- **Landing**: every speed of -1.0 … +3.0 m/s lands balanced, both characters, with the feet "
              "where they touched down (before this report counted skids, forward landings hopped back 7-15 cm "
              "under the body and were called balanced). Moving backward the legs straighten in flight from "
              "0.5 m/s on (FAST_BACKWARD_LANDING_SPEED; forward from 1.0 m/s): with the slow landing's bent "
              "knee the woman fell at -1.0 m/s at every foot delta.", ""]
    (ROOT / "docs" / "leap_report.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main())
