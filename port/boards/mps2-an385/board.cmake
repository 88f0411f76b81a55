# Arm MPS2 with the AN385 FPGA image: a Cortex-M3 (no FPU) on the board the
# example firmware uses. QEMU's mps2-an385 has the AN386's memory map (ZBT
# SSRAM1, 4 MiB at 0; SSRAM2/3, 4 MiB at 0x20000000) and its CMSDK UART0 at
# 0x40004000: the example's startup, board services and linker script serve
# as they are (startup.c enables the FPU only when the CPU has one).
set(DARAN_BOARD_QEMU_MACHINE mps2-an385)
set(DARAN_BOARD_QEMU_ARGS "")
set(DARAN_BOARD_SOURCES ${DARAN_MPS2_DIR}/startup.c ${DARAN_MPS2_DIR}/board.c ${DARAN_MPS2_DIR}/cortex_m.c)
set(DARAN_BOARD_INCLUDE_DIR ${DARAN_MPS2_DIR})
set(DARAN_BOARD_LINKER_SCRIPT ${DARAN_MPS2_DIR}/mps2_an386.ld)
set(DARAN_BOARD_TEST_MEMORY
  __daran_flash_size=4M __daran_ram_size=4M __daran_stack_size=64K __daran_heap_size=256K)
