# Arm MPS2+ with the AN505 FPGA image: a Cortex-M33 (FPv5 single precision,
# DSP, TrustZone) in an SSE-200 subsystem, QEMU mps2-an505. Another memory
# map than the MPS2 boards (mps2_an505.ld: Secure aliases, code at
# 0x10000000, RAM at 0x38000000) and UART0 elsewhere (board.c); the
# example's startup.c serves as it is.
set(DARAN_BOARD_QEMU_MACHINE mps2-an505)
set(DARAN_BOARD_QEMU_ARGS "")
set(DARAN_BOARD_SOURCES ${DARAN_MPS2_DIR}/startup.c ${DARAN_BOARD_DIR}/board.c ${DARAN_MPS2_DIR}/cortex_m.c)
set(DARAN_BOARD_DEFINITIONS DARAN_BOARD_SYSCLK_HZ=20000000u)
set(DARAN_BOARD_INCLUDE_DIR ${DARAN_MPS2_DIR})
set(DARAN_BOARD_LINKER_SCRIPT ${DARAN_BOARD_DIR}/mps2_an505.ld)
# SSRAM2 and SSRAM3 together: 4 MiB of RAM, 4 MiB of code, as on the AN386.
set(DARAN_BOARD_TEST_MEMORY
  __daran_flash_size=4M __daran_ram_size=4M __daran_stack_size=64K __daran_heap_size=256K)
