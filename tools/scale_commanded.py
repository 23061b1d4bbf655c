"""Carry a character's commanded take-off (issue 29) to another body by Hodgins & Pollard's Fig. 6
(adapt/settings.py): the source's commanded table's ``settings`` by ``scale_settings`` and its leap
table's ``commanded_*`` constants by ``scale_constants`` (both in ``--mode``), the thrust's extension slowed
by ``--timing-scale`` (the leap's ``commanded_timing_scale``: a body weaker for its size than Fig. 6's
scaling assumes extends more slowly, its joints' torques ~ 1/time^2), and the crouch pairs, the region and
the planner's own constants as measured on the new body (given on the command line; the scaled pairs are
printed for comparison); a turned region (``--turned-region``) once tools/turn_headings.py has measured the
new body's hop (its map is kept). Prints the tables; ``--write`` saves them through the table store (the new
character's ``jump_commanded`` table, and the ``constants`` section of its ``leap`` table):

    tools/scale_commanded.py --from woman --to man --mode mass --timing-scale 1.16 \\
        --crouch-by-air-time 0.63:0.39,0.61:0.455,0.59:0.495,0.55:0.535 \\
        --region 0.85,1.2,-0.02,0.02,0.42,0.52 --planner aim_trials=9 --write

``--const name=value`` replaces a scaled ``commanded_*`` constant by one measured on the new body (the man's
``commanded_lean_push`` 6: his slowed thrust adds more forward speed per lean than hers, docs/jump_to_target.md).
"""
from __future__ import annotations

import argparse
import json

from sim_core.adapt.scaling import ScaleFactors, Units, scale
from sim_core.adapt.settings import MODES, CharacterPair, scale_constants, scale_settings
from sim_core.character.spec import load_character
from sim_core.control.leap import LEAP_CONSTANTS, LEAP_SETTINGS, leap_constants
from sim_core.skills.jump_to_target import commanded  # noqa: F401  (declares the jump_commanded table's row type)
from sim_core.tuned.store import read, save


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--from", dest="source", default="woman")
    ap.add_argument("--to", dest="target", default="man")
    ap.add_argument("--mode", choices=MODES, default="mass")
    ap.add_argument("--timing-scale", type=float, default=1.0)
    ap.add_argument("--crouch-by-air-time", required=True, help="crouch:air time pairs (m:s) measured on the new body")
    ap.add_argument("--region", required=True, help="target_x low,high, target_y low,high, air_time low,high")
    ap.add_argument("--turned-region", help="distance low,high m, bearing low,high rad, air_time low,high s (turned "
                                            "first, then forward: the table's turned_region; needs its turn_headings)")
    ap.add_argument("--planner", action="append", default=[], help="name=value: the planner's own constants")
    ap.add_argument("--const", action="append", default=[],
                    help="name=value: a commanded_* leap constant measured on the new body instead of the scaled one")
    ap.add_argument("--measured", default="", help="how the region was measured (the table's 'measured')")
    ap.add_argument("--write", action="store_true")
    args = ap.parse_args()
    source = read("jump_commanded", args.source)
    pair = CharacterPair(load_character(args.source), load_character(args.target))
    settings = scale_settings(source["settings"], LEAP_SETTINGS, pair, args.mode)
    own = vars(leap_constants(args.source))
    constants = scale_constants({n: own[n] for n in LEAP_CONSTANTS.by_name if n.startswith("commanded_")},
                                LEAP_CONSTANTS, pair, args.mode)
    constants["commanded_timing_scale"] = args.timing_scale
    constants.update({n: float(v) for n, v in (item.split("=") for item in args.const)})
    pairs = sorted((float(t), float(h)) for h, t in (p.split(":") for p in args.crouch_by_air_time.split(",")))
    factors = ScaleFactors(pair.length)
    scaled_pairs = [(scale(t, Units.parse("s"), factors), scale(h, Units.parse("m"), factors))
                    for t, h in zip(source["crouch_by_air_time"]["air_time"], source["crouch_by_air_time"]["crouch_height"])]
    x0, x1, y0, y1, t0, t1 = (float(v) for v in args.region.split(","))
    body = {"script": f"tools/scale_commanded.py --from {args.source} --to {args.target} --mode {args.mode} "
                      f"--timing-scale {args.timing_scale:g} (settings scaled by Fig. 6, L = {pair.length:.4f}); crouch "
                      f"pairs and region measured on the {args.target} (docs/jump_to_target.md)",
            "settings": {k: round(v, 6) for k, v in settings.items()},
            "crouch_by_air_time": {"air_time": [t for t, _ in pairs], "crouch_height": [h for _, h in pairs]},
            "region": {"target_x": [x0, x1], "target_y": [y0, y1], "air_time": [t0, t1]},
            "measured": args.measured}
    for key, value in (read("jump_commanded", args.target) or {}).items():
        body.setdefault(key, value)     # what was measured on the target (the hop's map, the other rows, their regions,
        #                                 the planner's constants) is kept; the options below replace what they name
    if args.turned_region:
        d0, d1, b0, b1, a0, a1 = (float(v) for v in args.turned_region.split(","))
        body["turned_region"] = {"distance": [d0, d1], "bearing": [b0, b1], "air_time": [a0, a1]}
    if args.planner:
        body["constants"] = {n: json.loads(v) for n, v in (item.split("=") for item in args.planner)}
    leap_body = read("leap", args.target)
    leap_body["constants"] = {**leap_body.get("constants", {}), **{k: round(v, 6) for k, v in constants.items()}}
    print(f"L = {pair.length:.4f}; the {args.source}'s crouch pairs scaled (s: m): "
          + ", ".join(f"{t:.3f}: {h:.3f}" for t, h in scaled_pairs))
    print(json.dumps({"jump_commanded": body, "leap constants": leap_body["constants"]}, indent=1))
    if args.write:
        print("wrote", save("jump_commanded", args.target, body, source["strengths"]))
        print("wrote", save("leap", args.target, leap_body, leap_body["strengths"]))


if __name__ == "__main__":
    main()
