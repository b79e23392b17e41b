/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The memory this process can still have
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "util/available_memory.hpp"

#include <sys/resource.h>
#include <unistd.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <optional>
#include <string>

namespace sbrt {

namespace {

/// The first number after `key` on a line of a /proc or /sys file, times
/// `scale`; nothing when absent.
std::optional<double> field_of(const char *file, const char *key, double scale)
{
    std::ifstream in(file);
    std::string line;
    const std::string k = key;
    while (std::getline(in, line))
        if (line.compare(0, k.size(), k) == 0) {
            double v = 0;
            if (std::sscanf(line.c_str() + k.size(), "%lf", &v) == 1)
                return v * scale;
        }
    return std::nullopt;
}

} // namespace

double available_memory()
{
    double available = 0;
    if (auto kb = field_of("/proc/meminfo", "MemAvailable:", 1024))
        available = *kb;
    else if (sysconf(_SC_PHYS_PAGES) > 0 && sysconf(_SC_PAGE_SIZE) > 0)
        available = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
    auto least = [&](double v) {
        v = std::max(v, 1.0);
        available = available > 0 ? std::min(available, v) : v;
    };
    // ulimit -v: what is mapped already counts against it
    struct rlimit limit;
    if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
        least(double(limit.rlim_cur) -
              field_of("/proc/self/status", "VmSize:", 1024).value_or(0));
    // a container's memory (cgroup v2); "max" reads as no number
    if (auto max = field_of("/sys/fs/cgroup/memory.max", "", 1))
        least(*max - field_of("/sys/fs/cgroup/memory.current", "", 1).value_or(0));
    return available;
}

double resident_memory()
{
    return field_of("/proc/self/status", "VmRSS:", 1024).value_or(0);
}

void release_free_heap()
{
#ifdef __GLIBC__
    malloc_trim(0);
#endif
}

} // namespace sbrt
