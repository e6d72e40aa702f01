"""The exceptions of ricochet's Python module, one per status of the C
library (include/ricochet/ricochet.h, ``rc_status``).

Every one is a ``RicochetError`` carrying

- ``str(exc)``: the library's message, the text ``ricochet run`` prints
  after "ricochet: <status>: " (for an input error "file:line: card
  /X/Y/id, field F: expected ..., got ...");
- ``status``: the ``Status`` (an int: 2 input, 3 solver, 4 I/O, 5 out of
  memory, 6 internal, 7 interrupted, 8 physics check);
- ``exit_code``: the exit code ``ricochet run`` gives for it (2, 3, 4, 5
  for a physics check, 130 interrupted, 1 otherwise);
- ``dataset``: the results the run kept (partial, the file marked
  incomplete) read back, or None when nothing was written (input errors) or
  ``run`` was not asked for a dataset;
- ``path``: the results file when it was kept (``out=`` given), else None;
- ``stats``: the run's statistics (``RunStats``) when it ran, else None.
"""
# SPDX-License-Identifier: GPL-3.0-or-later
import enum


class Status(enum.IntEnum):
    """``rc_status`` of include/ricochet/ricochet.h."""
    OK = 0
    EINPUT = 2
    ESOLVER = 3
    EIO = 4
    ENOMEM = 5
    EINTERNAL = 6
    EINTERRUPT = 7
    EPHYSICS = 8


# rc_status_exit_code, for a status the library may not be loaded to ask
_EXIT = {Status.OK: 0, Status.EINPUT: 2, Status.ESOLVER: 3, Status.EIO: 4, Status.EPHYSICS: 5,
         Status.EINTERRUPT: 130}


class RicochetError(Exception):
    """A failure of the library, or of finding it (status None then)."""
    status = None

    def __init__(self, message, status=None, dataset=None, path=None, stats=None):
        super().__init__(message)
        if status is not None:
            self.status = Status(status) if status in Status._value2member_map_ else status
        self.dataset = dataset
        self.path = path
        self.stats = stats

    @property
    def message(self):
        return self.args[0] if self.args else ""

    @property
    def exit_code(self):
        """What ``ricochet run`` exits with for this status."""
        if self.status is None:
            return 1
        return _EXIT.get(self.status, 1)


class InputError(RicochetError):
    """The deck, a ``set=`` override or an argument is wrong; nothing was run
    or written. The message names file:line, card and field."""
    status = Status.EINPUT


class SolverError(RicochetError):
    """The integrator failed; the results up to there are kept, marked
    incomplete."""
    status = Status.ESOLVER


class RicochetIOError(RicochetError):
    """A file could not be read or written; the message says what the results
    file keeps. ``abandoned`` is True when HDF5 could not close a results
    file whose write failed (``rc_output_abandoned``): the process should
    then end with ``os._exit`` (HDF5's clean-up at exit would crash)."""
    status = Status.EIO
    abandoned = False


class PhysicsCheckError(RicochetError):
    """A physics check of the run failed (energy created, a dissipation
    decreasing, bodies passing through each other, non-finite values): the
    run stopped there, the results up to there kept."""
    status = Status.EPHYSICS


class InterruptedRun(RicochetError):
    """The run was stopped before its end time (by the event callback, or by
    closing a session early); the results up to there are kept, marked
    incomplete."""
    status = Status.EINTERRUPT


_CLASS = {Status.EINPUT: InputError, Status.ESOLVER: SolverError, Status.EIO: RicochetIOError,
          Status.EPHYSICS: PhysicsCheckError, Status.EINTERRUPT: InterruptedRun}


def error_for(status, message, **kw):
    """The exception for a non-zero status of the library."""
    cls = _CLASS.get(status, RicochetError)
    return cls(message, status=status, **kw)
