"""Calibrated tables: one store (load/save with a schema version, rows checked against the skill's
settings schema), see store.py and docs/tables.md."""
from .store import (DIRECTORY, SCHEMA_VERSION, TableError, TableType, characters_of, delete, exists, keyed, load,
                    load_fresh, provisional, read, register, require_calibrated, save, table_path)

__all__ = ["DIRECTORY", "SCHEMA_VERSION", "TableError", "TableType", "characters_of", "delete", "exists", "keyed", "load",
           "load_fresh", "provisional", "read", "register", "require_calibrated", "save", "table_path"]
