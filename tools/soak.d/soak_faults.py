"""The scripted faults, drawn from the seed one after the other: bus faults
(frame loss, mute, bus-off, unplug, for one drive or the whole bus) held for
a window then recovered, power cycles (between a drive's operations),
clients closing and reopening their pseudo-terminals, and kill -9 during a
save (every client between two operations; daran-sim restarted on the same
NVM folder, the value being saved must read back old or new). A daran-sim
that dies by itself is a defect; it is restarted and the run goes on."""
import time

from soak_clients import Unrecovered, random_value
from soak_links import PROPERTIES, LinkDown, NoAnswer, same_value
from soak_sim import SimDied

# which drives' answers a bus fault of node X can take: its own; drive 1's
# take the bridge's (drives 2 and 3); node 0 is the whole bus
FAULT_HITS = {0: (2, 3, 4), 1: (2, 3), 2: (2,), 3: (3,), 4: (4,)}
BUS_FAULTS = ("can-lose", "can-mute", "can-bus-off", "can-unplug")


class Orchestrator:
    def __init__(self, sim, ascii_link, can_link, clients, stats, faults, gate, drive_locks,
                 rng, stop, duration):
        self.sim = sim
        self.ascii_link = ascii_link
        self.can_link = can_link
        self.clients = clients
        self.stats = stats
        self.faults = faults
        self.gate = gate
        self.drive_locks = drive_locks
        self.rng = rng
        self.stop = stop
        self.duration = duration
        self.started = time.monotonic()
        self.pids = []
        self.inject_nvm_loss = False
        # kill -9 during a save: once in a short run, every ~5 minutes in a long one
        self.schedule_kills(duration / 2.0 if duration < 600 else 300.0)

    def schedule_kills(self, every):
        self.kill_every = every
        self.next_kill = self.started + every * self.rng.uniform(0.8, 1.0)

    def owner(self, drive):
        return next(c for c in self.clients if drive in c.paths)

    # -- daran-sim ---------------------------------------------------------

    def start_sim(self):
        ascii_path, slcan_path = self.sim.start()
        self.pids.append(self.sim.pid)
        self.ascii_link.open(ascii_path)
        self.can_link.open(slcan_path)

    def restart(self):
        """daran-sim again on the same NVM (the caller holds the gate): every
        drive lost power, its shaft may be elsewhere (the shaft file is
        written at a clean exit only)."""
        self.ascii_link.close()
        self.can_link.close()
        self.sim.kill()
        for client in self.clients:
            for model in client.models.values():
                model.power_lost()
                model.landing = None
        for attempt in range(3):
            try:
                self.start_sim()
                break
            except (SimDied, OSError) as err:
                self.stats.defect("daran-sim did not start again: %s" % err)
                time.sleep(1.0)
        self.stats.event("daran-sim restarts")

    def sample(self):
        use = self.sim.resources()
        if use:
            self.stats.sample(self.sim.pid, *use)

    # -- the schedule -------------------------------------------------------

    def run(self):
        while not self.stop.is_set():
            if not self.pause(self.rng.uniform(0.5, 2.5)):
                break
            try:
                if time.monotonic() >= self.next_kill:
                    self.next_kill += self.kill_every
                    self.kill_during_save()
                    continue
                kind = self.rng.choices(("bus", "power", "reopen"), (65, 28, 7))[0]
                if kind == "bus":
                    self.bus_fault()
                elif kind == "power":
                    self.power_cycle()
                else:
                    self.reopen()
            except (SimDied, LinkDown) as err:
                self.stats.failure("faults", "link down: %s" % str(err)[:40], True)
            except Unrecovered as err:
                self.stats.defect("faults: %s" % err)

    def pause(self, seconds):
        """Sleeps; checks that daran-sim is alive. False when stopping."""
        end = time.monotonic() + seconds
        while time.monotonic() < end:
            if self.stop.is_set():
                return False
            if not self.sim.alive():
                self.crashed()
            time.sleep(0.02)
        return True

    def crashed(self):
        status = self.sim.proc.returncode if self.sim.proc else None
        self.stats.defect("daran-sim (pid %s) died by itself: exit status %s; stderr: %s" %
                          (self.sim.pid, status, " | ".join(list(self.sim.stderr_tail)[-3:])))
        self.gate.take()
        try:
            self.restart()
        finally:
            self.gate.give()

    def bus_fault(self):
        node = self.rng.choices((0, 1, 2, 3, 4), (1, 2, 3, 3, 4))[0]
        kind = self.rng.choice(BUS_FAULTS)
        directive = "!fault %d %s" % (node, kind)
        if kind == "can-lose":
            directive += " %d" % self.rng.randint(1, 3)
        window = self.faults.begin(directive, FAULT_HITS[node])
        self.stats.trace("fault: " + directive)
        try:
            self.sim.directive(directive)
            self.pause(self.rng.uniform(0.05, 1.2))
            self.sim.directive("!fault %d can-recover" % node)
            self.stats.trace("fault: !fault %d can-recover" % node)
        finally:
            self.faults.end(window)
        self.stats.event("bus faults: %s %s" % (kind, "of the whole bus (node 0)" if node == 0
                                                 else "of one drive"))

    def power_cycle(self):
        drives = (1, 2, 3, 4) if self.rng.random() < 0.15 else (self.rng.randint(1, 4),)
        # between operations of the drives' clients; drive 1 is also the
        # gateway: no bridged line is on its way while it powers up
        for drive in drives:
            self.drive_locks[drive].acquire()
        # the gateway's power cycle empties its transmit queue: a bridged
        # command it accepted just before (its fence answered) may never
        # reach drive 2 or 3, whose operations go on meanwhile
        window = self.faults.begin("!power-cycle 1", FAULT_HITS[1]) if 1 in drives else None
        try:
            with self.ascii_link.lock:
                self.sim.directive("!power-cycle %d" % (0 if len(drives) > 1 else drives[0]))
                self.stats.trace("fault: !power-cycle %s" % (drives,))
                time.sleep(0.05)
            for drive in drives:
                self.owner(drive).models[drive].power_lost()
        finally:
            if window is not None:
                self.faults.end(window)
            for drive in drives:
                self.drive_locks[drive].release()
        self.stats.event("power cycles (%s)" % ("all drives" if len(drives) > 1 else "one drive"))

    def reopen(self):
        """A client closes its port and opens it again (fds must not pile up)."""
        if self.rng.random() < 0.5:
            with self.ascii_link.lock:
                self.ascii_link.open(self.sim.paths[0])
            self.stats.event("ASCII pty reopened")
        else:
            with self.can_link.lock:
                self.can_link.open(self.sim.paths[1])
            self.stats.event("slcan pty reopened")

    def kill_during_save(self):
        """A value written and read back, `ss` (or the save frame), SIGKILL
        0-4 ms later, daran-sim restarted: that value reads old or new, and
        everything else each drive's NVM held is still there."""
        self.gate.take()
        try:
            drive = self.rng.randint(1, 4)
            client = self.owner(drive)
            path = client.paths[drive]
            model = client.models[drive]
            try:
                if model.verify_pending:
                    client.verify(drive)
                name, kind, _ = self.rng.choice(PROPERTIES)
                new = client.write_read(drive, name, random_value(self.rng, kind))
                path.save_unwaited()
            except NoAnswer as err:
                self.stats.failure("faults", err.cause, False)
            # the save's line or frame reaches the drive within about a tick
            # (1 ms) and is written then: 0-3 ms catches it before, during
            # and after
            time.sleep(self.rng.uniform(0.0, 0.003))
            self.sim.kill()
            self.stats.trace("fault: kill -9 after a save of drive %d" % drive)
            # the save may have happened: NVM holds the old values or these
            for each, each_kind, _ in PROPERTIES:
                value = model.live.get(each)
                possible = model.saved.setdefault(each, [])
                if value is not None and not any(same_value(each_kind, value, v) for v in possible):
                    possible.append(value)
            self.restart()
            for each_client in self.clients:
                for each_drive in each_client.paths:
                    each_client.verify(each_drive)
            kept = "new" if same_value(kind, model.live[name], new) else "old"
            self.stats.event("kill -9 during a save: the %s value kept" % kept)
        finally:
            self.gate.give()

    def finish(self):
        """The end: SIGTERM (daran-sim must die of it), then once more on the
        same NVM to check every drive's saved config a last time."""
        self.gate.take()
        try:
            if not self.sim.alive():
                self.crashed_at_end()
            if self.inject_nvm_loss:
                self.lose_nvm()
            self.ascii_link.close()
            self.can_link.close()
            if not self.sim.stop():
                self.stats.defect("daran-sim did not die of SIGTERM (status %s)" %
                                  self.sim.proc.returncode)
            for client in self.clients:
                for model in client.models.values():
                    model.power_lost()
            self.start_sim()
            for client in self.clients:
                for drive in client.paths:
                    client.verify(drive)
            self.stats.event("NVM checked after the final SIGTERM and restart (drives)",
                             len([d for c in self.clients for d in c.paths]))
        except Exception as err:  # the report must still come
            self.stats.defect("the final NVM check failed: %r" % err)
        finally:
            self.ascii_link.close()
            self.can_link.close()
            self.sim.stop()
            self.gate.give()

    def lose_nvm(self):
        """--inject nvm-loss: drive 1 saves a new value, then its stored
        config is damaged (`!fault 1 nvm-corrupt`): the final check must
        find it lost."""
        client = self.owner(1)
        if client.models[1].verify_pending:
            client.verify(1)
        client.write_read(1)
        client.save(1)
        self.sim.directive("!fault 1 nvm-corrupt")
        time.sleep(0.05)

    def crashed_at_end(self):
        self.stats.defect("daran-sim (pid %s) had died by itself at the end: status %s" %
                          (self.sim.pid, self.sim.proc.returncode))
