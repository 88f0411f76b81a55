"""daran: Daran servo drives from Python, over a serial line or a CAN bus.

    import daran
    link = daran.open("/dev/ttyACM0")
    drive = link.drive(1)
    drive.trapezoid(90, 30, 60)
    drive.props.axis.output_shaft.vel_limit = 300
    print(drive.state())

Requests are built, replies read and numbers converted by the C client
(daran_client, compiled into daran._client): docs/python.md."""
from ._table import ERROR_REGISTERS, PROPERTIES, Property, Result
from .drive import Drive, Errors, State
from .errors import DaranError, DriveRefused, LinkError, NoReply
from ._link import Report

__version__ = "0.1.0"


def open(port, baudrate=115200, **options):  # noqa: A001 (the package's verb)
    """Open drives on a serial port (a path, or an open pyserial port).
    Options: checksum=False, timeout=0.05 (s, a query's reply), confirm=0.02
    (s, how long a silent command waits for a refusal), retries=1 (queries
    only), quiet=0.005 (s)."""
    from ._serial import SerialTransport
    from .link import Link
    return Link(SerialTransport(port, baudrate), **options)


def open_can(bus, **options):
    """Open drives on a CAN bus: any python-can bus (socketcan, slcan, virtual, ...)."""
    from .can import CanLink
    return CanLink(bus, **options)


def scan(ports=None, ids=range(1, 64), baudrate=115200, timeout=0.02):
    """The drives on each serial port: {port: [ids that answer `f`]}. `ports`: paths
    (None: every port pyserial lists). A port that cannot be opened is left out."""
    if ports is None:
        from serial.tools import list_ports
        ports = [port.device for port in list_ports.comports()]
    found = {}
    for port in ports:
        try:
            link = open(port, baudrate, retries=0)
        except OSError:
            continue
        with link:
            found[port] = link.scan(ids, timeout)
    return found


def sim(drives=3, can=False, args=(), **options):
    """Start daran-sim with `drives` drives and return an open link to them
    (daran._sim.sim)."""
    from ._sim import sim as start
    return start(drives, can, args, **options)


__all__ = ["open", "open_can", "sim", "scan", "Drive", "State", "Errors", "Report", "Property",
           "PROPERTIES", "ERROR_REGISTERS", "Result", "DaranError", "DriveRefused", "NoReply",
           "LinkError"]
