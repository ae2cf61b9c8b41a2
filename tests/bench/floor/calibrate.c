// A fixed amount of integer work (xorshift64, 2^28 steps, one dependency chain: no memory, no
// vectorisation), timed in CPU time. Its time says how fast this core runs now: benchmark figures
// recorded beside it can be compared across hours and machines by their ratio to it.
#include <stdint.h>
#include <stdio.h>
#include <time.h>

static double cpuSeconds(void) {
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int main(void) {
    uint64_t x = 88172645463325252ULL;
    const double start = cpuSeconds();
    for (uint64_t i = 0; i < (1ULL << 28); ++i) {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
    }
    const double seconds = cpuSeconds() - start;
    // The result is printed so the loop cannot be removed.
    printf("%.1f ms (checksum %llu)\n", 1e3 * seconds, (unsigned long long)(x & 0xffff));
    return 0;
}
