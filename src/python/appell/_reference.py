"""reference and score: certified values at many states, and another implementation scored on them."""

import math
from fractions import Fraction

import numpy as np

from . import _core
from ._interval import Interval
from ._scene import _scene_of
from .errors import InputError, Interrupted


class Reference:
    """Certified values of a scene's results at many states (``appell reference``).

    ``quantities`` names each quantity (a result's component, ``pivot_force[0]``; a derived
    value as ``derived.NAME``); ``states`` names each state; ``certified`` says per state
    whether it was certified (``reasons`` says why not: refused input, or no certificate);
    ``inputs`` holds per state the exact decimal each of ``fields`` was given.
    Per state and quantity, (states, quantities) float arrays: ``lower`` (rounded down),
    ``upper`` (rounded up), ``double`` (the double nearest the true value, where ``decided``),
    ``tolerance`` (what a double-precision engine is held to); NaN for a refused state.
    ``interval(i, q)`` is the exact enclosure as an ``Interval``; ``ref[q]`` a quantity's
    columns as a dict.
    """

    def __init__(self, core):
        self._r = core
        self.fields = list(core.fields)
        self.quantities = list(core.quantities)
        self.states = list(core.states)
        self.reasons = list(core.reasons)
        self.inputs = list(core.inputs)  # per state, the decimal given to each field
        self.certified = core.certified
        self.scalar = core.scalar
        self.bits = core.bits
        self.seconds = core.seconds
        self.interrupted = core.interrupted
        self._columns = {}

    def _column(self, what):
        if what not in self._columns:
            self._columns[what] = self._r.column(what)
        return self._columns[what]

    lower = property(lambda self: self._column("lower"), doc="Lower bounds, rounded down (states x quantities).")
    upper = property(lambda self: self._column("upper"), doc="Upper bounds, rounded up.")
    double = property(lambda self: self._column("double"), doc="The double nearest each enclosure.")
    tolerance = property(lambda self: self._column("tolerance"), doc="The tolerance of a double-precision engine.")
    rel_error_bound = property(lambda self: self._column("rel_error_bound"), doc="``double``'s relative error bound.")

    @property
    def amplification(self):
        """Per state, how much the problem amplifies rounding errors (io/amplification.hpp)."""
        return self._r.amplification()

    def index(self, quantity):
        """The column of a quantity, by name or index."""
        if isinstance(quantity, (int, np.integer)):
            return int(quantity)
        try:
            return self.quantities.index(quantity)
        except ValueError:
            raise KeyError(f"no quantity {quantity!r}; the quantities are {', '.join(self.quantities)}") from None

    def interval(self, state, quantity):
        """The certified enclosure of a quantity at a state, exactly (None where refused)."""
        lo, hi, _, _, _ = self._r.exact(int(state), self.index(quantity))
        return None if lo is None else Interval(lo, hi)

    def exact(self, state, quantity):
        """(lower, upper, double, tolerance, decided) as the text the dataset writes."""
        return self._r.exact(int(state), self.index(quantity))

    def __getitem__(self, quantity):
        j = self.index(quantity)
        return {k: getattr(self, k)[:, j] for k in ("lower", "upper", "double", "tolerance")}

    def __len__(self):
        return len(self.states)

    def __repr__(self):
        n = int(np.count_nonzero(self.certified))
        return f"<appell.Reference: {n}/{len(self.states)} states certified in {self.scalar}, {len(self.quantities)} quantities>"


def _states_table(states, fields, names):
    """(fields, values, names): values a 2-D float array or a list of rows of decimal text."""
    try:
        import pandas as pd
    except ImportError:  # pandas is optional
        pd = None
    if pd is not None and isinstance(states, pd.DataFrame):
        df = states
        if names is None and "state" in df.columns:
            names = [str(x) for x in df["state"]]
        cols = [c for c in df.columns if c != "state"] if fields is None else list(fields)
        states = {c: df[c].to_numpy() for c in cols}
        fields = cols
    if isinstance(states, dict):
        fields = list(states) if fields is None else list(fields)
        columns = [np.asarray(states[f]) for f in fields]
        if len({len(c) for c in columns}) > 1:
            raise InputError("states: the columns have different lengths")
        if columns and all(_is_double_dtype(c.dtype) for c in columns):
            return fields, np.column_stack(columns).astype(float), names
        rows = [[_text(c[i], f) for c, f in zip(columns, fields)] for i in range(len(columns[0]) if columns else 0)]
        return fields, rows, names
    if fields is None:
        raise InputError("states: an array needs fields=[...] naming its columns (or give a DataFrame or a dict)")
    fields = list(fields)
    a = np.asarray(states)
    if a.ndim == 1:
        a = a.reshape(-1, 1) if len(fields) == 1 else a.reshape(1, -1)
    if a.ndim != 2 or a.shape[1] != len(fields):
        raise InputError(f"states: expected a (states, {len(fields)}) array for the fields {fields}, got shape {a.shape}")
    if _is_double_dtype(a.dtype):
        return fields, a.astype(float), names
    if a.dtype.kind in "iu":
        return fields, [[str(int(x)) for x in row] for row in a], names
    return fields, [[_text(x, f) for x, f in zip(row, fields)] for row in a], names


def _is_double_dtype(dtype):
    """float64, or a narrower float every value of which is a double exactly."""
    return dtype.kind == "f" and dtype.itemsize <= 8


def _text(x, field):
    """A state's value as the decimal text certified: a str as written, an int exactly, a double
    exactly; a number that is no double (a long double, a Fraction) refused, never rounded."""
    import decimal

    if isinstance(x, str):
        return x
    if isinstance(x, (bool, np.bool_)):
        raise InputError(f"{field}: a bool is not a number")
    if isinstance(x, (int, np.integer)):
        return str(int(x))
    if isinstance(x, decimal.Decimal):
        return str(x)
    if isinstance(x, (float, np.floating)):
        f = float(x)
        if isinstance(x, np.floating) and x.dtype.itemsize > 8 and np.longdouble(f) != x:
            raise InputError(f"{field}: {x!r} is not a double; give it as a str (a decimal)")
        return _core._exact_decimal(f)
    raise InputError(f"{field}: a {type(x).__name__} is not a value of a state (str, int, float, Decimal)")


def reference(scene, states, *, fields=None, names=None, scalar="interval", bits=None, inputs="decimal",
              progress=None):
    """Certified values of the scene's results at each state (``appell reference``).

    ``states``: a pandas DataFrame (its columns the fields; a column ``state`` names the rows),
    a dict {field: column}, or a 2-D array with ``fields=[...]``.  A field is a key of the
    scene's "state" (``theta``, ``omega[1]``) or a dotted path from its root (``top.A``).
    A float is its double exactly; a str a decimal.  ``scalar``: interval, mpfi or arb
    (``bits``, default 256).  ``inputs="binary64"`` replaces every decimal of the scene and the
    states by the double nearest to it (an engine's view of the same numbers).  A state the
    scene refuses, or that cannot be certified, is kept with its reason (``certified`` False).

    Runs without the GIL at the command's throughput; ``progress(fraction)`` and Ctrl-C as in
    ``simulate`` (``Interrupted.result`` holds the states certified so far)."""
    s = _scene_of(scene)
    if inputs not in ("decimal", "binary64"):
        raise InputError(f"inputs: expected decimal or binary64, got {inputs!r}")
    fields, values, names = _states_table(states, fields, names)
    n = values.shape[0] if isinstance(values, np.ndarray) else len(values)
    names = [str(i + 1) for i in range(n)] if names is None else [str(x) for x in names]
    if len(names) != n:
        raise InputError(f"names: {len(names)} names for {n} states")
    if isinstance(values, np.ndarray):
        core = _core._reference_array(s._s, fields, values, names, scalar, bits, inputs == "binary64", progress)
    else:
        core = _core._reference(s._s, fields, values, names, scalar, bits, inputs == "binary64", progress)
    r = Reference(core)
    if r.interrupted:
        raise Interrupted("appell.reference interrupted: .result holds the states certified so far", r)
    return r


class Score:
    """Another implementation's values scored against a Reference (``appell score``).

    ``passed``: every value within its tolerance (and, with ``min_digits``, every quantity's
    median digits at least that), none missing.  ``quantities``: per quantity a dict with
    ``n``, ``inside`` (values inside the enclosure), ``within`` (within tolerance),
    ``min_digits``, ``median_digits``, ``worst_state``; ``digits[q]`` the correct digits of each
    value (-log10 of its relative error bound; absolute where the enclosure holds 0).
    ``missing`` lists quantities of the reference that were not given.  ``bool(score)`` is
    ``passed``, so ``assert appell.score(ref, values)`` reads as it should; ``report()`` is the
    table ``appell score`` prints."""

    def __init__(self, quantities, digits, missing, passed, min_digits):
        self.quantities = quantities
        self.digits = digits
        self.missing = missing
        self.passed = passed
        self.min_digits = min_digits

    def __bool__(self):
        return self.passed

    def failures(self):
        """The quantities with a value outside its tolerance (or short of min_digits)."""
        out = [q for q, s in self.quantities.items() if s["within"] < s["n"]]
        if self.min_digits is not None:
            out += [q for q, s in self.quantities.items() if s["median_digits"] < self.min_digits and q not in out]
        return out + self.missing

    def report(self):
        """The table ``appell score`` prints (without its first line, which names files), and its verdict."""
        fmt = lambda d: "exact" if math.isinf(d) else f"{d:.1f}"
        lines = [f"{'quantity':<24}{'values':>8}{'inside':>9}{'within tol.':>13}{'min digits':>12}{'median digits':>15}"
                 "  worst state"]
        for q, s in self.quantities.items():
            outside = f" (outside tolerance: worst {s['worst_tolerance_state']})" if s["within"] < s["n"] else ""
            lines.append(f"{q:<24}{s['n']:>8}{s['inside']:>9}{s['within']:>13}{fmt(s['min_digits']):>12}"
                         f"{fmt(s['median_digits']):>15}  {s['worst_state']}{outside}")
        if self.missing:
            lines += ["", f"FAILED: {len(self.missing)} quantities of the reference are not given: "
                      f"{', '.join(self.missing)} (skip=[NAME, ...] leaves a quantity out)"]
        within = not self.missing and all(s["within"] == s["n"] for s in self.quantities.values())
        verdict = ("not every value of the reference was given" if self.missing
                   else "every value within the suggested tolerance" if within
                   else "values outside the suggested tolerance")
        if self.min_digits is not None:
            enough = all(s["median_digits"] >= self.min_digits for s in self.quantities.values())
            verdict += (f"; {'every quantity has' if enough else 'not every quantity has'} a median of at least "
                        f"{self.min_digits:g} correct digits")
        return "\n".join(lines + ["", verdict])

    def __repr__(self):
        return f"<appell.Score: {'passed' if self.passed else 'failed'}, {len(self.quantities)} quantities>"


def _values_matrix(reference, values, skip):
    """The values as {quantity index: column} for the quantities given."""
    n = len(reference.states)
    try:
        import pandas as pd
    except ImportError:
        pd = None
    if pd is not None and isinstance(values, pd.DataFrame):
        df = values
        if "state" in df.columns:  # rows matched to the reference's states by name
            names = [str(x) for x in df["state"]]
            where = {name: i for i, name in enumerate(names)}
            if len(where) != len(names):
                raise InputError("values: a state named twice in the column 'state'")
            unknown = [x for x in names if x not in set(reference.states)]
            if unknown:
                raise InputError(f"values: no state {unknown[0]!r} in the reference")
            missing = [x for x in reference.states if x not in where]
            if missing:
                raise InputError(f"values: no row for the state {missing[0]!r} of the reference")
            df = df.iloc[[where[x] for x in reference.states]]
        values = {c: df[c].to_numpy() for c in df.columns if c != "state"}
    if isinstance(values, dict):
        out = {}
        for name, col in values.items():
            col = _doubles(col, f"values[{name!r}]")
            if col.shape != (n,):
                raise InputError(f"values[{name!r}]: expected {n} values, got shape {col.shape}")
            if name not in reference.quantities:
                raise InputError(f"values: no quantity {name!r} in the reference")
            out[reference.quantities.index(name)] = col
        return out
    a = _doubles(values, "values")
    if a.shape != (n, len(reference.quantities)):
        raise InputError(f"values: expected a ({n}, {len(reference.quantities)}) array in the order of "
                         f"reference.quantities, got shape {a.shape}")
    return {j: a[:, j] for j in range(a.shape[1])}


def _doubles(values, what):
    """Another implementation's values as float64, refused (never rounded) where they are not
    doubles: a long double, a decimal str, an object array."""
    a = np.asarray(values)
    if _is_double_dtype(a.dtype):
        return a.astype(float)
    if a.dtype.kind in "iu" and (a.size == 0 or np.abs(a).max() <= 2**53):
        return a.astype(float)
    raise InputError(f"{what}: expected doubles (an implementation's float64 results), got {a.dtype}; "
                     "a value that is no double has no certified score")


def _matches(pattern, name):
    import fnmatch

    return fnmatch.fnmatchcase(name, pattern.replace("[", "[[]"))


def score(reference, values, *, min_digits=None, skip=()):
    """Scores ``values`` (another implementation's results at the reference's states: a
    (states, quantities) array in the order of ``reference.quantities``, or a dict / DataFrame
    {quantity: column}) against the certified ``reference``.  ``skip`` leaves quantities out
    (names or patterns with ``*``).  Refused states are not scored.  Returns a ``Score``.

    Comparisons are exact: a value is the double it is, the bounds the decimals certified."""
    if not isinstance(reference, Reference):
        raise InputError("score: the first argument is an appell.Reference (from appell.reference)")
    for p in skip:
        if not any(_matches(p, q) for q in reference.quantities):
            raise InputError(f"skip: {p!r} matches no quantity of the reference")
    given = _values_matrix(reference, values, skip)
    scored = [j for j, q in enumerate(reference.quantities) if not any(_matches(p, q) for p in skip)]
    missing = [reference.quantities[j] for j in scored if j not in given]
    ok = np.asarray(reference.certified, dtype=bool)
    lo_all, hi_all, tol_all = reference.lower, reference.upper, reference.tolerance
    quantities, digits_of = {}, {}
    if not [j for j in scored if j in given]:
        raise InputError("score: no quantity scored (every quantity skipped or not given): a score must not pass on nothing")
    passed = not missing and bool(ok.any())
    for j in scored:
        if j not in given:
            continue
        name = reference.quantities[j]
        x = given[j][ok]
        lo, hi, tol = lo_all[ok, j], hi_all[ok, j], tol_all[ok, j]
        states = [s for s, c in zip(reference.states, ok) if c]
        rows = np.flatnonzero(ok)
        if not np.all(np.isfinite(x)):
            bad = states[int(np.flatnonzero(~np.isfinite(x))[0])]
            raise InputError(f"values[{name!r}]: not a finite number at state {bad}")
        # inside for certain where x >= the double above lo's float, and <= the one below hi's
        surely_inside = (x >= np.nextafter(lo, np.inf)) & (x <= np.nextafter(hi, -np.inf))
        worst_excess, worst_tolerance_state = 0.0, ""
        inside = surely_inside.copy()
        within = surely_inside.copy()
        for k in np.flatnonzero(~surely_inside):
            lo_t, hi_t, _, tol_t, _ = reference.exact(int(rows[k]), j)
            xe, lo_e, hi_e = Fraction(float(x[k])), Fraction(lo_t), Fraction(hi_t)
            if lo_e <= xe <= hi_e:
                inside[k] = within[k] = True
            else:
                dist = min(abs(xe - lo_e), abs(xe - hi_e))
                within[k] = tol_t == "inf" or dist <= Fraction(tol_t)
                if not within[k]:
                    excess = math.inf if Fraction(tol_t) == 0 else float(dist / Fraction(tol_t))
                    if excess > worst_excess:
                        worst_excess, worst_tolerance_state = excess, states[k]
        # |x - exact| <= max(|x - lo|, |hi - x|), relative to min |exact| where the enclosure
        # excludes 0 (absolute otherwise): each step nudged the way that lowers the digits
        err = np.nextafter(np.maximum(np.abs(x - lo), np.abs(hi - x)), np.inf)
        scale = np.nextafter(np.where(lo > 0, lo, np.where(hi < 0, -hi, 1.0)), 0)
        with np.errstate(divide="ignore", over="ignore"):
            d = np.where(np.maximum(np.abs(x - lo), np.abs(hi - x)) == 0, np.inf, -np.log10(np.nextafter(err / scale, np.inf)))
        digits_of[name] = d
        worst = int(np.argmin(d)) if len(d) else 0
        quantities[name] = {
            "n": int(len(x)),
            "inside": int(np.count_nonzero(inside)),
            "within": int(np.count_nonzero(within)),
            "min_digits": float(d.min()) if len(d) else math.inf,
            "median_digits": float(np.median(d)) if len(d) else math.inf,
            "worst_state": states[worst] if len(d) else "",
            "worst_tolerance_state": worst_tolerance_state,  # the value farthest outside, by tolerances
        }
        if quantities[name]["within"] < quantities[name]["n"]:
            passed = False
        if min_digits is not None and quantities[name]["median_digits"] < min_digits:
            passed = False
    return Score(quantities, digits_of, missing, passed, min_digits)
