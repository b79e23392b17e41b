/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The memory this process can still have, for the checks made
 *            before a large allocation (an import's grid, an image), and
 *            the memory it holds
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_AVAILABLE_MEMORY_HPP
#define SBRT_AVAILABLE_MEMORY_HPP

namespace sbrt {

/// Bytes this process can still have: the least of MemAvailable (else
/// physical memory), its address space limit (ulimit -v) less what it
/// maps, and its cgroup's memory.max less memory.current; 0 when none is
/// known.
double available_memory();

/// Bytes of this process resident in memory now (VmRSS); 0 when not known.
double resident_memory();

/// Gives the pages the C library's heap holds free back to the system
/// (glibc's malloc_trim: free chunks amid live ones too); nothing
/// elsewhere. Freed blocks of many sizes leave such holes: a cache that
/// drops and decodes blocks for long grew a tenth past its budget.
void release_free_heap();

} // namespace sbrt

#endif
