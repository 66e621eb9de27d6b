// The hlr process: its heap on transparent huge pages, and its end without freeing (process.cpp).
#pragma once

namespace hlr::cli {

/// Restarts the process once with glibc's malloc set to back its heap with transparent huge
/// pages, to grow it in large steps and to keep what it freed (GLIBC_TUNABLES
/// glibc.malloc.hugetlb, top_pad, trim_threshold, mmap_threshold), unless the environment
/// already sets glibc.malloc.hugetlb or HLR_MALLOC=system. A small job (render, info, explain,
/// clip or decompose of mesh files of 8 MiB at most) is not restarted: it sets the same
/// settings with mallopt and advises the first 256 MiB of its heap onto huge pages itself.
/// HLR_MALLOC=restart or =inprocess chooses; =show prints what was done. Returns (doing
/// nothing more) where the restart is not possible.
void use_huge_pages(char** argv);

/// Serves GMP's small blocks from the number pool (kernel/gmp_pool.hpp), unless
/// HLR_MALLOC=system or a sanitizer build. Call first thing, before any thread starts.
void use_number_pool();

/// Turns an arithmetic fault (SIGFPE: GMP's answer to a conversion of a number that is not
/// finite, or an integer division by zero) into a message and exit code 1 instead of a crash
/// (not in sanitizer builds, which report it with its stack). The outputs are written whole or
/// not at all, so none is left half-written.
void report_arithmetic_faults();

/// Ends the process with `code` once the output is written: flushes the standard streams and
/// exits without destroying what is still allocated (freeing a 1M-triangle model piece by piece
/// took 0.2 s after the SVG was on disk). Sanitizer builds return normally instead, so that the
/// leak check still sees everything.
void exit_without_teardown(int code);

}  // namespace hlr::cli
