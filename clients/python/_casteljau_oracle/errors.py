"""The client's exceptions: every failure it reports is an `OracleError`."""


class OracleError(Exception):
    """The oracle answered a request with an error (its message), stopped, or could not be
    run; or a request could not be sent as asked. Every error the client raises is one."""


class OracleInputError(OracleError, ValueError):
    """A value the client cannot send exactly (NaN or inf as an input, a bool, a float
    answer that is no float, an object that is no number)."""


class OracleTimeout(OracleError):
    """No answer came within the client's `timeout`; the oracle process was ended and the
    next request starts a new one."""


class OracleProtocolError(OracleError):
    """An answer line that is not the answer to the request sent (not JSON, or another
    request's id); the oracle process was ended and the next request starts a new one."""
