"""Adapting controllers to new characters (Hodgins & Pollard 1997): the Fig. 6 scaling rules
(scaling.py), the bodies each joint's gain moves (moved_bodies.py) and the mass scaling of a
spec's servos (servos.py)."""
