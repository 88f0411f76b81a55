# Toolchain file: Arm Cortex-M33 (ARMv8-M Mainline, single-precision FPv5,
# hard-float ABI, DSP), arm-none-eabi-gcc, size-optimised. Used by the
# `cortex-m33` preset (QEMU `mps2-an505`, SSE-200, run in the Secure state).
set(DARAN_ARM_CPU_FLAGS "-mcpu=cortex-m33 -mthumb -mfloat-abi=hard -mfpu=fpv5-sp-d16")
# The cortex-m4 file's optimisation flags, so figures compare CPU with CPU.
set(DARAN_ARM_OPT_FLAGS "-Os -fno-schedule-insns2 -fno-if-conversion")
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi.cmake)
