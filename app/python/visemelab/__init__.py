"""VisemeLab's core for Python: viseme and avatar reduction, speech, batches.

Every function takes and returns bytes, numpy arrays and plain dicts; bad input raises
visemelab.InputError (a ValueError) whose .culprit names the file and element at fault.
Long calls release the GIL, so threads (and Dask workers) run them in parallel.
See docs/batch.md ("Python API").
"""

from ._core import (  # noqa: F401 (the package's API)
    InputError,
    VisemeSet,
    __version__,
    load_visemes,
    reduce_avatar,
    reduce_visemes,
    run_jobs,
    say,
)
