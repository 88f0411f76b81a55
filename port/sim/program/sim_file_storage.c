/* Host only: file-backed storage for the simulated drives' NVM. */
#define _POSIX_C_SOURCE 200809L
#include "sim_file_storage.h"

#include <errno.h>
#include <fcntl.h>
#include <string.h>
#include <unistd.h>

static bool file_read(void *ctx, uint32_t offset, uint8_t *buf, uint32_t len)
{
    const daran_sim_file_storage_t *fs = ctx;
    uint32_t done = 0u;
    memset(buf, 0xFF, len);
    while (done < len) {
        ssize_t n = pread(fs->fd, buf + done, len - done, (off_t)(offset + done));
        if (n < 0 && errno == EINTR) {
            continue;
        }
        if (n < 0) {
            return false;
        }
        if (n == 0) {
            break; /* past the end: erased */
        }
        done += (uint32_t)n;
    }
    return true;
}

static bool file_write(void *ctx, uint32_t offset, const uint8_t *data, uint32_t len)
{
    const daran_sim_file_storage_t *fs = ctx;
    uint32_t done = 0u;
    off_t size = lseek(fs->fd, 0, SEEK_END);
    /* fill a hole with erased bytes so it never reads as zeros */
    while (size >= 0 && (uint64_t)size < offset) {
        static const uint8_t ff[64] = {
            0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF,
            0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF,
            0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF,
            0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF,
            0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF};
        uint64_t gap = (uint64_t)offset - (uint64_t)size;
        size_t chunk = gap < sizeof ff ? (size_t)gap : sizeof ff;
        ssize_t n = pwrite(fs->fd, ff, chunk, size);
        if (n <= 0) {
            return false;
        }
        size += n;
    }
    while (done < len) {
        ssize_t n = pwrite(fs->fd, data + done, len - done, (off_t)(offset + done));
        if (n < 0 && errno == EINTR) {
            continue;
        }
        if (n <= 0) {
            return false;
        }
        done += (uint32_t)n;
    }
    return true;
}

bool daran_sim_file_storage_open(daran_sim_file_storage_t *fs, const char *path,
                                 daran_sim_storage_t *st)
{
    fs->fd = open(path, O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fs->fd < 0) {
        return false;
    }
    st->ctx = fs;
    st->read = file_read;
    st->write = file_write;
    return true;
}

void daran_sim_file_storage_close(daran_sim_file_storage_t *fs)
{
    if (fs->fd >= 0) {
        (void)close(fs->fd);
        fs->fd = -1;
    }
}
