"""The serial transport (pyserial): bytes in and out of a port, waiting
with select() on its descriptor where the platform has one."""
import os
import select
import time


class SerialTransport:
    def __init__(self, port, baudrate=115200):
        import serial  # imported here: `import daran` stays fast
        if isinstance(port, str):
            port = serial.Serial(port, baudrate, timeout=0, write_timeout=1)
        self.port = port
        try:
            self._fd = port.fileno()
        except (AttributeError, OSError, ValueError):  # a port without a descriptor (Windows)
            self._fd = None
        #: the descriptor the C link reads and writes itself (None: it calls read/write)
        self.fd = self._fd

    def write(self, data):
        if self._fd is not None:
            view = memoryview(data)
            while view:
                try:
                    view = view[os.write(self._fd, view):]
                except BlockingIOError:
                    select.select([], [self._fd], [], 1.0)
            return True
        return self.port.write(data) == len(data)

    def read(self, size, timeout_ms):
        if self._fd is None:
            self.port.timeout = timeout_ms / 1000.0
            first = self.port.read(1)
            if not first:
                return b""
            return first + self.port.read(min(size - 1, self.port.in_waiting))
        if timeout_ms and not select.select([self._fd], [], [], timeout_ms / 1000.0)[0]:
            return b""
        try:
            return os.read(self._fd, size)
        except BlockingIOError:
            return b""

    def wait(self, seconds):
        """Return when bytes are there to read, or after `seconds`."""
        if self._fd is not None:
            select.select([self._fd], [], [], seconds)
        elif not self.port.in_waiting:
            time.sleep(seconds)

    def close(self):
        self.port.close()
