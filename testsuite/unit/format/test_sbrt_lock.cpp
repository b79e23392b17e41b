/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   The writers' lock of an SBRT (issue 48, item 3): holders one
 *            after the other, a bounded wait that ends in an error naming
 *            the SBRT, a lock file that is no regular file refused at once
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <sys/stat.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "format/sbrt_lock.hpp"
#include "test_support.hpp"
#include "util/error.hpp"

using namespace sbrt;
using std::chrono::milliseconds;

TEST(SbrtLock, LockFileIsAHiddenSibling)
{
    EXPECT_EQ(SbrtLock::lock_path("/g/loc/map/sbrt/geo"), "/g/loc/map/sbrt/.geo.lock");
    EXPECT_EQ(SbrtLock::lock_path("/g/loc/map/sbrt/geo//"), "/g/loc/map/sbrt/.geo.lock");
    EXPECT_EQ(SbrtLock::lock_path("geo"), ".geo.lock");
    EXPECT_THROW(SbrtLock::lock_path("/g/.."), Error);
    EXPECT_THROW(SbrtLock::lock_path("/"), Error);
}

TEST(SbrtLock, SecondHolderWaitsThenFailsNamingTheSbrt)
{
    const std::string dir = sbrt_test::temp_dir("lock_wait") + "/geo";
    const SbrtLock first(dir, milliseconds(0));
    const auto start = std::chrono::steady_clock::now();
    try {
        const SbrtLock second(dir, milliseconds(200));
        FAIL() << "a second lock while the first is held";
    }
    catch (const Error &e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(dir + ": another process is changing it"), std::string::npos)
            << message;
    }
    const auto waited = std::chrono::steady_clock::now() - start;
    EXPECT_GE(waited, milliseconds(200)); // it did wait for the holder
    EXPECT_LT(waited, milliseconds(5000)); // and no longer than bounded
}

TEST(SbrtLock, ReleasedWithItsHolder)
{
    const std::string dir = sbrt_test::temp_dir("lock_release") + "/geo";
    { const SbrtLock first(dir, milliseconds(0)); }
    EXPECT_NO_THROW(SbrtLock(dir, milliseconds(0)));
    // moved: the new owner holds it, the moved-from object lets nothing go
    SbrtLock held(dir, milliseconds(0));
    SbrtLock moved(std::move(held));
    EXPECT_THROW(SbrtLock(dir, milliseconds(0)), Error);
}

TEST(SbrtLock, HoldersChangeOneAfterTheOther)
{
    // read-modify-write of a counter by 8 threads, each under its own lock
    // (flock: each SbrtLock opens the file anew, so threads exclude each
    // other as processes do): without the lock, updates are lost
    const std::string dir = sbrt_test::temp_dir("lock_serial") + "/geo";
    std::atomic<int> counter{0};
    const int threads = 8, rounds = 50;
    std::vector<std::thread> workers;
    for (int t = 0; t < threads; ++t)
        workers.emplace_back([&] {
            for (int r = 0; r < rounds; ++r) {
                const SbrtLock lock(dir, milliseconds(30000));
                const int seen = counter.load();
                std::this_thread::yield();
                counter.store(seen + 1);
            }
        });
    for (std::thread &w : workers)
        w.join();
    EXPECT_EQ(counter.load(), threads * rounds);
}

TEST(SbrtLock, WaiterGetsTheLockOnlyOnceTheHolderLetsGo)
{
    const std::string dir = sbrt_test::temp_dir("lock_order") + "/geo";
    std::atomic<bool> released{false}, released_when_taken{false};
    auto first = std::make_unique<SbrtLock>(dir, milliseconds(0));
    std::thread waiter([&] {
        const SbrtLock second(dir, milliseconds(30000));
        released_when_taken = released.load();
    });
    std::this_thread::sleep_for(milliseconds(50)); // let the waiter start waiting
    released = true;
    first.reset();
    waiter.join();
    EXPECT_TRUE(released_when_taken.load());
}

TEST(SbrtLock, LockFileThatIsNoRegularFileIsRefusedAtOnce)
{
    const std::string parent = sbrt_test::temp_dir("lock_odd");
    ASSERT_EQ(mkfifo((parent + "/.fifo.lock").c_str(), 0644), 0);
    std::filesystem::create_directory(parent + "/.dir.lock");
    std::filesystem::create_symlink("/dev/zero", parent + "/.link.lock");
    for (const char *name : {"fifo", "dir", "link"}) {
        try {
            const SbrtLock lock(parent + "/" + name, milliseconds(0));
            ADD_FAILURE() << name << ": locked";
        }
        catch (const Error &e) {
            EXPECT_NE(std::string(e.what()).find(parent + "/." + name + ".lock"),
                      std::string::npos)
                << e.what();
        }
    }
}
