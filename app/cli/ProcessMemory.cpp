#include "app/cli/ProcessMemory.h"

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

namespace vl::cli {

namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;
// Virtual only: pages are backed when touched, so an idle reservation costs no memory.
constexpr std::size_t kHugeHeapReservation = std::size_t{512} << 20;

// Grows the heap by the reservation and marks it for huge pages. glibc's own switch for this
// (GLIBC_TUNABLES=glibc.malloc.hugetlb=1) is read at start-up only; when a user set it, leave it be.
void reserveHugeHeap() {
    if (const char* tunables = std::getenv("GLIBC_TUNABLES"); tunables && std::strstr(tunables, "hugetlb"))
        return;
    mallopt(M_TOP_PAD, static_cast<int>(kHugeHeapReservation));
    void* volatile grow = std::malloc(std::size_t{1} << 20); // volatile: the pair must not be elided
    void* volatile base = std::malloc(64);                   // the heap's top: where new blocks start
    const auto start = (reinterpret_cast<std::uintptr_t>(base) + kHugePage - 1) & ~(kHugePage - 1);
    std::free(base);
    std::free(grow);
    const auto end = reinterpret_cast<std::uintptr_t>(sbrk(0)) & ~(kHugePage - 1);
    if (end > start) madvise(reinterpret_cast<void*>(start), end - start, MADV_HUGEPAGE);
}

} // namespace

void tuneProcessMemory() {
    // glibc hands freed memory back to the kernel and maps large blocks afresh, so every buffer paid
    // its page faults again (a third of `say --avatar`'s time before huge pages). Keep it for reuse.
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    reserveHugeHeap();
    mallopt(M_TOP_PAD, 64 << 20);
}

} // namespace vl::cli
