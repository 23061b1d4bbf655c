"""A stand-in for a UI layout: records what a panel's draw() draws, checking that every
property and operator it names exists."""
from types import SimpleNamespace

import bpy


class Layout:
    """Records what a panel draws (and checks every property exists): ("prop", name, kind)."""

    def __init__(self, log):
        self.log = log

    def box(self):
        self.log.append(("box",))
        return self

    def row(self, **kw):
        return self

    def column(self, **kw):
        return self

    def prop(self, data, name, **kw):
        assert name in data.bl_rna.properties, f"{data} has no property {name!r}"
        self.log.append(("prop", name, data.bl_rna.properties[name].type))

    def operator(self, idname, **kw):
        module, name = idname.split(".")
        assert hasattr(getattr(bpy.ops, module), name), idname
        self.log.append(("operator", idname))

    def label(self, text="", **kw):
        self.log.append(("label", text))


def draw(panel_class, context):
    log = []
    panel_class.draw(SimpleNamespace(layout=Layout(log)), context)
    return log
