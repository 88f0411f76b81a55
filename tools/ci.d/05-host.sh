#!/usr/bin/env bash
# ci-alone
# CI step: the `host` workflow preset (gcc, Debug, ASan + UBSan): every test
# suite but the mutation check. Alone, first: its CLI tests drive a shell on a
# terminal and the simulator within timeouts that a machine busy with two
# other builds can miss. Its build/host is what 60-soak uses.
set -euo pipefail
cd "$(dirname "$0")/../.."
cmake --workflow --preset host
