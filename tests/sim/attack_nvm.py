#!/usr/bin/python3
"""Regression test, end to end through --nvm files:

  - a stored config with a valid CRC but values `w` refuses (load_inertia -5,
    vel_gain -1000, can_node_id 200, patched into a saved image and the CRC
    made to match) boots on defaults with the nvm_corrupt warning, and a
    `t 1 10` then moves the shaft to 10 deg, not to -774312 deg
  - the .shaft file that cannot be written at exit is reported on stderr
    and makes the exit status non-zero

usage: attack_nvm.py DARAN_SIM
"""
import os
import struct
import subprocess
import sys
import tempfile
import zlib


def run(sim, nvm, text, *args):
    p = subprocess.run([sim, "--nvm", nvm, *args], input=text.encode(), stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE, timeout=20)
    return p.returncode, p.stdout.decode().replace("\r", ""), p.stderr.decode()


def patch(image, old, new, what, failures):
    """Replace the one occurrence of @old in slot 0's payload with @new."""
    payload = image[16:512]
    if payload.count(old) != 1:
        failures.append("%s: %d occurrences of its marker value in the image"
                        % (what, payload.count(old)))
        return image
    k = 16 + payload.index(old)
    return image[:k] + new + image[k + len(old):]


def tampered_image(sim, nvm, failures):
    # distinctive values, saved the ordinary way, then found and replaced
    rc, _, err = run(sim, nvm, "w axis1.output_shaft.load_inertia 0.0123\n"
                               "w axis1.controller.config.vel_gain 0.1717\n"
                               "w axis1.config.can_node_id 47\nss 47\n")
    if rc != 0:
        failures.append("saving the config: %d %s" % (rc, err))
    path = os.path.join(nvm, "drive-1.nvm")
    with open(path, "rb") as f:
        image = f.read()
    image = patch(image, struct.pack("<f", 0.0123), struct.pack("<f", -5.0), "load_inertia",
                  failures)
    image = patch(image, struct.pack("<f", 0.1717), struct.pack("<f", -1000.0), "vel_gain",
                  failures)
    image = patch(image, struct.pack("<I", 47), struct.pack("<I", 200), "can_node_id", failures)
    length = struct.unpack("<H", image[6:8])[0]
    crc = zlib.crc32(image[4:12] + image[16:16 + length]) & 0xFFFFFFFF
    image = image[:12] + struct.pack("<I", crc) + image[16:]
    with open(path, "wb") as f:
        f.write(image)


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    sim = sys.argv[1]
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        nvm = os.path.join(tmp, "nvm")
        os.mkdir(nvm)
        tampered_image(sim, nvm, failures)
        rc, out, err = run(sim, nvm,
                           "r axis0.config.can_node_id\nr axis1.config_warnings\nr axis1.error\n"
                           "r axis1.output_shaft.load_inertia\nr axis1.controller.config.vel_gain\n"
                           "t 1 10\n!advance 2\nf 1\n")
        got = out.split("\n")
        want_head = ["1", "1", "0", "0", "0.16"]
        if rc != 0 or got[:5] != want_head or len(got) != 7:
            failures.append("boot on the tampered image: status %d, replies %r (want %r, then f 1)"
                            % (rc, got, want_head))
        else:
            pos, vel = (float(x) for x in got[5].split())
            if abs(pos - 10.0) > 0.2 or abs(vel) > 1.0:
                failures.append("t 1 10 on the tampered image ends at %g deg, %g r/min" % (pos, vel))

        # the shaft file cannot be written: a directory stands where it goes
        nvm2 = os.path.join(tmp, "nvm2")
        os.makedirs(os.path.join(nvm2, "drive-1.shaft", "in-the-way"))
        rc, out, err = run(sim, nvm2, "t 1 30\n!advance 1\nf 1\n")
        if rc == 0:
            failures.append("the .shaft write failed and the exit status is 0")
        if "drive-1.shaft" not in err:
            failures.append("the .shaft write failed and stderr does not say so: %r" % err)
        if out.count("\n") != 1:
            failures.append("replies before the failed exit: %r" % out)
        leftovers = [x for x in os.listdir(nvm2) if x not in ("drive-1.shaft", "drive-1.nvm")]
        if leftovers:
            failures.append("files left behind by the failed write: %r" % leftovers)
    for f in failures:
        print("FAIL:", f)
    print("nvm ranges and shaft file: %s" % ("failed" if failures else "all checks passed"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
