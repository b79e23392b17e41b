/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   A write killed at any moment leaves the previous SBRT intact
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <csignal>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "atomic_dir.hpp"
#include "format.hpp"
#include "test_support.hpp"
#include "voxel_builder.hpp"

using namespace sbrt;

namespace {

Model model_with_seed(unsigned seed, int size)
{
    return sbrt_test::build_model(sbrt_test::random_voxels(seed, size, size, 40));
}

} // namespace

TEST(AtomicWrite, UncommittedWriteLeavesTargetUntouched)
{
    const std::string dir = sbrt_test::temp_dir("atomic") + "/m";
    const Model old_model = model_with_seed(1, 8);
    write_sbrt(dir, old_model, "old\n");
    {
        AtomicDirectory pending(dir);
        pending.write_file("stacks", std::string("garbage"));
        // destroyed without commit(): as if the conversion failed
    }
    const Model back = read_sbrt(dir);
    EXPECT_EQ(encode_stacks(back), encode_stacks(old_model));
    remove_tree(dir.substr(0, dir.rfind('/')));
}

TEST(AtomicWrite, CommitReplacesAWholeDirectory)
{
    const std::string dir = sbrt_test::temp_dir("atomic") + "/m";
    write_sbrt(dir, model_with_seed(1, 8), "old\n");
    const Model new_model = model_with_seed(2, 9);
    write_sbrt(dir, new_model, "new\n");
    EXPECT_EQ(encode_stacks(read_sbrt(dir)), encode_stacks(new_model));
    remove_tree(dir.substr(0, dir.rfind('/')));
}

TEST(AtomicWrite, SigkillAtAnyMomentLeavesOldOrNewReadable)
{
    const std::string parent = sbrt_test::temp_dir("kill");
    const std::string dir = parent + "/m";
    const Model old_model = model_with_seed(3, 8);
    const Model new_model = model_with_seed(4, 120);
    const auto old_bytes = encode_stacks(old_model);
    const auto new_bytes = encode_stacks(new_model);
    write_sbrt(dir, old_model, "old\n");
    int saw_new = 0;
    // kills from 0.3 ms on; where no write got through (a slow machine, a
    // sanitizer build), on with doubling delays up to seconds
    for (int trial = 0; trial < 24 || (saw_new == 0 && trial < 36); ++trial) {
        const pid_t child = fork();
        ASSERT_GE(child, 0);
        if (child == 0) {
            for (;;)
                write_sbrt(dir, trial % 2 ? new_model : old_model, "x\n");
        }
        const long delay_us = trial < 24 ? 300 + trial * 997 : 25000L << ((trial - 24) / 2);
        std::this_thread::sleep_for(std::chrono::microseconds(delay_us));
        kill(child, SIGKILL);
        waitpid(child, nullptr, 0);
        const auto got = encode_stacks(read_sbrt(dir));
        EXPECT_TRUE(got == old_bytes || got == new_bytes) << "trial " << trial;
        saw_new += got == new_bytes;
    }
    EXPECT_GT(saw_new, 0); // the writes did get through sometimes
    remove_tree(parent);
}
