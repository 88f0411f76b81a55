# Toolchain file: Arm Cortex-M4F (single-precision FPU, hard-float ABI),
# arm-none-eabi-gcc, size-optimised. Used by the `cortex-m4` preset.
set(DARAN_ARM_CPU_FLAGS "-mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16")
# Size first: a protocol core competes with the motor control for flash.
# The in-order Cortex-M4 gains little from GCC's second scheduling pass and
# from if-conversion, and both cost code (46 bytes of the core).
set(DARAN_ARM_OPT_FLAGS "-Os -fno-schedule-insns2 -fno-if-conversion")
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi.cmake)
