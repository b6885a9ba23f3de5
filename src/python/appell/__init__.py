"""appell: certified analytical mechanics from Python.

appell implements E. Cotton's 1907 paper on Appell's equations (the Gibbs-Appell equations from
the acceleration energy, and Cotton's reactions of added constraints) over any scalar type, and
in interval arithmetic gives *rigorous* bounds: on accelerations, on the force each constraint or
joint transmits, and on whether a contact holds (pushes, within friction, its centre of pressure
on its sole).  This module calls the C++ library directly (no subprocess); the scene files are
those of the ``appell`` command (SCENES.md), and so are the results, to the byte.

Scenes
------
``Scene.from_file(path)``, ``Scene.from_dict(d)``, ``Scene.from_urdf(path, base="fixed", ...)``
make a scene; ``scene.with_state(theta="0.3")`` and ``scene.with_parameter("top.A", "2")``
derive variants without writing files.  A str is a decimal as a file writes it ("0.1" is one
tenth); a float is the exact value of its double; an int is exact.

Results
-------
``scene.eval(scalar="interval", bits=None)`` returns an ``Evaluation``: ``ev.results["name"]``
is an ``Interval`` in the interval scalars (``interval``, ``mpfi``, ``arb``), a float in
``double``, an ``mpmath.mpf`` at the scalar's precision in ``long-double``, ``dd``,
``float128`` and ``mpfr``.  An ``Interval`` carries its bounds exactly (``lo_text``,
``hi_text``: the decimals appell prints, rounded outward) and as floats rounded outward
(``lo``, ``hi``), with ``contains`` (exact), ``width``, ``mid`` and ``to_mpmath``.

Reference values and scores
---------------------------
``reference(scene, states, ...)`` certifies the results at many states (a NumPy array, a
dict of columns or a pandas DataFrame) and returns a ``Reference`` of enclosures and the
tolerance a double-precision engine is held to; ``score(reference, values)`` scores another
implementation's values on it and returns a ``Score`` whose ``passed`` (and truth value) a
pytest assertion uses.

Motion
------
``simulate(scene, t_end)`` (point scalars), ``enclose(scene, t_end)`` (a rigorous enclosure of
the motion over [0, t_end], each contact judged over every step) and
``validity(scene, (field, lo, hi), t_end)`` return the runs' rows as NumPy columns and their
summaries as dicts.  They release the GIL, report progress through ``progress(fraction)``, and
stop cleanly on Ctrl-C: ``appell.Interrupted`` (a KeyboardInterrupt) carries the partial
result in ``.result``.

Errors
------
``InputError`` (a ValueError; the command's exit status 2), ``NotCertified`` (an
ArithmeticError; exit 3), ``InternalError`` (exit 4), all ``appell.Error``; their messages are
the one line the command prints.

See docs/python.md for a precision study in twenty lines and an engine test in pytest.
"""

from . import _core
from ._interval import Interval
from ._reference import Reference, Score, reference, score
from ._scene import SCALARS, Evaluation, Run, Scene, Validity, enclose, simulate, validity
from .errors import Error, InputError, InternalError, Interrupted, NotCertified


def built_scalars():
    """The scalars this build compiled (a build may leave some out: CMake's APPELL_SCALARS)."""
    return [name for name, built in _core._scalars() if built]


__all__ = [
    "Scene",
    "Evaluation",
    "Interval",
    "Run",
    "Validity",
    "Reference",
    "Score",
    "simulate",
    "enclose",
    "validity",
    "reference",
    "score",
    "built_scalars",
    "SCALARS",
    "Error",
    "InputError",
    "NotCertified",
    "InternalError",
    "Interrupted",
]
