# Toolchain file: Arm Cortex-M3 (ARMv7-M: hardware divide, no FPU),
# arm-none-eabi-gcc, size-optimised, soft float from libgcc. Used by the
# `cortex-m3` preset (QEMU `mps2-an385`).
set(DARAN_ARM_CPU_FLAGS "-mcpu=cortex-m3 -mthumb -mfloat-abi=soft")
# The cortex-m4 file's optimisation flags, so figures compare CPU with CPU.
set(DARAN_ARM_OPT_FLAGS "-Os -fno-schedule-insns2 -fno-if-conversion")
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi.cmake)
