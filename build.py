"""Build generated assets: the character specs in rigs/ (and, later, rigged skins and the add-on zip).

    python build.py rigs      # regenerate rigs/man.json and rigs/woman.json from rigs/sdfast/*.sd
"""
from __future__ import annotations

import argparse
import json
import os
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent
sys.path.insert(0, str(ROOT))

THESIS_CHARACTERS = {
    "man": "Wooten 1998, Appendix A.1 (SD/FAST file), Tables 3.1 and 3.3",
    "woman": "Wooten 1998, Appendix A.2 (SD/FAST file), Tables 3.2 and 3.4",
}


def write_atomically(path: Path, text: str) -> None:
    tmp = path.with_suffix(path.suffix + ".tmp")
    tmp.write_text(text)
    os.replace(tmp, path)


def build_rigs() -> None:
    from sim_core.character.spec import CharacterSpec, build_spec_from_sdfast
    for name, source in THESIS_CHARACTERS.items():
        data = build_spec_from_sdfast(name, ROOT / "rigs" / "sdfast" / f"{name}.sd", source)
        CharacterSpec(data, name)              # validate before writing
        write_atomically(ROOT / "rigs" / f"{name}.json", json.dumps(data, indent=1) + "\n")
        print(f"wrote rigs/{name}.json ({len(data['bodies'])} bodies, {data['total_mass']:.2f} kg)")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("target", nargs="?", default="all", choices=["rigs", "all"])
    args = parser.parse_args(argv)
    if args.target in ("rigs", "all"):
        build_rigs()
    return 0


if __name__ == "__main__":
    sys.exit(main())
