# Toolchain file: Arm Cortex-M7 (ARMv7E-M, FPv5 with double precision as
# QEMU models it, hard-float ABI), arm-none-eabi-gcc, size-optimised. Used by
# the `cortex-m7` preset (QEMU `mps2-an500`).
set(DARAN_ARM_CPU_FLAGS "-mcpu=cortex-m7 -mthumb -mfloat-abi=hard -mfpu=fpv5-d16")
# The cortex-m4 file's optimisation flags, so figures compare CPU with CPU.
set(DARAN_ARM_OPT_FLAGS "-Os -fno-schedule-insns2 -fno-if-conversion")
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi.cmake)
