"""The skills' parameter tables in docs/skills/ are the schema's (the schema is the one source of
the docs); the README stays an entry point."""
import re
from pathlib import Path

from sim_core.cli import schema_markdown
from sim_core.skills import available_behaviours, behaviour_class

ROOT = Path(__file__).resolve().parents[1]
SKILL_DOCS = ROOT / "docs" / "skills"


def test_skill_docs_parameter_tables_match_the_schemas():
    text = "\n".join(p.read_text() for p in sorted(SKILL_DOCS.glob("*.md")))
    for name in available_behaviours():
        match = re.search(rf"<!-- schema:{name} -->\n(.*?)\n<!-- /schema:{name} -->", text, re.S)
        assert match, f"docs/skills has no <!-- schema:{name} --> table"
        assert match.group(1).strip() == schema_markdown(behaviour_class(name)).strip(), \
            f"regenerate with: tools/readme_schemas.py"


def test_readme_is_an_entry_point():
    assert len((ROOT / "README.md").read_text().splitlines()) <= 250
