/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   The render's worker pool: every row once, on workers kept
 *            from job to job, rows in runs on one worker, errors back to
 *            the caller, the pool usable after an error
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <algorithm>
#include <atomic>
#include <map>
#include <mutex>
#include <numeric>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "util/parallel.hpp"
#include "util/worker_pool.hpp"

using namespace sbrt;

TEST(WorkerPool, EveryRowOnceOnTheSameThreadsJobAfterJob)
{
    WorkerPool pool(4);
    EXPECT_EQ(pool.size(), 4u);
    std::set<std::thread::id> all_ids;
    for (int job = 0; job < 50; ++job) {
        std::vector<std::atomic<int>> done(size_t(100 + job));
        std::vector<std::thread::id> ids(pool.size());
        std::atomic<bool> bad_worker{false};
        pool.for_each_row(3, int(done.size()), [&](int row, unsigned worker) {
            if (worker >= pool.size())
                bad_worker = true;
            else
                ids[worker] = std::this_thread::get_id();
            ++done[size_t(row)];
        });
        EXPECT_FALSE(bad_worker);
        for (size_t r = 0; r < done.size(); ++r)
            ASSERT_EQ(done[r].load(), r >= 3 ? 1 : 0) << "job " << job << " row " << r;
        // the pool's threads are the same ones job after job: never more
        // than its three in all
        all_ids.insert(ids.begin(), ids.end());
        all_ids.erase(std::thread::id());
        all_ids.erase(std::this_thread::get_id());
        EXPECT_LE(all_ids.size(), 3u) << "new threads by job " << job;
    }
}

TEST(WorkerPool, AnErrorOnAnyWorkerReachesTheCallerAndThePoolGoesOn)
{
    WorkerPool pool(3);
    for (int failing : {0, 57, 199}) {
        std::atomic<int> rows{0};
        EXPECT_THROW(pool.for_each_row(0, 200,
                                       [&](int row, unsigned) {
                                           ++rows;
                                           if (row == failing)
                                               throw std::runtime_error("row failed");
                                       }),
                     std::runtime_error);
        EXPECT_LE(rows.load(), 200);
    }
    std::atomic<int> rows{0};
    pool.for_each_row(0, 500, [&](int, unsigned) { ++rows; });
    EXPECT_EQ(rows.load(), 500);
    // no rows: returns at once
    pool.for_each_row(5, 5, [&](int, unsigned) { ++rows; });
    EXPECT_EQ(rows.load(), 500);
}

/// Per worker, the rows it was called with, in call order.
using RowsSeen = std::vector<std::vector<int>>;

/// Whether each worker's rows come in runs of `run` consecutive rows, each
/// run starting at first + a multiple of run (the last may be shorter).
void expect_runs(const RowsSeen &seen, int first, int last, int run)
{
    std::vector<int> all;
    for (const std::vector<int> &rows : seen) {
        all.insert(all.end(), rows.begin(), rows.end());
        for (size_t k = 0; k < rows.size(); ++k) {
            const int at = (rows[k] - first) % run;
            if (at == 0)
                continue;
            // inside a run: straight after the row before it, on this worker
            ASSERT_GT(k, 0u) << "row " << rows[k];
            EXPECT_EQ(rows[k - 1], rows[k] - 1) << "row " << rows[k];
        }
        for (size_t k = 0; k + 1 < rows.size(); ++k) {
            if ((rows[k] - first) % run != run - 1 && rows[k] != last - 1) {
                EXPECT_EQ(rows[k + 1], rows[k] + 1) << "a run cut after row " << rows[k];
            }
        }
    }
    std::sort(all.begin(), all.end());
    std::vector<int> expected(size_t(last - first));
    std::iota(expected.begin(), expected.end(), first);
    EXPECT_EQ(all, expected);
}

TEST(WorkerPool, RowsTakenInRunsComeInOrderOnOneWorkerEach)
{
    // a thread traces a run of consecutive rows (their rays cross the same
    // cells: its cache keeps them), every row once
    WorkerPool pool(4);
    for (int run : {1, 3, 8}) {
        RowsSeen seen(pool.size());
        pool.for_each_row(5, 205, [&](int row, unsigned worker) { seen[worker].push_back(row); },
                          run);
        expect_runs(seen, 5, 205, run);
    }
    // the free function, on threads of its own
    std::mutex mutex;
    std::map<std::thread::id, std::vector<int>> by_thread;
    for_each_row_in_runs(2, 99, 3, 6, [&](int row) {
        const std::lock_guard<std::mutex> lock(mutex);
        by_thread[std::this_thread::get_id()].push_back(row);
    });
    RowsSeen seen;
    for (auto &[id, rows] : by_thread)
        seen.push_back(rows);
    expect_runs(seen, 2, 99, 6);
    // at least 8 runs a thread, at most 8 rows a run
    EXPECT_EQ(rows_per_take(884, 16), 6);
    EXPECT_EQ(rows_per_take(1768, 16), 8);
    EXPECT_EQ(rows_per_take(60, 16), 1);
    EXPECT_EQ(rows_per_take(5000, 2), 8);
}
