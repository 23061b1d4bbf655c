"""Rewrite the parameter tables in README.md from the behaviour schemas (the single source):

    python scripts/readme_schemas.py

Each table sits between <!-- schema:NAME --> and <!-- /schema:NAME -->; tests/test_docs.py
fails when one is stale."""
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from sim_core.cli import schema_markdown                                    # noqa: E402
from sim_core.control.behaviour import available_behaviours, behaviour_class  # noqa: E402


def main() -> int:
    readme = ROOT / "README.md"
    text = readme.read_text()
    for name in available_behaviours():
        block = f"<!-- schema:{name} -->\n{schema_markdown(behaviour_class(name))}\n<!-- /schema:{name} -->"
        pattern = re.compile(rf"<!-- schema:{name} -->\n(?:.*?\n)?<!-- /schema:{name} -->", re.S)
        if pattern.search(text):
            text = pattern.sub(lambda _: block, text)
        else:
            print(f"README has no table for {name}; add '<!-- schema:{name} -->' and '<!-- /schema:{name} -->'")
    readme.write_text(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
