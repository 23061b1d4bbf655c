"""The world a scene happens in: ``World`` (what a run asks for: ground, slope, props) and the prop
builders that add its geoms to an MjSpec (sim_core.world.props). The body knows the body, the
world knows the props: a skill *asks* for props through ``Behaviour.scene``, it never builds them."""
from .props import PROP_BUILDERS, add_attachments, add_world, prop_builder
from .apparatus import world_geom_mask
from . import hill  # noqa: F401  (registers the hill's builder)
from .world import World, gravity_for_slope

__all__ = ["World", "gravity_for_slope", "PROP_BUILDERS", "add_world", "add_attachments", "prop_builder",
           "world_geom_mask"]
