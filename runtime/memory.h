// Memory of a contactcert process (the CLI, the benchmarks, the Python module). Exact arithmetic makes and drops
// millions of small numbers (a rational's denominator is one limb, most numerators one or two), and GMP asks its
// allocator for every one: blocks of up to kPooledBytes come from per-thread free lists, one per size in limbs, carved
// from 64 KiB slabs; larger blocks from malloc. Out of memory throws std::bad_alloc (GMP's default functions abort),
// which the CLI reports as exit 3.
#pragma once

#include <cstddef>

namespace contactcert::runtime {

/// Largest block served from the free lists (8 limbs); a freed block is kept for the next request of its size.
inline constexpr std::size_t kPooledBytes = 64;

/// Makes GMP, and MPFR through it, allocate with these functions (before any GMP number is made).
void use_pooled_gmp_memory();

/// For a library loaded into a process it does not own (the Python module): use_pooled_gmp_memory() if GMP still
/// allocates with its default functions, i.e. no other library in the process has replaced them (else nothing);
/// returns whether it did. Numbers made before stay valid: the default functions allocate with malloc, as these do
/// above kPooledBytes, and a smaller block freed here joins a free list. A library that replaces GMP's functions
/// later (Sage, python-gmp) would free pooled blocks with its own: it cannot share the process.
bool use_pooled_gmp_memory_if_default();

/// glibc gives the top of the heap back to the system once 128 KiB are free there, and serves large blocks from mmap:
/// a search that makes and drops one LP tableau after another then pays page faults for the same memory each time
/// (a jammed nc = 40 problem: 479 heap resizes and 4 times the solve time). The process keeps its heap until it
/// exits instead; blocks above 32 MiB still come from mmap.
///
/// The first touch of each 4 KiB page is a page fault, and on a virtual machine a fault costs 15-20 us: a ucp run on
/// a 58 KB problem touched ~500 heap pages, a third of its CPU time. The next 16 MiB of the heap are therefore asked
/// for as transparent huge pages (madvise; the kernel may decline), where one fault maps 2 MiB. Only the pages a run
/// touches are ever backed.
void keep_heap_until_exit();

}  // namespace contactcert::runtime
