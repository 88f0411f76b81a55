#!/usr/bin/env bash
# ci-weight: 300
# CI step: the `host` workflow preset (gcc, Debug, ASan + UBSan): every test
# suite but the mutation check. Its build/host is what 60-soak uses.
set -euo pipefail
cd "$(dirname "$0")/../.."
cmake --workflow --preset host
