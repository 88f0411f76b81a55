# Shared part of the bare-metal Arm toolchain files: the GNU Arm Embedded
# compilers and binutils, the C library per image (newlib-nano for firmware),
# no host programs in try_compile.
# A per-CPU file (cortex-m4.cmake) sets DARAN_ARM_CPU_FLAGS (and optionally
# DARAN_ARM_OPT_FLAGS) and includes this.
include_guard(GLOBAL)

set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)

set(DARAN_ARM_PREFIX "arm-none-eabi-" CACHE STRING "Prefix of the bare-metal Arm binutils and gcc")

find_program(CMAKE_C_COMPILER NAMES ${DARAN_ARM_PREFIX}gcc REQUIRED)
find_program(CMAKE_ASM_COMPILER NAMES ${DARAN_ARM_PREFIX}gcc REQUIRED)
find_program(CMAKE_AR NAMES ${DARAN_ARM_PREFIX}ar REQUIRED)
find_program(CMAKE_RANLIB NAMES ${DARAN_ARM_PREFIX}ranlib REQUIRED)
find_program(CMAKE_OBJCOPY NAMES ${DARAN_ARM_PREFIX}objcopy REQUIRED)
find_program(CMAKE_OBJDUMP NAMES ${DARAN_ARM_PREFIX}objdump REQUIRED)
find_program(CMAKE_NM NAMES ${DARAN_ARM_PREFIX}nm REQUIRED)
find_program(CMAKE_SIZE NAMES ${DARAN_ARM_PREFIX}size REQUIRED)

# A bare-metal link needs a startup file and a linker script: compiler checks
# build a static library instead of an executable.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

# Never pick up host libraries or headers.
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

set(DARAN_ARM_COMMON_FLAGS "${DARAN_ARM_CPU_FLAGS} ${DARAN_ARM_OPT_FLAGS} -ffunction-sections -fdata-sections")
set(CMAKE_C_FLAGS_INIT "${DARAN_ARM_COMMON_FLAGS}")
set(CMAKE_ASM_FLAGS_INIT "${DARAN_ARM_CPU_FLAGS}")
set(CMAKE_EXE_LINKER_FLAGS_INIT "${DARAN_ARM_CPU_FLAGS} -Wl,--gc-sections")

# The C library, chosen per image at link time: newlib-nano for the firmware
# (the small C library; the firmware brings its own startup and uses no
# stdio, so no syscall stubs are linked and a stray printf fails the link or
# the symbol budget instead of pulling in kilobytes), the full newlib for the
# Unity test images (printf of floats, %a and %zu in the tests' messages).
# daran_fw_image() in port/mps2-an386 adds these flags to firmware images only.
set(DARAN_ARM_NANO_LINK_FLAGS "--specs=nano.specs")

set(CMAKE_C_FLAGS_DEBUG_INIT "-Og -g3")

set(CMAKE_EXECUTABLE_SUFFIX_C ".elf")
