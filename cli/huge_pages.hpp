// Memory for large jobs: the process's heap on transparent huge pages (see huge_pages.cpp).
#pragma once

namespace hlr::cli {

/// Restarts the process once with glibc's malloc set to back its heap with transparent huge
/// pages, to grow it in large steps and to keep what it freed (GLIBC_TUNABLES
/// glibc.malloc.hugetlb, top_pad, trim_threshold, mmap_threshold), unless the environment
/// already sets glibc.malloc.hugetlb or HLR_MALLOC=system. Returns (doing nothing) where the
/// restart is not possible.
void use_huge_pages(char** argv);

}  // namespace hlr::cli
