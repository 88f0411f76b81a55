/* Flash measurement only (bench/extensions/build.sh): the five omissions of
 * examples/port-brake/brake_options.h, without its two rows. */
#ifndef BENCH_OMIT_ONLY_H
#define BENCH_OMIT_ONLY_H
#define DARAN_OMIT_PROPERTIES(X) \
    X(ENCODER_SPI_BUFF_0) \
    X(ENCODER_SPI_BUFF_1) \
    X(ENCODER_SPI_BUFF_2) \
    X(ENCODER_POS_ABS) \
    X(ENCODER_TURN_ABS)
#endif
