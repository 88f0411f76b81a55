# BBC micro:bit: an nRF51822 (Cortex-M0: ARMv6-M, no FPU, no hardware
# divide, no unaligned access), QEMU microbit. Its own UART (board.c) and
# memory map (nrf51.ld); the example's startup.c serves as it is (the
# nRF51 has 32 interrupts, as the table there).
set(DARAN_BOARD_QEMU_MACHINE microbit)
# The unit suites' test data do not fit the nRF51's 16 KiB of RAM (see
# nrf51.ld): QEMU's SRAM is made 2 MiB for the test images, which link for
# that much. daran-perf.elf needs and assumes only the real 16 KiB
# (measure_insns.py runs it without this option).
set(DARAN_BOARD_QEMU_ARGS -global nrf51-soc.sram-size=0x200000)
set(DARAN_BOARD_SOURCES ${DARAN_MPS2_DIR}/startup.c ${DARAN_BOARD_DIR}/board.c ${DARAN_MPS2_DIR}/cortex_m.c)
set(DARAN_BOARD_DEFINITIONS DARAN_BOARD_SYSCLK_HZ=16000000u)
set(DARAN_BOARD_INCLUDE_DIR ${DARAN_MPS2_DIR})
set(DARAN_BOARD_LINKER_SCRIPT ${DARAN_BOARD_DIR}/nrf51.ld)
set(DARAN_BOARD_TEST_MEMORY
  __daran_flash_size=256K __daran_ram_size=2M __daran_stack_size=64K __daran_heap_size=256K)
