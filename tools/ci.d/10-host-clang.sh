#!/usr/bin/env bash
# ci-weight: 140
# CI step: the `host-clang` workflow preset (clang-14, Debug, ASan + UBSan):
# every suite whose result can depend on the compiler. The test preset leaves
# out what only checks text, CMake logic or the CLI's scripts against a build
# (docs_*, porting_configure_*, label cli): the `host` workflow ran them.
set -euo pipefail
cd "$(dirname "$0")/../.."
cmake --workflow --preset host-clang
