"""Errors a user can cause, each with a message that names the bad value and what is allowed."""


class SimAthleticsError(Exception):
    """Base class: the CLI prints these as one line and exits non-zero."""


class RigFileError(SimAthleticsError):
    """A character spec or SD/FAST file is malformed."""


class ParameterError(SimAthleticsError):
    """A behaviour parameter is unknown, non-numeric, NaN or out of range."""


class UnknownNameError(SimAthleticsError):
    """An unknown behaviour, character or world."""


class ReplayMismatchError(SimAthleticsError):
    """A replayed run did not reproduce the recorded one."""


class Cancelled(SimAthleticsError):
    """The user cancelled a run, a search or a plan; nothing was written."""
