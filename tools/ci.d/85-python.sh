#!/usr/bin/env bash
# ci-weight: 40
# ci-after: 05-host.sh
# CI step: the Python package (python/, docs/python.md) installed the way its
# docs say, offline, into a fresh virtual environment over Debian's packages
# (`pip install --no-build-isolation`: the cffi extension compiled once, here
# with ASan and UBSan, whose runtimes are preloaded into the interpreter),
# then its pytest suite against build/host's daran-sim on a pty and on its
# slcan adapter. Cases marked `slow` (the figures of docs/python.md) are left
# out. Builds daran-sim only when 05-host.sh has not.
set -euo pipefail
cd "$(dirname "$0")/../.."

sim=build/host/port/sim/daran-sim
if [ ! -x "$sim" ]; then
  cmake --preset host >/dev/null
  cmake --build --preset host --target daran-sim -j 2 >/dev/null
fi
work=$(mktemp -d "${TMPDIR:-/tmp}/daran-python.XXXXXX")
trap 'rm -rf "$work"' EXIT
repo=$(pwd)

# the environment without a pip of its own (creating one costs ~10 s): Debian's
# pip installs into it (`pip --python`), as the environment's pip would
/usr/bin/python3 -m venv --without-pip --system-site-packages "$work/venv"
# setuptools builds inside the package's folder: a copy of python/ beside links
# to the C sources it compiles keeps the checkout clean
mkdir "$work/tree"
cp -r python "$work/tree/python"
rm -rf "$work/tree/python/build" "$work/tree/python/"*.egg-info
for dir in include src client cli; do ln -s "$repo/$dir" "$work/tree/$dir"; done
sanitizers="-fsanitize=address,undefined -fno-sanitize-recover=undefined"
CFLAGS="$sanitizers -fno-omit-frame-pointer" LDFLAGS="$sanitizers" \
  /usr/bin/python3 -m pip --python "$work/venv/bin/python" install --quiet --no-index \
  --no-build-isolation "$work/tree/python"
cd "$work"
# leaks are CPython's own (interned objects at exit), not the extension's
LD_PRELOAD="$(gcc -print-file-name=libasan.so) $(gcc -print-file-name=libubsan.so)" \
  ASAN_OPTIONS=detect_leaks=0 DARAN_SIM="$repo/$sim" \
  "$work/venv/bin/python" -P -m pytest -x -q -m 'not slow' -p no:cacheprovider \
  --rootdir "$repo/python" "$repo/python/tests"
