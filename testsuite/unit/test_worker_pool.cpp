/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   The render's worker pool: every row once, on workers kept
 *            from job to job, errors back to the caller, the pool usable
 *            after an error
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <atomic>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

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
