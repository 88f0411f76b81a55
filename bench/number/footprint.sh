#!/bin/sh
# Flash cost on Cortex-M4 (arm-none-eabi-gcc -Os, newlib-nano): the number module
# alone, then whole-program deltas of newlib strtof, newlib snprintf("%f") and
# our module over an empty program. Usage: bench/number/footprint.sh
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
out=$(mktemp -d)
cflags="-Os -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16 -ffunction-sections -fdata-sections"
arm-none-eabi-gcc $cflags -std=c99 -I"$root/include" -I"$root/src" -I"$root/src/text" -c "$root/src/text/number.c" -o "$out/number.o"
echo "== number.o ($cflags)"
arm-none-eabi-size "$out/number.o"
echo "== aeabi double helpers referenced by number.o (should be none):"
arm-none-eabi-nm "$out/number.o" | grep -i aeabi_d || echo "(none)"
echo "== double-precision instructions in number.o (should be none):"
arm-none-eabi-objdump -d "$out/number.o" | grep -E '\.f64|vcvt\.f64' || echo "(none)"
base=0
for v in 0 1 2 3; do
    extra=""
    [ "$v" = 2 ] && extra="-u _printf_float"
    src="$root/bench/number/footprint/fp_main.c"
    objs=""
    [ "$v" = 3 ] && objs="$out/number.o"
    arm-none-eabi-gcc $cflags -DVARIANT=$v -I"$root/include" -I"$root/src" -I"$root/src/text" "$src" $objs \
        --specs=nano.specs --specs=nosys.specs -Wl,--gc-sections $extra -o "$out/v$v.elf"
    set -- $(arm-none-eabi-size "$out/v$v.elf" | tail -1)
    total=$(( $1 + $2 ))
    [ "$v" = 0 ] && base=$total
    case $v in 0) name="empty program";; 1) name="newlib-nano strtof";; 2) name="newlib-nano snprintf %f (-u _printf_float)";; 3) name="daran_parse_f32 + daran_format_float";; esac
    printf '%-45s text+data %6d  delta %6d\n' "$name" "$total" $(( total - base ))
done
rm -rf "$out"
