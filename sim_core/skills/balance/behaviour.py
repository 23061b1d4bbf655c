"""The balance skill (Wooten ch. 7): the balance basis controller of control/balance.py
(stand, knee bend, torso pitch, COM offset), offered as a skill."""
from ...control.balance import Balance
from ...control.behaviour import register

register(Balance)
