"""Writing a file whole or not at all: a temporary file beside it, then a rename, so that a
failed or cancelled write never leaves a half-written table, spec or trajectory."""
from __future__ import annotations

import os
import tempfile
from pathlib import Path
from typing import Callable


def write_atomically(path: str | Path, text: str | None = None, write: Callable[[str], None] | None = None) -> Path:
    """Write ``text`` to ``path`` (or let ``write(temporary_path)`` write it) through a temporary
    file in the same folder, renamed over ``path`` only once it is complete."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=path.stem, suffix=".tmp" + path.suffix)
    try:
        if write is None:
            with os.fdopen(fd, "w") as f:
                f.write(text)
        else:
            os.close(fd)
            write(tmp)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path
