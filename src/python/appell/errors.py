"""appell's exceptions, one class per exit status of the ``appell`` command.

=================  ===========  =====================================================
class              exit status  raised for
=================  ===========  =====================================================
``InputError``     2            bad input: a scene, a field, a value, an option (the
                                message names it, as the command's one line does)
``NotCertified``   3            a result that could not be certified (an interval too
                                wide to decide, a value outside a function's domain)
``InternalError``  4            a bug in appell (please report it with the scene)
``Interrupted``    (Ctrl-C)     a long call stopped by KeyboardInterrupt: ``.result``
                                holds what it computed until then
=================  ===========  =====================================================

``InputError`` is a ``ValueError`` and ``NotCertified`` an ``ArithmeticError``, so code that
catches the built-in classes keeps working; ``appell.Error`` catches all three.
"""


class Error(Exception):
    """The base of appell's errors (InputError, NotCertified, InternalError)."""

    exit_status = None


class InputError(Error, ValueError):
    """Bad input, naming the field or option (exit status 2 of the ``appell`` command)."""

    exit_status = 2


class NotCertified(Error, ArithmeticError):
    """A result that could not be certified (exit status 3 of the ``appell`` command)."""

    exit_status = 3


class InternalError(Error, RuntimeError):
    """A bug in appell (exit status 4 of the ``appell`` command)."""

    exit_status = 4


class Interrupted(KeyboardInterrupt):
    """A long call (enclose, simulate, validity, reference) stopped by Ctrl-C.

    ``result`` holds what the call computed before it stopped (marked incomplete), so that
    ``except KeyboardInterrupt as e: partial = e.result`` keeps the work done.
    """

    def __init__(self, message, result=None):
        super().__init__(message)
        self.result = result
