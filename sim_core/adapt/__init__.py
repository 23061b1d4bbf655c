"""Adapting controllers to new characters (Hodgins & Pollard 1997): the Fig. 6 scaling rules
(scaling.py), the bodies each joint's gain moves (moved_bodies.py), the scaling of a spec's servos
(servos.py) and of a skill's settings (settings.py), and the seed's Fig. 5/8 experiment
(experiment.py: unscaled, geometric and mass-scaled controllers on bodies from the man to the woman)."""
