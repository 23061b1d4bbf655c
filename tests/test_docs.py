"""The README's parameter tables are the schema's (the schema is the one source of the docs)."""
import re
from pathlib import Path

from sim_core.cli import schema_markdown
from sim_core.control.behaviour import available_behaviours, behaviour_class

README = Path(__file__).resolve().parents[1] / "README.md"


def test_readme_parameter_tables_match_the_schemas():
    text = README.read_text()
    for name in available_behaviours():
        match = re.search(rf"<!-- schema:{name} -->\n(.*?)\n<!-- /schema:{name} -->", text, re.S)
        assert match, f"README has no <!-- schema:{name} --> table"
        assert match.group(1).strip() == schema_markdown(behaviour_class(name)).strip(), \
            f"regenerate with: python3 -m sim_core describe {name} --markdown"
