"""A refused write names its file.

A write or close that the operating system refuses (a full disk, a file size limit) raises an OSError that carries
no file name, and matplotlib's savefig passes it on as it is. gdnav's writers end such a run with one line naming the
file and the OS error (docs/runtime.md, "Exit codes"); `naming(path)` gives the report scripts the same line.
"""
import contextlib


@contextlib.contextmanager
def naming(path):
    """Re-raises an OSError raised inside the block without a file name as the same error naming PATH (a new
    OSError(errno, strerror, PATH): it keeps its name through a worker process's pickling)."""
    try:
        yield
    except OSError as e:
        if e.filename is not None:
            raise
        raise OSError(e.errno, e.strerror or str(e), path) from e
