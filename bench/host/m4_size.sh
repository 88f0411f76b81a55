#!/bin/sh
# Flash and RAM on Cortex-M4F: daran-ascii against the sscanf/printf
# (baseline) and the hand-written yardsticks, each linked into the minimal image of m4_main.c with newlib-nano and
# --gc-sections, minus the same image without a parser.
#
#   bench/host/m4_size.sh [OUT_DIR]      (default build/bench/m4)
#
# Prints one table row per image and, from the link maps, how many bytes of
# each image come from the core/baseline, libc (newlib-nano), libm and libgcc.
set -eu
cd "$(dirname "$0")/../.."
out=${1:-build/bench/m4}
mkdir -p "$out"
cc=arm-none-eabi-gcc
cpu="-mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16"
cflags="$cpu -Os -std=c99 -ffunction-sections -fdata-sections -fno-math-errno -fno-tree-loop-distribute-patterns -Iinclude -Isrc $(for room in src/*/; do printf -- "-I%s " "${room%/}"; done)-I$out/generated -Ibench/baseline"
ldflags="$cpu --specs=nano.specs --specs=nosys.specs -Wl,--gc-sections"
# The core's sources: the DARAN_CORE_SOURCES list of cmake/DaranAddLibrary.cmake.
core_sources=$(sed -n '/PROPERTY DARAN_CORE_SOURCES/,/)/p' cmake/DaranAddLibrary.cmake |
  grep -o '[a-z_0-9/]*\.c' | sed 's|^|src/|')
if [ -z "$core_sources" ]; then
  echo "m4_size.sh: no core sources found in cmake/DaranAddLibrary.cmake" >&2
  exit 1
fi

# Objects first, one folder per part, so the link maps say where each byte came from.
compile() { # part parser-number sources...
  part=$1 parser=$2
  shift 2
  mkdir -p "$out/obj/$part"
  for source in "$@"; do
    # shellcheck disable=SC2086
    $cc $cflags -DBENCH_PARSER="$parser" -DDARAN_VERSION_STRING='"bench"' -c "$source" \
      -o "$out/obj/$part/$(basename "$source" .c).o"
  done
}
link() { # image extra-flags parts...
  image=$1 extra=$2
  shift 2
  objects=""
  for part in "$@"; do
    objects="$objects $out/obj/$part/*.o"
  done
  # shellcheck disable=SC2086
  $cc $objects $ldflags $extra -Wl,-Map="$out/$image.map" -lm -o "$out/$image.elf"
}

rm -rf "$out/obj"
# The core's property index (perfect hash), generated as the core's build does.
mkdir -p "$out/generated"
python3 tools/gen_property_index.py --list include/daran_properties.h --omit "" \
  --out "$out/generated/property_index.h"
compile main-empty 0 bench/host/m4_main.c
compile main-daran 1 bench/host/m4_main.c
compile main-baseline 2 bench/host/m4_main.c
compile main-handwritten 3 bench/host/m4_main.c
# shellcheck disable=SC2086
compile core 1 $core_sources
compile baseline 2 bench/baseline/baseline.c
compile handwritten 3 bench/baseline/handwritten.c
# The same core without the `h` help strings (DARAN_ENABLE_HELP=0).
all_cflags=$cflags
cflags="$cflags -DDARAN_ENABLE_HELP=0"
# shellcheck disable=SC2086
compile core-nohelp 1 $core_sources
cflags=$all_cflags

link empty "" main-empty
link daran "" main-daran core
link daran-nohelp "" main-daran core-nohelp
# A firmware that scans and prints floats with newlib-nano must ask for it.
link baseline "-u _printf_float -u _scanf_float" main-baseline baseline
link handwritten "" main-handwritten handwritten

commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
dirty=""
[ -n "$(git status --porcelain -- src include 2>/dev/null)" ] && dirty=" with uncommitted changes in src/ or include/"
echo "Measured on commit $commit$dirty, $($cc --version | head -1), newlib-nano; flags:"
echo "\`$cflags\`, link \`$ldflags\` (+ \`-u _printf_float -u _scanf_float\` for the baseline)."
echo
python3 bench/host/m4_map_summary.py "$out"
echo
echo "\`arm-none-eabi-size\` of the five images:"
echo
echo '```'
(cd "$out" && arm-none-eabi-size empty.elf daran.elf daran-nohelp.elf baseline.elf handwritten.elf)
echo '```'

