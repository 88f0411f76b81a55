#!/bin/sh
# The Cortex-M0 image of bench/m0 (QEMU `microbit`, nRF51822, no FPU): the
# core compiled as the cortex-m4 preset compiles it (-Os, sections, no loop
# patterns, -DNDEBUG) but for -mcpu=cortex-m0 -mthumb, soft float from
# libgcc, newlib-nano, linked with bench/m0/m0_main.c and nrf51.ld.
#
#   bench/m0/build.sh [OUT_DIR]        (default build/bench/m0)
#
# Writes OUT_DIR/daran-m0.elf (and .map), then prints the core's flash: its
# objects (arm-none-eabi-size -t, as CTest budget_core_flash measures the
# Cortex-M4 library) and what the linked image keeps of them and pulls from
# libgcc/libm/libc (from the link map).
set -eu
cd "$(dirname "$0")/../.."
out=${1:-build/bench/m0}
cc=arm-none-eabi-gcc
cpu="-mcpu=cortex-m0 -mthumb -mfloat-abi=soft"
cflags="$cpu -Os -std=c11 -g -Wall -Wextra -ffunction-sections -fdata-sections -fno-math-errno -fno-tree-loop-distribute-patterns -DNDEBUG -Iinclude -Isrc $(for room in src/*/; do printf -- "-I%s " "${room%/}"; done)-I$out/generated"
# The core's sources: the DARAN_CORE_SOURCES list of cmake/DaranAddLibrary.cmake.
core_sources=$(sed -n '/PROPERTY DARAN_CORE_SOURCES/,/)/p' cmake/DaranAddLibrary.cmake |
  grep -o '[a-z_0-9/]*\.c' | sed 's|^|src/|')
if [ -z "$core_sources" ]; then
  echo "bench/m0/build.sh: no core sources found in cmake/DaranAddLibrary.cmake" >&2
  exit 1
fi

rm -rf "$out/obj"
mkdir -p "$out/obj/core" "$out/obj/main" "$out/generated"
python3 tools/gen_property_index.py --list include/daran_properties.h --omit "" \
  --out "$out/generated/property_index.h"
for source in $core_sources; do
  # shellcheck disable=SC2086
  $cc $cflags -DDARAN_VERSION_STRING='"m0"' -c "$source" -o "$out/obj/core/$(basename "$source" .c).o"
done
# shellcheck disable=SC2086
$cc $cflags -c bench/m0/m0_main.c -o "$out/obj/main/m0_main.o"
# shellcheck disable=SC2086
$cc $cpu -nostartfiles -T bench/m0/nrf51.ld -Wl,--gc-sections -Wl,-Map="$out/daran-m0.map" \
  "$out"/obj/main/*.o "$out"/obj/core/*.o --specs=nano.specs -lm -lc -lgcc -o "$out/daran-m0.elf"

commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
dirty=""
[ -n "$(git status --porcelain -- src include 2>/dev/null)" ] && dirty=" with uncommitted changes in src/ or include/"
echo "Core of commit $commit$dirty, $($cc --version | head -1), flags \`$cflags\`."
echo
echo "Core objects (\`arm-none-eabi-size -t $out/obj/core/*.o\`, last line):"
echo
echo '```'
arm-none-eabi-size -t "$out"/obj/core/*.o | tail -1
echo '```'
echo
python3 bench/m0/map_summary.py "$out/daran-m0.map"
