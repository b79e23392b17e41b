/****************************************************************************
 * MODULE:    benchmarks/machine_probe (r3.sbrt addon)
 * PURPOSE:   What the machine itself gives `threads` threads of one
 *            process, each with work of its own (nothing shared, nothing
 *            waited for), against one thread alone: issue 32 asks, where
 *            the CPU tracer's 16-core efficiency falls short, for the
 *            machine's own limit shown with figures. Three kinds of work:
 *              compute  floating-point chains in registers (the clock, and
 *                       cores that are a hyperthread's siblings)
 *              stream   reading a buffer of the thread's own, far larger
 *                       than the caches (memory bandwidth)
 *              chase    dependent random reads in one buffer shared by
 *                       all threads, as large as a model's stacks (memory
 *                       latency under load: the tracer's pattern)
 *            Each thread's own rate, the slowest and the mean, and the
 *            mean as a share of one thread's (efficiency).
 * USAGE:     machine_probe [threads=N] (all cores) [mib=64] [chase_mib=128]
 *            (run it under taskset -c 0-(N-1), as the scaling table runs
 *            trace_bench)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <numeric>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

/// Runs work(thread) on `threads` threads started together; each one's
/// seconds.
std::vector<double> timed_on_threads(unsigned threads,
                                     const std::function<double(unsigned)> &work)
{
    std::vector<double> seconds(threads, 0.0), sink(threads, 0.0);
    std::vector<std::thread> pool;
    for (unsigned t = 0; t < threads; ++t)
        pool.emplace_back([&, t] {
            const auto start = Clock::now();
            sink[t] = work(t);
            seconds[t] = std::chrono::duration<double>(Clock::now() - start).count();
        });
    for (std::thread &t : pool)
        t.join();
    // the results are used, so no work is optimised away
    if (std::accumulate(sink.begin(), sink.end(), 0.0) == 1.2345)
        std::puts("");
    return seconds;
}

/// Eight independent multiply-add chains, `rounds` times.
double compute(uint64_t rounds)
{
    double x[8];
    for (int k = 0; k < 8; ++k)
        x[k] = 1.0 + k * 1e-3;
    for (uint64_t r = 0; r < rounds; ++r)
        for (int k = 0; k < 8; ++k)
            x[k] = x[k] * 0.9999999 + 1e-7;
    return std::accumulate(x, x + 8, 0.0);
}

/// The sum of `words`, read `passes` times.
double stream(const std::vector<uint64_t> &words, int passes)
{
    uint64_t sum = 0;
    for (int p = 0; p < passes; ++p)
        for (uint64_t w : words)
            sum += w;
    return double(sum);
}

/// `steps` dependent reads through `next`, from `start`.
double chase(const std::vector<uint32_t> &next, uint32_t start, uint64_t steps)
{
    uint32_t at = start;
    for (uint64_t s = 0; s < steps; ++s)
        at = next[at];
    return double(at);
}

/// The best of three runs of `work` on `threads` threads (by the mean of
/// the threads' rates, work_per_thread / seconds): each thread's rate.
std::vector<double> best_rates(unsigned threads, double work_per_thread,
                               const std::function<double(unsigned)> &work)
{
    std::vector<double> best;
    double best_mean = 0;
    for (int run = 0; run < 3; ++run) {
        std::vector<double> rate;
        for (double s : timed_on_threads(threads, work))
            rate.push_back(work_per_thread / s);
        const double mean = std::accumulate(rate.begin(), rate.end(), 0.0) / double(threads);
        if (mean > best_mean) {
            best_mean = mean;
            best = rate;
        }
    }
    return best;
}

/// One kind of work alone and on `threads` threads, printed.
void probe(const char *kind, const char *unit, unsigned threads, double work_per_thread,
           const std::function<double(unsigned)> &work)
{
    const double alone = best_rates(1, work_per_thread, work).front();
    const std::vector<double> rate = best_rates(threads, work_per_thread, work);
    const double mean = std::accumulate(rate.begin(), rate.end(), 0.0) / double(threads);
    const double least = *std::min_element(rate.begin(), rate.end());
    std::printf("machine %s threads=%u %s_alone=%.3g %s_per_thread=%.3g least=%.3g "
                "total=%.3g efficiency=%.3f\n",
                kind, threads, unit, alone, unit, mean, least, mean * threads, mean / alone);
}

} // namespace

int main(int argc, char *argv[])
{
    const uint64_t rounds_warm_up = 50'000'000;
    unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    size_t mib = 64, chase_mib = 128;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const size_t eq = a.find('=');
        const std::string key = a.substr(0, eq), value = eq == a.npos ? "" : a.substr(eq + 1);
        if (key == "threads")
            threads = unsigned(std::max(1, std::atoi(value.c_str())));
        else if (key == "mib")
            mib = size_t(std::max(1, std::atoi(value.c_str())));
        else if (key == "chase_mib")
            chase_mib = size_t(std::max(1, std::atoi(value.c_str())));
        else {
            std::fprintf(stderr, "machine_probe: unknown argument %s\n", argv[i]);
            return 2;
        }
    }
    compute(rounds_warm_up); // the clock up before the first figure
    const uint64_t rounds = 25'000'000;
    probe("compute", "flops", threads, 8.0 * double(rounds),
          [&](unsigned) { return compute(rounds); });

    // stream: each thread's own buffer, written by it first (its pages)
    std::vector<std::vector<uint64_t>> buffers(threads);
    timed_on_threads(threads, [&](unsigned t) {
        buffers[t].assign(mib << 17, uint64_t(t) + 1);
        return 0.0;
    });
    const int passes = 8;
    probe("stream", "bytes_per_s", threads, double(mib << 20) * passes,
          [&](unsigned t) { return stream(buffers[t], passes); });
    buffers.clear();

    // chase: one random cycle through a buffer all threads share, each
    // thread from another place in it
    std::vector<uint32_t> next((chase_mib << 20) / sizeof(uint32_t));
    std::vector<uint32_t> order(next.size());
    std::iota(order.begin(), order.end(), 0u);
    std::shuffle(order.begin() + 1, order.end(), std::mt19937(7));
    for (size_t k = 0; k < order.size(); ++k)
        next[order[k]] = order[(k + 1) % order.size()];
    const uint64_t steps = 1'000'000;
    probe("chase", "reads_per_s", threads, double(steps), [&](unsigned t) {
        return chase(next, order[(uint64_t(t) * 7919u) % order.size()], steps);
    });
    return 0;
}
