/** @file daran_update.h
 * Updating a drive's firmware over its own link (docs/update.md): the image
 * format, what the port gives (two flash regions and its boot control), and
 * the update module a drive binds (compiled with DARAN_ENABLE_UPDATE).
 *
 * The host sends `ub` (begin), `uw` (chunks, each with its offset and
 * CRC-32), `uv` (verify), `uc` (commit: boot the new image once, as a
 * test), and from the new image `uk` (keep it); `ua` aborts; `us` says the
 * state and the next offset the drive wants, so a host resumes after a lost
 * line, a closed port, a reboot or a power cut. The module writes only the
 * inactive slot and its journal; the running slot is never written. */
#ifndef DARAN_UPDATE_H
#define DARAN_UPDATE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "daran_drive.h"

#ifdef __cplusplus
extern "C" {
#endif

/** The image header: the first DARAN_UPDATE_HEADER_SIZE bytes of an image,
 * little-endian; the payload follows it. */
#define DARAN_UPDATE_HEADER_SIZE 128u
#define DARAN_UPDATE_MAGIC 0x554e5244u /**< "DRNU" */
#define DARAN_UPDATE_HEADER_VERSION 1u /**< the header's layout below */
/** Byte offsets of the header's fields. */
#define DARAN_UPDATE_AT_MAGIC 0u          /**< u32 DARAN_UPDATE_MAGIC */
#define DARAN_UPDATE_AT_HEADER_VERSION 4u /**< u16 DARAN_UPDATE_HEADER_VERSION */
#define DARAN_UPDATE_AT_FLAGS 6u          /**< u16 DARAN_UPDATE_FLAG_ bits */
#define DARAN_UPDATE_AT_PAYLOAD_SIZE 8u   /**< u32 bytes after the header */
#define DARAN_UPDATE_AT_VERSION 12u       /**< u32 the firmware's version */
#define DARAN_UPDATE_AT_HARDWARE_ID 16u   /**< u32 the board it runs on */
#define DARAN_UPDATE_AT_BUILD 20u         /**< u32 its property table's build signature */
#define DARAN_UPDATE_AT_PAYLOAD_CRC 24u   /**< u32 CRC-32 of the payload */
#define DARAN_UPDATE_AT_SHA256 32u        /**< 32 bytes: SHA-256 of the payload */
#define DARAN_UPDATE_AT_SIGNATURE 64u     /**< 64 bytes: Ed25519 over the SHA-256, when signed */
#define DARAN_UPDATE_FLAG_SIGNED 0x0001u /**< the header carries a signature */

/** The flash regions the port gives: the inactive slot (images are written
 * here from offset 0) and the update journal (one page, apart from both
 * slots, where the module keeps what survives a power cut). */
typedef enum daran_update_region {
    DARAN_UPDATE_SLOT = 0,
    DARAN_UPDATE_JOURNAL = 1
} daran_update_region_t;

/** What a slot holds, as the port's boot control says. */
typedef enum daran_update_slot_state {
    DARAN_SLOT_EMPTY = 0,     /**< no bootable image */
    DARAN_SLOT_CONFIRMED = 1, /**< an image kept (`uk`, or the factory's) */
    DARAN_SLOT_TESTING = 2,   /**< committed (`uc`): boots once; reverts unless kept */
    DARAN_SLOT_REVERTED = 3   /**< a test image that was not kept */
} daran_update_slot_state_t;

/** Both slots and which one runs. */
typedef struct daran_update_slots {
    uint32_t version[2]; /**< each slot's image version (0: none) */
    uint8_t state[2];    /**< daran_update_slot_state_t */
    uint8_t running;     /**< 0 or 1 */
    uint8_t reserved;    /**< 0 */
} daran_update_slots_t;

/** What the port gives the update module (daran_hal_t.update); every
 * function gets the drive's context. Flash functions return DARAN_OK or
 * DARAN_ERR_MOTOR_FAULT. */
typedef struct daran_update_port {
    uint32_t slot_size;   /**< bytes of the inactive slot (a whole number of pages) */
    uint32_t page_size;   /**< the erase unit, also the journal's size; 256..65536 */
    uint32_t hardware_id; /**< this board's: an image for another is refused at `ub` */
    bool require_signature; /**< refuse an image without a good signature */
    /** Set the page that holds @p offset to all ones. */
    daran_result_t (*erase)(void *ctx, daran_update_region_t region, uint32_t offset);
    /** Program @p len bytes at @p offset (bits only go from 1 to 0). */
    daran_result_t (*program)(void *ctx, daran_update_region_t region, uint32_t offset,
                              const uint8_t *data, size_t len);
    /** Read @p len bytes at @p offset. */
    daran_result_t (*read)(void *ctx, daran_update_region_t region, uint32_t offset,
                           uint8_t *data, size_t len);
    /** Mark the inactive slot to boot once as a test, then reset the drive
     * once the reply has gone out (the port's choice of how). */
    daran_result_t (*commit)(void *ctx);
    /** Keep the running image (it boots from now on). */
    daran_result_t (*confirm)(void *ctx);
    /** Both slots' versions and states, and which runs. */
    void (*slots)(void *ctx, daran_update_slots_t *out);
    /** Optional (NULL: signatures are not checked): is @p signature a good
     * Ed25519 signature of @p sha256 by the port's key? */
    bool (*signature_ok)(void *ctx, const uint8_t sha256[32], const uint8_t signature[64]);
} daran_update_port_t;

/** The module's state (`us`'s first value). */
typedef enum daran_update_state {
    DARAN_UPDATE_IDLE = 0,      /**< no update open */
    DARAN_UPDATE_RECEIVING = 1, /**< `ub` accepted: chunks are taken */
    DARAN_UPDATE_VERIFIED = 2   /**< `uv` accepted: `uc` may commit */
} daran_update_state_t;

/** @cond INTERNAL */
typedef struct daran_update {
    daran_drive_t *drive;
    uint32_t size;    /* the image's bytes, as `ub` gave them */
    uint32_t crc;     /* its CRC-32 */
    uint32_t version;
    uint32_t hardware_id;
    uint32_t next;    /* the next offset wanted */
    uint8_t state;    /* daran_update_state_t */
    uint8_t reserved[3];
} daran_update_t;
/** @endcond */

/** Bind @p update to @p drive (initialised with daran_init(), whose port
 * description has an `update` member) and read the journal: an update a
 * reset or a power cut interrupted is open again, its next offset the
 * start of the first page not written whole. DARAN_ERR_BAD_ARGUMENT for a
 * NULL pointer or a port without update functions. */
DARAN_NODISCARD daran_result_t daran_update_init(daran_update_t *update, daran_drive_t *drive);

/** Whether an update is open (motion is then refused: `update open`). */
bool daran_update_open(const daran_update_t *update);

#ifdef __cplusplus
}
#endif

#endif /* DARAN_UPDATE_H */
