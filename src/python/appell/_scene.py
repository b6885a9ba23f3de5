"""Scene, Evaluation, and the motion calls (simulate, enclose, validity)."""

import json
import math
import os

import numpy as np

from . import _core
from ._interval import Interval
from .errors import InputError, Interrupted

SCALARS = ("double", "long-double", "dd", "float128", "mpfr", "interval", "mpfi", "arb")


def _exact_json(value, where="scene"):
    """A dict/list of a scene with every float replaced by the exact decimal of its double."""
    if isinstance(value, bool) or value is None or isinstance(value, (str, int)):
        return value
    if isinstance(value, float):
        if not math.isfinite(value):
            raise InputError(f"{where}: {value!r} is not a number of a scene")
        return _core._exact_decimal(value)
    if isinstance(value, dict):
        return {str(k): _exact_json(v, f"{where}.{k}") for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_exact_json(v, f"{where}[{i}]") for i, v in enumerate(value)]
    if isinstance(value, np.generic):
        return _exact_json(value.item(), where)
    try:
        import decimal

        if isinstance(value, decimal.Decimal):
            return str(value)
    except ImportError:  # pragma: no cover
        pass
    raise InputError(f"{where}: a {type(value).__name__} is not a value of a scene (str, int, float, list, dict)")


def _number(t, scalar, bits):
    """A printed number (is_interval, lo_text, hi_text, lo, hi) as Python gives it."""
    is_interval, lo_text, hi_text, lo, hi = t
    if is_interval:
        return Interval(lo_text, hi_text, lo, hi)
    if scalar == "double" or bits <= 53:
        return lo
    import mpmath

    with mpmath.workprec(bits):
        return mpmath.mpf(lo_text)


class Evaluation:
    """A scene's results in one scalar, as ``appell eval`` prints them.

    ``results``, ``checks`` and ``derived`` are dicts from a result's name to its value: an
    ``Interval`` in the interval scalars (interval, mpfi, arb), a float in double, an
    ``mpmath.mpf`` at the scalar's precision in the others; a vector result (a force) is a list
    of three.  ``contacts`` maps each contact to its verdict (``holds``, ``fails``,
    ``undecided``), its mu, the friction it requires and a sole's centre of pressure.
    ``scalar``, ``bits`` and ``rigorous`` say what computed them.  ``json()`` and ``text()``
    are the documents of ``appell eval`` (``--format json`` / ``text``), byte for byte.
    ``names()`` and ``bounds()`` give every result component at once (NumPy).
    """

    def __init__(self, core):
        self._e = core
        self._d = None

    def _data(self):
        if self._d is None:
            d = self._e.as_dict()
            scalar, bits = d["scalar"], d["bits"]

            def group(items):
                out = {}
                for name, is_vector, values in items:
                    vs = [_number(v, scalar, bits) for v in values]
                    out[name] = vs if is_vector else vs[0]
                return out

            contacts = {}
            for c in d["contacts"]:
                contacts[c["name"]] = {
                    "verdict": c["verdict"],
                    "mu": c["mu"],
                    "required_mu": None if c["required_mu"] is None else _number(c["required_mu"], scalar, bits),
                    "center_of_pressure": None
                    if c["center_of_pressure"] is None
                    else tuple(_number(x, scalar, bits) for x in c["center_of_pressure"]),
                }
            d["results_py"] = group(d["results"])
            d["checks_py"] = group(d["checks"])
            d["derived_py"] = group(d["derived"])
            d["contacts_py"] = contacts
            self._d = d
        return self._d

    model = property(lambda self: self._data()["model"], doc="The scene's model.")
    scalar = property(lambda self: self._data()["scalar"], doc="The scalar it was computed in.")
    bits = property(lambda self: self._data()["bits"], doc="The scalar's precision in bits.")
    rigorous = property(lambda self: self._data()["rigorous"], doc="Whether the values are proved enclosures.")
    results = property(lambda self: self._data()["results_py"], doc="Result name -> value (or list of 3).")
    checks = property(lambda self: self._data()["checks_py"], doc="Check name -> value (0 in truth).")
    derived = property(lambda self: self._data()["derived_py"], doc="The state the inputs imply.")
    contacts = property(lambda self: self._data()["contacts_py"], doc="Contact name -> its verdict.")

    def __getitem__(self, name):
        """The result called ``name`` (``ev["pivot_force"]``)."""
        try:
            return self.results[name]
        except KeyError:
            raise KeyError(f"no result named {name!r}; the results are {', '.join(self.results)}") from None

    def names(self):
        """Every result component's name: ``name`` for a scalar, ``name[i]`` for a vector's entries."""
        out = []
        for name, is_vector, values in self._data()["results"]:
            out += [f"{name}[{i}]" for i in range(len(values))] if is_vector else [name]
        return out

    def bounds(self):
        """An (n, 2) float array of every result component's bounds, in the order of names():
        rounded outward for an interval scalar; a point value's nearest float twice otherwise."""
        return self._e.result_bounds()

    def json(self):
        """The document ``appell eval --format json`` prints."""
        return self._e.json()

    def text(self):
        """The document ``appell eval --format text`` prints."""
        return self._e.text()

    def __repr__(self):
        return f"<appell.Evaluation of {self.model} in {self.scalar} ({self.bits} bits): {len(self.results)} results>"


class Scene:
    """A scene (SCENES.md): a model and its inputs, read and validated once.

    Make one with ``Scene.from_file(path)``, ``Scene.from_dict(d)`` or ``Scene.from_urdf(path,
    ...)``; derive variants with ``with_state(...)`` and ``with_parameter(...)`` (no file is
    written).  Numbers: a str is a decimal as a scene file writes it ("0.1" is one tenth), an
    int is exact, a float is the exact value of its double (0.1 is 0.1000000000000000055...):
    the number an engine given that float computes with.  Bad input raises ``InputError``
    naming the field, as ``appell eval`` exits 2.
    """

    def __init__(self, core):
        self._s = core

    # -- making scenes
    @classmethod
    def from_file(cls, path):
        """The scene in the JSON file ``path`` (paths in it relative to its directory)."""
        return cls(_core._scene_from_file(os.fspath(path)))

    @classmethod
    def from_dict(cls, scene, directory="."):
        """The scene given as a dict (the JSON of a scene file); paths in it (a URDF's ``file``,
        a table's ``csv``) are relative to ``directory``."""
        if not isinstance(scene, dict):
            raise InputError(f"a scene is a dict, not a {type(scene).__name__}")
        text = json.dumps(_exact_json(scene))
        return cls(_core._scene_from_text(text, os.fspath(directory), "<dict>"))

    @classmethod
    def from_json(cls, text, directory="."):
        """The scene in JSON text (a scene file's contents)."""
        return cls(_core._scene_from_text(text, os.fspath(directory), "<json>"))

    @classmethod
    def from_urdf(cls, path, base="fixed", **fields):
        """A ``urdf`` scene of the robot in ``path``: ``base`` "fixed" or "floating", and the
        scene's other fields as keywords (``state={"j1": {"q": "0.3", "q_dot": "0"}}``,
        ``torques={...}``, ``gravity=[...]``, ``contacts=...``; SCENES.md, "urdf")."""
        scene = {"model": "urdf", "file": os.path.abspath(os.fspath(path)), "base": base}
        scene.update(fields)
        return cls.from_dict(scene)

    # -- what it is
    @property
    def model(self):
        """The scene's model (``euler_body``, ``heavy_top``, ``system``, ``urdf``, ...)."""
        return self._s.model

    @property
    def name(self):
        """The file it was read from, or ``<dict>``."""
        return self._s.name

    def to_dict(self):
        """The scene as a dict (numbers as their decimal text where the file wrote strings)."""
        return json.loads(self._s.json())

    def state_fields(self):
        """The scene fields of the model's motion state, in the order of the state."""
        return list(self._s.state_fields())

    def __repr__(self):
        return f"<appell.Scene {self.model} from {self.name}>"

    # -- variants
    def with_state(self, fields=None, /, **more):
        """A copy with state values replaced: ``with_state(theta="0.3", psi_dot=1.5)`` or
        ``with_state({"omega[1]": 2})``.  A plain name is a key of the scene's "state" (with
        ``[i]`` for a list entry); a dotted name is a path from the scene's root."""
        d = dict(fields or {})
        d.update(more)
        return Scene(self._s.with_fields(d, True))

    def with_parameter(self, path=None, value=None, /, **more):
        """A copy with numbers of the scene replaced by their path from the root:
        ``with_parameter("top.A", "1.5")``, ``with_parameter({"gravity[2]": "-9.80665",
        "parameters.m": 2})``, or a top-level number as a keyword (``with_parameter(mu="0.4")``).
        Each path names one number (``[i]`` for a list's entry)."""
        d = {}
        if isinstance(path, dict):
            d.update(path)
        elif path is not None:
            d[path] = value
        d.update(more)
        return Scene(self._s.with_fields(d, False))

    # -- results
    def eval(self, scalar="interval", bits=None, checks=True):
        """The results and checks in ``scalar`` (``appell eval --scalar``): one of
        ``appell.SCALARS``; ``bits`` for mpfr, mpfi and arb (default 256).  ``checks=False``
        leaves out the identities only the checks need (faster; the results are the same)."""
        return Evaluation(self._s.eval(scalar, bits, checks))

    def simulate(self, t_end, **options):
        """``appell.simulate(self, t_end, ...)``."""
        return simulate(self, t_end, **options)

    def enclose(self, t_end, **options):
        """``appell.enclose(self, t_end, ...)``."""
        return enclose(self, t_end, **options)

    def validity(self, vary, t_end, **options):
        """``appell.validity(self, vary, t_end, ...)``."""
        return validity(self, vary, t_end, **options)


class Run:
    """What simulate or enclose computed: ``summary`` (the dict of summary.json), and the
    tables as NumPy columns.

    ``table(name)`` is a dict from column name to a float array (a column of strings, a
    verdict, stays a list); ``columns(name)`` its columns in order; ``text(name)`` the exact
    decimals as the run wrote them.  Tables: ``trajectory`` (simulate), ``steps`` and
    ``contacts`` (enclose).  In the steps of enclose, a column ``x_lo`` is rounded down and
    ``x_hi`` up, ``t0`` down and ``t1`` up: every row stays an enclosure.  ``complete`` says
    whether the run reached its end (``summary["reason"]`` or ``["failure"]`` says why not).
    """

    def __init__(self, summary, tables, interrupted):
        self.summary = summary
        self._tables = tables
        self.interrupted = bool(interrupted)

    @property
    def complete(self):
        """Whether the run reached t_end."""
        if "complete" in self.summary:
            return bool(self.summary["complete"])
        return not self.summary.get("failure")

    @property
    def tables(self):
        """The names of the tables the run wrote."""
        return list(self._tables)

    def table(self, name=None):
        """A table as {column: array}; the run's first table by default."""
        if name is None:
            if not self._tables:
                return {}
            name = next(iter(self._tables))
        if name not in self._tables:
            raise KeyError(f"no table {name!r}; the run wrote {', '.join(self._tables) or 'none'}")
        return self._tables[name]["values"]

    def columns(self, name=None):
        """The column names of a table, in order."""
        name = name or next(iter(self._tables))
        return list(self._tables[name]["columns"])

    def text(self, name=None):
        """A table's cells as the exact decimals the run wrote, {column: list of str}."""
        name = name or next(iter(self._tables))
        return self._tables[name]["text"]

    def array(self, name=None):
        """A table's numeric columns as one (rows, columns) float array, and their names."""
        t = self.table(name)
        names = [c for c, v in t.items() if isinstance(v, np.ndarray)]
        if not names:
            return np.empty((0, 0)), names
        return np.column_stack([t[c] for c in names]), names

    def __repr__(self):
        state = "complete" if self.complete else "incomplete"
        return f"<appell.Run {self.summary.get('command', '')} of {self.summary.get('model', '')}: {state}, tables {self.tables}>"


class Validity:
    """What validity found: ``summary`` (summary.json's dict: ``ranges`` per verdict, ...) and
    ``pieces``, a dict of arrays per piece (``lo``, ``hi`` rounded outward, ``verdict``,
    ``holds_until``, ``why``, ``steps``, ``seconds``, and the exact ``lo_text``/``hi_text``)."""

    def __init__(self, summary, pieces, interrupted):
        self.summary = summary
        self.pieces = pieces
        self.interrupted = bool(interrupted)

    @property
    def complete(self):
        return bool(self.summary.get("complete"))

    def ranges(self, verdict="holds"):
        """The ranges (lo, hi) where every piece's verdict is ``verdict`` (decimal text)."""
        return [tuple(r) for r in self.summary["ranges"].get(verdict, [])]

    def __repr__(self):
        return f"<appell.Validity of {self.summary.get('field')}: {len(self.pieces['verdict'])} pieces>"


def _scene_of(scene):
    if isinstance(scene, Scene):
        return scene
    if isinstance(scene, dict):
        return Scene.from_dict(scene)
    if isinstance(scene, (str, os.PathLike)):
        return Scene.from_file(scene)
    raise InputError(f"a scene is an appell.Scene, a dict or a path, not a {type(scene).__name__}")


def _finish(result, what):
    if result.interrupted:
        raise Interrupted(f"appell.{what} interrupted: .result holds what it computed", result)
    return result


def simulate(scene, t_end, *, scalar="double", bits=None, every=None, order=None, tol=None, max_seconds=None,
             progress=None):
    """The motion from t = 0 to ``t_end`` in a point scalar (``appell simulate``): Taylor steps
    with error control, rows every ``every`` (default t_end / 100).  Returns a ``Run`` whose
    ``trajectory`` table holds t, the state, the results and the invariants.

    ``progress(fraction)`` is called as the run goes (at most 20 times a second); the run
    releases the GIL; Ctrl-C stops it cleanly (within 20 ms) and raises ``appell.Interrupted``
    whose ``result`` is the Run up to there.  A run that cannot go on (a step collapse, a state no
    longer finite, ``max_seconds``) returns incomplete (``run.complete`` False)."""
    options = dict(scalar=scalar, bits=bits, t_end=t_end, every=every, order=order, tol=tol, max_seconds=max_seconds)
    s = _scene_of(scene)
    return _finish(Run(*s._s.simulate(options, progress)), "simulate")


def enclose(scene, t_end, *, scalar="interval", bits=None, order=None, tol=None, max_width=1.0, max_seconds=None,
            locate=None, mu=None, until_contact_fails=False, progress=None):
    """A rigorous enclosure of the motion over [0, t_end] (``appell enclose``): every true
    state, result and invariant lies in its step's bounds.  Returns a ``Run`` with the tables
    ``steps`` (per step [t0, t1]: the state at t1 and over the step, the results and
    invariants over the step, as ``*_lo``/``*_hi`` columns) and, with contacts, ``contacts``
    (each contact's verdict per step).  ``summary["contacts"]`` holds each contact's verdict
    over the run and, with ``locate=width``, its first failure narrowed to that width.

    Progress, the GIL and Ctrl-C as in ``simulate``."""
    options = dict(scalar=scalar, bits=bits, t_end=t_end, order=order, tol=tol, max_width=max_width,
                   max_seconds=max_seconds, locate=locate, mu=mu, until_contact_fails=until_contact_fails)
    s = _scene_of(scene)
    return _finish(Run(*s._s.enclose(options, progress)), "enclose")


def validity(scene, vary, t_end, *, scalar="interval", bits=None, resolution=None, mu=None, order=None, tol=None,
             max_width=1.0, max_seconds=None, jobs=0, progress=None):
    """The range ``vary = (field, lo, hi)`` of one field (a state component, a model
    parameter, a joint's torque given as a number as "torques.JOINT", a sole's half-length as
    "contacts.NAME.sole.half_lengths[0]" or "[1]", a table's K-th value as "tables.NAME.value[K]",
    or "mu") split into pieces until each is proved to keep every contact over
    [0, t_end] ("holds"), proved to lose one ("fails"), or is narrower than ``resolution``
    (``appell validity``).  ``jobs`` threads run the pieces.  Returns a ``Validity``."""
    if not (isinstance(vary, (tuple, list)) and len(vary) == 3):
        raise InputError("vary: expected (field, lo, hi)")
    options = dict(scalar=scalar, bits=bits, t_end=t_end, vary=tuple(vary), resolution=resolution, mu=mu,
                   order=order, tol=tol, max_width=max_width, max_seconds=max_seconds, jobs=jobs)
    s = _scene_of(scene)
    return _finish(Validity(*s._s.validity(options, progress)), "validity")
