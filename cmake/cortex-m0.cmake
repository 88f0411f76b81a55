# Toolchain file: Arm Cortex-M0 (ARMv6-M: no FPU, no hardware divide, no
# unaligned access), arm-none-eabi-gcc, size-optimised, soft float from
# libgcc. Used by the `cortex-m0` preset (QEMU `microbit`, nRF51822).
set(DARAN_ARM_CPU_FLAGS "-mcpu=cortex-m0 -mthumb -mfloat-abi=soft")
# The cortex-m4 file's optimisation flags, so figures compare CPU with CPU.
set(DARAN_ARM_OPT_FLAGS "-Os -fno-schedule-insns2 -fno-if-conversion")
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi.cmake)
