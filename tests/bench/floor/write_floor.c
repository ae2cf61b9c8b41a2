/* The physical write floor of scripts/bench-large-mesh.sh, built outside VisemeLab: writes files of
 * the given sizes into FOLDER from one buffer (no formatting), fsyncs each file and the folder.
 * usage: write_floor FOLDER SIZE... */
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int main(int argc, char** argv) {
    if (argc < 3) return fprintf(stderr, "usage: write_floor FOLDER SIZE...\n"), 2;
    size_t largest = 0;
    for (int i = 2; i < argc; ++i) {
        const size_t size = strtoull(argv[i], NULL, 10);
        if (size > largest) largest = size;
    }
    char* buffer = malloc(largest ? largest : 1);
    if (!buffer) return perror("malloc"), 1;
    memset(buffer, 'x', largest); /* counted: a writer has its bytes in memory before writing them */
    for (int i = 2; i < argc; ++i) {
        char path[4096];
        snprintf(path, sizeof path, "%s/f%d", argv[1], i);
        const int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd < 0) return perror(path), 1;
        size_t done = 0, size = strtoull(argv[i], NULL, 10);
        while (done < size) {
            const ssize_t n = write(fd, buffer + done, size - done);
            if (n < 0) return perror("write"), 1;
            done += (size_t)n;
        }
        if (fsync(fd) != 0) return perror("fsync"), 1;
        close(fd);
    }
    const int dir = open(argv[1], O_RDONLY);
    if (dir < 0 || fsync(dir) != 0) return perror(argv[1]), 1;
    close(dir);
    free(buffer);
    return 0;
}
