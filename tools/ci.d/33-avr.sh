#!/usr/bin/env bash
# ci-weight: 15
# A 16-bit-int machine: the core built with avr-gcc (ATmega1284P, -Os, the
# core's warning set as errors) runs tests/portability/portable_check.c under
# simavr, and its output must equal the same program's on the host: numbers
# parsed and printed, protocol lines and their replies. About 20 s.
set -euo pipefail
cd "$(dirname "$0")/../.."
repo=$(pwd)

need=()
command -v avr-gcc >/dev/null 2>&1 || need+=(gcc-avr avr-libc)
command -v simavr >/dev/null 2>&1 || need+=(simavr)
if [ ${#need[@]} -gt 0 ]; then
  echo "33-avr: installing ${need[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null
fi

work=$(mktemp -d "${TMPDIR:-/tmp}/daran-avr.XXXXXX")
trap 'rm -rf "$work"' EXIT
python3 tools/gen_property_index.py --list include/daran_properties.h --omit "" \
  --out "$work/property_index.h"
warnings=(-Wall -Wextra -Wpedantic -Wconversion -Wshadow -Wstrict-prototypes
          -Wmissing-prototypes -Werror)
includes=(-Iinclude -Isrc -Itests/support -I"$work")
for room in src/*/; do includes+=(-I"${room%/}"); done

# The host's answer: gcc, the same sources.
gcc -std=c11 -O2 "${warnings[@]}" "${includes[@]}" -o "$work/host" \
  src/*.c src/*/*.c tests/support/stub_hal.c tests/portability/portable_check.c -lm
"$work/host" >"$work/host.txt"

# The AVR's: C99 core (no <stdatomic.h> there; avr-gcc ships no __atomic
# library calls either, so the port's barrier), newlib-free avr-libc.
avr=(avr-gcc -mmcu=atmega1284p -Os -std=c99 -fno-math-errno
     '-DDARAN_PORT_BARRIER()=__sync_synchronize()' "${warnings[@]}" "${includes[@]}")
objs=()
for f in src/*.c src/*/*.c tests/support/stub_hal.c tests/portability/portable_check.c; do
  o="$work/$(basename "$f" .c).o"
  "${avr[@]}" -c "$f" -o "$o"
  objs+=("$o")
done
avr-gcc -mmcu=atmega1284p -Os "${objs[@]}" -lm -o "$work/avr.elf"
avr-size "$work/avr.elf" | tail -1 | awk '{print "33-avr: image text " $1 ", data " $2 ", bss " $3}'

# simavr shows the UART one line at a time, colour codes around it and a '.'
# where the newline was; the program writes no '.' at a line's end itself.
timeout 120 simavr -m atmega1284p -f 16000000 "$work/avr.elf" >"$work/raw.txt" 2>&1 || true
sed -e 's/\x1b\[[0-9;]*m//g' "$work/raw.txt" | grep -v '^Loaded \|^$\|^SIMAVR\|^simavr' |
  sed -e 's/\.$//' >"$work/avr.txt"

if diff -u "$work/host.txt" "$work/avr.txt" >"$work/diff.txt"; then
  echo "33-avr: $(wc -l <"$work/host.txt") records identical on the host and the 16-bit AVR"
else
  echo "33-avr: the AVR's output differs from the host's:"
  head -60 "$work/diff.txt"
  exit 1
fi
