#pragma once

namespace vl::cli {

// Sets the process's heap up for runs that allocate, fill and free buffers of the input's size
// (file, decoded accessors, world-space geometry, output): freed memory is kept for reuse, and the
// heap's first reservation is backed by transparent huge pages where the kernel allows them
// (`madvise` mode). On the virtual machines we run on a 4 KiB page fault costs ~10 us, which was
// two thirds of `say --avatar` on a 15 MB avatar; 2 MiB pages make that 512 times rarer.
// Call once, first thing in main. Harmless where THP is off or `madvise` fails.
void tuneProcessMemory();

} // namespace vl::cli
