#!/bin/sh
# Flash of the port-extension mechanism on the Cortex-M4, and the two
# instruction-count images of bench/extensions (issue 14).
#
#   bench/extensions/build.sh [OUT_DIR]      (default build/bench/extensions)
#
# The core is built by its own CMake with cmake/cortex-m4.cmake and
# MinSizeRel, as the cortex-m4 preset builds it (-Os), four times:
#   none   no options header (no port rows, the default)
#   brake  examples/port-brake/brake_options.h (2 rows, 5 vendor rows omitted)
#   rows   bench/extensions/rows_only.h (the example's 2 rows only)
#   omit   bench/extensions/omit_only.h (the example's 5 omissions only)
# then src/ascii/drive.c and src/ascii/command_table.c once more with the core's exact
# compile command, through no_port_drive.c / no_port_command_table.c (the
# port hooks compiled away), for what the hooks add to those objects.
# Links OUT_DIR/ext-none.elf and OUT_DIR/ext-brake.elf (ext_main.c,
# examples/port-brake/brake_port.c, the mps2-an386 board's startup and UART
# with semihosting exit, newlib-nano) and prints the flash tables (flash.py).
set -eu
cd "$(dirname "$0")/../.."
out=${1:-build/bench/extensions}
mkdir -p "$out"
root=$(pwd)
cpu="-mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16"
# the cortex-m4 preset's flags for the core (cmake/cortex-m4.cmake, MinSizeRel)
cflags="$cpu -Os -fno-schedule-insns2 -fno-if-conversion -ffunction-sections -fdata-sections -DNDEBUG -fno-math-errno -fno-tree-loop-distribute-patterns -std=c99"

core() { # name options-header
  cmake -S . -B "$out/core-$1" -G Ninja -DCMAKE_TOOLCHAIN_FILE="$root/cmake/cortex-m4.cmake" \
    -DCMAKE_BUILD_TYPE=MinSizeRel -DCMAKE_EXPORT_COMPILE_COMMANDS=ON \
    -DDARAN_BUILD_FIRMWARE=OFF -DDARAN_BUILD_TESTS=OFF -DDARAN_BUILD_SIM=OFF \
    -DDARAN_BUILD_DEMO=OFF -DDARAN_BUILD_BENCH=OFF -DDARAN_CONFIG_HEADER="$2" >/dev/null
  cmake --build "$out/core-$1" --target daran_ascii >/dev/null
}
core none ""
core brake "$root/examples/port-brake/brake_options.h"
core rows "$root/bench/extensions/rows_only.h"
core omit "$root/bench/extensions/omit_only.h"

# The hooks compiled away: the core's own command for the object, on the wrapper.
python3 - "$out/core-none" <<'EOF'
import glob, json, os, shlex, subprocess, sys
tree = sys.argv[1]
commands = json.load(open(os.path.join(tree, "compile_commands.json")))
for source, wrapper in (("ascii/drive.c", "no_port_drive.c"),
                        ("ascii/command_table.c", "no_port_command_table.c")):
    entry = next(e for e in commands if e["file"].endswith("/src/" + source))
    args = shlex.split(entry["command"])
    args = [a for a in args if not a.startswith(("-fstack-usage", "-fcallgraph-info"))]
    out = os.path.abspath(os.path.join(tree, "no-port-" + os.path.basename(source)[:-2] + ".o"))
    args[args.index("-o") + 1] = out
    args[args.index("-c") + 1] = os.path.abspath(os.path.join("bench/extensions", wrapper))
    for room in ["src"] + sorted(glob.glob("src/*/")):
        args.insert(1, "-I" + os.path.abspath(room))
    subprocess.run(args, check=True, cwd=entry["directory"])
EOF

image() { # name options-header
  obj=$out/obj-$1
  rm -rf "$obj"
  mkdir -p "$obj"
  config=""
  [ -n "$2" ] && config="-DDARAN_CONFIG_HEADER=$2"
  for source in bench/extensions/ext_main.c examples/port-brake/brake_port.c \
      port/mps2-an386/startup.c port/mps2-an386/board.c port/mps2-an386/cortex_m.c; do
    # shellcheck disable=SC2086
    arm-none-eabi-gcc $cflags -Wall -Wextra -Werror $config -DDARAN_FW_SEMIHOSTING=1 \
      -Iinclude -Iport/mps2-an386 -Iexamples/port-brake -c "$source" \
      -o "$obj/$(basename "$source" .c).o"
  done
  # shellcheck disable=SC2086
  arm-none-eabi-gcc $cpu -nostartfiles -T port/mps2-an386/mps2_an386.ld --specs=nano.specs \
    -Wl,--gc-sections -Wl,-Map="$out/ext-$1.map" "$obj"/*.o "$out/core-$1/src/libdaran_ascii.a" \
    -lm -o "$out/ext-$1.elf"
}
image none ""
image brake "$root/examples/port-brake/brake_options.h"

commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
dirty=""
[ -n "$(git status --porcelain -- src include examples/port-brake 2>/dev/null)" ] &&
  dirty=" with uncommitted changes in src/, include/ or examples/port-brake/"
echo "Measured on commit $commit$dirty, $(arm-none-eabi-gcc --version | head -1),"
echo "the core built with \`cmake/cortex-m4.cmake\` and MinSizeRel (\`-Os\`, as the \`cortex-m4\` preset);"
echo "the port's object with \`$cflags\`."
echo
python3 bench/extensions/flash.py "$out"
