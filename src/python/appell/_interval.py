"""Interval: an enclosure as appell prints it, its bounds exact (decimal text) and as floats."""

import math
import sys
from fractions import Fraction

from . import _core


def exact(x):
    """x as an exact Fraction: an int, a float (its double exactly), a decimal str, a Fraction,
    a decimal.Decimal or an mpmath.mpf."""
    if isinstance(x, Fraction):
        return x
    if isinstance(x, bool):
        raise TypeError("a bool is not a number")
    if isinstance(x, (int, float, str)):
        try:
            return Fraction(x)
        except (ValueError, OverflowError) as e:
            raise ValueError(f"{x!r} is not a finite number") from e
    raw = getattr(x, "_mpf_", None)  # mpmath.mpf: (sign, mantissa, exponent, bits)
    if raw is not None:
        sign, man, e, _ = raw
        if not man and (e or sign):  # mpmath's inf, -inf and nan have a zero mantissa
            raise ValueError(f"{x!r} is not a finite number")
        q = Fraction(man) * (Fraction(2) ** e)
        return -q if sign else q
    try:
        return Fraction(x)  # decimal.Decimal, NumPy's numbers
    except TypeError as e:
        raise TypeError(f"{type(x).__name__} is not a number appell compares exactly") from e


def _float_up(q):
    """The least double >= the Fraction q (inf beyond the doubles' range)."""
    try:
        f = float(q)
    except OverflowError:  # beyond the largest double: inf above, the most negative double below
        return math.inf if q > 0 else -sys.float_info.max
    if Fraction(f) < q:
        f = math.nextafter(f, math.inf)
    return f


def _float_nearest(q):
    """The double nearest the Fraction q (+-inf beyond the doubles' range)."""
    try:
        return float(q)
    except OverflowError:
        return math.inf if q > 0 else -math.inf


class Interval:
    """A rigorous enclosure [lo, hi] of a result.

    ``lo_text`` and ``hi_text`` are its bounds exactly as appell prints them (decimals rounded
    outward from the scalar's own bounds); ``lo`` and ``hi`` are floats rounded outward from the
    scalar's own bounds (in ``interval`` they are its bounds exactly; an Interval made from text
    rounds the text outward), so ``[lo, hi]`` is an enclosure too, though not always of the text.
    ``x in iv`` and ``iv.contains(x)`` compare exactly (an int, float, decimal str, Fraction,
    Decimal, ``mpmath.mpf``, or another Interval: contained whole)."""

    __slots__ = ("lo", "hi", "lo_text", "hi_text")

    def __init__(self, lo_text, hi_text, lo=None, hi=None):
        self.lo_text = str(lo_text)
        self.hi_text = str(hi_text)
        self.lo = _core._decimal_double(self.lo_text, "down") if lo is None else lo
        self.hi = _core._decimal_double(self.hi_text, "up") if hi is None else hi
        if not Fraction(self.lo_text) <= Fraction(self.hi_text):
            raise ValueError(f"Interval: lower bound {self.lo_text} above upper bound {self.hi_text}")

    def contains(self, x):
        """Whether x (a number, or an Interval whole) lies in [lo_text, hi_text], exactly."""
        lo, hi = Fraction(self.lo_text), Fraction(self.hi_text)
        if isinstance(x, Interval):
            return lo <= Fraction(x.lo_text) and Fraction(x.hi_text) <= hi
        if type(x).__name__ == "ivmpf":  # mpmath's interval (mpmath.iv.mpf, mpmath.mpi)
            import mpmath

            return lo <= exact(mpmath.mpf(x.a)) and exact(mpmath.mpf(x.b)) <= hi
        return lo <= exact(x) <= hi

    __contains__ = contains

    def width(self):
        """hi - lo, rounded up to a float (an upper bound of the width)."""
        return _float_up(Fraction(self.hi_text) - Fraction(self.lo_text))

    def mid(self):
        """The midpoint of the exact bounds, rounded to the nearest float."""
        return _float_nearest((Fraction(self.lo_text) + Fraction(self.hi_text)) / 2)

    def mag(self):
        """max |x| over the interval, rounded up to a float."""
        return _float_up(max(abs(Fraction(self.lo_text)), abs(Fraction(self.hi_text))))

    def excludes_zero(self):
        """Whether 0 is certainly not in the interval (its sign is proved)."""
        return Fraction(self.lo_text) > 0 or Fraction(self.hi_text) < 0

    def to_mpmath(self):
        """The enclosure as an ``mpmath.mpi`` (mpmath's interval), its bounds rounded outward at
        mpmath's ``iv.prec`` (53 bits unless changed): it contains this interval."""
        import mpmath

        return mpmath.iv.mpf([self.lo_text, self.hi_text])

    def __iter__(self):  # lo, hi = interval
        yield self.lo
        yield self.hi

    def __eq__(self, other):
        return isinstance(other, Interval) and Fraction(self.lo_text) == Fraction(other.lo_text) and Fraction(
            self.hi_text
        ) == Fraction(other.hi_text)

    def __hash__(self):
        return hash((Fraction(self.lo_text), Fraction(self.hi_text)))

    def __repr__(self):
        return f"Interval('{self.lo_text}', '{self.hi_text}')"

    def __str__(self):
        return f"[{self.lo_text}, {self.hi_text}]"
