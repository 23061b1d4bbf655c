"""The balance skill (Wooten ch. 7): the balance basis controller of control/balance.py
(stand, knee bend, torso pitch, COM offset), offered as a skill."""
from sim_core.control.balance import Balance
from sim_core.control.behaviour import register

register(Balance)
