// Small-number storage for GMP (the exact kernel's rationals, course notes section 19 on
// why every decision is exact): a rational of a few digits keeps its numerator and its
// denominator in one 64-bit limb each, and glibc's malloc hands out at least 32 bytes for
// each (a 16-byte header and alignment). A million-triangle drawing holds tens of millions
// of such limbs (vertices, split parameters of the pieces), so that overhead was a third of
// its memory. The pool serves GMP's requests of up to 32 bytes from slabs of equal blocks.
//
// Which class a block belongs to follows from its address (each class has its own range of
// one address-space reservation), never from the size GMP passes back, so a caller that
// frees with a wrong size cannot corrupt the pool; blocks allocated before install() (static
// constants) and larger requests stay with malloc. Freed blocks go to the freeing thread's
// list and are reused; the pool never returns memory to the system (a command-line run
// ends soon after its peak). Programs opt in: the `hlr` tool installs it first thing; the
// library and the Python module leave GMP's allocator as the program that loads them set it.
#pragma once

#include <cstddef>

namespace hlr::gmp_pool {

/// Routes GMP's allocations of up to 32 bytes through the pool from now on. Call before
/// starting threads. Returns false (and changes nothing) when the address space cannot be
/// reserved; a second call does nothing and returns true. `huge_pages`: ask for transparent
/// huge pages on the slabs (fewer page faults on large runs).
bool install(bool huge_pages);

/// Whether install() succeeded.
bool installed();

/// Bytes of slab address space handed out so far (every class, touched or not).
std::size_t reserved_bytes();

}  // namespace hlr::gmp_pool
