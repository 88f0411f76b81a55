"""The asyncio API: the same names as the sync one, each a coroutine.

    link = await daran.aio.open("/dev/ttyACM0")
    drive = link.drive(1)
    await drive.trapezoid(90, 60, 120)
    print(await drive.state())
    async for report in link.telemetry():
        ...

Each link has one worker thread that runs its requests one at a time through
the sync link (the C client's). A cancelled call stops being awaited, but its
request runs to the end of its reply in the worker, so the link is never
left in the middle of a reply: the next call finds it clean."""
import asyncio
import concurrent.futures
import functools

from . import open as _open_sync, open_can as _open_can_sync, sim as _sim_sync


class AsyncDrive:
    """A Drive whose methods are coroutines (`props` stays sync: use get/set)."""

    def __init__(self, link, drive):
        self._link = link
        self._drive = drive
        self.id = drive.id

    def __getattr__(self, name):
        method = getattr(self._drive, name)
        if not callable(method):
            return method

        @functools.wraps(method)
        async def call(*args, **kwargs):
            return await self._link._run(method, *args, **kwargs)
        return call

    def __repr__(self):
        return f"<daran.aio.AsyncDrive {self.id}>"


class AsyncLink:
    """A link whose requests are coroutines: drive(), move_together(), start(),
    scan(), telemetry() (an async iterator), close()."""

    def __init__(self, link):
        self.link = link
        self._worker = concurrent.futures.ThreadPoolExecutor(1, thread_name_prefix="daran")

    async def _run(self, function, *args, **kwargs):
        loop = asyncio.get_running_loop()
        return await loop.run_in_executor(self._worker,
                                          functools.partial(function, *args, **kwargs))

    def drive(self, drive_id):
        return AsyncDrive(self, self.link.drive(drive_id))

    async def move_together(self, kind, presets, relative=False, *, wait=None):
        return await self._run(self.link.move_together, kind, presets, relative, wait=wait)

    async def start(self, kind, relative=False, *, wait=None):
        return await self._run(self.link.start, kind, relative, wait=wait)

    async def scan(self, ids=range(1, 64), timeout=0.02):
        return await self._run(self.link.scan, ids, timeout)

    async def telemetry(self, timeout=None, poll=0.005):
        """Telemetry reports as they come; ends after `timeout` s without one (None: never)."""
        loop = asyncio.get_running_loop()
        last = loop.time()
        while True:
            if self.link.reports:
                last = loop.time()
                yield self.link.reports.popleft()
                continue
            if timeout is not None and loop.time() - last > timeout:
                return
            await self._run(self.link.service)
            if not self.link.reports:
                await asyncio.sleep(poll)

    @property
    def sim(self):
        return self.link.sim

    async def close(self):
        await self._run(self.link.close)
        self._worker.shutdown(wait=True)

    async def __aenter__(self):
        return self

    async def __aexit__(self, *exc):
        await self.close()


async def _opened(opener, *args, **kwargs):
    loop = asyncio.get_running_loop()
    return AsyncLink(await loop.run_in_executor(None, functools.partial(opener, *args, **kwargs)))


async def open(port, baudrate=115200, **options):  # noqa: A001
    """daran.open, awaited: an AsyncLink."""
    return await _opened(_open_sync, port, baudrate, **options)


async def open_can(bus, **options):
    """daran.open_can, awaited: an AsyncLink."""
    return await _opened(_open_can_sync, bus, **options)


async def sim(drives=3, can=False, args=(), **options):
    """daran.sim, awaited: an AsyncLink to simulated drives."""
    return await _opened(_sim_sync, drives, can, args, **options)
