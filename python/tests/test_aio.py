"""The asyncio API, and telemetry while drives are commanded."""
import asyncio

import pytest
import pytest_asyncio

import daran
import daran.aio


@pytest_asyncio.fixture
async def alink():
    link = await daran.aio.sim(drives=3, timeout=1.0, confirm=0.05)
    yield link
    await link.close()


@pytest.mark.asyncio
async def test_the_same_names_as_coroutines(alink):
    drive = alink.drive(2)
    assert await drive.info() == (100, 3, 2026000002)
    await drive.trapezoid(15, 120, 300)
    while not (await drive.state()).done or abs((await drive.position_velocity())[0] - 15) > 0.5:
        await asyncio.sleep(0.01)
    await drive.set("axis2.output_shaft.vel_limit", 200)
    assert await drive.get("axis2.output_shaft.vel_limit") == 200.0
    with pytest.raises(daran.DriveRefused):
        await drive.set("vbus_voltage", 1, wait=2.0)
    assert await alink.scan(range(1, 5), timeout=0.3) == [1, 2, 3]


@pytest.mark.asyncio
async def test_a_call_cancelled_mid_reply_leaves_the_link_usable(alink):
    drive = alink.drive(1)
    cancelled = 0
    for delay in (0, 0.0005, 0.001, 0.002):
        task = asyncio.ensure_future(drive.discover())  # 165 reply lines, then `end`
        await asyncio.sleep(delay)
        task.cancel()
        await asyncio.gather(task, return_exceptions=True)
        cancelled += task.cancelled()
        assert await drive.info() == (100, 3, 2026000001)
        assert await drive.position_velocity() == (0.0, 0.0)
    assert cancelled >= 2
    assert not alink.link.strays and alink.link.bad_lines == 0


@pytest.mark.asyncio
async def test_two_drives_stream_while_a_third_is_commanded(alink):
    await alink.drive(1).stream(0.01, ("position", "velocity"))
    await alink.drive(2).stream(0.01, ("position", "done"))
    third = alink.drive(3)
    await third.velocity(30)
    seen = {1: 0, 2: 0}
    async for report in alink.telemetry(timeout=1.0):
        seen[report.id] += 1
        assert len(report.values) == 2
        if report.id == 2:
            assert report.values[1] == 1  # done
        assert (await third.position_velocity())[0] is not None
        if min(seen.values()) >= 10:
            break
    assert min(seen.values()) >= 10
    assert abs((await third.position_velocity())[1] - 30) < 1
    await alink.drive(1).stop_stream()
    await alink.drive(2).stop_stream()


def test_sync_telemetry_iterator(sim3):
    drive = sim3.drive(1)
    drive.stream(0.005, ("position", "velocity", "torque"))
    reports = []
    for report in sim3.telemetry(timeout=0.5):
        reports.append(report)
        if len(reports) == 20:
            break
    drive.stop_stream()
    assert len(reports) == 20 and all(r.id == 1 and len(r.values) == 3 for r in reports)
    assert reports[-1].time > reports[0].time
