#!/bin/sh
# Flash and instructions per line of the port-extension mechanism on the
# Cortex-M4 (issue 14; docs/performance.md, "Port extensions: flash and
# instructions"). Prints a Markdown block.
#
#   bench/extensions/measure.sh [OUT_DIR]      (default build/bench/extensions)
#
# build.sh builds the core four ways with the cortex-m4 toolchain (no port
# rows, examples/port-brake's options header, its rows only, its omissions
# only), prints the flash tables and links ext-none.elf / ext-brake.elf
# (ext_main.c with the example's `sb` table); both then run under QEMU
# mps2-an386 with tools/qemu-insn-count/measure_insns.py, and report.py puts
# the counts side by side. Needs arm-none-eabi-gcc, cmake, ninja,
# qemu-system-arm (mps2-an386), a host cc for the plugin, python3. About 11 s
# from nothing (the four core configurations), 4 s again.
set -eu
cd "$(dirname "$0")/../.."
out=${1:-build/bench/extensions}
sh bench/extensions/build.sh "$out"
for image in none brake; do
  python3 tools/qemu-insn-count/measure_insns.py --elf "$out/ext-$image.elf" \
    --json "$out/ext-$image.json" >/dev/null
done
echo
echo "Instructions per step, $(qemu-system-arm --version | head -1), machine \`mps2-an386\`"
echo "(\`python3 tools/qemu-insn-count/measure_insns.py --elf $out/ext-{none,brake}.elf\`; the"
echo "marker's cost subtracted; each line through \`daran_rx_write()\` + \`daran_poll()\` as in"
echo "\`tests/target/perf_main.c\`, replies to a sink that counts them):"
echo
python3 bench/extensions/report.py "$out/ext-none.json" "$out/ext-brake.json"
