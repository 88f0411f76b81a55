/* Configuration (c) of the configuration tests, given to the build as a user
 * options header: -DDARAN_CONFIG_HEADER=<path to this file>. It is what a
 * firmware project would keep next to its own sources. */
#ifndef CONFIG_C_H
#define CONFIG_C_H

#define DARAN_ENABLE_MULTI_MOTOR 0
#define DARAN_RX_RING_SIZE 32
#define DARAN_LINE_MAX 256

#endif /* CONFIG_C_H */
