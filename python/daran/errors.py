"""The exceptions: every failure carries its daran_result_t as `.result`."""
from ._table import Result, phrase


class DaranError(Exception):
    """Any failure of a request; `.result` is its Result."""

    def __init__(self, result: int, what: str = ""):
        self.result = Result(result)
        self.phrase = phrase(result)
        super().__init__(f"{what}: {self.phrase}" if what else self.phrase)


class DriveRefused(DaranError):
    """The drive answered `error: <phrase>`: it did not run the request."""


class NoReply(DaranError):
    """No complete reply within the timeout (or a gateway's `error: no reply`).
    A command that moves is never sent again: whether it ran is unknown."""


class LinkError(DaranError):
    """The link failed: the port could not write, or a reply was damaged
    (checksum, unreadable line), or the port is closed."""


def raise_for(result: int, drive_error: bool, what: str = "") -> None:
    """Raise the exception of a non-OK result of the C link."""
    if result == Result.ERR_NO_REPLY:
        raise NoReply(result, what)
    if drive_error:
        raise DriveRefused(result, what)
    raise LinkError(result, what)
