#!/usr/bin/env bash
# ci-weight: 80
# CI step: a drive maker's project out of the tree (examples/adopter, the
# ACME X1) built the way docs/testing-your-drive.md says, from what the
# package installs and from the source tree:
#   1. the `library` preset (no tests, no Unity) installed to a temporary prefix,
#      and the X1's firmware for a Cortex-M4 from it (tests/consumer/firmware);
#   2. examples/adopter from that prefix (find_package): its core for its own
#      options header, the conformance suite, the fuzz replay, the recorded
#      session replayed into daran-sim and into its own port, its own test
#      over the simulated drive (all CTest);
#   3. the same with clang-14: the libFuzzer harnesses fuzz 10 s of frames,
#      then 10 s of lines;
#   4. examples/adopter again through add_subdirectory of the source tree.
# Prints the time each step took: the time a new port needs from an
# installed package to a green conformance run is step 2's configure+build+
# conformance. Exits non-zero on the first failure, with that step's log.
set -euo pipefail
cd "$(dirname "$0")/../.."
repo=$(pwd)

source tools/ci-steps.bash
ci_steps_begin 55-adopter

prefix="$work/prefix"
install_package() {
  cmake --preset library -B "$work/library" &&
    cmake --build "$work/library" "${jobs[@]}" &&
    cmake --install "$work/library" --prefix "$prefix"
}
step "install: the library preset (core, simulated drive, test kit, programs) to a prefix" install_package

# The X1's firmware for a Cortex-M4 from the same prefix, with the toolchain
# file it installs (tests/consumer/firmware): the core compiled for the X1's
# header by arm-none-eabi-gcc, its HAL and a bare-metal main loop, linked.
firmware_from_prefix() {
  local build="$work/firmware" elf="$work/firmware/acme-fw.elf"
  cmake -S tests/consumer/firmware -B "$build" -DCMAKE_BUILD_TYPE=MinSizeRel \
    --toolchain "$prefix/share/daran_ascii/toolchains/cortex-m4.cmake" \
    -DCMAKE_PREFIX_PATH="$prefix" &&
    cmake --build "$build" "${jobs[@]}" || return 1
  arm-none-eabi-size "$elf"
  arm-none-eabi-readelf -h "$elf" | grep -q "Machine: *ARM$" || { echo "not an Arm image"; return 1; }
  arm-none-eabi-readelf -h "$elf" | grep -q "hard-float ABI" || { echo "not hard-float"; return 1; }
  arm-none-eabi-readelf -A "$elf" | grep -q "Tag_CPU_arch: v7E-M$" || { echo "not built for v7E-M"; return 1; }
  # daran_init() is daran_init_checked() with the build signature, from the
  # core built for the X1's header, next to the X1's HAL; no heap, no stdio.
  local symbols
  symbols=$(arm-none-eabi-nm "$elf")
  for wanted in "T daran_init_checked" "T daran_poll" "R acme_hal"; do
    grep -q " $wanted$" <<<"$symbols" || { echo "acme-fw.elf lacks $wanted"; return 1; }
  done
  if grep -E " (malloc|_malloc_r|printf|_printf_r)$" <<<"$symbols"; then
    echo "acme-fw.elf links the heap or stdio"; return 1
  fi
}
step "adopter's firmware from the prefix: core and port for the Cortex-M4, linked and inspected" \
  firmware_from_prefix

adopter_from_prefix() {
  cmake -S examples/adopter -B "$work/adopter" -DCMAKE_BUILD_TYPE=Debug \
    -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_C_COMPILER=gcc &&
    cmake --build "$work/adopter" "${jobs[@]}" &&
    ctest --test-dir "$work/adopter" --output-on-failure --no-tests=error -R acme_conformance
}
step "adopter from the prefix: configure, build, a green conformance run" adopter_from_prefix
step "adopter from the prefix: every test (fuzz replay, recorded session, own test over the sim)" \
  ctest --test-dir "$work/adopter" --output-on-failure --no-tests=error

adopter_fuzz() {
  cmake -S examples/adopter -B "$work/adopter-clang" -DCMAKE_BUILD_TYPE=Debug \
    -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_C_COMPILER=clang-14 &&
    cmake --build "$work/adopter-clang" "${jobs[@]}" &&
    cmake --build "$work/adopter-clang" --target acme_fuzz_run
}
step "adopter with clang-14: the libFuzzer harnesses fuzz 10 s of frames, then 10 s of lines" adopter_fuzz

adopter_subdirectory() {
  cmake -S examples/adopter -B "$work/adopter-subdir" -DCMAKE_BUILD_TYPE=Debug \
    -DACME_DARAN_SOURCE_DIR="$repo" -DCMAKE_C_COMPILER=gcc &&
    cmake --build "$work/adopter-subdir" "${jobs[@]}" &&
    ctest --test-dir "$work/adopter-subdir" --output-on-failure --no-tests=error
}
step "adopter through add_subdirectory of the source tree: every test" adopter_subdirectory

ci_steps_end
