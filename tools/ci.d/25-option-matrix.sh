#!/usr/bin/env bash
# ci-weight: 190
# The unit suites under the other daran_config.h options (LF-only replies,
# small and large rings, help or the multi-motor commands compiled out, the
# update module compiled in):
# tests/unit/run_option_matrix.sh, gcc + ASan + UBSan, about 90 s.
set -euo pipefail
cd "$(dirname "$0")/../.."
sh tests/unit/run_option_matrix.sh
