#!/usr/bin/env bash
# ci-weight: 165
# Packaging and configuration suite (issue 8), run by tools/test:
#   1. the API reference builds with no doxygen warning;
#   2. `cmake --install` of a release build, then three consumers build and run
#      against it (find_package, add_subdirectory, pkg-config), a master-side
#      one links daran_ascii::daran_client from the prefix (find_package only:
#      daran_ascii.pc names the core alone), and the package's version file
#      answers SameMajorVersion;
#   3. an install built with a user options header (DARAN_CONFIG_HEADER) still
#      agrees with its consumers, and one built with other options is refused;
#      relative headers name files of the consumer's folders;
#   4. seven daran_config.h configurations (defaults, the issue's (b) and (c),
#      the lower and the upper limits, discovery/telemetry/port commands/S-curve
#      off, the seed-only header) each build the core and pass tests/config, and
#      impossible options stop the compiler at #error.
# Release flags, Ninja, no sanitizers; budget 2 minutes. Exits non-zero on the
# first failure, after printing that step's log.
set -euo pipefail
cd "$(dirname "$0")/../.."
repo=$(pwd)

need=()
command -v doxygen >/dev/null 2>&1 || need+=(doxygen)
command -v pkg-config >/dev/null 2>&1 || need+=(pkg-config)
if [ ${#need[@]} -gt 0 ]; then
  echo "50-package: installing ${need[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null
fi

source tools/ci-steps.bash
ci_steps_begin 50-package

doxygen_clean() {
  # WARN_AS_ERROR=YES already fails the run; an empty log proves it said nothing.
  (cat Doxyfile; echo "OUTPUT_DIRECTORY=$work/doxygen") | doxygen - >"$work/doxygen.log" 2>&1 ||
    { cat "$work/doxygen.log"; return 1; }
  if [ -s "$work/doxygen.log" ]; then cat "$work/doxygen.log"; return 1; fi
  test -f "$work/doxygen/html/daran__drive_8h.html"
}

# install_core BUILD PREFIX [cmake args...]: a library-only release build, installed.
install_core() {
  local build=$1 prefix=$2
  shift 2
  cmake -S "$repo" -B "$build" -DCMAKE_BUILD_TYPE=Release -DDARAN_BUILD_TESTS=OFF \
    -DDARAN_BUILD_SIM=OFF -DDARAN_BUILD_DEMO=OFF -DDARAN_BUILD_BENCH=OFF "$@" &&
    cmake --build "$build" "${jobs[@]}" &&
    cmake --install "$build" --prefix "$prefix"
}

check_install_tree() {
  local prefix=$1
  for f in include/daran_ascii.h include/daran_drive.h include/daran_hal.h \
           include/daran_config.h include/daran_properties.h include/daran_result.h \
           include/daran_can.h include/daran_client.h include/daran_protocol.h lib/libdaran_client.a \
           lib/libdaran_ascii.a lib/pkgconfig/daran_ascii.pc lib/pkgconfig/daran_client.pc \
           lib/cmake/daran_ascii/daran_asciiConfig.cmake \
           lib/cmake/daran_ascii/daran_asciiConfigVersion.cmake \
           lib/cmake/daran_ascii/daran_asciiTargets.cmake; do
    [ -f "$prefix/$f" ] || { echo "missing from the install: $f"; return 1; }
  done
  # the command-line tool, built and installed with the package, runs from the prefix
  [ -x "$prefix/bin/daran" ] || { echo "missing from the install: bin/daran"; return 1; }
  "$prefix/bin/daran" --help | grep -q "^  scan" || { echo "bin/daran --help lists no commands"; return 1; }
}

# consumer_cmake SOURCE BUILD [cmake args...]: configure, build and run tests/consumer/*.
consumer_cmake() {
  local src=$1 build=$2
  shift 2
  cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release "$@" &&
    cmake --build "$build" "${jobs[@]}" &&
    "$build/consumer"
}

consumer_pkg_config() {
  local prefix=$1 out=$2
  export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
  [ "$(pkg-config --modversion daran_ascii)" = "$(sed -n "s/^#define DARAN_VERSION_\(MAJOR\|MINOR\|PATCH\) \([0-9]*\).*/\2/p" include/daran_version.h | paste -sd.)" ] || { echo "wrong --modversion"; return 1; }
  pkg-config --static --libs daran_ascii | grep -q -- -lm || { echo "no -lm in --static --libs"; return 1; }
  # shellcheck disable=SC2046  # the flags must split into words
  cc -std=c99 -Wall -Wextra -Werror -Itests/support -o "$out" tests/consumer/consumer.c tests/support/stub_hal.c \
    $(pkg-config --cflags --libs daran_ascii) &&
    "$out"
}

# The client through its own .pc (which requires the core's).
client_pkg_config() {
  local prefix=$1 out=$2
  export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
  # shellcheck disable=SC2046  # the flags must split into words
  cc -std=c99 -Wall -Wextra -Werror -Itests/support -o "$out" tests/consumer/client_consumer.c \
    tests/support/stub_hal.c $(pkg-config --cflags --libs daran_client) &&
    "$out"
}

# config_suite NAME [cmake args...]: one configuration of daran_config.h.
config_suite() {
  local build="$work/config-$1"
  shift
  cmake -S tests/config -B "$build" -DCMAKE_BUILD_TYPE=Release "$@" &&
    cmake --build "$build" "${jobs[@]}" &&
    ctest --test-dir "$build" --output-on-failure --no-tests=error
}

step "doxygen: API reference from include/, no warnings" doxygen_clean

prefix="$work/prefix"
step "install: release build of the core to a temporary prefix" \
  install_core "$work/core" "$prefix"
step "install: headers, library, CMake package and .pc are in place" check_install_tree "$prefix"
step "install: version file is SameMajorVersion (0.1 yes, 1.0 no)" \
  cmake -DPREFIX="$prefix" -P tests/consumer/version_check.cmake
step "consumer: find_package(daran_ascii CONFIG) from the prefix" \
  consumer_cmake tests/consumer/find_package "$work/consumer-find" -DCMAKE_PREFIX_PATH="$prefix"
step "consumer: daran_ascii::daran_client from the prefix builds, reads and talks to a core" \
  "$work/consumer-find/client_consumer"
step "consumer: add_subdirectory of the source tree" \
  consumer_cmake tests/consumer/add_subdirectory "$work/consumer-subdir" -DDARAN_SOURCE_DIR="$repo"
step "consumer: cc \$(pkg-config --cflags --libs daran_ascii)" \
  consumer_pkg_config "$prefix" "$work/consumer-pc"
step "consumer: cc \$(pkg-config --cflags --libs daran_client)" \
  client_pkg_config "$prefix" "$work/client-pc"

# A program compiled with other size options than the library must be refused
# by daran_init() (sizeof check), not run on a daran_drive_t of the wrong size.
consumer_mismatch_refused() {
  local prefix=$1 out=$2
  export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
  # shellcheck disable=SC2046
  cc -std=c99 -Wall -Wextra -Werror -DDARAN_LINE_MAX=64 -Itests/support -o "$out" tests/consumer/consumer.c tests/support/stub_hal.c \
    $(pkg-config --cflags --libs daran_ascii) || return 1
  if "$out" >"$out.log" 2>&1; then
    echo "a consumer built with DARAN_LINE_MAX=64 ran against a 128 library"; return 1
  fi
  cat "$out.log"
  grep -q "daran_init refused the instance: build mismatch" "$out.log"
}
step "consumer: built with other size options, daran_init() refuses it" \
  consumer_mismatch_refused "$prefix" "$work/consumer-mismatch"

# docs/porting.md 5.1: a project names its options header with a plain set()
# before add_subdirectory(); under its CMake 3.20 policies (CMP0126 OLD) the
# header must still reach the library (it used to be dropped silently).
step "consumer: set(DARAN_CONFIG_HEADER ...) before add_subdirectory reaches the library (CMP0126 OLD)" \
  consumer_cmake tests/consumer/add_subdirectory "$work/consumer-subdir-c" -DDARAN_SOURCE_DIR="$repo" \
  -DCONSUMER_OPTIONS_HEADER="$repo/tests/config/config_c.h" -DCONSUMER_EXPECT_LINE_MAX=256

# Relative options headers: DARAN_CONFIG_HEADER against the consumer's
# top-level folder, daran_ascii_add_library(CONFIG_HEADER) against the folder
# of its caller (the first used to be looked for under the library's src/).
relative_headers() {
  local build="$work/consumer-relative"
  cmake -S tests/consumer/relative_header -B "$build" -DCMAKE_BUILD_TYPE=Release \
    -DDARAN_SOURCE_DIR="$repo" &&
    cmake --build "$build" "${jobs[@]}" --target consumer_project_header consumer_app_header &&
    "$build/consumer_project_header" && "$build/app/consumer_app_header"
}
step "consumer: relative options headers, of the project's top folder and of the caller's folder" \
  relative_headers

# Same size, another property table: a program compiled with a header that
# leaves a row out must be refused by the library built without it.
consumer_table_mismatch_refused() {
  local prefix=$1 out=$2
  export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
  printf '#define DARAN_OMIT_PROPERTIES(X) X(ENCODER_POS_ABS)\n' >"$work/omits_one_row.h"
  # shellcheck disable=SC2046
  cc -std=c99 -Wall -Wextra -Werror -DDARAN_CONFIG_HEADER="$work/omits_one_row.h" -Itests/support \
    -o "$out" tests/consumer/consumer.c tests/support/stub_hal.c \
    $(pkg-config --cflags --libs daran_ascii) || return 1
  if "$out" >"$out.log" 2>&1; then
    echo "a consumer built with another property table ran against the vendor-table library"; return 1
  fi
  cat "$out.log"
  grep -q "daran_init refused the instance: build mismatch" "$out.log"
}
step "consumer: built with another property table (same size), daran_init() refuses it" \
  consumer_table_mismatch_refused "$prefix" "$work/consumer-table-mismatch"

# The library's own suites and benchmarks with an adopter's options header,
# named as docs/performance.md does (relative to the top folder): the suites
# that assume the vendor's table step aside (tests/CMakeLists.txt,
# bench/host/CMakeLists.txt), the rest pass; tests/stress compiles its copy
# of the core for that header. The examples (DARAN_BUILD_DEMO) build cores of
# their own headers and run in the host presets: left out for time.
adopter_header_suites() {
  cmake --preset release -B "$work/adopter-header" -DDARAN_BUILD_DEMO=OFF \
    -DDARAN_CONFIG_HEADER=examples/port-brake/brake_options.h &&
    cmake --build "$work/adopter-header" "${jobs[@]}" &&
    ctest --test-dir "$work/adopter-header" --output-on-failure --no-tests=error -j 2
}
step "release preset with examples/port-brake/brake_options.h: every suite and benchmark it registers passes" \
  adopter_header_suites

# The options header must travel with the installed package: consumers check
# that a 256-byte line (config_c.h) is accepted by the library they link.
prefix_c="$work/prefix-c"
step "install: core built with DARAN_CONFIG_HEADER=tests/config/config_c.h" \
  install_core "$work/core-c" "$prefix_c" -DDARAN_CONFIG_HEADER="$repo/tests/config/config_c.h"
step "consumer: find_package of the configured install agrees on DARAN_LINE_MAX 256" \
  consumer_cmake tests/consumer/find_package "$work/consumer-find-c" -DCMAKE_PREFIX_PATH="$prefix_c"
step "consumer: daran_ascii::daran_client of the configured install talks to its core" \
  "$work/consumer-find-c/client_consumer"
step "consumer: pkg-config of the configured install agrees on DARAN_LINE_MAX 256" \
  consumer_pkg_config "$prefix_c" "$work/consumer-pc-c"

step "config (a): defaults, and impossible options stop at #error" \
  config_suite a -DDARAN_TEST_OPTION_ERRORS=ON \
  "-DDARAN_TEST_EXPECT=line_max=128;ring=128;reply_max=160;crlf=1;motor_id_max=63;help=1;multi=1;discovery=1;telemetry=1;port_commands=1;s_curve=1;prop_rows=165"
step "config (b): DARAN_LINE_MAX=64, DARAN_REPLY_CRLF=0, DARAN_ENABLE_HELP=0, the core as C99" \
  config_suite b "-DDARAN_TEST_DEFINES=DARAN_LINE_MAX=64;DARAN_REPLY_CRLF=0;DARAN_ENABLE_HELP=0" \
  -DDARAN_CORE_C_STANDARD=99 "-DDARAN_TEST_EXPECT=line_max=64;crlf=0;help=0;multi=1;ring=128;discovery=0"
step "config (c): user header: no multi-motor, 32-byte ring, 256-byte lines" \
  config_suite c -DDARAN_CONFIG_HEADER="$repo/tests/config/config_c.h" \
  "-DDARAN_TEST_EXPECT=line_max=256;ring=32;multi=0;help=1;crlf=1"
# The largest values daran_config.h allows: 16-bit ring and line indices at
# their edge (ids past 63 leave no room for CAN's 6-bit node ids: no CAN).
step "config (d): upper limits: 1024-byte lines and replies, 32768-byte ring, ids to 255, no CAN" \
  config_suite d \
  "-DDARAN_TEST_DEFINES=DARAN_LINE_MAX=1024;DARAN_RX_RING_SIZE=32768;DARAN_REPLY_MAX=1024;DARAN_MOTOR_ID_MAX=255;DARAN_ENABLE_CAN=0" \
  "-DDARAN_TEST_EXPECT=line_max=1024;ring=32768;reply_max=1024;motor_id_max=255"
# The smallest values daran_config.h allows, with both features off: a ring
# smaller than a line, and ids only up to 1 (the one-digit fast path).
step "config (e): lower limits: 32-byte lines, 16-byte ring, id 1 only, no help, no multi" \
  config_suite e \
  "-DDARAN_TEST_DEFINES=DARAN_LINE_MAX=32;DARAN_RX_RING_SIZE=16;DARAN_MOTOR_ID_MAX=1;DARAN_ENABLE_HELP=0;DARAN_ENABLE_MULTI_MOTOR=0" \
  "-DDARAN_TEST_EXPECT=line_max=32;ring=16;motor_id_max=1;help=0;multi=0"
# The features the seed document lacks, each compiled out (docs/porting.md 5.1),
# with the vendor's whole table and the smallest reply a build may have.
step "config (f): no discovery, telemetry, port commands or S-curve; 88-byte replies" \
  config_suite f \
  "-DDARAN_TEST_DEFINES=DARAN_ENABLE_DISCOVERY=0;DARAN_ENABLE_TELEMETRY=0;DARAN_ENABLE_PORT_COMMANDS=0;DARAN_ENABLE_S_CURVE=0;DARAN_REPLY_MAX=88" \
  "-DDARAN_TEST_EXPECT=help=1;multi=1;discovery=0;telemetry=0;port_commands=0;s_curve=0;reply_max=88;prop_rows=165"
# The seed-only build (the cortex-m4-seed preset's header) on the host.
step "config (g): tests/config/seed_options.h: the seed's 57 rows, its features only" \
  config_suite g -DDARAN_CONFIG_HEADER="$repo/tests/config/seed_options.h" \
  "-DDARAN_TEST_EXPECT=help=1;multi=1;discovery=0;telemetry=0;port_commands=0;s_curve=0;prop_rows=57"

ci_steps_end
