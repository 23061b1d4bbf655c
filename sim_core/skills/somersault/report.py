"""The somersault's report is the tumbling report (dives, standing somersaults and the back handspring
together, docs/tumbling.md): ``python -m sim_core report somersault`` runs it."""
from ..dive.report import main

__all__ = ["main"]
