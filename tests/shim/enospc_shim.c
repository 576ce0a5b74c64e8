/* LD_PRELOAD shim for the data-safety tests: makes writes to chosen files fail as on a full disk.
 *   GRANREPRO_SHIM_FAIL_WRITE=<substring>  write/pwrite to a file whose path contains it fail with
 *                                          ENOSPC once GRANREPRO_SHIM_FAIL_AFTER bytes (default 0)
 *                                          were written to such files by this process;
 *   GRANREPRO_SHIM_FAIL_FSYNC=<substring>  fsync/fdatasync of such a file fail with EIO;
 *   GRANREPRO_SHIM_FAIL_UNLINK=<substring> unlink/unlinkat/remove of a path (or, for unlinkat, a
 *                                          name) that contains it fail with EPERM, as for a file
 *                                          that root cannot delete either (chattr +i).
 * The path of a descriptor is read from /proc/self/fd. Writes inside libc (fwrite, e.g. gnuplot's)
 * are not seen; ours (write(2)) and HDF5's (pwrite(2)) are. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <unistd.h>

static long long written = 0;

static int matches(int fd, const char* var) {
    const char* want = getenv(var);
    if (!want || !*want) return 0;
    char link[64], path[4096];
    snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
    const ssize_t n = readlink(link, path, sizeof path - 1);
    if (n <= 0) return 0;
    path[n] = '\0';
    return strstr(path, want) != NULL;
}

/* How many of `count` bytes may still be written; -1 with errno = ENOSPC if none. */
static ssize_t allowance(int fd, size_t count) {
    if (!matches(fd, "GRANREPRO_SHIM_FAIL_WRITE")) return (ssize_t)count;
    const char* after = getenv("GRANREPRO_SHIM_FAIL_AFTER");
    const long long limit = after ? atoll(after) : 0;
    if (written >= limit) {
        errno = ENOSPC;
        return -1;
    }
    const long long left = limit - written;
    return (ssize_t)((long long)count < left ? (long long)count : left);
}

ssize_t write(int fd, const void* buf, size_t count) {
    static ssize_t (*real)(int, const void*, size_t);
    if (!real) real = (ssize_t (*)(int, const void*, size_t))dlsym(RTLD_NEXT, "write");
    const ssize_t allowed = allowance(fd, count);
    if (allowed < 0) return -1;
    const ssize_t n = real(fd, buf, (size_t)allowed);
    if (n > 0 && matches(fd, "GRANREPRO_SHIM_FAIL_WRITE")) written += n;
    return n;
}

ssize_t pwrite(int fd, const void* buf, size_t count, off_t offset) {
    static ssize_t (*real)(int, const void*, size_t, off_t);
    if (!real) real = (ssize_t (*)(int, const void*, size_t, off_t))dlsym(RTLD_NEXT, "pwrite");
    const ssize_t allowed = allowance(fd, count);
    if (allowed < 0) return -1;
    const ssize_t n = real(fd, buf, (size_t)allowed, offset);
    if (n > 0 && matches(fd, "GRANREPRO_SHIM_FAIL_WRITE")) written += n;
    return n;
}

ssize_t pwrite64(int fd, const void* buf, size_t count, off_t offset) { return pwrite(fd, buf, count, offset); }

int fsync(int fd) {
    static int (*real)(int);
    if (!real) real = (int (*)(int))dlsym(RTLD_NEXT, "fsync");
    if (matches(fd, "GRANREPRO_SHIM_FAIL_FSYNC")) {
        errno = EIO;
        return -1;
    }
    return real(fd);
}

int fdatasync(int fd) { return fsync(fd); }

static int undeletable(const char* path) {
    const char* want = getenv("GRANREPRO_SHIM_FAIL_UNLINK");
    if (!want || !*want || !path || !strstr(path, want)) return 0;
    errno = EPERM;
    return 1;
}

int unlink(const char* path) {
    static int (*real)(const char*);
    if (!real) real = (int (*)(const char*))dlsym(RTLD_NEXT, "unlink");
    return undeletable(path) ? -1 : real(path);
}

int unlinkat(int dirfd, const char* path, int flags) {
    static int (*real)(int, const char*, int);
    if (!real) real = (int (*)(int, const char*, int))dlsym(RTLD_NEXT, "unlinkat");
    return undeletable(path) ? -1 : real(dirfd, path, flags);
}

int remove(const char* path) {
    static int (*real)(const char*);
    if (!real) real = (int (*)(const char*))dlsym(RTLD_NEXT, "remove");
    return undeletable(path) ? -1 : real(path);
}
