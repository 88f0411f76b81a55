"""The soak's summary: calls and latencies per client, failures by cause,
events, daran-sim's RSS and fds over time with the leak verdict, defects.
Returns the exit status (0: nothing wrong)."""
import collections

from soak_record import percentile

# growth allowed between a daran-sim's first sample (after its start-up)
# and its last: more is a leak
RSS_GROWTH_KB = 2048
FD_GROWTH = 2
WARM_UP = 5.0


def leaks(stats):
    by_pid = collections.OrderedDict()
    for seconds, pid, rss, fds in stats.samples:
        by_pid.setdefault(pid, []).append((seconds, rss, fds))
    found = []
    for pid, rows in by_pid.items():
        rows = [r for r in rows if r[0] - rows[0][0] >= WARM_UP] or rows[-1:]
        first, last = rows[0], rows[-1]
        if last[1] - first[1] > RSS_GROWTH_KB:
            found.append("daran-sim pid %d: RSS %d -> %d kB over %.0f s"
                         % (pid, first[1], last[1], last[0] - first[0]))
        if last[2] - first[2] > FD_GROWTH:
            found.append("daran-sim pid %d: fds %d -> %d over %.0f s"
                         % (pid, first[2], last[2], last[0] - first[0]))
    return found


def report(stats, orchestrator, elapsed, args, sim_path, nvm_dir):
    for leak in leaks(stats):
        stats.defect("leak: " + leak)
    for line in orchestrator.sim.sanitizer_reports[:10]:
        stats.defect("daran-sim's sanitizers: " + line)
    out = []
    out.append("soak: %.0f s (asked %.0f s, at most %d calls), seed %d, %s"
               % (elapsed, args.duration, min(args.max_calls, 10 ** 9), args.seed, sim_path))
    out.append("topology: daran-sim --drives 4 --pty --slcan --bridge --nvm DIR; ascii -> drive 1,"
               " bridge -> drives 2 and 3 (through drive 1), can -> drive 4 (slcan)")
    out.append("")
    out.append("%-8s %9s %9s %11s %9s %9s" % ("client", "calls", "failed", "median ms",
                                               "p99 ms", "max ms"))
    failed_by_client = collections.Counter()
    for (client, _, _), count in stats.failures.items():
        failed_by_client[client] += count
    for client in ("ascii", "bridge", "can"):
        lat = stats.latencies.get(client, [])
        out.append("%-8s %9d %9d %11.2f %9.2f %9.2f" % (
            client, stats.calls[client], failed_by_client[client],
            percentile(lat, 0.5) * 1e3, percentile(lat, 0.99) * 1e3,
            (max(lat) if lat else float("nan")) * 1e3))
    out.append("%-8s %9d %9d" % ("all", sum(stats.calls.values()), sum(failed_by_client.values())))
    out.append("")
    out.append("failures by cause (client, cause, when):")
    if not stats.failures:
        out.append("  none")
    for (client, cause, in_fault), count in sorted(stats.failures.items(),
                                                   key=lambda kv: (kv[0][0], -kv[1])):
        out.append("  %-7s %6d  %s  [%s]" % (client, count, cause,
                                             "in a fault window" if in_fault else "OUTSIDE any fault"))
    out.append("")
    out.append("events:")
    for name, count in sorted(stats.events.items()):
        out.append("  %6d  %s" % (count, name))
    if stats.landing_errors:
        out.append("  landing error of the moves that landed: median %.4f deg, max %.4f deg"
                   % (percentile(stats.landing_errors, 0.5), max(stats.landing_errors)))
    out.append("  daran-sim pids: %s; stderr lines: %d; console output: %.1f MB"
               % (" ".join(str(p) for p in orchestrator.pids), orchestrator.sim.stderr_lines,
                  orchestrator.sim.console_bytes / 1e6))
    out.append("  CAN frames the CAN client received that were not its answers (the bridge's"
               " traffic, late replies drained): %d" % orchestrator.can_link.foreign_frames)
    for line in list(orchestrator.sim.stderr_tail)[-5:]:
        out.append("    stderr: %s" % line)
    if nvm_dir:
        out.append("  NVM folder: %s" % nvm_dir)
    out.append("")
    out.append("daran-sim over time (RSS growth allowed %d kB, fds %d, after %.0f s of each run):"
               % (RSS_GROWTH_KB, FD_GROWTH, WARM_UP))
    out.append("  %8s %8s %9s %5s" % ("t s", "pid", "RSS kB", "fds"))
    samples = stats.samples
    step = max(1, len(samples) // 30)
    shown = samples[::step]
    if samples and shown[-1] is not samples[-1]:
        shown.append(samples[-1])
    for seconds, pid, rss, fds in shown:
        out.append("  %8.1f %8d %9d %5d" % (seconds, pid, rss, fds))
    out.append("")
    if stats.defects:
        out.append("DEFECTS (%d):" % len(stats.defects))
        out.extend("  " + d for d in stats.defects[:50])
        out.append("soak: FAILED")
    else:
        out.append("defects: none (no wrong value, no lost or double motion, NVM kept, "
                   "no crash, no leak)")
        out.append("soak: passed")
    print("\n".join(out), flush=True)
    return 1 if stats.defects else 0
