"""Rewrite the parameter tables in docs/skills/*.md from the behaviour schemas (the single source):

    tools/readme_schemas.py

Each table sits between <!-- schema:NAME --> and <!-- /schema:NAME -->; tests/test_docs.py
fails when one is stale."""
import re
import sys
from pathlib import Path

ROOT = Path.cwd()                   # docs are written under the folder it runs in (the checkout)

from sim_core.cli import schema_markdown
from sim_core.skills import available_behaviours, behaviour_class


def main(argv=None) -> int:
    docs = sorted((ROOT / "docs" / "skills").glob("*.md"))
    texts = {path: path.read_text() for path in docs}
    for name in available_behaviours():
        block = f"<!-- schema:{name} -->\n{schema_markdown(behaviour_class(name))}\n<!-- /schema:{name} -->"
        pattern = re.compile(rf"<!-- schema:{name} -->\n(?:.*?\n)?<!-- /schema:{name} -->", re.S)
        found = [path for path, text in texts.items() if pattern.search(text)]
        for path in found:
            texts[path] = pattern.sub(lambda _: block, texts[path])
        if not found:
            print(f"docs/skills has no table for {name}; add '<!-- schema:{name} -->' and '<!-- /schema:{name} -->'")
    for path, text in texts.items():
        path.write_text(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
