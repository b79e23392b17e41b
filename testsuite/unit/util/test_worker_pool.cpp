/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   The render's worker pool: every row once, on workers kept
 *            from job to job, rows in runs on one worker, errors back to
 *            the caller, the pool usable after an error
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <map>
#include <mutex>
#include <numeric>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "tracing/cpu_tracing.hpp"
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

/// Per worker (or thread), the rows it was called with, in call order.
using RowsSeen = std::vector<std::vector<int>>;

/// Every row of [first, last) once among `seen`; returns the count of runs
/// of consecutive rows the workers were called with (a take, or takes one
/// after another).
size_t runs_of_rows(const RowsSeen &seen, int first, int last)
{
    std::vector<int> all;
    size_t runs = 0;
    for (const std::vector<int> &rows : seen) {
        all.insert(all.end(), rows.begin(), rows.end());
        for (size_t k = 0; k < rows.size(); ++k)
            runs += k == 0 || rows[k] != rows[k - 1] + 1;
    }
    std::sort(all.begin(), all.end());
    std::vector<int> expected(size_t(last - first));
    std::iota(expected.begin(), expected.end(), first);
    EXPECT_EQ(all, expected);
    return runs;
}

TEST(WorkerPool, RowsTakenInRunsComeInOrderOnOneWorkerEach)
{
    // a thread traces runs of consecutive rows (their rays cross the same
    // cells: its cache keeps them), fewer rows a take as the rows run out,
    // every row once; rows that take a while (20 us), so that every worker
    // takes some between the others' takes
    const auto slow = [] { std::this_thread::sleep_for(std::chrono::microseconds(20)); };
    WorkerPool pool(4);
    RowsSeen seen(pool.size());
    pool.for_each_row(5, 805, [&](int row, unsigned worker) {
        slow();
        seen[worker].push_back(row);
    }, 8);
    // takes of 8 until 64 rows are left, then fewer: about 120 takes or
    // fewer (adjacent ones may join), against 800 a row at a time
    EXPECT_LE(runs_of_rows(seen, 5, 805), 150u);
    // the free function, on threads of its own
    std::mutex mutex;
    std::map<std::thread::id, std::vector<int>> by_thread;
    for_each_row_in_runs(2, 399, 3, 8, [&](int row) {
        slow();
        const std::lock_guard<std::mutex> lock(mutex);
        by_thread[std::this_thread::get_id()].push_back(row);
    });
    RowsSeen threads;
    for (auto &[id, rows] : by_thread)
        threads.push_back(rows);
    EXPECT_LE(runs_of_rows(threads, 2, 399), 70u);
    // a row at a time: the workers' rows interleave
    RowsSeen single(pool.size());
    pool.for_each_row(0, 200, [&](int row, unsigned worker) {
        slow();
        single[worker].push_back(row);
    });
    EXPECT_GT(runs_of_rows(single, 0, 200), 60u);
    // takes: at most `most`, half a thread's share of what is left, one
    // at the end
    EXPECT_EQ(rows_to_take(1000, 16, 8), 8);
    EXPECT_EQ(rows_to_take(100, 16, 8), 3);
    EXPECT_EQ(rows_to_take(5, 16, 8), 1);
    EXPECT_EQ(rows_to_take(0, 16, 8), 1);
    EXPECT_EQ(rows_to_take(1000, 2, 1), 1);
}

TEST(WorkerPool, TakesAndTheirBlocksCoverEveryPixelOnce)
{
    // the renderer's order: takes of consecutive rows, each traced block
    // by block (for_each_block), a block's rows top to bottom
    WorkerPool pool(3);
    const int first = 3, last = 203, cols = 2 * COLS_PER_BLOCK + 21;
    std::vector<int> visits(size_t(last) * size_t(cols), 0);
    std::mutex mutex;
    std::vector<std::pair<int, int>> takes;
    pool.for_each_take(first, last, [&](int take_first, int take_end, unsigned) {
        std::vector<std::array<int, 3>> order;
        for_each_block(take_first, take_end, cols,
                       [&](int row, int c0, int c1) { order.push_back({c0, row, c1}); });
        // blocks left to right, each down the take's rows
        EXPECT_TRUE(std::is_sorted(order.begin(), order.end()));
        EXPECT_EQ(order.size(), size_t(take_end - take_first) * 3);
        const std::lock_guard<std::mutex> lock(mutex);
        takes.emplace_back(take_first, take_end);
        for (const auto &[c0, row, c1] : order) {
            EXPECT_LE(c1 - c0, COLS_PER_BLOCK);
            for (int col = c0; col < c1; ++col)
                ++visits[size_t(row) * size_t(cols) + size_t(col)];
        }
    }, ROWS_PER_TAKE);
    for (int row = 0; row < last; ++row)
        for (int col = 0; col < cols; ++col)
            ASSERT_EQ(visits[size_t(row) * size_t(cols) + size_t(col)], row >= first ? 1 : 0)
                << "row " << row << ", column " << col;
    // consecutive takes of at most ROWS_PER_TAKE rows, end to end
    std::sort(takes.begin(), takes.end());
    int next = first;
    for (const auto &[take_first, take_end] : takes) {
        EXPECT_EQ(take_first, next);
        EXPECT_GE(take_end - take_first, 1);
        EXPECT_LE(take_end - take_first, ROWS_PER_TAKE);
        next = take_end;
    }
    EXPECT_EQ(next, last);
}
